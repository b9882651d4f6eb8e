// Readers of the blocks shared by the 2-D and 3-D study files; see study_blocks.h.
#include "coupling/study_blocks.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace framedyn::coupling {

namespace {

using core::Quantity;
constexpr double kDegree = M_PI / 180.0;

template <class Chain, class ReadPoint>
void read_chain_into(const YamlMap& chain, Chain& c, ReadPoint point) {
  chain.allow_only({"boom_point", "chain_pin", "chain_angle_deg", "moment_arm", "tooth_static_force", "tooth_damping", "chain_speed",
                    "static_reduction", "damping_reduction", "tooth_spacing", "length_in_ground", "ramp_time"});
  c.boom_point = point(chain, "boom_point");
  c.chain_pin = point(chain, "chain_pin");
  c.chain_angle = chain.number("chain_angle_deg", Quantity::dimensionless) * kDegree;
  c.moment_arm = chain.number("moment_arm", Quantity::length);
  c.tooth_static_force = chain.non_negative("tooth_static_force", Quantity::force);
  c.tooth_damping = chain.non_negative("tooth_damping", Quantity::translational_damping);
  c.chain_speed = chain.positive("chain_speed", Quantity::velocity);
  c.static_reduction = chain.fraction("static_reduction", 1.0);
  c.damping_reduction = chain.fraction("damping_reduction", 1.0);
  c.tooth_spacing = chain.positive("tooth_spacing", Quantity::length);
  c.length_in_ground = chain.positive("length_in_ground", Quantity::length);
  if (c.length_in_ground < c.tooth_spacing) throw chain.error("length_in_ground", "at least one tooth spacing of chain in the ground", "less");
  c.ramp_time = chain.non_negative_or("ramp_time", Quantity::time, 0.0);
}

template <class Plow>
void read_plow_linkage_to_bounce_tire_into(const YamlMap& plow, Plow& pl) {
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
  if (auto in = bounce.optional_map("input")) pl.bounce_input = read_ground_input(*in);
}

}  // namespace

void check_machine(const MachineParameters& p, const std::vector<std::string>& fixed_coordinates, const YamlMap& root, const std::string& file) {
  try {
    const rigid::VehicleModel check = build_vehicle_model(p);
    // Each value is in range (yaml_input.cpp); their products need not be: a 1e200 lbf/in spring 1e200 in from the CG.
    for (const auto& [name, matrix] : {std::pair<const char*, Eigen::MatrixXd>{"mass", check.m},
                                       {"stiffness", check.k_full}, {"damping", check.c_full}})
      if (!matrix.allFinite())
        throw core::InputError({file, 0, "machine"}, "masses, stiffnesses, dampings and positions whose products are finite",
                               fmt::format("a {} matrix with an infinite or undefined entry (values too large?)", name));
    for (const std::string& f : fixed_coordinates)
      if (check.coordinate(f) < 0) throw root.map("analysis").error("fixed_coordinates", "coordinate names of this model", "'" + f + "'");
  } catch (const std::invalid_argument& e) {
    throw core::InputError({file, 0, "machine"}, "a consistent machine", e.what());
  } catch (const rigid::StaticsError& e) {
    // STUDY-84: no equilibrium on contacts that only push (rigid/contact_statics.h).
    throw core::InputError({file, 0, "contacts"}, "a machine that rests under gravity on contacts that only push (docs/theory/rigid.md section 11)",
                           "none: " + e.detail());
  } catch (const core::NumericalError& e) {
    // The machine's own check (rigid/multibody check_definiteness) names the
    // body or coordinate; at read time that is the study's fault, not the run's
    // (found by fuzz_study_reader: a part 1.5e111 in above the frame leaves Y
    // with no inertia to 12 digits of the matrix's scale).
    throw core::InputError({file, 0, "machine"}, "a machine with a positive definite mass matrix and springs and dampers that are not negative",
                           e.what());
  }
}

std::optional<YamlMap> attachment_block(const YamlMap& root, const std::string& key, bool wanted, const std::string& refusal,
                                        const std::string& found) {
  if (wanted) return root.map(key);
  if (root.has(key)) throw root.error(key, refusal, found);
  return std::nullopt;
}

Eigen::Vector3d read_point3(const YamlMap& m, const std::string& key) {
  const std::vector<double> v = m.numbers(key, Quantity::length);
  if (!m.has(key) || v.size() != 3) throw m.error(key, "a point [X, Y, Z]", m.has(key) ? fmt::format("{} numbers", v.size()) : "nothing");
  return {v[0], v[1], v[2]};
}

StudyHeader read_study_header(const YAML::Node& doc, const std::string& file, std::initializer_list<const char*> top_keys) {
  core::UnitSystem si = core::UnitSystem::si();
  YamlMap top(doc, "", file, &si);
  if (top.integer("framedyn_study") != 1) throw top.error("framedyn_study", "1 (the study format this framedyn reads)", top.text("framedyn_study"));
  top.allow_only(top_keys);
  StudyHeader h;
  h.name = top.text_or("name", file);
  const std::string units = top.text("units");
  try {
    h.units = core::UnitSystem::from_name(units);
  } catch (const std::invalid_argument&) {
    throw top.error("units", "in-lbf-s, m-N-s (or SI) or mm-N-s", "'" + units + "'");
  }
  return h;
}

rigid::Attachment read_attachment(const YamlMap& root) {
  const std::string attachment = root.text("attachment");
  if (attachment == "plow") return rigid::Attachment::plow;
  if (attachment == "chain") return rigid::Attachment::chain;
  if (attachment == "none") return rigid::Attachment::none;
  throw root.error("attachment", "plow, chain or none", "'" + attachment + "'");
}

rigid::ContactLaw read_contact_law(const YamlMap& root) {
  const std::string law = root.text_or("contacts", "unilateral");
  if (law == "unilateral") return rigid::ContactLaw::unilateral;
  if (law == "linear") return rigid::ContactLaw::linear;
  throw root.error("contacts", "unilateral (tires and bounce tire push only) or linear (the thesis's bilateral springs)", "'" + law + "'");
}

