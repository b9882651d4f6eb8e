// The frame side of the pipeline as one study: a load history at named load
// points drives the beam model of the frame (fem/), whose transient response
// gives section forces and corner stresses along the rails over time.
//
// The study's `frame:` block (docs/user-guide.md, "Frame transient studies"):
//
//   frame:
//     mesh: meshes/r100_frame.inp          # path relative to the study file
//     loads: offset_plowing_loads.csv      # load-history file (coupling/load_history.h)
//     supports: fixed_rear_end             # or free_free_inertia_relief
//     modes: 20                            # elastic modes, or "all"
//     method: mode_acceleration            # mode_displacement | mode_acceleration | direct
//     damping: {modal_ratio: 0.02}         # or {rayleigh: {alpha: 1/s, beta: s}}
//     output_interval: 0.002               # s (default: every load-history time)
//     stations: 5                          # per element, ends included
//     pvd: true                            # ParaView time series
//
// Reading (read_frame_block / read_frame_study), running (run_frame_study)
// and writing (write_frame_outputs, frame_summary_json) are separate, so a
// study or a Python binding can run many cases without files.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/results_folder.h"
#include <nlohmann/json.hpp>
#include "core/units.h"
#include "coupling/load_history.h"
#include "coupling/load_mapping.h"
#include "coupling/rail_stress.h"
#include "coupling/yaml_input.h"
#include "fem/direct_integration.h"
#include "fem/frame_model.h"
#include "fem/modal_transient.h"

namespace framedyn::coupling {

enum class FrameSupports {
  fixed_rear_end,            // all six DOFs of the mesh's REAR_END nodes fixed (the thesis's SAPIV model)
  free_free_inertia_relief,  // no supports; loads relieved by the rigid-body inertia (Eq. T.9)
};

enum class FrameMethod { mode_displacement, mode_acceleration, direct };

struct FrameStudyRequest {
  std::string file;                          // the study file, for messages
  std::string name;
  core::UnitSystem units = core::UnitSystem::si();  // the study's units (output columns)
  std::filesystem::path mesh;                // resolved against the study file's folder
  std::optional<std::filesystem::path> loads;  // load-history file; empty: the caller supplies the history
  FrameSupports supports = FrameSupports::fixed_rear_end;
  std::string support_set = "REAR_END";
  int modes = -1;                            // elastic modes used; -1: all (dense eigensolution)
  FrameMethod method = FrameMethod::mode_acceleration;
  fem::ModalDamping damping = fem::ModalDamping::ratio(0.02);
  std::optional<double> output_interval;     // s
  int stations = 5;
  bool pvd = false;
  int direct_substeps = 4;                   // Newmark steps per load-history interval
  bool convert_units = false;                // mesh or load history in other units than the study: convert (else refuse)
  std::vector<RailSpec> rails = {{"left_rail", "LEFT_RAIL"}, {"right_rail", "RIGHT_RAIL"}};
  // Where the keys checked only once the mesh and loads are read (supports,
  // support_set, modes, loads) were given, so those messages name a line:
  // the key's own line, or the block's when the key was left to its default.
  std::map<std::string, core::InputLocation> key_locations;
  // The location of a key of the frame block: from key_locations, else (a
  // request built in code) the study file and "frame.KEY" without a line.
  core::InputLocation where(const std::string& key) const;
};

// The `frame:` map of a study; throws core::InputError with file, line and key path.
FrameStudyRequest read_frame_block(const YamlMap& frame, const std::filesystem::path& study_dir);
// A study file with `framedyn_study: 1`, `units`, `model: frame_transient` and a `frame:` block.
FrameStudyRequest read_frame_study(const std::string& file);

struct FrameStudyResults {
  fem::FrameModel model;                     // the mesh with the study's supports
  LoadHistory loads;
  LoadMapping mapping;
  Eigen::VectorXd frequencies_hz;            // elastic modes (those used; the lowest 20 for `direct`)
  fem::TransientResult response;
  std::vector<RailRecovery> rails;
  double wall_seconds = 0.0;
};

// Runs the study. `loads` replaces the request's load-history file (e.g. the
// loads the rigid-body run just recovered). Throws core::InputError for a
// load point the mesh cannot take, core::NumericalError for a failed solve.
FrameStudyResults run_frame_study(const FrameStudyRequest& request, const LoadHistory* loads = nullptr);

// frame_modes.csv, frame_rails_envelope.csv, frame_rails_series.csv and, with
// request.pvd, frame_response.pvd + frame_response_NNNNN.vtu, in the study's units.
void write_frame_outputs(const FrameStudyResults& results, const FrameStudyRequest& request, const core::ResultsFolder& folder);
// The summary's "frame" object as JSON text: modes[i].frequency_hz,
// peak_bending_moment.left_rail / .right_rail, peak_normal_stress (value + unit,
// where and when), bending_share.
nlohmann::ordered_json frame_summary(const FrameStudyResults& results, const FrameStudyRequest& request);
std::string frame_summary_json(const FrameStudyResults& results, const FrameStudyRequest& request);  // frame_summary(...).dump(2)

}  // namespace framedyn::coupling
