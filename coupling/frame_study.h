// The frame side of the pipeline as one study: a load history at named load
// points drives the beam model of a frame (fem/), whose transient response
// gives nodal histories at the node sets and section forces and corner
// stresses along the element sets the study names as outputs.
//
// The study's `frame:` block (docs/user-guide.md, "Frame transient studies"):
//
//   frame:
//     mesh: meshes/r100_frame.inp          # path relative to the study file
//     loads: offset_plowing_loads.csv      # load-history file (coupling/load_history.h)
//     supports: clamped                    # clamped | mesh_boundary | none (= free_free_inertia_relief) | axle_pins | fixed_rear_end
//     support_set: REAR_END                # node set(s) clamped (a name or a list)
//     modes: 20                            # elastic modes, or "all"
//     method: mode_acceleration            # mode_displacement | mode_acceleration | direct
//     damping: {modal_ratio: 0.02}         # or {rayleigh: {alpha: 1/s, beta: s}}
//     output_interval: 0.002               # s (default: every load-history time)
//     stations: 5                          # per element, ends included
//     outputs:                             # output sets by name
//       left_rail: {element_set: LEFT_RAIL}
//       tip: {node_set: TIP}
//     paraview: xdmf                       # ParaView time series: xdmf (default) | vtu | none (older key pvd: true = vtu)
//     mesh_loads: constant                 # the mesh's *CLOAD/*DLOAD: constant loads throughout | none
//     steady_from: 0.5                     # s: steady operation from (else the rigid model's report, else the last half)
//     stress_histories: hot_spots          # none | hot_spots | all: frame_stress_histories.csv
//     yield_strength: 36000                # stress: warn when a von Mises stress exceeds it
//     dead_load: true                      # pipeline only: static state (gravity, static loads) + dynamic
//     compare_supports: [fixed_rear_end]   # pipeline only: the same loads on further supports, side by side
//
// Defaults: a `frame-response` study (read_frame_study) is supported by the
// mesh's own *BOUNDARY and has no output sets unless it names them; the
// pipeline's `frame_response` block of a 3-D study (FrameDefaults::pipeline)
// keeps the trencher's: REAR_END clamped, outputs left_rail and right_rail
// (element sets LEFT_RAIL, RIGHT_RAIL).
//
// Reading (read_frame_block / read_frame_study) and running (run_frame_study)
// are here; writing (report/frame_outputs.h) is separate, so a study or a
// Python binding can run many cases without files.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>


#include "core/results_folder.h"
#include "core/units.h"
#include "core/warnings.h"
#include "coupling/frame_balance.h"
#include "coupling/frame_dead_load.h"
#include "coupling/frame_fatigue.h"
#include "coupling/frame_parts.h"
#include "coupling/frame_sections.h"
#include "coupling/hot_spots.h"
#include "coupling/load_history.h"
#include "coupling/load_mapping.h"
#include "coupling/output_sets.h"
#include "coupling/rail_stress.h"
#include "coupling/yaml_input.h"
#include "fem/direct_integration.h"
#include "fem/frame_model.h"
#include "fem/inp_reader.h"
#include "fem/solver_counters.h"
#include "fem/modal_transient.h"