rigid::SpringDamperValues read_spring_damper(const YamlMap& m) {
  m.allow_only({"stiffness", "damping"});
  return {m.non_negative("stiffness", Quantity::translational_stiffness), m.non_negative_or("damping", Quantity::translational_damping, 0.0)};
}

rigid::GroundInput read_ground_input(const YamlMap& m) {
  m.allow_only({"kind", "amplitude", "frequency_hz", "phase_deg", "start", "duration", "times", "values", "class", "speed", "behind", "seed", "length"});
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
  } else if (kind == "road") {  // ISO 8608 rough ground (docs/theory/fatigue.md section 6)
    g.kind = rigid::GroundInput::Kind::road;
    const std::string cls = m.text("class");
    rigid::RoadProfileOptions o;
    if (cls.size() != 1 || std::string("ABCDEFGHabcdefgh").find(cls[0]) == std::string::npos)
      throw m.error("class", "an ISO 8608 road class, A to H", "'" + cls + "'");
    o.road_class = rigid::road_class_from_letter(cls[0]);
    if (m.has("seed")) {
      const int seed = m.integer("seed");
      if (seed < 0) throw m.error("seed", "a seed >= 0", std::to_string(seed));
      o.seed = static_cast<std::uint64_t>(seed);
    }
    o.length = m.has("length") ? m.positive("length", Quantity::length) : 100.0;
    if (o.length * (o.n_max - o.n_min) < 1.0 || o.length * o.n_min > 1e6)
      throw m.error("length", "a profile length L (m) with at least one line k / L in ISO 8608's band 0.011 to 2.83 cycle/m", describe(m.node()["length"]));
    g.road = std::make_shared<const rigid::RoadProfile>(o);
    g.speed = m.positive("speed", Quantity::velocity);
    g.behind_given = m.has("behind");
    g.behind = g.behind_given ? m.non_negative("behind", Quantity::length) : 0.0;
  } else {
    throw m.error("kind", "sine, bump, table or road", "'" + kind + "'");
  }
  return g;
}

void read_soil_law(const YamlMap& soil, rigid::SoilLaw& law) {
  law.stiffness = soil.non_negative("stiffness", Quantity::translational_stiffness);
  law.damping = soil.non_negative("damping", Quantity::translational_damping);
  law.stiffness_reduction = soil.fraction("stiffness_reduction", 0.0);
  law.damping_reduction = soil.fraction("damping_reduction", 1.0);
  const std::string reference = soil.text_or("spring_reference", "equilibrium");
  if (reference != "equilibrium" && reference != "contact" && reference != "cut_face" && reference != "soil_line")
    throw soil.error("spring_reference",
                     "equilibrium (Eq. 2.37 as printed), contact (the soil pushed from the point of contact), soil_line (from the point of "
                     "contact, carried rearward with the unpenetrated soil at VS) or cut_face (no spring while the blade cuts)",
                     "'" + reference + "'");
  law.cut_face = reference == "cut_face";
  law.spring_from_contact = reference == "contact" || reference == "soil_line" || law.cut_face;
  // The soil_line anchor and the cut face stream rearward with the soil (both models).
  law.contact_moves_with_soil = reference == "soil_line" || law.cut_face;
}

void read_chain(const YamlMap& chain, rigid::Chain2D& c) {
  read_chain_into(chain, c, [](const YamlMap& m, const std::string& key) { return m.point(key); });
}
void read_chain(const YamlMap& chain, rigid::Chain3D& c) { read_chain_into(chain, c, read_point3); }

void read_plow_linkage_to_bounce_tire(const YamlMap& plow, rigid::Plow2D& pl) {
  read_plow_linkage_to_bounce_tire_into(plow, pl);
}
void read_plow_linkage_to_bounce_tire(const YamlMap& plow, rigid::Plow3D& pl) {
  read_plow_linkage_to_bounce_tire_into(plow, pl);
}

ResponseRequest read_response_request(const YamlMap& r) {
  r.allow_only({"duration", "output_interval", "method", "rk4_step", "relative_tolerance"});
  ResponseRequest req;
  req.duration = r.positive("duration", Quantity::time);
  req.output_interval = r.positive("output_interval", Quantity::time);
  const std::string method = r.text_or("method", "event_located");
  if (method == "event_located") req.method = ResponseRequest::Method::event_located;
  else if (method == "rk4") req.method = ResponseRequest::Method::rk4;
  else throw r.error("method", "event_located or rk4", "'" + method + "'");
  if (req.method == ResponseRequest::Method::rk4) {
    req.rk4_step = r.positive("rk4_step", Quantity::time);
    const double ratio = req.output_interval / req.rk4_step;
    if (std::abs(ratio - std::round(ratio)) > 1e-9 * ratio || std::round(ratio) < 1)
      throw r.error("rk4_step", "a step that divides output_interval a whole number of times",
                    fmt::format("{} s against an output interval of {} s", req.rk4_step, req.output_interval));
  }
  req.relative_tolerance = r.number_or("relative_tolerance", Quantity::dimensionless, 1e-8);
  if (!(req.relative_tolerance > 0 && req.relative_tolerance < 1e-2))
    throw r.error("relative_tolerance", "a tolerance between 0 and 0.01", describe(r.node()["relative_tolerance"]));
  return req;
}

AnalysisBlock read_analysis(const YamlMap& root) {
  AnalysisBlock a;
  const std::optional<YamlMap> analysis = root.optional_map("analysis");
  if (!analysis) return a;
  analysis->allow_only({"modes", "fixed_coordinates", "modal_soil", "response"});
  a.modes = analysis->boolean_or("modes", true);
  a.fixed_coordinates = analysis->strings("fixed_coordinates");
  const std::string modal_soil = analysis->text_or("modal_soil", "cutting");
  if (modal_soil == "cutting") a.modal_soil = rigid::ModalSoil::cutting;
  else if (modal_soil == "backing") a.modal_soil = rigid::ModalSoil::backing;
  else if (modal_soil == "none") a.modal_soil = rigid::ModalSoil::none;
  else throw analysis->error("modal_soil", "cutting (K5), backing (REK K5) or none", "'" + modal_soil + "'");
  if (auto r = analysis->optional_map("response")) a.response = read_response_request(*r);
  return a;
}

