// Rigid-body studies (the thesis's CMW2D and CMW3D runs, model: rigid_2d or
// rigid_3d): a YAML study file describes the machine and what to compute —
// natural frequencies with their dominant coordinates, a forced response with
// force recovery, the frame loads. Reading and running are
// separate: read_rigid_study turns the file into plain data (SI), and
// run_rigid_study computes results without touching files.
// The study format: docs/user-guide.md, "Study files".
#pragma once

#include <optional>
#include <limits>
#include <string>
#include <variant>
#include <vector>

#include "core/error.h"

namespace YAML { class Node; }
#include "core/units.h"
#include "coupling/contact_report.h"
#include "coupling/static_report.h"
#include "coupling/frame_loads_2d.h"
#include "coupling/frame_loads_3d.h"
#include "coupling/frame_study.h"
#include "coupling/steady_report.h"
#include "rigid/calibration.h"
#include "rigid/calibration_limits.h"
#include "rigid/machine_2d.h"
#include "rigid/machine_3d.h"
#include "rigid/rigid_modes.h"
#include "rigid/time_integration.h"
#include "rigid/vehicle_model.h"

namespace framedyn::coupling {

struct ResponseRequest {
  double duration = 0.5;           // s
  double output_interval = 5e-4;   // s
  enum class Method { event_located, rk4 } method = Method::event_located;
  double rk4_step = 5e-4;          // s
  double relative_tolerance = 1e-8;
};

// Fit named machine parameters to target frequencies before the analysis,
// each within bounds (docs/user-guide.md, calibration; docs/theory/rigid.md,
// section 9).
struct ParameterBound {
  double lower = 0.0, upper = 0.0;  // SI
  std::string basis;                // where the bounds come from (default rule or the study's reason)
  // A rotary inertia whose body's box is declared (bounds[i].dimensions): the
  // range that box allows (docs/theory/rigid.md, Eqs. 14.2-14.4) and the
  // body's mass. The default bounds are this range; bounds overridden beyond
  // it are allowed with a reason, and a fitted value outside it is warned of.
  double body_mass = 0.0;  // SI; 0: no dimensions declared
  double physical_lower = 0.0, physical_upper = std::numeric_limits<double>::infinity();
};
// A measured mode shape of one calibration target (calibration.targets[i].shape):
// each component at a coordinate (in that coordinate's unit) or at a point of the
// frame (its displacement along x, y or z); turned into a rigid::ShapeTarget with
// the machine's coordinate table and frame-point Jacobians (shape_target).
struct ShapeComponent {
  std::string coordinate;            // empty for a frame point
  std::vector<double> frame_point;   // SI: [X, Z] (2-D) or [X, Y, Z] (3-D); empty for a coordinate
  int direction = -1;                // frame point: 0, 1, 2 for x, y, z
  double as_length = 0.0;            // the value read, in SI as a length (a translation or a frame point)
  double as_angle = 0.0;             // the value read as an angle (rad, the same in every system)
  core::InputLocation where;         // the component's `coordinate` (or `frame_point`) key
};
struct ShapeRequest {
  std::vector<ShapeComponent> components;
  double weight = 1.0;               // of the shape residual (9.6)
};
struct CalibrationRequest {
  std::vector<std::string> parameters;            // e.g. "tires.front.normal.stiffness"
  std::vector<rigid::FrequencyTarget> targets;    // shapes are filled in by calibrate_parameters from `shapes`
  std::vector<std::optional<ShapeRequest>> shapes;  // one per target
  std::vector<ParameterBound> bounds;             // one per parameter
  double regularization = 0.0;                    // calibration.regularization.weight (0: none; underdetermined fits refused)
  core::InputLocation where;                      // the calibration block, for the refusal of an underdetermined fit
  // calibration.pair_with: symmetric_modes (3-D) pairs the targets only with
  // the modes symmetric about the X-Z plane (a planar table's modes); false:
  // all modes. pair_with_where: the key, for its errors.
  bool symmetric_modes = false;
  core::InputLocation pair_with_where;
};

// A body's declared size (`dimensions: {length, width, height}` and
// `distributed` on the body's map): its stated or fitted radii of gyration are
// checked against what a body of that size can have (docs/theory/rigid.md,
// section 15; coupling/study_blocks.h, check_stated_inertias and
// body_size_warnings).
struct DeclaredBodySize {
  std::string body;              // the body's key path, e.g. "frame.parts[boom]", "cab"
  std::string parameter_prefix;  // calibration parameters of this body start with it ("cab.", "frame.added_masses.boom.")
  core::InputLocation where;     // the dimensions key
  rigid::BodyBox box;
  std::vector<int> axes;         // the axes the model gives the body inertia about (3-D: 0, 1, 2; 2-D: 1)
};

// Where to report the frame's stress resultants (Eq. 2.47) and the rail's
// top-fiber stress: up to 24 output points along the frame.
struct FrameOutputRequest {
  std::vector<double> points;      // X, m
  double height = 0.0;             // Z of the output points, m
  double rail_area = 0.0;          // one rail: A, m^2 (0: no stress)
  double rail_second_moment = 0.0; // I about the rail's horizontal axis, m^4
  double rail_top_fiber = 0.0;     // distance from the rail's axis to its top, m
};

// The machine of a study: the 2-D model's parameters (model: rigid_2d) or the
// 3-D model's (model: rigid_3d), each turned into the one rigid::VehicleModel
// by its builder (rigid::build_vehicle_model).
using MachineParameters = std::variant<rigid::Machine2DParameters, rigid::Machine3DParameters>;

// The machine's parameters of one model; a std::logic_error for the other
// model's (a caller that asked a 2-D study for its 3-D machine).
const rigid::Machine2DParameters& machine_2d(const MachineParameters& m);
rigid::Machine2DParameters& machine_2d(MachineParameters& m);
const rigid::Machine3DParameters& machine_3d(const MachineParameters& m);
rigid::Machine3DParameters& machine_3d(MachineParameters& m);
// The one vehicle model of either machine (rigid::build_vehicle_model).
rigid::VehicleModel build_vehicle_model(const MachineParameters& m);

// The machine parameters a calibration may adjust, by name (SI values), for
// the machine's model (docs/user-guide.md, calibration). 2-D names:
//   tires.<front|rear>.<normal|tractive>.stiffness, tires.tractive.stiffness (front and rear together),
//   tires.contact_depth, cab.<front_mount|rear_mount>.stiffness, cab.mass, cab.inertia, plow.mass,
//   plow.inertia, plow.bounce_tire.stiffness, plow.lift_cylinder.stiffness, soil.stiffness,
//   (soil.damping, for sweeps), frame.mass_per_length, frame.added_masses.<name>.<mass|inertia>
// 3-D names:
//   tires.<front|rear>.<vertical|longitudinal|lateral>.stiffness  (both tires of the axle)
//   tires.contact_depth (all four contacts), cab.<mounts|front_mounts|rear_mounts>.<x|y|z>.stiffness
//   (all four, the two ahead of or behind the mounts' mean X), cab.mass, cab.inertia.<xx|yy|zz>
//   frame.parts.mass_scale, frame.parts.inertia_scale.<xx|yy|zz> (the parts' total; setting it scales every part alike)
//   front_axle.inertia.xx, front_axle.mass, plow.swing_spring.stiffness, soil.stiffness, soil.lateral.stiffness,
//   plow.bounce_tire.stiffness, plow.lift_cylinder.stiffness, plow.mass
// get/set/parameter_quantity throw std::invalid_argument for an unknown name.
std::vector<std::string> calibratable_parameters(const MachineParameters& p);
double get_parameter(const MachineParameters& p, const std::string& name);
void set_parameter(MachineParameters& p, const std::string& name, double value);
core::Quantity parameter_quantity(const MachineParameters& p, const std::string& name);

// The `model:` key of a study file ("rigid_2d", "rigid_3d", ...); throws
// core::InputError if the file cannot be read or has no such key.
std::string study_model(const std::string& file);
std::string study_model(const YAML::Node& doc, const std::string& file);  // of a parsed document

// A vehicle study, 2-D or 3-D: the blocks every model reads the same way
// (units, analysis: modes, fixed coordinates, modal soil and response;
// calibration; contacts; the bodies' declared sizes) once, the machine of
// its model, and the one block each model alone has, refused in the other
// with the reason (docs/user-guide.md, "Study files": which keys are common).
struct RigidStudy {
  std::string file;
  std::string name;
  core::UnitSystem units;
  MachineParameters machine;
  bool modes = true;
  std::vector<std::string> fixed_coordinates;   // held in the modal analysis
  // The soil stiffness the modal analysis (and a calibration) sees:
  // analysis.modal_soil = cutting (K5, the default: the state the response starts in, Eq. 11.7),
  // backing (REK K5) or none. The thesis does not say which CMW2D used; docs/theory/rigid.md, section 5.
  rigid::ModalSoil modal_soil = rigid::ModalSoil::cutting;
  std::optional<ResponseRequest> response;
  std::optional<CalibrationRequest> calibration;  // parameter names of calibratable_parameters(machine)
  std::vector<DeclaredBodySize> body_sizes;  // bodies with declared dimensions (section 15)
  // 2-D only (STUDY-139 in a 3-D study): the frame loads and the resultants of Eq. 2.47 along the tube.
  std::optional<FrameOutputRequest> frame_output;
  // 3-D only (STUDY-142 in a 2-D study): the pipeline (issue 5), this run's
  // frame loads at points 24-31 into the beam model of the frame
  // (coupling/frame_study.h). Needs analysis.response; takes no `loads` key.
  std::optional<FrameStudyRequest> frame_response;