namespace framedyn::coupling {

class FrameModelCache;

enum class FrameSupports {
  fixed_rear_end,            // all six DOFs of the support sets fixed (REAR_END: the thesis's SAPIV model)
  clamped,                   // the same on any mesh: all six DOFs of the support sets fixed
  mesh_boundary,             // the mesh's own *BOUNDARY only
  free_free_inertia_relief,  // no supports ("none"); loads relieved by the rigid-body inertia (Eq. T.9)
  axle_pins,                 // held where the machine holds it: the same inertia relief, its statically determinate
                             // auxiliary supports at the rear axle pin, the front axle pin and the leveling cylinder
                             // (docs/theory/coupling.md, section 12)
};

// The defaults of keys a `frame` block leaves out.
enum class FrameDefaults {
  standalone,  // framedyn frame-response: supports mesh_boundary, no output sets
  pipeline,    // a 3-D study's frame_response: fixed_rear_end at REAR_END, outputs left_rail / right_rail
};

enum class FrameMethod { mode_displacement, mode_acceleration, direct };

// The ParaView time series: one XDMF 3 file + one HDF5 file (report/xdmf_writer),
// a .pvd collection + one .vtu per output time (report/vtu_writer), or none.
enum class ParaviewOutput { xdmf, vtu, none };

struct FrameStudyRequest {
  std::string file;                          // the study file, for messages
  std::string name;
  core::UnitSystem units = core::UnitSystem::si();  // the study's units (output columns)
  std::filesystem::path mesh;                // resolved against the study file's folder
  std::optional<std::filesystem::path> loads;  // load-history file; empty: the caller supplies the history
  // The members' defaults are the pipeline's (a request built in code is a trencher frame's).
  FrameSupports supports = FrameSupports::fixed_rear_end;
  std::vector<std::string> support_sets = {"REAR_END"};  // node sets clamped by fixed_rear_end / clamped
  // Pipeline only (frame_response.compare_supports): further supports the same
  // run's loads are applied on, each a study of its own (its own assembly and
  // factorisation), for the envelopes side by side and their peaks in the
  // summary (none, axle_pins, fixed_rear_end). Default: none compared.
  std::vector<FrameSupports> compare_supports;
  int modes = -1;                            // elastic modes used; -1: all (dense eigensolution)
  FrameMethod method = FrameMethod::mode_acceleration;
  fem::ModalDamping damping = fem::ModalDamping::ratio(0.02);
  std::optional<double> output_interval;     // s
  int stations = 5;
  ParaviewOutput paraview = ParaviewOutput::none;  // a study file's default: xdmf
  int direct_substeps = 4;                   // Newmark steps per load-history interval
  bool convert_units = false;                // mesh or load history in other units than the study: convert (else refuse)
  // frame.inp_dialect: how the mesh's SECTION=CIRC values are read (radius
  // for abaqus, diameter for calculix; docs/theory/fem.md section 23). Unset:
  // Abaqus's reading, and the circ_radius_or_diameter warning in the summary.
  std::optional<fem::InpDialect> inp_dialect;
  // frame.sections: section dimensions by element set, written into the mesh text before it is read (coupling/frame_sections.h).
  std::vector<SectionOverride> sections;
  // The mesh's own *CLOAD and *DLOAD (gravity) as constant loads acting
  // throughout, the response starting from the static equilibrium under them
  // (frame-response's default; the pipeline's loads come from the vehicle model).
  bool mesh_loads = false;
  // Static plus dynamic (docs/theory/coupling.md, section 11): the frame
  // model's static state under gravity and the vehicle model's static loads,
  // added to the dynamic response at every section point. The pipeline's
  // default (frame_response.dead_load: false for the thesis's dynamic-only
  // stresses); a frame-response study has no key (mesh_loads: constant there).
  bool dead_load = false;
  // m/s^2 in the frame model's axes: the vehicle model's axes, whose Z is
  // vertical whatever the ground slope (the ground, not gravity, is inclined).
  Eigen::Vector3d gravity{0.0, 0.0, -9.80665};
  // Output sets: element sets (section forces and stresses; the rails in the
  // pipeline) and node sets (nodal histories), in the study's order.
  std::vector<RailSpec> rails = {{"left_rail", "LEFT_RAIL"}, {"right_rail", "RIGHT_RAIL"}};
  std::vector<NodeOutputSpec> node_outputs;
  // Where the keys checked only once the mesh and loads are read (supports,
  // support_set, modes, loads, outputs.NAME) were given, so those messages
  // name a line: the key's own line, or the block's when the key was left to
  // its default.
  std::map<std::string, core::InputLocation> key_locations;
  // The frame assembly's parts the frame model carries as masses on rigid links or
  // distributing couplings to their mounts (coupling/frame_parts.h, SI); a 3-D study sets them from its frame.parts less
  // the frame structure the mesh models (coupling/frame_mass_source.h). Empty: the mesh alone.
  std::vector<FramePart> parts;
  std::string structure_part;                  // the frame part the mesh models ("" without a vehicle model)
  std::string structure_source;                // "mesh": the vehicle model took the structure's mass from the mesh
  std::vector<std::string> parts_carried_by_mesh;
  // Hot spots and stress histories (coupling/hot_spots.h): where steady operation
  // starts when the rigid-body model does not say (s), which histories to write,
  // and the yield strength a von Mises stress is checked against (Pa).
  std::optional<double> steady_from;
  enum class StressHistoryOutput { none, hot_spots, all } stress_histories = StressHistoryOutput::none;
  std::optional<double> yield_strength;
  // The fatigue life map (coupling/frame_fatigue.h): FAT classes per element set, hours.
  std::optional<FatigueRequest> fatigue;
  // The stress histories at every station and section point with their hot
  // spots and (with `fatigue`) the life map, and the section-force histories of
  // the outputs with `history`. Off for a run whose summary is read only where
  // none of them shows (a design study's outputs, report::StudyRunOptions::
  // summary_outputs): results.stress, static_forces, hot_spots, life and
  // sections stay empty; the rails' peaks, envelopes and series are the same.
  bool hot_spots = true;
  // Duty cycles only (coupling/duty_cycle.h; docs/theory/fatigue.md section 15): the steady
  // window's transient alone. With a modal method, the modal transient starts a lead-in
  // L = ln(1/eps) / min_i(decay rate of mode i) before the window's start t_s (the hot spots' own:
  // the rigid-body model's steady report, else frame.steady_from, else the record's last half;
  // coupling/hot_spots.h) (decay rate zeta_i omega_i for an
  // underdamped mode), from the static equilibrium under that time's loads, so that the free
  // response this start leaves has decayed to eps of its amplitude by t_s; and everything after the
  // transient (rails, stresses, hot spots, life map) covers the window alone. The value is eps;
  // unset (every study file's run): the whole record, from its first time.
  std::optional<double> window_lead_in_decay;
  // The location of a key of the frame block: from key_locations, else (a
  // request built in code) the study file and "frame.KEY" without a line.
  core::InputLocation where(const std::string& key) const;
};

// The `frame:` map of a study; throws core::InputError with file, line and key path.
FrameStudyRequest read_frame_block(const YamlMap& frame, const std::filesystem::path& study_dir,
                                   FrameDefaults defaults = FrameDefaults::pipeline);
// A study file with `framedyn_study: 1`, `units`, `model: frame_transient` and a `frame:` block.
FrameStudyRequest read_frame_study(const std::string& file);

struct FrameStudyResults {
  fem::FrameModel model;                     // the mesh with the study's supports and the mounted parts
  std::vector<MountedPart> parts;            // request.parts as placed on the model
  RigidBodyMass mass;                        // the model's rigid-body mass (tubes and parts; Eq. 9.3)
  LoadHistory loads;
  LoadMapping mapping;
  Eigen::VectorXd frequencies_hz;            // elastic modes (those used; the lowest 20 for `direct`)
  Eigen::MatrixXd mode_shapes;               // all DOFs x the lowest (up to 4) elastic modes, M-normalised: for figures
  fem::TransientResult response;
  std::vector<RailRecovery> rails;           // the element-set outputs, in request.rails' order
  std::vector<NodalHistory> nodal;           // the node-set outputs, in request.node_outputs' order
  std::vector<SectionHistory> sections;      // per element-set output with history (empty entries otherwise; none without request.hot_spots)
  double wall_seconds = 0.0;
  // Assemblies and factorisations during the run (fem/solver_counters.h): one
  // assembly of K and M, one mass-only assembly (the rigid-body mass) and one
  // factorisation with modes: all (more for modes: N or method: direct, whose
  // K - sigma M, M and Newmark matrices are other matrices than K).
  fem::SolverCounts solver_counts;
  // The mesh's loads applied as constant loads (mesh_loads: constant), all
  // DOFs (N, N m); empty when none acted.
  Eigen::VectorXd constant_load;
  int constant_cloads = 0, constant_dloads = 0;  // *CLOAD entries (GRAV on masses among them), beams with *DLOAD
  int free_rigid_motions = 0;                    // rigid motions the supports leave free (relieved, docs/theory/fem.md section 19)
  // supports: axle_pins: the six DOFs that hold the frame statically determinately (global DOF numbers,
  // node * 6 + dof; section 12); empty otherwise (free-free's own 3-2-1 choice is internal to the solver).
  std::vector<int> pin_supports;
  // With request.dead_load: the static state (gravity and the static loads),
  // whose section forces per output station the section-stress code takes.
  std::optional<FrameStaticState> static_state;
  // Stress histories at every station and section point of the element-set
  // outputs (dynamic section forces, single precision) and their hot spots
  // (docs/theory/coupling.md section 10). `static_forces`: the static
  // section forces per stress station (from static_state), added to the
  // dynamic ones (total = static + dynamic); empty: zero (no static state).
  StressHistories stress;
  std::vector<fem::SectionForces> static_forces;
  HotSpotReport hot_spots;
  // With request.fatigue: damage per hour and life at every station and section point.
  std::optional<LifeMap> life;
  // With request.window_lead_in_decay (a modal method, damped modes): where the modal transient started
  // and the outputs begin (s), the lead-in (s) and the slowest modal decay rate it was set from
  // (1/s). Unset otherwise; `transient_from` equals the record's first time when the lead-in
  // reaches back to it (the whole record was run; the outputs still start at the window).
  struct WindowOnly {
    double transient_from = 0.0, outputs_from = 0.0, lead_in = 0.0, decay_rate = 0.0;
  };
  std::optional<WindowOnly> window_only;
};

// The study's mesh read in the study's inp_dialect, refused (naming
// frame.mesh) when it is in other units than the study and convert_units is
// not set. The reader's warnings stay in the model's reader_warnings, which
// frame_warnings lists first.
fem::FrameModel read_frame_mesh(const FrameStudyRequest& request);

// Runs the study. `loads` replaces the request's load-history file (e.g. the
// loads the rigid-body run just recovered); `rigid_steady_from` is where the
// rigid-body model's steady report puts the start of steady operation (s),
// which the hot spots take before the study's frame.steady_from. Throws core::InputError for a
// support or output set the mesh lacks (naming the study's key and the mesh
// file) or a load point the mesh cannot take, core::NumericalError for a
// failed solve.
// `static_loads` (with request.dead_load): the static loads at the same load
// points as the history (one row; static_frame_loads_3d), null for gravity alone.
// `rigid_steady_from`: when the vehicle model reached steady operation (s), for the hot spots.
// `cache` (coupling/frame_model_cache.h): the model, its dynamics and modes are
// taken from it when built before for the same key, else built and kept there.
// `share` (core/work_share.h): idle workers of a pool may take output times and
// stations of the response, section forces, stresses, hot spots and life map;
// the results are the same numbers without it.
FrameStudyResults run_frame_study(const FrameStudyRequest& request, const LoadHistory* loads = nullptr, const LoadHistory* static_loads = nullptr,
                                  std::optional<double> rigid_steady_from = std::nullopt, FrameModelCache* cache = nullptr,
                                  core::WorkShare* share = nullptr);

// The names of the supports and the method as a study file spells them.
const char* supports_name(FrameSupports supports);
const char* method_name(FrameMethod method);

// Artificial supports: the clamp of `clamped` and `fixed_rear_end` (the
// thesis's SAPIV model), all six DOFs of the support_set nodes fixed, which a
// frame on a moving machine does not have (the mesh's own *BOUNDARY is taken
// as its author's real supports). `peak_at_artificial_support`: an output
// set's peak normal stress or resultant bending moment lies on an element
// with a clamped node (at the clamp or within one element of it), where the
// clamp's reaction sets the stress. One warning per output set when both
// peaks share the element. `stress_above_yield`: the peak von Mises stress
// exceeds the study's frame.yield_strength. The mesh reader's own warnings
// (results.model.reader_warnings: a CIRC section read without
// frame.inp_dialect) come first.
std::vector<core::Warning> frame_warnings(const FrameStudyResults& results, const FrameStudyRequest& request);

}  // namespace framedyn::coupling