GroundBlock read_ground(const YamlMap& root, bool with_travel_angle) {
  constexpr double kDegree = M_PI / 180.0;
  GroundBlock g;
  const std::optional<YamlMap> ground = root.optional_map("ground");
  if (!ground) return g;
  if (with_travel_angle) ground->allow_only({"slope_deg", "forward_speed", "travel_angle_deg"});
  else ground->allow_only({"slope_deg", "forward_speed"});
  g.slope = ground->number_or("slope_deg", core::Quantity::dimensionless, 0.0) * kDegree;
  g.forward_speed = ground->number_or("forward_speed", core::Quantity::velocity, 0.0);
  if (with_travel_angle && ground->has("travel_angle_deg")) g.travel_angle = ground->number("travel_angle_deg", core::Quantity::dimensionless) * kDegree;
  return g;
}

ParameterBound calibration_default_bounds(double nominal, core::Quantity q, double factor) {
  if (q == Quantity::rotary_inertia || q == Quantity::dimensionless) {
    // The radius of gyration within kRadiusFactor of its nominal value.
    constexpr double kRadiusFactor = 1.5;
    return {nominal / (kRadiusFactor * kRadiusFactor), nominal * kRadiusFactor * kRadiusFactor,
            "default: radius of gyration within a factor 1.5 of nominal (no body dimensions declared)"};
  }
  return {nominal / factor, nominal * factor, fmt::format("default: within a factor {:g} of nominal", factor)};
}

namespace {

// Radius-of-gyration bounds about one axis from the range its declared box
// allows (rigid/calibration_limits.h): at most the half-diagonal (all the mass
// at the corners); a body declared distributed at least the uniform solid's
// sqrt((a^2+b^2)/12), else at least 1/1.5 of the nominal k.
ParameterBound inertia_bounds_from_dimensions(double mass, const rigid::GyrationRange& g, bool distributed, double nominal_k) {
  const double k_min = distributed ? g.smallest : std::min(nominal_k / 1.5, g.largest);
  return {mass * k_min * k_min, mass * g.largest * g.largest,
          distributed ? "dimensions: between the uniform solid of the declared box and all mass at its corners"
                      : "dimensions: at most all mass at the declared box's corners; at least 1/1.5 of the nominal radius of gyration"};
}

}  // namespace

namespace {

// calibration.targets[i].shape: {weight, components: [{coordinate, value} or
// {frame_point, direction, value}]}.
ShapeRequest read_shape(const YamlMap& s, bool three_d) {
  s.allow_only({"components", "weight"});
  ShapeRequest shape;
  shape.weight = s.has("weight") ? s.positive("weight", Quantity::dimensionless) : 1.0;
  const std::vector<YamlMap> items = s.list_of_maps("components");
  if (items.empty()) throw s.error("components", "a list of {coordinate, value} or {frame_point, direction, value}", "none");
  for (const YamlMap& c : items) {
    c.allow_only({"coordinate", "frame_point", "direction", "value"});
    ShapeComponent k;
    if (c.has("coordinate") == c.has("frame_point"))
      throw c.error("coordinate", "exactly one of coordinate or frame_point", c.has("coordinate") ? "both" : "neither");
    if (c.has("coordinate")) {
      k.coordinate = c.text("coordinate");
      k.where = c.location("coordinate");
      if (c.has("direction")) throw c.error("direction", "direction only with frame_point", "direction with coordinate");
    } else {
      k.frame_point = c.numbers("frame_point", Quantity::length);
      k.where = c.location("frame_point");
      if (k.frame_point.size() != (three_d ? 3u : 2u))
        throw c.error("frame_point", three_d ? "[X, Y, Z] of a point of the frame" : "[X, Z] of a point of the frame", describe(c.node()["frame_point"]));
      const std::string d = c.text("direction");
      const std::string allowed = three_d ? "x, y or z" : "x or z";
      if (d == "x") k.direction = 0;
      else if (d == "y" && three_d) k.direction = 1;
      else if (d == "z") k.direction = 2;
      else throw c.error("direction", allowed, "'" + d + "'");
    }
    k.as_length = c.number("value", Quantity::length);
    k.as_angle = c.number("value", Quantity::angle);
    shape.components.push_back(std::move(k));
  }
  return shape;
}

}  // namespace

rigid::ShapeTarget shape_target(const ShapeRequest& s, const rigid::Multibody& model,
                                const std::function<rigid::Jacobian(const std::vector<double>&)>& frame_point_jacobian) {
  const std::vector<std::string>& names = model.coordinate_names();
  const Eigen::Index m = static_cast<Eigen::Index>(s.components.size()), n = model.size();
  rigid::ShapeTarget t;
  t.weight = s.weight;
  t.observation = Eigen::MatrixXd::Zero(m, n);
  t.measured.resize(m);
  for (Eigen::Index i = 0; i < m; ++i) {
    const ShapeComponent& k = s.components[static_cast<std::size_t>(i)];
    if (!k.coordinate.empty()) {
      const auto it = std::find(names.begin(), names.end(), k.coordinate);
      if (it == names.end()) {
        std::string list;
        for (const std::string& name : names) list += (list.empty() ? "" : ", ") + name;
        throw core::InputError(k.where, "one of the machine's coordinates (" + list + ")", "'" + k.coordinate + "'");
      }
      const Eigen::Index j = it - names.begin();
      t.observation(i, j) = 1.0;
      t.measured(i) = model.coordinate_quantities()[static_cast<std::size_t>(j)] == Quantity::angle ? k.as_angle : k.as_length;
    } else {
      t.observation.row(i) = frame_point_jacobian(k.frame_point).row(k.direction);
      t.measured(i) = k.as_length;
    }
  }
  if (!(t.measured.squaredNorm() > 0)) {
    core::InputLocation where = s.components.front().where;
    where.key = where.key.substr(0, where.key.rfind(".components"));
    throw core::InputError(where, "a measured shape with a non-zero component", "every component zero");
  }
  return t;
}