  int dimensions() const { return machine.index() == 0 ? 2 : 3; }
  const char* model() const { return dimensions() == 2 ? "rigid_2d" : "rigid_3d"; }
  const rigid::Machine2DParameters& machine_2d() const { return coupling::machine_2d(machine); }
  rigid::Machine2DParameters& machine_2d() { return coupling::machine_2d(machine); }
  const rigid::Machine3DParameters& machine_3d() const { return coupling::machine_3d(machine); }
  rigid::Machine3DParameters& machine_3d() { return coupling::machine_3d(machine); }
  rigid::Attachment attachment() const {
    return std::visit([](const auto& m) { return m.attachment; }, machine);
  }
  double shaker_frequency() const {  // Hz; the plow's (0 without one)
    return std::visit([](const auto& m) { return m.attachment == rigid::Attachment::plow ? m.plow.shaker_frequency : 0.0; }, machine);
  }
};

// The one reader of vehicle studies (model: rigid_2d or rigid_3d): the
// common blocks once, the machine by its model's builder. Throws
// core::InputError naming the file, line and key path.
RigidStudy read_rigid_study(const std::string& file);
// The same from a parsed document; `file` names it in messages and anchors relative paths.
RigidStudy read_rigid_study(const YAML::Node& doc, const std::string& file);

// One recovered time history with its unit.
struct Series {
  std::string name;
  core::Quantity quantity;
  std::vector<double> values;  // SI
};

// What a run of a vehicle study gives, the same fields with the same meaning
// in 2-D and 3-D (docs/theory/rigid.md section 13): filled by the one runner
// (coupling/study_blocks.h, run_vehicle_study) and the one peak function
// (set_plow_force_peaks); each model's results add only their own extras.
struct VehicleResults {
  std::vector<std::string> coordinates;
  std::vector<core::Quantity> coordinate_quantities;  // length or angle, one per coordinate (the model's table)
  std::optional<rigid::CalibrationResult> calibration;  // with the study's CalibrationRequest
  std::vector<rigid::RigidMode> modes;
  std::vector<StaticContact> static_contacts;        // the equilibrium the response starts from (Eqs. 11.1-11.3)
  std::vector<StateModes> modes_by_state;            // with modes: cutting, backing_off, contact_lost (Eq. 11.7)
  // Response (empty if none was asked for).
  rigid::Trajectory trajectory;
  std::vector<Series> series;                        // blade motion, blade force, element forces (2-D), chain force
  std::vector<ContactSummary> contacts;              // tires and bounce tire
  std::vector<core::Warning> warnings;               // validity warnings (contact_in_tension, ...)
  SteadyReport steady;                               // steady operation and the peaks before and in it
  // The blade's (or boom's) soil force |RPF| and motion, set_plow_force_peaks.
  std::optional<double> plow_vertical_peak_to_peak;  // m, average over whole shaker cycles
  std::optional<double> peak_cutting_force;          // N, largest |RPF| while the soil law says the blade cuts
  std::optional<double> peak_backing_force;          // N, largest |RPF| while it backs off
  // N: the thesis's "average peak" forces (Figure 10): each whole shaker
  // cycle's largest |RPF| while cutting (backing off), averaged over the
  // cycles in which the blade cuts (backs off) at all.
  std::optional<double> average_peak_cutting_force;
  std::optional<double> average_peak_backing_force;
};

// The results of a run of either model: the common ones (VehicleResults),
// the machine as analysed and the frame loads of the model's own kind.
struct RigidResults : VehicleResults {
  MachineParameters machine;  // as analysed (after any calibration)
  // 2-D, with a response and a frame_output request: the loads on the frame
  // tube and its resultants (Eq. 2.47).
  std::vector<FrameLoad2D> frame_loads_2d;
  std::optional<StressResultants> resultants;
  std::vector<std::vector<double>> rail_top_stress;  // Pa, [sample][output point]: (SRX/2)/A - (SRMY/2) c / I
  // 3-D, with a response: the loads at points 24-31 and 19, over the run and
  // at the static equilibrium (static_frame_loads_3d).
  std::optional<FrameLoads3D> frame_loads_3d;
  std::optional<FrameLoads3D> static_frame_loads_3d;

  const rigid::Machine2DParameters& machine_2d() const { return coupling::machine_2d(machine); }
  const rigid::Machine3DParameters& machine_3d() const { return coupling::machine_3d(machine); }
};

// The one runner: calibration, modes, statics, the response with its
// recovered series, the model's frame loads, steady operation and warnings.
RigidResults run_rigid_study(const RigidStudy& study);

}  // namespace framedyn::coupling
