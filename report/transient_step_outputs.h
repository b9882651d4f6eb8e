// The outputs of `framedyn transient` (a *MODAL DYNAMIC or *DYNAMIC step of a
// deck): displacement_history.csv (time, node, ux..rz of the output nodes at
// every output time), section_force_history.csv (time, element, end, N, Vy,
// Vz, T, My, Mz at both ends of the output elements, recovered from the
// displacements as `framedyn static` recovers them: fem/section_forces.h),
// the ParaView series transient.xdmf + transient.h5 (displacement and
// rotation per node, the twelve end forces per element, at every output
// time) and summary.json (key "frame.transient": procedure, scheme,
// increment, period, modes used, the largest translation with its node, DOF
// and time, the largest end bending moment with its element, end and time,
// and the reader's warnings), in the mesh's units.
#pragma once

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "core/results_folder.h"
#include "fem/section_forces.h"
#include "fem/transient_step.h"

namespace framedyn::report {

struct TransientStepRun {
  std::string mesh_path;
  std::vector<int> output_nodes;  // node indices
  std::string element_set;        // the section-force history's *ELSET; empty: every beam
  std::vector<int> output_beams;  // indices into model.beams of the section-force history
  bool paraview = true;           // transient.xdmf + transient.h5
};

// The largest translation component |u| over the output nodes and times. Of
// entries within 1e-6 relative of the largest the earliest time, then the
// lowest node index, then the lowest DOF is named, so that round-off never
// picks between near-equal peaks.
struct TransientPeak {
  double value = 0.0;  // SI, signed
  int node = 0;        // mesh node number
  int dof = 0;         // 0..2
  double time = 0.0;   // s
};
TransientPeak transient_peak(const fem::FrameModel& model, const fem::TransientResult& r, const std::vector<int>& output_nodes);

// Section forces at both ends of every beam at every output time (fixed-end
// terms of the step's line loads included): [time][2 * beam + end], SI.
using EndForceHistory = std::vector<std::vector<fem::SectionForces>>;
EndForceHistory transient_end_forces(const fem::FrameModel& model, const fem::TransientStepResult& result);

// The largest resultant bending moment sqrt(My^2 + Mz^2) at the ends of the
// output beams over the output times; of values within 1e-6 relative of it
// the earliest time, then the lowest beam index, then end 1 is named.
struct TransientMomentPeak {
  double value = 0.0;  // N m
  int element = 0;     // mesh element number
  int end = 1;         // 1: node a, 2: node b
  double time = 0.0;   // s
};
TransientMomentPeak transient_moment_peak(const fem::FrameModel& model, const fem::TransientResult& r, const EndForceHistory& forces,
                                          const std::vector<int>& output_beams);

// Writes displacement_history.csv, section_force_history.csv and (with
// run.paraview) transient.xdmf + transient.h5, and returns summary.json's
// content with the model's reader warnings (the caller writes it).
nlohmann::ordered_json write_transient_step_results(const fem::FrameModel& model, const fem::TransientStepResult& result,
                                                    const TransientStepRun& run, const core::ResultsFolder& folder);

}  // namespace framedyn::report