CalibrationRequest read_calibration_request(const YamlMap& cal, const std::function<double(const std::string&)>& value,
                                            const std::function<core::Quantity(const std::string&)>& quantity,
                                            const std::vector<std::string>& known, bool three_d) {
  cal.allow_only({"parameters", "targets", "fit_labels", "bounds", "stiffness_factor", "regularization", "pair_with"});
  if (cal.has("fit_labels"))
    throw cal.error("fit_labels", "no fit_labels (the dominant coordinates are never fitted: they are checked after the fit, as a prediction)",
                    "fit_labels");
  CalibrationRequest req;
  req.where = cal.location("parameters");
  req.parameters = cal.strings("parameters");
  if (req.parameters.empty()) throw cal.error("parameters", "a list of parameter names to fit", "none");
  const double factor = cal.number_or("stiffness_factor", Quantity::dimensionless, 3.0);
  if (!(factor > 1.0 && factor <= 100.0)) throw cal.error("stiffness_factor", "a factor above 1 and at most 100", describe(cal.node()["stiffness_factor"]));
  std::vector<double> nominal;
  for (const std::string& name : req.parameters) {
    double v = 0;
    try {
      v = value(name);
    } catch (const std::invalid_argument&) {
      std::string names;
      for (const std::string& k : known) names += (names.empty() ? "" : ", ") + k;
      throw cal.error("parameters", "one of " + names, "'" + name + "'");
    }
    if (!(v > 0)) throw cal.error("parameters", "parameters with a positive starting value", name + " <= 0");
    if (std::count(req.parameters.begin(), req.parameters.end(), name) > 1) throw cal.error("parameters", "each parameter once", "'" + name + "' twice");
    nominal.push_back(v);
    req.bounds.push_back(calibration_default_bounds(v, quantity(name), factor));
  }
  for (const YamlMap& b : cal.list_of_maps("bounds")) {
    b.allow_only({"parameter", "lower", "upper", "dimensions", "distributed", "reason"});
    const std::string name = b.text("parameter");
    const auto it = std::find(req.parameters.begin(), req.parameters.end(), name);
    if (it == req.parameters.end()) throw b.error("parameter", "one of calibration.parameters", "'" + name + "'");
    const std::size_t i = static_cast<std::size_t>(it - req.parameters.begin());
    const core::Quantity q = quantity(name);
    ParameterBound bound = req.bounds[i];
    if (b.has("dimensions")) {
      // [Lx, Ly, Lz] of the body's box; the axis from the parameter's name (2-D: Y).
      if (q != Quantity::rotary_inertia) throw b.error("dimensions", "dimensions only for a rotary inertia parameter", "'" + name + "'");
      const std::vector<double> d = b.numbers("dimensions", Quantity::length);
      if (d.size() != 3 || !(d[0] >= 0 && d[1] >= 0 && d[2] >= 0)) throw b.error("dimensions", "[Lx, Ly, Lz], lengths >= 0", describe(b.node()["dimensions"]));
      const char axis = name.size() > 3 && name.compare(name.size() - 3, 3, ".xx") == 0   ? 'x'
                        : name.size() > 3 && name.compare(name.size() - 3, 3, ".zz") == 0 ? 'z'
                                                                                           : 'y';
      const std::string mass_name = name.substr(0, name.find(".inertia")) + ".mass";
      double mass = 0;
      try {
        mass = value(mass_name);
      } catch (const std::invalid_argument&) {
        throw b.error("dimensions", "an inertia whose body has a mass parameter '" + mass_name + "'", "'" + name + "'");
      }
      const bool distributed = b.boolean_or("distributed", false);
      const rigid::BodyBox box{{d[0], d[1], d[2]}, distributed};
      bound = inertia_bounds_from_dimensions(mass, rigid::gyration_range(box, axis == 'x' ? 0 : axis == 'y' ? 1 : 2), distributed,
                                             std::sqrt(nominal[i] / mass));
      bound.body_mass = mass;
      bound.physical_upper = bound.upper;  // Eq. 14.3: no distribution inside the box reaches further
      if (distributed) bound.physical_lower = bound.lower;  // Eq. 14.4
    } else if (b.has("distributed")) {
      throw b.error("distributed", "distributed only with dimensions", "no dimensions");
    }
    if (b.has("lower") || b.has("upper")) {
      if (!b.has("reason")) throw b.error("reason", "a reason for bounds that override the default", "none");
      bound.lower = b.number_or("lower", q, bound.lower);
      bound.upper = b.number_or("upper", q, bound.upper);
    }
    if (b.has("reason")) bound.basis = b.text("reason");
    if (!(bound.lower > 0 && bound.lower <= nominal[i] && nominal[i] <= bound.upper))
      throw b.error("parameter", "bounds 0 < lower <= starting value <= upper",
                    fmt::format("[{:.6g}, {:.6g}] SI about {:.6g} for '{}'", bound.lower, bound.upper, nominal[i], name));
    req.bounds[i] = bound;
  }
  for (const YamlMap& t : cal.list_of_maps("targets")) {
    t.allow_only({"frequency_hz", "dominant", "shape"});
    req.targets.push_back({t.positive("frequency_hz", Quantity::frequency), t.text_or("dominant", ""), std::nullopt});
    req.shapes.push_back(std::nullopt);
    if (auto s = t.optional_map("shape")) req.shapes.back() = read_shape(*s, three_d);
  }
  if (req.targets.empty()) throw cal.error("targets", "a list of {frequency_hz, dominant}", "none");
  if (auto r = cal.optional_map("regularization")) {
    r->allow_only({"weight"});
    req.regularization = r->positive("weight", Quantity::dimensionless);
  }
  if (cal.has("pair_with")) {
    const std::string pair = cal.text("pair_with");
    if (pair == "symmetric_modes" && three_d)
      req.symmetric_modes = true;
    else if (pair != "all_modes")
      throw cal.error("pair_with", three_d ? "all_modes or symmetric_modes" : "all_modes (symmetric_modes is for 3-D studies)", "'" + pair + "'");
    req.pair_with_where = cal.error("pair_with", "", "").where();
  }
  return req;
}

