// Readers of the YAML blocks that the 2-D and the 3-D rigid-body study files
// share (coupling/rigid_study.h, coupling/study_machine.h): the header
// (format version, name, units), the attachment, spring-dampers, ground
// inputs, the soil law, the chain, the plow's linkage, shaker and bounce
// tire, analysis.response and the calibration block. Each reads strictly in
// the way of coupling/yaml_input.h and throws core::InputError naming the
// file, line, key path, what was expected and what was found; the messages
// are those of the study readers (tests check them word for word).
// Also the steps both runners share: the calibration, the forced response's
// integration and the blade's average peak-to-peak motion.
#pragma once

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <functional>
#include <initializer_list>
#include <optional>
#include <string>
#include <vector>

#include "core/units.h"
#include "rigid/calibration.h"
#include "rigid/rigid_modes.h"
#include "rigid/switched_system.h"
#include "rigid/time_integration.h"
#include "coupling/rigid_study.h"
#include "coupling/yaml_input.h"
#include "rigid/machine_2d.h"
#include "rigid/machine_3d.h"
#include "rigid/vehicle_model.h"
#include "rigid/vehicle_run.h"

namespace framedyn::coupling {

// `framedyn_study: 1`, the top-level keys, `name` (default: the file) and `units`.
struct StudyHeader {
  std::string name;
  core::UnitSystem units;
};
StudyHeader read_study_header(const YAML::Node& doc, const std::string& file, std::initializer_list<const char*> top_keys);

// `attachment: plow | chain | none`.
rigid::Attachment read_attachment(const YamlMap& root);

// `contacts: unilateral | linear` (default unilateral: tires and bounce tire
// push only; linear: the thesis's bilateral springs, for parity with its tables).
rigid::ContactLaw read_contact_law(const YamlMap& root);

// The block `key` of an attachment (soil, plow, chain): required if `wanted`,
// else refused with expected `refusal` ("no chain data unless attachment is
// chain") and found `found` ("a chain map"); empty if neither.
std::optional<YamlMap> attachment_block(const YamlMap& root, const std::string& key, bool wanted, const std::string& refusal,
                                        const std::string& found);

// A point [X, Y, Z] (length units).
Eigen::Vector3d read_point3(const YamlMap& m, const std::string& key);

// {stiffness, damping} (damping optional, 0).
rigid::SpringDamperValues read_spring_damper(const YamlMap& m);

// A reference ground input: kind sine, bump, table or road (the same under a 2-D and a 3-D tire).
rigid::GroundInput read_ground_input(const YamlMap& m);

// The soil law's keys (after the caller's allow_only): stiffness, damping,
// stiffness_reduction, damping_reduction, spring_reference (equilibrium,
// contact, soil_line or cut_face; the same in 2-D and 3-D).
void read_soil_law(const YamlMap& soil, rigid::SoilLaw& law);

// The chain block: boom_point, chain_pin ([X, Z] in 2-D, [X, Y, Z] in 3-D),
// angle, moment arm and the tooth law of Appendix D.
void read_chain(const YamlMap& chain, rigid::Chain2D& c);
void read_chain(const YamlMap& chain, rigid::Chain3D& c);

// The plow's keys from linkage to bounce_tire (after cg): the four-bar
// linkage, blade point, shaker and bounce tire (with its ground input).
void read_plow_linkage_to_bounce_tire(const YamlMap& plow, rigid::Plow2D& pl);
void read_plow_linkage_to_bounce_tire(const YamlMap& plow, rigid::Plow3D& pl);

// Builds the machine once so that geometric errors (a toggle linkage, a
// massless coordinate) are reported against the study file, and checks the
// names of analysis.fixed_coordinates.
void check_machine(const MachineParameters& p, const std::vector<std::string>& fixed_coordinates, const YamlMap& root, const std::string& file);

// analysis.response.
ResponseRequest read_response_request(const YamlMap& r);

// The `analysis` block, the same in 2-D and 3-D: modes (default true),
// fixed_coordinates, modal_soil (cutting, the default; backing; none: the soil
// state the modes and a calibration see) and response. Without the block: the
// defaults and no response.
struct AnalysisBlock {
  bool modes = true;
  std::vector<std::string> fixed_coordinates;
  rigid::ModalSoil modal_soil = rigid::ModalSoil::cutting;
  std::optional<ResponseRequest> response;
};
AnalysisBlock read_analysis(const YamlMap& root);

// The `ground` block: slope_deg, forward_speed, and with `with_travel_angle`
// (3-D: a travel direction needs the Y axis) travel_angle_deg; SI (rad, m/s).
struct GroundBlock {
  double slope = 0.0, forward_speed = 0.0;
  std::optional<double> travel_angle;  // given
};
GroundBlock read_ground(const YamlMap& root, bool with_travel_angle);

// The calibration block; `value` gives a parameter's starting value and
// throws std::invalid_argument for a name not in `known`; `quantity` its
// physical quantity (for the units of its bounds). Every parameter gets
// bounds: the block's `bounds` entry for it (with its reason), else the
// default rule of calibration_default_bounds.
// `three_d`: frame points of measured shapes are [X, Y, Z], else [X, Z].
CalibrationRequest read_calibration_request(const YamlMap& cal, const std::function<double(const std::string&)>& value,
                                            const std::function<core::Quantity(const std::string&)>& quantity,
                                            const std::vector<std::string>& known, bool three_d);

// The measured shape `s` as a rigid::ShapeTarget of `model`: a coordinate's
// component observes that coordinate (its value in its own quantity), a frame
// point's the row of frame_point_jacobian(point) along its direction. Unknown
// coordinates and all-zero shapes are input errors at their keys.
rigid::ShapeTarget shape_target(const ShapeRequest& s, const rigid::Multibody& model,
                                const std::function<rigid::Jacobian(const std::vector<double>&)>& frame_point_jacobian);

// The default bounds of a parameter with nominal value `nominal` (SI):
// stiffness, damping, mass, length: [nominal / f, nominal f] with f the
// block's stiffness_factor (default 3); rotary inertias and inertia scales:
// the radius of gyration within a factor 1.5 of nominal (inertia within
// [1/2.25, 2.25] of nominal), or, with declared body dimensions, between the
// limits those allow (docs/theory/rigid.md, section 9).
ParameterBound calibration_default_bounds(double nominal, core::Quantity q, double factor);

// Runs the calibration request: `value` reads a named parameter of the
// machine, modes_of gives the modes for a set of values of c.parameters.
rigid::CalibrationResult run_calibration(const CalibrationRequest& c, const std::function<double(const std::string&)>& value,
                                         const rigid::ModesOfParameters& modes_of, const rigid::ModeFamily& family = {});

// The family of modes calibration.pair_with admits (match_targets): with
// symmetric_modes, the modes whose kinetic energy in the coordinates that
// change sign under the X-Z mirror (y, theta_x, theta_z, v, theta_u,
// theta_w, eta, alpha) is below kSymmetricShareLimit; else all (empty).
constexpr double kSymmetricShareLimit = 1e-6;
rigid::ModeFamily calibration_mode_family(const CalibrationRequest& c, const std::vector<std::string>& coordinates);

// A `calibration_not_converged` warning for a fit stopped at its iteration
// limit (its residual, the target missed most, the parameters held at a
// bound; docs/theory/rigid.md, section 9), then a
// `calibration_outside_physical_range` warning for every fitted rotary
// inertia outside the range its body's declared box allows (bounds overridden
// beyond it with a reason; docs/theory/rigid.md, section 14), with the fitted
// value, its radius of gyration and the limit crossed, in `units`.
std::vector<core::Warning> calibration_warnings(const CalibrationRequest& c, const rigid::CalibrationResult& r, const core::UnitSystem& units);

// A body map's `dimensions: {length, width, height}` (its bounding box along
// X, Y, Z; lengths > 0, at least one given) and `distributed` (only with
// dimensions; default false) appended to `sizes` as body `body` with
// calibration parameters starting with `prefix` and inertia about `axes`;
// nothing without them (docs/theory/rigid.md, section 15).
void read_body_size(const YamlMap& m, const std::string& body, const std::string& prefix, std::vector<int> axes,
                    std::vector<DeclaredBodySize>& sizes);

// A body's mass and its inertias about its own X, Y, Z (SI) in a machine.
struct BodyInertia {
  double mass = 0.0;
  Eigen::Vector3d inertia = Eigen::Vector3d::Zero();
};

// The default bounds (those the study's calibration.bounds does not set) of
// every calibrated inertia of a body with declared dimensions, from the range
// its box allows about the inertia's axis (Eqs. 15.1-15.2, as a bounds entry's
// own dimensions do): k at most the half-diagonal, at least the uniform
// solid's if distributed; a side the box leaves open keeps the default's
// factor 1.5 on k; never past the stated start. Names: "<prefix>inertia" (about
// the body's only axis, 2-D) or "<prefix>inertia.xx|yy|zz"; the frame parts'
// scales are totals, not a body's, and keep theirs.
void bound_inertias_by_body_sizes(CalibrationRequest& c, const std::vector<DeclaredBodySize>& sizes,
                                  const std::function<BodyInertia(const DeclaredBodySize&)>& inertia_of);

// A declared body's mass and inertias in the machine of either model
// (DeclaredBodySize::body: 2-D an added mass of the frame, the cab or the
// plow, about Y; 3-D any part, about its own axes); zero for an unknown body.
BodyInertia body_inertia(const MachineParameters& p, const DeclaredBodySize& b);

// A stated radius of gyration beyond the corners of its body's declared box
// (Eq. 14.3: no mass inside the box reaches it) is an InputError at the
// body's dimensions key: the study's statements contradict each other.
void check_stated_inertia(const DeclaredBodySize& b, const BodyInertia& m, const core::UnitSystem& units);

// After any calibration, every declared body's radii of gyration against its
// box (section 15): `calibration_outside_physical_range` for a body whose mass
// or inertia was fitted (a calibration parameter starts with its prefix) and
// that left the range of Eqs. 14.3-14.4; `inertia_below_uniform_body` for a
// distributed body, stated or fitted, below the uniform solid (Eq. 14.4). In
// the order of the bodies, then of the axes X, Y, Z.
std::vector<core::Warning> body_size_warnings(const std::vector<DeclaredBodySize>& sizes,
                                              const std::function<BodyInertia(const DeclaredBodySize&)>& inertia_of,
                                              const std::optional<CalibrationRequest>& calibration, const core::UnitSystem& units);

// Calibrates `parameters` in place (run_calibration, then the fitted values
// set with set_parameter): modes(model) gives a vehicle model's modes as the
// analysis sees them (the model built from the trial parameters by
// build_vehicle_model). A fit the targets cannot determine is an InputError at
// the calibration block.
rigid::CalibrationResult calibrate_parameters(MachineParameters& parameters, const CalibrationRequest& c,
                                              const std::function<std::vector<rigid::RigidMode>(const rigid::VehicleModel&)>& modes);

// The forced response from rest (q = v = 0 at t = 0), event-located or RK4
// as requested, of a switched system; the coordinate names (or none) name the
// state in the integrator's messages.
rigid::Trajectory integrate_response(rigid::SwitchedSystem& system, const ResponseRequest& req,
                                     const std::vector<std::string>& coordinate_names = {});
// A run of `model` from rest with a fresh state (rigid::start_run at t = 0):
// the state it leaves (for force recovery) and its trajectory.
rigid::VehicleRun response_from_rest(const rigid::VehicleModel& model, const ResponseRequest& req);

// The one runner of a vehicle study, 2-D or 3-D (docs/theory/rigid.md
// section 13): the coordinate table, the modes (K in `modal_soil`), the static
// contacts and the modes by contact state of `model`; with a response, the run
// from rest (response_from_rest) into r.trajectory, the contacts' summary and
// their warnings. Returns the state the run left (for force recovery), or
// nothing without a response.
std::optional<rigid::VehicleRunState> run_vehicle_study(const rigid::VehicleModel& model, bool modes, const std::vector<std::string>& fixed,
                                                        rigid::ModalSoil modal_soil, const std::optional<ResponseRequest>& response,
                                                        const core::UnitSystem& units, VehicleResults& r);

// Every peak key of the blade's (or boom's) soil force, with one meaning in
// 2-D and 3-D: `magnitude` |RPF| and `cutting` the soil law's state at each
// sample of `time`. peak_cutting_force (peak_backing_force): the largest
// magnitude over the samples in which the blade cuts (backs off), 0 if it never
// does. With a shaker (shaker_hz > 0) over whole periods within `duration`:
// average_peak_cutting_force (backing): average_cycle_peak of the magnitude
// while cutting (backing off), and plow_vertical_peak_to_peak:
// average_peak_to_peak of `blade_z`.
void set_plow_force_peaks(const std::vector<double>& time, const std::vector<double>& blade_z, const std::vector<double>& magnitude,
                          const std::vector<bool>& cutting, double shaker_hz, double duration, VehicleResults& r);

// The force in element `element` at every sample of a run, named "<element>_force":
// spring + damper + static (Eq. 2.42: TF = k (XK - XR) + c (VC - VR) + SF),
// compression positive, zero for a contact lost (Eq. 4a.4); the same in 2-D and 3-D.
Series element_force_series(const rigid::VehicleModel& model, const rigid::VehicleRunState& run, const rigid::Trajectory& tr, int element);

// The chain force RCH at every sample of a run.
Series chain_force_series(const rigid::VehicleModel& model, const rigid::VehicleRunState& run, const rigid::Trajectory& tr);

// The average over whole periods (of `period`, within `duration`) of the
// peak-to-peak of `values` sampled at `time`; empty if no period has a sample.
std::optional<double> average_peak_to_peak(const std::vector<double>& time, const std::vector<double>& values, double period, double duration);

// The thesis's "average peak" plow force (Figures 9-10): the mean, over the
// whole periods within `duration` in which `values` rises above zero, of each
// period's largest value; empty if it never does. Pass the signed force
// magnitude for the cutting force, its negative for the backing force.
std::optional<double> average_cycle_peak(const std::vector<double>& time, const std::vector<double>& values, double period, double duration);

}  // namespace framedyn::coupling
