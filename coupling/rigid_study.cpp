// The one study reader and the one runner of vehicle studies, 2-D and 3-D;
// see rigid_study.h. The machine's keys are its model's builder's
// (coupling/study_machine.h); everything else is read and run here, once.
#include "coupling/rigid_study.h"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

#include "coupling/frame_loads_2d.h"
#include "coupling/frame_loads_3d.h"
#include "coupling/study_blocks.h"
#include "coupling/study_machine.h"
#include "coupling/yaml_input.h"

namespace framedyn::coupling {

namespace {

using core::Quantity;
constexpr double kDegree = M_PI / 180.0;

template <class Machine>
Machine& machine_of(std::variant<rigid::Machine2DParameters, rigid::Machine3DParameters>& m, const char* model) {
  if (Machine* p = std::get_if<Machine>(&m)) return *p;
  throw std::logic_error(std::string("the study's machine is not a ") + model + " machine");
}

}  // namespace

const rigid::Machine2DParameters& machine_2d(const MachineParameters& m) { return machine_of<rigid::Machine2DParameters>(const_cast<MachineParameters&>(m), "2-D"); }
rigid::Machine2DParameters& machine_2d(MachineParameters& m) { return machine_of<rigid::Machine2DParameters>(m, "2-D"); }
const rigid::Machine3DParameters& machine_3d(const MachineParameters& m) { return machine_of<rigid::Machine3DParameters>(const_cast<MachineParameters&>(m), "3-D"); }
rigid::Machine3DParameters& machine_3d(MachineParameters& m) { return machine_of<rigid::Machine3DParameters>(m, "3-D"); }

rigid::VehicleModel build_vehicle_model(const MachineParameters& p) {
  return std::visit([](const auto& m) { return rigid::build_vehicle_model(m); }, p);
}

std::vector<std::string> calibratable_parameters(const MachineParameters& p) {
  return p.index() == 0 ? internal::calibratable_parameters_2d() : internal::calibratable_parameters_3d();
}

double get_parameter(const MachineParameters& p, const std::string& name) {
  return p.index() == 0 ? internal::get_parameter_2d(machine_2d(p), name) : internal::get_parameter_3d(machine_3d(p), name);
}

void set_parameter(MachineParameters& p, const std::string& name, double value) {
  if (p.index() == 0) internal::set_parameter_2d(machine_2d(p), name, value);
  else internal::set_parameter_3d(machine_3d(p), name, value);
}

core::Quantity parameter_quantity(const MachineParameters& p, const std::string& name) {
  return p.index() == 0 ? internal::parameter_quantity_2d(machine_2d(p), name) : internal::parameter_quantity_3d(name);
}

BodyInertia body_inertia(const MachineParameters& p, const DeclaredBodySize& b) {
  return p.index() == 0 ? internal::body_inertia_2d(machine_2d(p), b) : internal::body_inertia_3d(machine_3d(p), b);
}

std::string study_model(const std::string& file) { return study_model(load_yaml_file(file), file); }

std::string study_model(const YAML::Node& doc, const std::string& file) {
  core::UnitSystem si = core::UnitSystem::si();
  return YamlMap(doc, "", file, &si).text("model");
}

namespace {

// The study in an already-parsed document; `file` names it in messages.
RigidStudy read_rigid_study_document(const YAML::Node& doc, const std::string& file) {
  {
    // The model first: another model's keys would otherwise be reported as unknown.
    core::UnitSystem si = core::UnitSystem::si();
    const YamlMap top(doc, "", file, &si);
    const std::string model = top.text("model");
    if (model == "frame_transient")
      throw top.error("model", "a rigid-body study (rigid_2d; rigid_3d with framedyn run)", "'frame_transient' (a frame study: run it with framedyn frame-response)");
    // The frame pipeline takes the 3-D model's six load components at the load points; the 2-D model
    // has no lateral force and no roll or yaw moment to give it (docs/theory/coupling.md section 17).
    if (model == "rigid_2d" && top.has("frame_response"))
      throw top.error("frame_response",
                      "model: rigid_3d for the frame pipeline (it loads the frame with lateral forces and roll and yaw moments, which the "
                      "2-D model does not have; docs/theory/coupling.md section 17), or frame_output for the 2-D frame loads and resultants",
                      "a frame_response block in a rigid_2d study");
    // Eq. 2.47's resultants are those of the 2-D model's one frame tube; the 3-D frame is the beam model's (STUDY-139).
    if (model == "rigid_3d" && top.has("frame_output"))
      throw top.error("frame_output",
                      "model: rigid_2d for frame_output (the resultants of Eq. 2.47 along the 2-D model's one frame tube; the 3-D model "
                      "gives its frame loads at points 24-31 in rigid.frame_loads and, with a frame_response block, the beam model's section "
                      "forces and stresses along both rails)",
                      "a frame_output block in a rigid_3d study");
  }
  const bool three_d = study_model(doc, file) == "rigid_3d";
  // The top-level keys: the common ones and the model's own (any other model: the 2-D list, then its refusal below).
  const StudyHeader header =
      three_d ? read_study_header(doc, file, {"framedyn_study", "name", "units", "model", "attachment", "ground", "frame", "front_axle", "cab",
                                              "tires", "plow", "chain", "soil", "analysis", "calibration", "contacts", "frame_response"})
              : read_study_header(doc, file, {"framedyn_study", "name", "units", "model", "attachment", "ground", "frame", "cab", "tires", "plow",
                                              "chain", "soil", "analysis", "calibration", "contacts", "frame_output"});
  RigidStudy s;
  s.file = file;
  s.name = header.name;
  s.units = header.units;
  YamlMap root(doc, "", file, &s.units);
  const std::string model = root.text("model");
  if (model != "rigid_2d" && model != "rigid_3d")
    throw root.error("model", "rigid_2d or rigid_3d (framedyn run), or frame_transient (framedyn frame-response)", "'" + model + "'");

  // The machine: its model's builder.
  const rigid::Attachment attachment = read_attachment(root);
  const rigid::ContactLaw contacts = read_contact_law(root);
  internal::StudyFrameParts frame_parts;
  if (three_d) s.machine = internal::read_machine_3d(root, attachment, contacts, s.body_sizes, frame_parts);
  else s.machine = internal::read_machine_2d(root, attachment, contacts, s.body_sizes);

  // What to compute, the same keys in 2-D and 3-D.
  AnalysisBlock analysis = read_analysis(root);
  s.modes = analysis.modes;
  s.fixed_coordinates = std::move(analysis.fixed_coordinates);
  s.modal_soil = analysis.modal_soil;
  s.response = analysis.response;
  if (auto fo = root.optional_map("frame_output")) s.frame_output = internal::read_frame_output(*fo, s.machine_2d(), s.units);  // 2-D (above)
  if (auto cal = root.optional_map("calibration"))
    s.calibration = read_calibration_request(
        *cal, [&](const std::string& name) { return get_parameter(s.machine, name); },
        [&](const std::string& name) { return parameter_quantity(s.machine, name); }, calibratable_parameters(s.machine), three_d);
  if (s.calibration) bound_inertias_by_body_sizes(*s.calibration, s.body_sizes, [&](const DeclaredBodySize& b) { return body_inertia(s.machine, b); });
  if (three_d) internal::read_frame_response(root, file, frame_parts, s);
  // Build once now so that geometric errors (a toggle linkage, a massless
  // coordinate) are reported against the study file.
  check_machine(s.machine, s.fixed_coordinates, root, file);
  for (const DeclaredBodySize& b : s.body_sizes) check_stated_inertia(b, body_inertia(s.machine, b), s.units);
  return s;
}

}  // namespace

RigidStudy read_rigid_study(const std::string& file) { return read_rigid_study_document(load_yaml_file(file), file); }

RigidStudy read_rigid_study(const YAML::Node& doc, const std::string& file) { return read_rigid_study_document(doc, file); }

namespace {

// The blade's (or boom's) motion and soil force at every sample, and the
// peaks of that force (set_plow_force_peaks, one meaning in 2-D and 3-D);
// the series are named as response.csv has them, one name for one quantity in
// both models (the thesis's RPF, Eq. 2.37, the blade's push on the soil): 2-D
// blade_x, blade_z, plow_force_x, plow_force_z, the signed magnitude and the
// angle (Eqs. 2.38-2.39); 3-D blade_x, blade_y, blade_z, plow_force_x, _y, _z.
void blade_series(const RigidStudy& study, const rigid::VehicleModel& model, const rigid::VehicleRunState& state, RigidResults& r) {
  const rigid::Trajectory& tr = r.trajectory;
  const std::size_t ns = tr.time.size();
  const bool two_d = study.dimensions() == 2;
  const rigid::Jacobian& j = model.multibody.points()[static_cast<std::size_t>(model.blade_point)].displacement;
  Series bx{"blade_x", Quantity::length, {}}, by{"blade_y", Quantity::length, {}}, bz{"blade_z", Quantity::length, {}};
  Series fx{"plow_force_x", Quantity::force, {}}, fy{"plow_force_y", Quantity::force, {}}, fz{"plow_force_z", Quantity::force, {}};
  Series mag{"plow_force_signed_magnitude", Quantity::force, {}}, angle{"plow_force_angle_deg", Quantity::dimensionless, {}};
  std::vector<double> magnitude(ns);
  std::vector<bool> cutting(ns);
  for (std::size_t i = 0; i < ns; ++i) {
    const Eigen::Vector3d d = j * tr.q[i];
    bx.values.push_back(d.x());
    by.values.push_back(d.y());
    bz.values.push_back(d.z());
    // The soil's force on the blade is minus the sum of the soil elements' pull on it.
    const Eigen::Vector3d f = rigid::plow_force(model, state, tr.time[i], tr.q[i], tr.v[i]);
    fx.values.push_back(f.x());
    fy.values.push_back(f.y());
    fz.values.push_back(f.z());
    cutting[i] = rigid::soil_state_at(state, tr.time[i]).cutting;
    if (!two_d) {
      magnitude[i] = f.norm();
      continue;
    }
    // Eq. 2.38-2.39 (with |RPFX|): magnitude positive for forward blade travel (RPFX < 0).
    const Eigen::Vector2d f2(f.x(), f.z());
    const double m = f2.norm();
    mag.values.push_back(f2.x() < 0 ? m : -m);
    magnitude[i] = m;
    double phi;
    if (f2.x() > 0) phi = -std::atan(f2.y() / std::abs(f2.x())) + M_PI;
    else if (f2.x() < 0) phi = std::atan(f2.y() / std::abs(f2.x()));
    else phi = (f2.y() >= 0 ? 1.0 : -1.0) * M_PI / 2;
    angle.values.push_back(phi / kDegree);
  }
  const double shaker_hz = study.attachment() == rigid::Attachment::plow ? study.shaker_frequency() : 0.0;
  set_plow_force_peaks(tr.time, bz.values, magnitude, cutting, shaker_hz, study.response->duration, r);
  if (two_d)
    for (Series* s : {&bx, &bz, &fx, &fz, &mag, &angle}) r.series.push_back(std::move(*s));
  else
    for (Series* s : {&bx, &by, &bz, &fx, &fy, &fz}) r.series.push_back(std::move(*s));
}

}  // namespace

RigidResults run_rigid_study(const RigidStudy& study_in) {
  RigidStudy study = study_in;
  RigidResults r;
  if (study.calibration)
    r.calibration = calibrate_parameters(study.machine, *study.calibration, [&](const rigid::VehicleModel& m) {
      return rigid::rigid_modes(m.m, rigid::modal_stiffness(m, study.modal_soil), m.multibody.coordinate_names(), study.fixed_coordinates);
    });
  if (r.calibration) r.warnings = calibration_warnings(*study.calibration, *r.calibration, study.units);
  for (core::Warning& w : body_size_warnings(study.body_sizes, [&](const DeclaredBodySize& b) { return body_inertia(study.machine, b); },
                                             study.calibration, study.units))
    r.warnings.push_back(std::move(w));
  r.machine = study.machine;
  const rigid::VehicleModel model = build_vehicle_model(study.machine);
  const std::optional<rigid::VehicleRunState> run =
      run_vehicle_study(model, study.modes, study.fixed_coordinates, study.modal_soil, study.response, study.units, r);
  if (!run) return r;
  const rigid::VehicleRunState& state = *run;
  const rigid::Trajectory& tr = r.trajectory;
  const std::size_t ns = tr.time.size();
  const rigid::Multibody& mb = model.multibody;

  // The recovered series, in each model's order of response.csv's columns.
  if (study.dimensions() == 2)
    // Element forces: spring + damper + static (Eq. 2.42), compression positive.
    for (std::size_t e = 0; e < mb.elements().size(); ++e)
      if (mb.elements()[e].name.rfind("soil", 0) != 0)  // the soil's force is the plow/boom force below
        r.series.push_back(element_force_series(model, state, tr, static_cast<int>(e)));
  if (model.blade_point >= 0) blade_series(study, model, state, r);
  if (study.attachment() == rigid::Attachment::chain) r.series.push_back(chain_force_series(model, state, tr));

  if (study.dimensions() == 2) {
    if (study.frame_output) {
      const rigid::Machine2DParameters& p = study.machine_2d();
      const FrameOutputRequest& fo = *study.frame_output;
      r.frame_loads_2d = frame_loads_2d(model, p, state, tr);
      r.resultants = frame_stress_resultants(model, p.frame, tr, r.frame_loads_2d, fo.points, fo.height);
      if (fo.rail_area > 0) {
        // Each of the two rails carries half of the whole frame's resultants (Eq. 2.47d).
        r.rail_top_stress.assign(ns, std::vector<double>(fo.points.size(), 0.0));
        for (std::size_t i = 0; i < ns; ++i)
          for (std::size_t k = 0; k < fo.points.size(); ++k)
            r.rail_top_stress[i][k] = 0.5 * r.resultants->srx[i][k] / fo.rail_area -
                                      0.5 * r.resultants->srmy[i][k] * fo.rail_top_fiber / fo.rail_second_moment;
      }
    }
  } else {
    const rigid::Machine3DParameters& p = study.machine_3d();
    r.frame_loads_3d = frame_loads_3d(model, p, state, tr);
    r.static_frame_loads_3d = static_frame_loads_3d(model, p);
    // The tires' forces, vertical, longitudinal and lateral, as the 2-D model's tire normal and
    // tractive forces (Eq. 2.42, compression positive): response.csv's last columns (issue 20).
    // Before assess_response, so that rigid.steady.peaks holds each tire's peaks as the 2-D model
    // holds its contacts' (issue 15); the detector watches only the blade and the frame loads, so
    // reached_at does not depend on them.
    for (const char* tire : {"front_left_tire", "front_right_tire", "rear_left_tire", "rear_right_tire"})
      for (const char* direction : {"_vertical", "_longitudinal", "_lateral"})
        r.series.push_back(element_force_series(model, state, tr, mb.element_index(std::string(tire) + direction)));
  }
  assess_response(study, model, state, r);  // steady operation, validity warnings (issue 15)
  return r;
}

}  // namespace framedyn::coupling
