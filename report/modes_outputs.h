// The outputs of `framedyn modes`: summary.json (key "frame": masses,
// rigid-body modes, the Sturm check, per mode its frequency, participation
// factors and effective masses, docs/theory/fem.md Eqs. 7.4, 7.5), modes.csv
// (one row per mode), mode_shapes.csv (mass-normalised shapes per node) and
// modes.vtu (ParaView), in the mesh's units with the units from core/units.
#pragma once

#include <string>

#include "core/results_folder.h"
#include "fem/frame_model.h"
#include "fem/modal_analysis.h"

namespace framedyn::report {

// What the run was asked (summary.json's input and solver entries).
struct ModesRun {
  std::string mesh_path;
  bool lumped = false;
  double shift_hz = 1.0;
};

void write_modes_results(const fem::FrameModel& model, const fem::ModalResult& result, const ModesRun& run, const core::ResultsFolder& folder);

}  // namespace framedyn::report
