// Refined frame meshes for benchmarks and peer tests: every beam of a base frame (the
// shipped R-100-like frame) cut into k equal elements, written as an .inp
// deck that framedyn and CalculiX both read. Tube sections are replaced by
// solid RECT sections of the same outline, because CalculiX's B31 accepts
// only RECT and CIRC; the rear end is clamped as in the thesis's SAPIV model.
#pragma once

#include <string>

#include "fem/frame_model.h"

namespace framedyn::testing {

// Number of subdivisions that gives about `target_dofs` free DOFs.
int subdivisions_for(const fem::FrameModel& base, long target_dofs);
// The deck (in the base model's units), clamped at the nodes of `clamped_set`.
std::string refined_frame_inp(const fem::FrameModel& base, int subdivisions, const std::string& clamped_set);

}  // namespace framedyn::testing