namespace {
// The coordinates of the 3-D machines that change sign when the machine is
// mirrored in its X-Z plane: lateral translations, rolls and yaws.
bool mirror_antisymmetric(const std::string& name) {
  static const char* const kNames[] = {"y", "theta_x", "theta_z", "v", "theta_u", "theta_w", "eta", "alpha"};
  return std::find(std::begin(kNames), std::end(kNames), name) != std::end(kNames);
}
}  // namespace

rigid::ModeFamily calibration_mode_family(const CalibrationRequest& c, const std::vector<std::string>& coordinates) {
  if (!c.symmetric_modes) return {};
  std::vector<Eigen::Index> odd;
  for (std::size_t i = 0; i < coordinates.size(); ++i)
    if (mirror_antisymmetric(coordinates[i])) odd.push_back(static_cast<Eigen::Index>(i));
  return [odd](const rigid::RigidMode& m) {
    // Of a machine symmetric about X-Z a mode is symmetric or antisymmetric
    // exactly; its kinetic energy in the antisymmetric coordinates is then
    // round-off (1e-6: far from both 0-ish round-off and any coupled mode).
    double share = 0.0;
    for (Eigen::Index i : odd)
      if (i < m.energy_share.size()) share += std::abs(m.energy_share(i));
    return share < kSymmetricShareLimit;
  };
}

std::vector<core::Warning> calibration_warnings(const CalibrationRequest& c, const rigid::CalibrationResult& r, const core::UnitSystem& units) {
  std::vector<core::Warning> out;
  if (r.iteration_limit_reached) {
    // The target missed most (the first of those within 1e-9 of the largest
    // miss, so that round-off cannot pick another) and the parameters the
    // bounds hold: what keeps the model from its targets.
    std::size_t worst = 0;
    std::vector<double> miss;
    for (std::size_t t = 0; t < c.targets.size() && t < r.achieved_hz.size(); ++t)
      miss.push_back(std::abs(r.achieved_hz[t] - c.targets[t].frequency_hz) / c.targets[t].frequency_hz);
    for (std::size_t t = 0; t < miss.size(); ++t)
      if (miss[t] > miss[worst] + 1e-9) worst = t;
    std::string held;
    for (std::size_t i = 0; i < r.at_bound.size() && i < c.parameters.size(); ++i)
      if (r.at_bound[i]) held += (held.empty() ? "" : ", ") + c.parameters[i];
    const std::string missed =
        miss.empty() ? std::string()
                     : fmt::format("; its largest miss is the {:g} Hz target{} on a {:.4g} Hz mode{}", c.targets[worst].frequency_hz,
                                   c.targets[worst].dominant.empty() ? "" : " (" + c.targets[worst].dominant + ")", r.achieved_hz[worst],
                                   r.achieved_dominant[worst].empty() ? "" : " (" + r.achieved_dominant[worst] + "-led)");
    core::add_warning(out, "calibration_not_converged",
                      fmt::format("calibration: the fit stopped at its iteration limit ({} iterations) with the residual still falling, its largest "
                                  "frequency error {:.3g} %{}{}: the fitted values are not a converged fit, and the model does not reach its targets "
                                  "within its bounds (docs/theory/rigid.md, section 9)",
                                  r.iterations, 100 * r.max_relative_error, missed,
                                  held.empty() ? std::string() : "; held at a bound: " + held),
                      {{"residual_max", r.max_relative_error, "1"}, {"iterations", static_cast<double>(r.iterations), "1"}});
  }
  constexpr double kSlack = 1e-6;  // relative: a value on the limit is inside it
  for (std::size_t i = 0; i < c.bounds.size() && i < r.fitted.size(); ++i) {
    const ParameterBound& b = c.bounds[i];
    if (!(b.body_mass > 0)) continue;
    const double v = r.fitted[i];
    const bool high = v > b.physical_upper * (1 + kSlack), low = v < b.physical_lower * (1 - kSlack);
    if (!high && !low) continue;
    const double k = std::sqrt(v / b.body_mass), limit = std::sqrt((high ? b.physical_upper : b.physical_lower) / b.body_mass);
    const std::string L = units.label(Quantity::length), I = units.label(Quantity::rotary_inertia);
    core::add_warning(out, "calibration_outside_physical_range",
                      fmt::format("calibration: '{}' fitted to {:.4g} {}, a radius of gyration of {:.4g} {} {} the {:.4g} {} its declared box allows "
                                  "(docs/theory/rigid.md, section 14); the study's bounds ({}) let it out: the fitted machine is not a physical one",
                                  c.parameters[i], units.from_si(v, Quantity::rotary_inertia), I, units.from_si(k, Quantity::length), L,
                                  high ? "above" : "below", units.from_si(limit, Quantity::length), L, b.basis),
                      {{"fitted", units.from_si(v, Quantity::rotary_inertia), I},
                       {"radius_of_gyration", units.from_si(k, Quantity::length), L},
                       {high ? "largest_radius_of_gyration" : "smallest_radius_of_gyration", units.from_si(limit, Quantity::length), L}});
  }
  return out;
}

