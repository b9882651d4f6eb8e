// Reading and running rigid-body studies; see rigid_study.h.
#include "coupling/rigid_study.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "coupling/yaml_input.h"

namespace framedyn::coupling {

namespace {

using core::Quantity;
constexpr double kGravity = 9.80665;  // m/s^2, to turn weights into masses
constexpr double kDegree = M_PI / 180.0;

double inertia_of(const YamlMap& m, double mass, const std::string& what) {
  const bool has_i = m.has("inertia"), has_k = m.has("radius_of_gyration");
  if (has_i == has_k)
    throw m.error("", "exactly one of 'inertia' or 'radius_of_gyration' for the " + what, has_i ? "both" : "neither");
  if (has_i) return m.non_negative("inertia", Quantity::rotary_inertia);
  const double k = m.non_negative("radius_of_gyration", Quantity::length);
  return mass * k * k;
}

rigid::SpringDamperValues spring_damper(const YamlMap& m) {
  m.allow_only({"stiffness", "damping"});
  return {m.non_negative("stiffness", Quantity::translational_stiffness), m.non_negative_or("damping", Quantity::translational_damping, 0.0)};
}

rigid::GroundInput ground_input(const YamlMap& m) {
  m.allow_only({"kind", "amplitude", "frequency_hz", "phase_deg", "start", "duration", "times", "values"});
  rigid::GroundInput g;
  const std::string kind = m.text("kind");
  if (kind == "sine") {
    g.kind = rigid::GroundInput::Kind::sine;
    g.amplitude = m.number("amplitude", Quantity::length);
    g.frequency = m.positive("frequency_hz", Quantity::frequency);
    g.phase = m.number_or("phase_deg", Quantity::dimensionless, 0.0) * kDegree;
  } else if (kind == "bump") {
    g.kind = rigid::GroundInput::Kind::bump;
    g.amplitude = m.number("amplitude", Quantity::length);
    g.start = m.non_negative("start", Quantity::time);
    g.duration = m.positive("duration", Quantity::time);
  } else if (kind == "table") {
    g.kind = rigid::GroundInput::Kind::table;
    g.times = m.numbers("times", Quantity::time);
    g.values = m.numbers("values", Quantity::length);
    if (g.times.size() < 2 || g.times.size() != g.values.size())
      throw m.error("values", "as many values as times (at least two)", fmt::format("{} times and {} values", g.times.size(), g.values.size()));
    for (std::size_t i = 1; i < g.times.size(); ++i)
      if (!(g.times[i] > g.times[i - 1])) throw m.error("times", "increasing times", "a time that does not increase");
  } else {
    throw m.error("kind", "sine, bump or table", "'" + kind + "'");
  }
  return g;
}

rigid::Tire2D tire(const YamlMap& m) {
  m.allow_only({"contact", "normal", "tractive", "normal_input", "tractive_input"});
  rigid::Tire2D t;
  t.contact = m.point("contact");
  t.normal = spring_damper(m.map("normal"));
  t.tractive = spring_damper(m.map("tractive"));
  if (auto in = m.optional_map("normal_input")) t.normal_input = ground_input(*in);
  if (auto in = m.optional_map("tractive_input")) t.tractive_input = ground_input(*in);
  return t;
}

rigid::CabMount mount(const YamlMap& m) {
  m.allow_only({"position", "stiffness", "damping"});
  return {m.point("position"), {m.non_negative("stiffness", Quantity::translational_stiffness), m.non_negative_or("damping", Quantity::translational_damping, 0.0)}};
}

}  // namespace

std::vector<std::string> calibratable_parameters() {
  return {"tires.front.normal.stiffness", "tires.front.tractive.stiffness", "tires.rear.normal.stiffness", "tires.rear.tractive.stiffness",
          "tires.tractive.stiffness", "tires.contact_depth", "cab.front_mount.stiffness", "cab.rear_mount.stiffness", "cab.mass",
          "cab.inertia", "plow.mass", "plow.inertia", "plow.bounce_tire.stiffness", "plow.lift_cylinder.stiffness", "soil.stiffness",
          "frame.mass_per_length", "frame.added_masses.<name>.mass", "frame.added_masses.<name>.inertia"};
}

namespace {

// The storage of a plain parameter, or nullptr for derived ones and unknown names.
double* parameter_slot(rigid::Machine2DParameters& p, const std::string& name, Quantity& q) {
  q = Quantity::translational_stiffness;
  if (name == "tires.front.normal.stiffness") return &p.front_tire.normal.stiffness;
  if (name == "tires.front.tractive.stiffness" || name == "tires.tractive.stiffness") return &p.front_tire.tractive.stiffness;
  if (name == "tires.rear.normal.stiffness") return &p.rear_tire.normal.stiffness;
  if (name == "tires.rear.tractive.stiffness") return &p.rear_tire.tractive.stiffness;
  if (name == "cab.front_mount.stiffness") return &p.cab.front.vertical.stiffness;
  if (name == "cab.rear_mount.stiffness") return &p.cab.rear.vertical.stiffness;
  if (name == "plow.bounce_tire.stiffness") return &p.plow.bounce_tire.stiffness;
  if (name == "plow.lift_cylinder.stiffness") return &p.plow.lift_cylinder.stiffness;
  if (name == "soil.stiffness") return &p.soil.stiffness;
  q = Quantity::translational_damping;
  if (name == "soil.damping") return &p.soil.damping;  // C5, for sweeps
  q = Quantity::mass;
  if (name == "cab.mass") return &p.cab.mass;
  if (name == "plow.mass") return &p.plow.mass;
  q = Quantity::rotary_inertia;
  if (name == "cab.inertia") return &p.cab.inertia;
  if (name == "plow.inertia") return &p.plow.inertia;
  q = Quantity::mass_per_length;
  if (name == "frame.mass_per_length") return &p.frame.mass_per_length;
  if (name.rfind("frame.added_masses.", 0) == 0) {
    // frame.added_masses.<name>.mass or .inertia
    const std::string rest = name.substr(19);
    const std::size_t dot = rest.rfind('.');
    if (dot == std::string::npos) return nullptr;
    const std::string mass_name = rest.substr(0, dot), field = rest.substr(dot + 1);
    for (rigid::AddedMass& a : p.frame.added_masses)
      if (a.name == mass_name && field == "mass") return q = Quantity::mass, &a.mass;
      else if (a.name == mass_name && field == "inertia") return q = Quantity::rotary_inertia, &a.inertia;
  }
  return nullptr;
}

}  // namespace

core::Quantity parameter_quantity(const rigid::Machine2DParameters& p, const std::string& name) {
  if (name == "tires.contact_depth") return Quantity::length;
  rigid::Machine2DParameters copy = p;
  Quantity q;
  if (!parameter_slot(copy, name, q)) throw std::invalid_argument("unknown parameter '" + name + "'");
  return q;
}

double get_parameter(const rigid::Machine2DParameters& p, const std::string& name) {
  // The tractive springs' line of action, as a depth below the rails' axis.
  if (name == "tires.contact_depth") return -0.5 * (p.front_tire.contact.y() + p.rear_tire.contact.y());
  rigid::Machine2DParameters copy = p;
  Quantity q;
  const double* slot = parameter_slot(copy, name, q);
  if (!slot) throw std::invalid_argument("unknown parameter '" + name + "'");
  return *slot;
}

void set_parameter(rigid::Machine2DParameters& p, const std::string& name, double value) {
  if (name == "tires.contact_depth") {
    p.front_tire.contact.y() = -value;
    p.rear_tire.contact.y() = -value;
    return;
  }
  if (name == "tires.tractive.stiffness") {
    // Front and rear together, keeping their ratio: one parameter for the x mode.
    const double ratio = p.front_tire.tractive.stiffness > 0 ? p.rear_tire.tractive.stiffness / p.front_tire.tractive.stiffness : 1.0;
    p.front_tire.tractive.stiffness = value;
    p.rear_tire.tractive.stiffness = value * ratio;
    return;
  }
  Quantity q;
  double* slot = parameter_slot(p, name, q);
  if (!slot) throw std::invalid_argument("unknown parameter '" + name + "'");
  *slot = value;
}

RigidStudy read_rigid_study(const std::string& file) {
  const YAML::Node doc = load_yaml_file(file);
  core::UnitSystem si = core::UnitSystem::si();
  YamlMap top(doc, "", file, &si);
  if (top.integer("framedyn_study") != 1) throw top.error("framedyn_study", "1 (the study format this framedyn reads)", top.text("framedyn_study"));
  top.allow_only({"framedyn_study", "name", "units", "model", "attachment", "ground", "frame", "cab", "tires", "plow", "chain", "soil", "analysis",
                  "calibration", "frame_output"});
  RigidStudy s;
  s.file = file;
  s.name = top.text_or("name", file);
  const std::string units = top.text("units");
  try {
    s.units = core::UnitSystem::from_name(units);
  } catch (const std::invalid_argument&) {
    throw top.error("units", "in-lbf-s, m-N-s (or SI) or mm-N-s", "'" + units + "'");
  }
  YamlMap root(doc, "", file, &s.units);
  const std::string model = root.text("model");
  if (model != "rigid_2d") throw root.error("model", "rigid_2d (rigid_3d studies are read by read_rigid_study_3d)", "'" + model + "'");

  rigid::Machine2DParameters& p = s.machine;
  const std::string attachment = root.text("attachment");
  if (attachment == "plow") p.attachment = rigid::Attachment::plow;
  else if (attachment == "chain") p.attachment = rigid::Attachment::chain;
  else if (attachment == "none") p.attachment = rigid::Attachment::none;
  else throw root.error("attachment", "plow, chain or none", "'" + attachment + "'");

  if (auto g = root.optional_map("ground")) {
    g->allow_only({"slope_deg", "forward_speed"});
    p.ground_slope = g->number_or("slope_deg", Quantity::dimensionless, 0.0) * kDegree;
    p.forward_speed = g->number_or("forward_speed", Quantity::velocity, 0.0);
  }

  const YamlMap frame = root.map("frame");
  frame.allow_only({"uniform_section", "added_masses"});
  const YamlMap tube = frame.map("uniform_section");
  tube.allow_only({"front_end", "length", "mass_per_length", "weight_per_length"});
  p.frame.front_end = tube.number("front_end", Quantity::length);
  p.frame.length = tube.positive("length", Quantity::length);
  if (tube.has("mass_per_length") == tube.has("weight_per_length"))
    throw tube.error("", "exactly one of 'mass_per_length' or 'weight_per_length'", tube.has("mass_per_length") ? "both" : "neither");
  p.frame.mass_per_length = tube.has("mass_per_length") ? tube.non_negative("mass_per_length", Quantity::mass_per_length)
                                                        : tube.non_negative("weight_per_length", Quantity::force_per_length) / kGravity;
  const std::vector<YamlMap> added = frame.list_of_maps("added_masses");
  if (added.size() > 30) throw frame.error("added_masses", "at most 30 added masses (the thesis's limit)", fmt::format("{}", added.size()));
  for (const YamlMap& a : added) {
    a.allow_only({"name", "mass", "weight", "inertia", "radius_of_gyration", "position", "attachment"});
    rigid::AddedMass m;
    m.name = a.text("name");
    m.mass = a.mass(kGravity);
    m.inertia = inertia_of(a, m.mass, "added mass " + m.name);
    m.position = a.point("position");
    m.attachment = a.has("attachment") ? a.point("attachment") : m.position;
    p.frame.added_masses.push_back(m);
  }

  const YamlMap cab = root.map("cab");
  cab.allow_only({"mass", "weight", "inertia", "radius_of_gyration", "position", "front_mount", "rear_mount"});
  p.cab.mass = cab.mass(kGravity);
  p.cab.inertia = inertia_of(cab, p.cab.mass, "cab");
  // theta_v has no other inertia: a zero one would leave M singular.
  if (!(p.cab.inertia > 0))
    throw cab.error(cab.has("inertia") ? "inertia" : "radius_of_gyration", "a positive value (the cab's pitch theta_v needs inertia)", "0");
  p.cab.cg = cab.point("position");
  p.cab.front = mount(cab.map("front_mount"));
  p.cab.rear = mount(cab.map("rear_mount"));

  const YamlMap tires = root.map("tires");
  tires.allow_only({"front", "rear"});
  p.front_tire = tire(tires.map("front"));
  p.rear_tire = tire(tires.map("rear"));

  if (p.attachment != rigid::Attachment::none) {
    const YamlMap soil = root.map("soil");
    soil.allow_only({"stiffness", "damping", "stiffness_reduction", "damping_reduction", "spring_reference"});
    p.soil.stiffness = soil.non_negative("stiffness", Quantity::translational_stiffness);
    p.soil.damping = soil.non_negative("damping", Quantity::translational_damping);
    p.soil.stiffness_reduction = soil.fraction("stiffness_reduction", 0.0);
    p.soil.damping_reduction = soil.fraction("damping_reduction", 1.0);
    const std::string reference = soil.text_or("spring_reference", "equilibrium");
    if (reference != "equilibrium" && reference != "contact" && reference != "soil_line")
      throw soil.error("spring_reference",
                       "equilibrium (Eq. 2.37 as printed), contact (the soil pushed from the point of contact) or soil_line (from the point of "
                       "contact, carried rearward with the unpenetrated soil at VS)",
                       "'" + reference + "'");
    p.soil.spring_from_contact = reference == "contact" || reference == "soil_line";
    p.soil.contact_moves_with_soil = reference == "soil_line";
  } else if (root.has("soil")) {
    throw root.error("soil", "no soil data without an attachment", "a soil map");
  }

  if (p.attachment == rigid::Attachment::plow) {
    const YamlMap plow = root.map("plow");
    plow.allow_only({"mass", "weight", "inertia", "radius_of_gyration", "cg", "linkage", "blade_point", "shaker", "bounce_tire", "lift_cylinder"});
    rigid::Plow2D& pl = p.plow;
    pl.mass = plow.mass(kGravity);
    pl.inertia = inertia_of(plow, pl.mass, "plow");
    pl.cg = plow.point("cg");
    const YamlMap link = plow.map("linkage");
    link.allow_only({"upper_pivot", "lower_pivot", "upper_joint", "lower_joint"});
    pl.linkage = {link.point("upper_pivot"), link.point("lower_pivot"), link.point("upper_joint"), link.point("lower_joint")};
    try {
      (void)rigid::four_bar_velocity_ratios(pl.linkage);
    } catch (const std::invalid_argument& e) {
      throw link.error("", "a linkage with a unique small motion", e.what());
    }
    pl.blade_point = plow.point("blade_point");
    const YamlMap shaker = plow.map("shaker");
    shaker.allow_only({"point", "force", "frequency_hz", "phase_deg"});
    pl.shaker_point = shaker.point("point");
    pl.shaker_amplitude = shaker.non_negative("force", Quantity::force);
    pl.shaker_frequency = shaker.non_negative("frequency_hz", Quantity::frequency);
    pl.shaker_phase = shaker.number_or("phase_deg", Quantity::dimensionless, 0.0) * kDegree;
    const YamlMap bounce = plow.map("bounce_tire");
    bounce.allow_only({"point", "stiffness", "damping", "input"});
    pl.bounce_tire_point = bounce.point("point");
    pl.bounce_tire = {bounce.non_negative("stiffness", Quantity::translational_stiffness), bounce.non_negative_or("damping", Quantity::translational_damping, 0.0)};
    if (auto in = bounce.optional_map("input")) pl.bounce_input = ground_input(*in);
    const YamlMap cyl = plow.map("lift_cylinder");
    cyl.allow_only({"frame_point", "arm_point", "stiffness", "damping"});
    pl.cylinder_frame_point = cyl.point("frame_point");
    pl.cylinder_arm_point = cyl.point("arm_point");
    pl.lift_cylinder = {cyl.non_negative("stiffness", Quantity::translational_stiffness), cyl.non_negative_or("damping", Quantity::translational_damping, 0.0)};
  } else if (root.has("plow")) {
    throw root.error("plow", "no plow data unless attachment is plow", "a plow map");
  }

  if (p.attachment == rigid::Attachment::chain) {
    const YamlMap chain = root.map("chain");
    chain.allow_only({"boom_point", "chain_pin", "chain_angle_deg", "moment_arm", "tooth_static_force", "tooth_damping", "chain_speed",
                      "static_reduction", "damping_reduction", "tooth_spacing", "length_in_ground", "ramp_time"});
    rigid::Chain2D& c = p.chain;
    c.boom_point = chain.point("boom_point");
    c.chain_pin = chain.point("chain_pin");
    c.chain_angle = chain.number("chain_angle_deg", Quantity::dimensionless) * kDegree;
    c.moment_arm = chain.number("moment_arm", Quantity::length);
    c.tooth_static_force = chain.non_negative("tooth_static_force", Quantity::force);
    c.tooth_damping = chain.non_negative("tooth_damping", Quantity::translational_damping);
    c.chain_speed = chain.positive("chain_speed", Quantity::velocity);
    c.static_reduction = chain.fraction("static_reduction", 1.0);
    c.damping_reduction = chain.fraction("damping_reduction", 1.0);
    c.tooth_spacing = chain.positive("tooth_spacing", Quantity::length);
    c.length_in_ground = chain.positive("length_in_ground", Quantity::length);
    if (c.length_in_ground < c.tooth_spacing)
      throw chain.error("length_in_ground", "at least one tooth spacing of chain in the ground", "less");
    c.ramp_time = chain.non_negative_or("ramp_time", Quantity::time, 0.0);
  } else if (root.has("chain")) {
    throw root.error("chain", "no chain data unless attachment is chain", "a chain map");
  }

  if (auto analysis = root.optional_map("analysis")) {
    analysis->allow_only({"modes", "fixed_coordinates", "modal_soil", "response"});
    s.modes = analysis->boolean_or("modes", true);
    s.fixed_coordinates = analysis->strings("fixed_coordinates");
    const std::string modal_soil = analysis->text_or("modal_soil", "cutting");
    if (modal_soil == "cutting") s.modal_soil = rigid::Machine2D::ModalSoil::cutting;
    else if (modal_soil == "backing") s.modal_soil = rigid::Machine2D::ModalSoil::backing;
    else if (modal_soil == "none") s.modal_soil = rigid::Machine2D::ModalSoil::none;
    else throw analysis->error("modal_soil", "cutting (K5), backing (REK K5) or none", "'" + modal_soil + "'");
    if (auto r = analysis->optional_map("response")) {
      r->allow_only({"duration", "output_interval", "method", "rk4_step", "relative_tolerance"});
      ResponseRequest req;
      req.duration = r->positive("duration", Quantity::time);
      req.output_interval = r->positive("output_interval", Quantity::time);
      const std::string method = r->text_or("method", "event_located");
      if (method == "event_located") req.method = ResponseRequest::Method::event_located;
      else if (method == "rk4") req.method = ResponseRequest::Method::rk4;
      else throw r->error("method", "event_located or rk4", "'" + method + "'");
      if (req.method == ResponseRequest::Method::rk4) {
        req.rk4_step = r->positive("rk4_step", Quantity::time);
        const double ratio = req.output_interval / req.rk4_step;
        if (std::abs(ratio - std::round(ratio)) > 1e-9 * ratio || std::round(ratio) < 1)
          throw r->error("rk4_step", "a step that divides output_interval a whole number of times",
                         fmt::format("{} s against an output interval of {} s", req.rk4_step, req.output_interval));
      }
      req.relative_tolerance = r->number_or("relative_tolerance", Quantity::dimensionless, 1e-8);
      if (!(req.relative_tolerance > 0 && req.relative_tolerance < 1e-2)) throw r->error("relative_tolerance", "a tolerance between 0 and 0.01", "out of range");
      s.response = req;
    }
  }
  if (auto fo = root.optional_map("frame_output")) {
    fo->allow_only({"points", "height", "rail"});
    FrameOutputRequest req;
    req.points = fo->numbers("points", Quantity::length);
    if (req.points.empty() || req.points.size() > 24)
      throw fo->error("points", "a list of 1 to 24 X positions (the thesis's limit)", fmt::format("{} points", req.points.size()));
    req.height = fo->number_or("height", Quantity::length, 0.0);
    if (auto rail = fo->optional_map("rail")) {
      rail->allow_only({"area", "second_moment", "top_fiber"});
      req.rail_area = rail->positive("area", Quantity::area);
      req.rail_second_moment = rail->positive("second_moment", Quantity::second_moment_of_area);
      req.rail_top_fiber = rail->positive("top_fiber", Quantity::length);
    }
    s.frame_output = req;
  }
  if (auto cal = root.optional_map("calibration")) {
    cal->allow_only({"parameters", "targets", "fit_labels"});
    CalibrationRequest req;
    req.parameters = cal->strings("parameters");
    if (req.parameters.empty()) throw cal->error("parameters", "a list of parameter names to fit", "none");
    for (const std::string& name : req.parameters) {
      try {
        if (get_parameter(p, name) <= 0) throw cal->error("parameters", "parameters with a positive starting value", name + " <= 0");
      } catch (const std::invalid_argument&) {
        std::string known;
        for (const std::string& k : calibratable_parameters()) known += (known.empty() ? "" : ", ") + k;
        throw cal->error("parameters", "one of " + known, "'" + name + "'");
      }
    }
    for (const YamlMap& t : cal->list_of_maps("targets")) {
      t.allow_only({"frequency_hz", "dominant"});
      req.targets.push_back({t.positive("frequency_hz", Quantity::frequency), t.text_or("dominant", "")});
    }
    if (req.targets.empty()) throw cal->error("targets", "a list of {frequency_hz, dominant}", "none");
    req.fit_labels = cal->boolean_or("fit_labels", false);
    s.calibration = req;
  }
  // Build once now so that geometric errors (a toggle linkage, a massless
  // coordinate) are reported against the study file.
  try {
    rigid::Machine2D check(p);
    for (const std::string& f : s.fixed_coordinates)
      if (check.coordinate(f) < 0) throw root.map("analysis").error("fixed_coordinates", "coordinate names of this model", "'" + f + "'");
  } catch (const std::invalid_argument& e) {
    throw core::InputError({file, 0, "machine"}, "a consistent machine", e.what());
  }
  return s;
}

RigidResults run_rigid_study(const RigidStudy& study_in) {
  RigidStudy study = study_in;
  RigidResults r;
  if (study.calibration) {
    const CalibrationRequest& c = *study.calibration;
    std::vector<double> initial;
    for (const std::string& name : c.parameters) initial.push_back(get_parameter(study.machine, name));
    const rigid::ModesOfParameters modes_of = [&](const std::vector<double>& values) {
      rigid::Machine2DParameters p = study.machine;
      for (std::size_t i = 0; i < values.size(); ++i) set_parameter(p, c.parameters[i], values[i]);
      rigid::Machine2D m(p);
      return rigid::rigid_modes(m.mass_matrix(), m.stiffness_matrix(study.modal_soil), m.model().coordinate_names(), study.fixed_coordinates);
    };
    rigid::CalibrationOptions options;
    if (c.fit_labels) options.coordinates = rigid::Machine2D(study.machine).model().coordinate_names();
    r.calibration = rigid::calibrate(modes_of, initial, c.targets, options);
    for (std::size_t i = 0; i < c.parameters.size(); ++i) set_parameter(study.machine, c.parameters[i], r.calibration->fitted[i]);
  }
  rigid::Machine2D machine(study.machine);
  r.coordinates = machine.model().coordinate_names();
  if (study.modes) r.modes = rigid::rigid_modes(machine.mass_matrix(), machine.stiffness_matrix(study.modal_soil), r.coordinates, study.fixed_coordinates);
  if (!study.response) return r;

  const ResponseRequest& req = *study.response;
  const int n = machine.size();
  const Eigen::VectorXd q0 = Eigen::VectorXd::Zero(n), v0 = Eigen::VectorXd::Zero(n);
  machine.reset(0.0, q0);
  rigid::IntegrationOptions o;
  o.end_time = req.duration;
  o.output_interval = req.output_interval;
  o.relative_tolerance = req.relative_tolerance;
  o.absolute_tolerance = 1e-12;
  o.velocity_scale = 100.0;
  r.trajectory = req.method == ResponseRequest::Method::event_located ? rigid::integrate_event_located(machine, q0, v0, o)
                                                                      : rigid::integrate_rk4(machine, q0, v0, req.rk4_step, o);
  const rigid::Trajectory& tr = r.trajectory;
  const std::size_t ns = tr.time.size();

  // Element forces: spring + damper + static (Eq. 2.42), compression positive.
  const rigid::Multibody& mb = machine.model();
  const std::vector<double> statics = machine.static_element_forces();
  for (std::size_t e = 0; e < mb.elements().size(); ++e) {
    const rigid::SpringDamper& el = mb.elements()[e];
    if (el.name.rfind("soil", 0) == 0) continue;  // the soil's force is the plow/boom force below
    const Eigen::RowVectorXd g = mb.elongation_map(static_cast<int>(e));
    Series s{el.name + "_force", Quantity::force, {}};
    const rigid::GroundInput* in = machine.ground_input_of(static_cast<int>(e));
    for (std::size_t i = 0; i < ns; ++i) {
      // Eq. 2.42: TF = k (XK - XR) + c (VC - VR) + SF, compression positive.
      const double xr = in ? in->displacement(tr.time[i]) : 0.0, vr = in ? in->velocity(tr.time[i]) : 0.0;
      s.values.push_back(-(el.stiffness * (g.dot(tr.q[i]) - xr) + el.damping * (g.dot(tr.v[i]) - vr)) + statics[e]);
    }
    r.series.push_back(std::move(s));
  }
  if (machine.blade_point() >= 0) {
    const rigid::Jacobian& j = mb.points()[static_cast<std::size_t>(machine.blade_point())].displacement;
    Series bx{"blade_x", Quantity::length, {}}, bz{"blade_z", Quantity::length, {}};
    Series fx{"plow_force_x", Quantity::force, {}}, fz{"plow_force_z", Quantity::force, {}};
    Series mag{"plow_force_signed_magnitude", Quantity::force, {}}, angle{"plow_force_angle_deg", Quantity::dimensionless, {}};
    for (std::size_t i = 0; i < ns; ++i) {
      const Eigen::Vector3d d = j * tr.q[i];
      bx.values.push_back(d(0));
      bz.values.push_back(d(2));
      const Eigen::Vector2d f = machine.plow_force(tr.time[i], tr.q[i], tr.v[i]);
      fx.values.push_back(f.x());
      fz.values.push_back(f.y());
      // Eq. 2.38-2.39 (with |RPFX|): magnitude positive for forward blade travel (RPFX < 0).
      const double m = f.norm();
      mag.values.push_back(f.x() < 0 ? m : -m);
      double phi;
      if (f.x() > 0) phi = -std::atan(f.y() / std::abs(f.x())) + M_PI;
      else if (f.x() < 0) phi = std::atan(f.y() / std::abs(f.x()));
      else phi = (f.y() >= 0 ? 1.0 : -1.0) * M_PI / 2;
      angle.values.push_back(phi / kDegree);
    }
    if (!mag.values.empty()) {
      r.peak_cutting_force = std::max(0.0, *std::max_element(mag.values.begin(), mag.values.end()));
      r.peak_backing_force = std::max(0.0, -*std::min_element(mag.values.begin(), mag.values.end()));
    }
    if (study.machine.attachment == rigid::Attachment::plow && study.machine.plow.shaker_frequency > 0) {
      // Average peak-to-peak vertical blade motion over whole shaker cycles.
      const double period = 1.0 / study.machine.plow.shaker_frequency;
      const int cycles = static_cast<int>(std::floor(req.duration / period + 1e-9));
      double sum = 0.0;
      int counted = 0;
      for (int c = 0; c < cycles; ++c) {
        double lo = 1e300, hi = -1e300;
        for (std::size_t i = 0; i < ns; ++i)
          if (tr.time[i] >= c * period - 1e-12 && tr.time[i] <= (c + 1) * period + 1e-12) {
            lo = std::min(lo, bz.values[i]);
            hi = std::max(hi, bz.values[i]);
          }
        if (hi >= lo) {
          sum += hi - lo;
          ++counted;
        }
      }
      if (counted > 0) r.plow_vertical_peak_to_peak = sum / counted;
    }
    for (Series* s : {&bx, &bz, &fx, &fz, &mag, &angle}) r.series.push_back(std::move(*s));
  }
  if (study.machine.attachment == rigid::Attachment::chain) {
    Series c{"chain_force", Quantity::force, {}};
    for (std::size_t i = 0; i < ns; ++i) c.values.push_back(machine.chain_force(tr.time[i]));
    r.series.push_back(std::move(c));
  }
  if (study.frame_output) {
    const FrameOutputRequest& fo = *study.frame_output;
    r.frame_loads = frame_loads_2d(machine, tr);
    r.resultants = frame_stress_resultants(machine, tr, r.frame_loads, fo.points, fo.height);
    if (fo.rail_area > 0) {
      // Each of the two rails carries half of the whole frame's resultants (Eq. 2.47d).
      r.rail_top_stress.assign(ns, std::vector<double>(fo.points.size(), 0.0));
      for (std::size_t i = 0; i < ns; ++i)
        for (std::size_t k = 0; k < fo.points.size(); ++k)
          r.rail_top_stress[i][k] = 0.5 * r.resultants->srx[i][k] / fo.rail_area -
                                    0.5 * r.resultants->srmy[i][k] * fo.rail_top_fiber / fo.rail_second_moment;
    }
  }
  return r;
}

}  // namespace framedyn::coupling
