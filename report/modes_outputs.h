// The outputs of `framedyn modes`: summary.json (key "frame": masses,
// rigid-body modes, the Sturm check, per mode its frequency, participation
// factors and effective masses, docs/theory/fem.md Eqs. 7.4, 7.5), modes.csv
// (one row per mode), on request mode_shapes.csv (mass-normalised shapes per
// node), and the ParaView output: modes.xdmf + modes.h5 (each mode a "time",
// its number, so ParaView's time controls step through the modes with one
// field "mode_shape") or modes.vtu (one field per mode), in the mesh's units
// with the units from core/units.
#pragma once

#include <string>

#include "core/results_folder.h"
#include "fem/frame_model.h"
#include "coupling/frame_study.h"
#include "fem/modal_analysis.h"

namespace framedyn::report {

// The ParaView output of `framedyn modes` (the same choice as a frame study's).
using ParaviewOutput = coupling::ParaviewOutput;

// What the run was asked (summary.json's input and solver entries).
struct ModesRun {
  std::string mesh_path;
  bool lumped = false;
  double shift_hz = 1.0;
  ParaviewOutput paraview = ParaviewOutput::xdmf;
  bool mode_shapes_csv = false;  // the text table of full shapes (161 MB on a 10^6-DOF frame)
};

void write_modes_results(const fem::FrameModel& model, const fem::ModalResult& result, const ModesRun& run, const core::ResultsFolder& folder);

}  // namespace framedyn::report