void read_body_size(const YamlMap& m, const std::string& body, const std::string& prefix, std::vector<int> axes,
                    std::vector<DeclaredBodySize>& sizes) {
  const auto dims = m.optional_map("dimensions");
  if (!dims) {
    if (m.has("distributed")) throw m.error("distributed", "distributed only with dimensions", "no dimensions");
    return;
  }
  dims->allow_only({"length", "width", "height"});
  DeclaredBodySize b;
  b.body = body;
  b.parameter_prefix = prefix;
  b.where = m.location("dimensions");
  static const char* const kSides[] = {"length", "width", "height"};
  for (std::size_t i = 0; i < 3; ++i)
    if (dims->has(kSides[i])) b.box.side[i] = dims->positive(kSides[i], Quantity::length);
  if (!b.box.side[0] && !b.box.side[1] && !b.box.side[2])
    throw m.error("dimensions", "at least one of length, width, height (the body's box along X, Y, Z)", "none");
  b.box.distributed = m.boolean_or("distributed", false);
  b.axes = std::move(axes);
  sizes.push_back(std::move(b));
}

namespace {
const char* axis_name(int axis) { return axis == 0 ? "X" : axis == 1 ? "Y" : "Z"; }
}  // namespace

namespace {
// The axis of the body's inertia that calibration parameter `name` is
// ("<prefix>inertia" about a 2-D body's only axis, "<prefix>inertia.xx|yy|zz"), or -1.
int body_inertia_axis(const DeclaredBodySize& b, const std::string& name) {
  if (name.rfind(b.parameter_prefix, 0) != 0) return -1;
  const std::string rest = name.substr(b.parameter_prefix.size());
  if (rest == "inertia" && b.axes.size() == 1) return b.axes[0];
  if (rest == "inertia.xx") return 0;
  if (rest == "inertia.yy") return 1;
  if (rest == "inertia.zz") return 2;
  return -1;
}
}  // namespace

namespace {
// Whether calibration parameter `name` is the body's own mass or inertia
// ("<prefix>mass", "<prefix>inertia[.xx|.yy|.zz]", the frame parts'
// "mass_scale" and "inertia_scale.*"): a sub-part's parameter under the body's
// prefix (the cab's mounts, the plow's bounce tire, lift cylinder or swing
// spring) moves neither, so it does not make the body fitted
// (docs/theory/rigid.md, section 16).
bool fits_body_mass_or_inertia(const DeclaredBodySize& b, const std::string& name) {
  if (name.rfind(b.parameter_prefix, 0) != 0) return false;
  const std::string rest = name.substr(b.parameter_prefix.size());
  return rest == "mass" || rest == "mass_scale" || rest == "inertia" || rest.rfind("inertia.", 0) == 0 || rest.rfind("inertia_scale.", 0) == 0;
}
}  // namespace

void bound_inertias_by_body_sizes(CalibrationRequest& c, const std::vector<DeclaredBodySize>& sizes,
                                  const std::function<BodyInertia(const DeclaredBodySize&)>& inertia_of) {
  for (std::size_t i = 0; i < c.parameters.size() && i < c.bounds.size(); ++i) {
    const std::string& name = c.parameters[i];
    ParameterBound& bound = c.bounds[i];
    if (bound.basis.rfind("default:", 0) != 0) continue;  // set by the study's bounds entry
    for (const DeclaredBodySize& b : sizes) {
      const int axis = body_inertia_axis(b, name);
      if (axis < 0) continue;
      const BodyInertia m = inertia_of(b);
      const rigid::GyrationRange g = rigid::gyration_range(b.box, axis);
      if (!(m.mass > 0) || (!std::isfinite(g.largest) && !(g.smallest > 0))) continue;  // the box says nothing about this axis
      constexpr double kRadiusFactor = 1.5;  // the default's, on a side the box leaves open
      const double k = std::sqrt(std::max(m.inertia(axis), 0.0) / m.mass);
      const double k_low = std::min(g.smallest > 0 ? g.smallest : k / kRadiusFactor, k);
      const double k_high = std::max(std::isfinite(g.largest) ? g.largest : k * kRadiusFactor, k);
      bound.lower = m.mass * k_low * k_low;
      bound.upper = m.mass * k_high * k_high;
      bound.basis = "dimensions of " + b.body + ": the radius of gyration within what its declared box allows (docs/theory/rigid.md, section 15)";
      bound.body_mass = m.mass;
      bound.physical_lower = m.mass * g.smallest * g.smallest;
      bound.physical_upper = std::isfinite(g.largest) ? m.mass * g.largest * g.largest : std::numeric_limits<double>::infinity();
    }
  }
}

void check_stated_inertia(const DeclaredBodySize& b, const BodyInertia& m, const core::UnitSystem& units) {
  if (!(m.mass > 0)) return;
  const std::string L = units.label(Quantity::length);
  for (int axis : b.axes) {
    const rigid::GyrationRange g = rigid::gyration_range(b.box, axis);
    const double k = std::sqrt(std::max(m.inertia(axis), 0.0) / m.mass);
    if (rigid::judge_gyration(k, g) != rigid::GyrationVerdict::beyond_corners) continue;
    throw core::InputError(
        b.where,
        fmt::format("a radius of gyration about {} of at most {:.4g} {} for {} (half the diagonal of its box across {}: all the mass at the "
                    "corners; docs/theory/rigid.md, section 15)",
                    axis_name(axis), units.from_si(g.largest, Quantity::length), L, b.body, axis_name(axis)),
        fmt::format("{:.4g} {} (an inertia of {:.4g} {} on a mass of {:.4g} {})", units.from_si(k, Quantity::length), L, units.from_si(m.inertia(axis), Quantity::rotary_inertia),
                    units.label(Quantity::rotary_inertia), units.from_si(m.mass, Quantity::mass), units.label(Quantity::mass)));
  }
}

std::vector<core::Warning> body_size_warnings(const std::vector<DeclaredBodySize>& sizes,
                                              const std::function<BodyInertia(const DeclaredBodySize&)>& inertia_of,
                                              const std::optional<CalibrationRequest>& calibration, const core::UnitSystem& units) {
  std::vector<core::Warning> out;
  const std::string L = units.label(Quantity::length), I = units.label(Quantity::rotary_inertia);
  for (const DeclaredBodySize& b : sizes) {
    bool fitted = false;
    if (calibration)
      for (const std::string& name : calibration->parameters) fitted = fitted || fits_body_mass_or_inertia(b, name);
    const BodyInertia m = inertia_of(b);
    if (!(m.mass > 0)) continue;
    for (int axis : b.axes) {
      // An inertia calibrated with its box's range in its bounds is warned of by calibration_warnings.
      bool bounded = false;
      if (calibration)
        for (std::size_t i = 0; i < calibration->parameters.size() && i < calibration->bounds.size(); ++i)
          bounded = bounded || (body_inertia_axis(b, calibration->parameters[i]) == axis && calibration->bounds[i].body_mass > 0);
      if (bounded) continue;
      const rigid::GyrationRange g = rigid::gyration_range(b.box, axis);
      const double k = std::sqrt(std::max(m.inertia(axis), 0.0) / m.mass);
      const rigid::GyrationVerdict v = rigid::judge_gyration(k, g);
      if (v == rigid::GyrationVerdict::inside) continue;
      const bool high = v == rigid::GyrationVerdict::beyond_corners;
      const double limit = high ? g.largest : g.smallest;
      const std::vector<core::WarningFigure> figures{{fitted ? "fitted" : "inertia", units.from_si(m.inertia(axis), Quantity::rotary_inertia), I},
                                                     {"radius_of_gyration", units.from_si(k, Quantity::length), L},
                                                     {high ? "largest_radius_of_gyration" : "smallest_radius_of_gyration",
                                                      units.from_si(limit, Quantity::length), L}};
      const std::string what = fmt::format("{}'s radius of gyration about {} is {:.4g} {}, {} the {:.4g} {} {}", b.body, axis_name(axis),
                                           units.from_si(k, Quantity::length), L, high ? "above" : "below", units.from_si(limit, Quantity::length), L,
                                           high ? "of all its mass at its declared box's corners" : "of its declared box as a uniform solid");
      if (!fitted && high) continue;  // a stated value there was refused when read (check_stated_inertia)
      if (fitted)
        core::add_warning(out, "calibration_outside_physical_range",
                          fmt::format("calibration: after the fit {} (docs/theory/rigid.md, section 15): the fitted machine is not a physical one", what),
                          figures);
      else
        core::add_warning(out, "inertia_below_uniform_body",
                          fmt::format("{} (docs/theory/rigid.md, section 15): its mass lies nearer its c.g. than a body spread through its box "
                                      "allows; check the inertia, the dimensions or `distributed`",
                                      what),
                          figures);
    }
  }
  return out;
}

rigid::CalibrationResult run_calibration(const CalibrationRequest& c, const std::function<double(const std::string&)>& value,
                                         const rigid::ModesOfParameters& modes_of, const rigid::ModeFamily& family) {
  std::vector<double> initial;
  for (const std::string& name : c.parameters) initial.push_back(value(name));
  rigid::CalibrationOptions options;
  for (const ParameterBound& b : c.bounds) {
    options.lower.push_back(b.lower);
    options.upper.push_back(b.upper);
  }
  options.regularization = c.regularization;
  options.admissible = family;
  return rigid::calibrate(modes_of, initial, c.targets, options);
}

rigid::Trajectory integrate_response(rigid::SwitchedSystem& system, const ResponseRequest& req,
                                     const std::vector<std::string>& coordinate_names) {
  const int n = system.size();
  const Eigen::VectorXd q0 = Eigen::VectorXd::Zero(n), v0 = Eigen::VectorXd::Zero(n);
  rigid::IntegrationOptions o;
  o.end_time = req.duration;
  o.output_interval = req.output_interval;
  o.relative_tolerance = req.relative_tolerance;
  o.absolute_tolerance = 1e-12;
  o.velocity_scale = 100.0;
  o.coordinate_names = coordinate_names;
  return req.method == ResponseRequest::Method::event_located ? rigid::integrate_event_located(system, q0, v0, o)
                                                              : rigid::integrate_rk4(system, q0, v0, req.rk4_step, o);
}

rigid::VehicleRun response_from_rest(const rigid::VehicleModel& model, const ResponseRequest& req) {
  rigid::VehicleRun run{rigid::start_run(model, 0.0, Eigen::VectorXd::Zero(model.size())), {}};
  rigid::VehicleDynamics dynamics(model, run.state);
  run.trajectory = integrate_response(dynamics, req, model.multibody.coordinate_names());
  return run;
}

std::optional<rigid::VehicleRunState> run_vehicle_study(const rigid::VehicleModel& model, bool modes, const std::vector<std::string>& fixed,
                                                        rigid::ModalSoil modal_soil, const std::optional<ResponseRequest>& response,
                                                        const core::UnitSystem& units, VehicleResults& r) {
  r.coordinates = model.multibody.coordinate_names();
  r.coordinate_quantities = model.multibody.coordinate_quantities();
  if (modes) r.modes = rigid::rigid_modes(model.m, rigid::modal_stiffness(model, modal_soil), r.coordinates, fixed);
  r.static_contacts = static_contacts(model);
  if (modes) r.modes_by_state = modes_by_contact_state(model, fixed);
  if (!response) return std::nullopt;
  rigid::VehicleRun run = response_from_rest(model, *response);
  r.trajectory = std::move(run.trajectory);
  r.contacts = summarize_contacts(run.state, r.trajectory);
  for (core::Warning& w : contact_warnings(r.contacts, units)) r.warnings.push_back(std::move(w));  // after the calibration's, if any
  return std::move(run.state);
}

void set_plow_force_peaks(const std::vector<double>& time, const std::vector<double>& blade_z, const std::vector<double>& magnitude,
                          const std::vector<bool>& cutting, double shaker_hz, double duration, VehicleResults& r) {
  if (time.empty()) return;
  // Each state's magnitude, zero in the other state.
  std::vector<double> cutting_magnitude(time.size(), 0.0), backing_magnitude(time.size(), 0.0);
  double cut = 0.0, back = 0.0;
  for (std::size_t i = 0; i < time.size(); ++i) {
    (cutting[i] ? cutting_magnitude : backing_magnitude)[i] = magnitude[i];
    cut = std::max(cut, cutting_magnitude[i]);
    back = std::max(back, backing_magnitude[i]);
  }
  r.peak_cutting_force = cut;
  r.peak_backing_force = back;
  if (!(shaker_hz > 0)) return;
  const double period = 1.0 / shaker_hz;
  r.plow_vertical_peak_to_peak = average_peak_to_peak(time, blade_z, period, duration);
  r.average_peak_cutting_force = average_cycle_peak(time, cutting_magnitude, period, duration);
  r.average_peak_backing_force = average_cycle_peak(time, backing_magnitude, period, duration);
}

Series element_force_series(const rigid::VehicleModel& model, const rigid::VehicleRunState& run, const rigid::Trajectory& tr, int element) {
  const double statics = model.statics.element_forces.at(static_cast<std::size_t>(element));
  Series s{model.multibody.elements().at(static_cast<std::size_t>(element)).name + "_force", core::Quantity::force, {}};
  s.values.reserve(tr.time.size());
  for (std::size_t i = 0; i < tr.time.size(); ++i) s.values.push_back(statics - rigid::element_tension(model, run, element, tr.time[i], tr.q[i], tr.v[i]));
  return s;
}

Series chain_force_series(const rigid::VehicleModel& model, const rigid::VehicleRunState& run, const rigid::Trajectory& tr) {
  Series c{"chain_force", core::Quantity::force, {}};
  for (std::size_t i = 0; i < tr.time.size(); ++i) c.values.push_back(rigid::chain_force(model, run, tr.time[i]));
  return c;
}

namespace {
// Calls visit(lowest, highest) for each whole period [c T, (c + 1) T] within
// `duration` that holds a sample (both ends included).
template <class Visit>
void for_each_period(const std::vector<double>& time, const std::vector<double>& values, double period, double duration, Visit visit) {
  const int cycles = static_cast<int>(std::floor(duration / period + 1e-9));
  for (int c = 0; c < cycles; ++c) {
    double lo = 1e300, hi = -1e300;
    for (std::size_t i = 0; i < time.size(); ++i)
      if (time[i] >= c * period - 1e-12 && time[i] <= (c + 1) * period + 1e-12) {
        lo = std::min(lo, values[i]);
        hi = std::max(hi, values[i]);
      }
    if (hi >= lo) visit(lo, hi);
  }
}
}  // namespace

std::optional<double> average_peak_to_peak(const std::vector<double>& time, const std::vector<double>& values, double period, double duration) {
  double sum = 0.0;
  int counted = 0;
  for_each_period(time, values, period, duration, [&](double lo, double hi) {
    sum += hi - lo;
    ++counted;
  });
  if (counted > 0) return sum / counted;
  return std::nullopt;
}

std::optional<double> average_cycle_peak(const std::vector<double>& time, const std::vector<double>& values, double period, double duration) {
  double sum = 0.0;
  int counted = 0;
  for_each_period(time, values, period, duration, [&](double, double hi) {
    if (hi > 0.0) {
      sum += hi;
      ++counted;
    }
  });
  if (counted > 0) return sum / counted;
  return std::nullopt;
}

}  // namespace framedyn::coupling

namespace framedyn::coupling {

rigid::CalibrationResult calibrate_parameters(MachineParameters& parameters, const CalibrationRequest& c,
                                              const std::function<std::vector<rigid::RigidMode>(const rigid::VehicleModel&)>& modes) {
  CalibrationRequest request = c;
  {
    // Measured shapes seen through the nominal machine (the calibrated
    // parameters do not move its points or change its coordinates).
    const rigid::VehicleModel nominal = build_vehicle_model(parameters);
    const auto jacobian = [&](const std::vector<double>& point) {
      // Frame points are [X, Z] in 2-D, [X, Y, Z] in 3-D.
      return nominal.dimensions == 2 ? rigid::frame_point_jacobian(nominal, Eigen::Vector3d(point.at(0), 0.0, point.at(1)))
                                     : rigid::frame_point_jacobian(nominal, Eigen::Vector3d(point.at(0), point.at(1), point.at(2)));
    };
    for (std::size_t t = 0; t < c.shapes.size(); ++t)
      if (c.shapes[t]) request.targets[t].shape = shape_target(*c.shapes[t], nominal.multibody, jacobian);
  }
  const rigid::ModesOfParameters modes_of = [&](const std::vector<double>& values) {
    MachineParameters p = parameters;
    for (std::size_t i = 0; i < values.size(); ++i) set_parameter(p, c.parameters[i], values[i]);
    return modes(build_vehicle_model(p));
  };
  rigid::ModeFamily family;
  if (c.symmetric_modes) {
    const rigid::VehicleModel nominal = build_vehicle_model(parameters);
    family = calibration_mode_family(c, nominal.multibody.coordinate_names());
    std::size_t n = 0;
    const auto modes_now = modes(nominal);
    for (const rigid::RigidMode& m : modes_now) n += family(m) ? 1 : 0;
    if (n < c.targets.size())
      throw core::InputError(c.pair_with_where, fmt::format("as many modes symmetric about the X-Z plane as targets ({})", c.targets.size()),
                             fmt::format("{} of the machine's {} modes (a machine not symmetric about X-Z has none)", n, modes_now.size()));
  }
  rigid::CalibrationResult result;
  try {
    result = run_calibration(request, [&](const std::string& name) { return get_parameter(parameters, name); }, modes_of, family);
  } catch (const rigid::UnderdeterminedFit& e) {
    throw core::InputError(c.where, "no more parameters than independent targets, or calibration.regularization.weight", e.what());
  }
  for (std::size_t i = 0; i < c.parameters.size(); ++i) set_parameter(parameters, c.parameters[i], result.fitted[i]);
  return result;
}

}  // namespace framedyn::coupling
