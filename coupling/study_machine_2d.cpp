// The 2-D machine builder of the one study reader (model: rigid_2d); see study_machine.h.
#include "coupling/study_machine.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>
#include <vector>

#include "coupling/frame_loads_2d.h"
#include "coupling/study_blocks.h"
#include "coupling/yaml_input.h"

namespace framedyn::coupling::internal {

namespace {

using core::Quantity;
constexpr double kGravity = 9.80665;  // m/s^2, to turn weights into masses

double inertia_of(const YamlMap& m, double mass, const std::string& what) {
  const bool has_i = m.has("inertia"), has_k = m.has("radius_of_gyration");
  if (has_i == has_k)
    throw m.error("", "exactly one of 'inertia' or 'radius_of_gyration' for the " + what, has_i ? "both" : "neither");
  if (has_i) return m.non_negative("inertia", Quantity::rotary_inertia);
  const double k = m.non_negative("radius_of_gyration", Quantity::length);
  return mass * k * k;
}

// A 2-D body's declared box must hold the points the model puts on the body
// (its c.g., its mounts, pins and contact points, [X, Z]): a declared length
// (X) or height (Z) shorter than their span along it describes no body
// (STUDY-146, at the body's dimensions key; docs/theory/rigid.md, section 16).
void check_box_holds_points(const DeclaredBodySize& b, const std::vector<std::pair<const char*, Eigen::Vector2d>>& points,
                            const core::UnitSystem& units) {
  const std::string L = units.label(Quantity::length);
  for (const auto& [side, along, name] : {std::tuple(0, 0, "length (X)"), std::tuple(2, 1, "height (Z)")}) {
    if (!b.box.side[static_cast<std::size_t>(side)]) continue;
    const double declared = *b.box.side[static_cast<std::size_t>(side)];
    std::size_t lo = 0, hi = 0;
    for (std::size_t i = 1; i < points.size(); ++i) {
      if (points[i].second[along] < points[lo].second[along]) lo = i;
      if (points[i].second[along] > points[hi].second[along]) hi = i;
    }
    const double span = points[hi].second[along] - points[lo].second[along];
    if (span <= declared * (1 + 1e-9)) continue;
    throw core::InputError(b.where,
                           fmt::format("a {} of at least {:.4g} {} for {} (the span of its own points, from its {} at {:.4g} to its {} at {:.4g} {}: "
                                       "the box holds the whole body; docs/theory/rigid.md, section 16)",
                                       name, units.from_si(span, Quantity::length), L, b.body, points[lo].first,
                                       units.from_si(points[lo].second[along], Quantity::length), points[hi].first,
                                       units.from_si(points[hi].second[along], Quantity::length), L),
                           fmt::format("{:.4g} {}", units.from_si(declared, Quantity::length), L));
  }
}

rigid::Tire2D tire(const YamlMap& m) {
  m.allow_only({"contact", "normal", "tractive", "normal_input", "tractive_input"});
  rigid::Tire2D t;
  t.contact = m.point("contact");
  t.normal = read_spring_damper(m.map("normal"));
  t.tractive = read_spring_damper(m.map("tractive"));
  if (auto in = m.optional_map("normal_input")) t.normal_input = read_ground_input(*in);
  if (auto in = m.optional_map("tractive_input")) t.tractive_input = read_ground_input(*in);
  return t;
}

// F.30 in 2-D (docs/theory/fatigue.md section 11): a road input without `behind` runs
// behind = x_tire - x_front behind the front axle (X grows rearward): the wheelbase for the
// rear tire, 0 for the front one. A rear tire ahead of the front one needs `behind` (STUDY-160).
void derive_road_delays(rigid::Machine2DParameters& p, const YamlMap& tires) {
  const double x_front = p.front_tire.contact.x();
  const double scale = std::max({1.0, std::abs(x_front), std::abs(p.rear_tire.contact.x())});
  for (const auto& [axle, t] : {std::pair("front", &p.front_tire), std::pair("rear", &p.rear_tire)})
    for (const auto& [key, input] : {std::pair("normal_input", &t->normal_input), std::pair("tractive_input", &t->tractive_input)}) {
      if (input->kind != rigid::GroundInput::Kind::road || input->behind_given) continue;
      const double behind = t->contact.x() - x_front;
      if (behind < -1e-9 * scale)
        throw tires.map(axle).map(key).error(
            "", "a rear tire on or behind the front tire (contact X >= the front tire's X, X growing rearward) to derive its road delay, or 'behind'",
            fmt::format("contact X {} ahead of the front tire's {}", tires.map(axle).node()["contact"][0].Scalar(), tires.map("front").node()["contact"][0].Scalar()));
      input->behind = std::max(0.0, behind);
    }
}

rigid::CabMount mount(const YamlMap& m) {
  m.allow_only({"position", "stiffness", "damping"});
  return {m.point("position"), {m.non_negative("stiffness", Quantity::translational_stiffness), m.non_negative_or("damping", Quantity::translational_damping, 0.0)}};
}

}  // namespace

std::vector<std::string> calibratable_parameters_2d() {
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

core::Quantity parameter_quantity_2d(const rigid::Machine2DParameters& p, const std::string& name) {
  if (name == "tires.contact_depth") return Quantity::length;
  rigid::Machine2DParameters copy = p;
  Quantity q;
  if (!parameter_slot(copy, name, q)) throw std::invalid_argument("unknown parameter '" + name + "'");
  return q;
}

double get_parameter_2d(const rigid::Machine2DParameters& p, const std::string& name) {
  // The tractive springs' line of action, as a depth below the rails' axis.
  if (name == "tires.contact_depth") return -0.5 * (p.front_tire.contact.y() + p.rear_tire.contact.y());
  rigid::Machine2DParameters copy = p;
  Quantity q;
  const double* slot = parameter_slot(copy, name, q);
  if (!slot) throw std::invalid_argument("unknown parameter '" + name + "'");
  return *slot;
}

void set_parameter_2d(rigid::Machine2DParameters& p, const std::string& name, double value) {
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

// The mass and pitch inertia (about Y) of a declared body (DeclaredBodySize::body) of the
// machine: an added mass of the frame, the cab or the plow (docs/theory/rigid.md, section 16).
BodyInertia body_inertia_2d(const rigid::Machine2DParameters& p, const DeclaredBodySize& b) {
  for (const rigid::AddedMass& a : p.frame.added_masses)
    if (b.body == "frame.added_masses[" + a.name + "]") return {a.mass, Eigen::Vector3d(0.0, a.inertia, 0.0)};
  if (b.body == "cab") return {p.cab.mass, Eigen::Vector3d(0.0, p.cab.inertia, 0.0)};
  if (b.body == "plow") return {p.plow.mass, Eigen::Vector3d(0.0, p.plow.inertia, 0.0)};
  return {};
}


rigid::Machine2DParameters read_machine_2d(const YamlMap& root, rigid::Attachment attachment, rigid::ContactLaw contacts,
                                           std::vector<DeclaredBodySize>& body_sizes) {
  rigid::Machine2DParameters p;
  p.attachment = attachment;
  p.contacts = contacts;

  const GroundBlock ground = read_ground(root, /*with_travel_angle=*/false);
  p.ground_slope = ground.slope;
  p.forward_speed = ground.forward_speed;

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
  require_distinct_names(added, "added mass", part_load_names_2d());
  for (const YamlMap& a : added) {
    a.allow_only({"name", "mass", "weight", "inertia", "radius_of_gyration", "position", "attachment", "dimensions", "distributed"});
    rigid::AddedMass m;
    m.name = a.text("name");
    read_body_size(a, "frame.added_masses[" + m.name + "]", "frame.added_masses." + m.name + ".", {1}, body_sizes);
    m.mass = a.mass(kGravity);
    m.inertia = inertia_of(a, m.mass, "added mass " + m.name);
    m.position = a.point("position");
    m.attachment = a.has("attachment") ? a.point("attachment") : m.position;
    p.frame.added_masses.push_back(m);
  }
  // The frame's x, z and theta_y need inertia: the tube or an added mass must weigh something.
  if (!(p.frame.mass_per_length > 0) && p.frame.added_masses.empty())
    throw tube.error(tube.has("mass_per_length") ? "mass_per_length" : "weight_per_length",
                     "a frame with mass (a positive mass or weight per length, or frame.added_masses)", "0 and no added masses");

  const YamlMap cab = root.map("cab");
  cab.allow_only({"mass", "weight", "inertia", "radius_of_gyration", "position", "front_mount", "rear_mount", "dimensions", "distributed"});
  p.cab.mass = cab.mass(kGravity);
  p.cab.inertia = inertia_of(cab, p.cab.mass, "cab");
  // theta_v has no other inertia: a zero one would leave M singular.
  if (!(p.cab.inertia > 0))
    throw cab.error(cab.has("inertia") ? "inertia" : "radius_of_gyration", "a positive value (the cab's pitch theta_v needs inertia)", "0");
  p.cab.cg = cab.point("position");
  p.cab.front = mount(cab.map("front_mount"));
  p.cab.rear = mount(cab.map("rear_mount"));
  const std::size_t sizes_before_cab = body_sizes.size();
  read_body_size(cab, "cab", "cab.", {1}, body_sizes);
  if (body_sizes.size() > sizes_before_cab)
    check_box_holds_points(body_sizes.back(), {{"c.g.", p.cab.cg}, {"front mount", p.cab.front.position}, {"rear mount", p.cab.rear.position}}, root.units());

  const YamlMap tires = root.map("tires");
  tires.allow_only({"front", "rear"});
  p.front_tire = tire(tires.map("front"));
  p.rear_tire = tire(tires.map("rear"));
  derive_road_delays(p, tires);

  if (auto soil = attachment_block(root, "soil", p.attachment != rigid::Attachment::none, "no soil data without an attachment", "a soil map")) {
    soil->allow_only({"stiffness", "damping", "stiffness_reduction", "damping_reduction", "spring_reference"});
    read_soil_law(*soil, p.soil);
  }

  if (auto plow_block = attachment_block(root, "plow", p.attachment == rigid::Attachment::plow, "no plow data unless attachment is plow", "a plow map")) {
    const YamlMap& plow = *plow_block;
    plow.allow_only({"mass", "weight", "inertia", "radius_of_gyration", "cg", "linkage", "blade_point", "shaker", "bounce_tire", "lift_cylinder",
                     "dimensions", "distributed"});
    rigid::Plow2D& pl = p.plow;
    pl.mass = plow.mass(kGravity);
    pl.inertia = inertia_of(plow, pl.mass, "plow");
    pl.cg = plow.point("cg");
    read_plow_linkage_to_bounce_tire(plow, pl);
    const YamlMap cyl = plow.map("lift_cylinder");
    cyl.allow_only({"frame_point", "arm_point", "stiffness", "damping"});
    pl.cylinder_frame_point = cyl.point("frame_point");
    pl.cylinder_arm_point = cyl.point("arm_point");
    if (pl.cylinder_arm_point == pl.cylinder_frame_point)
      throw cyl.error("arm_point", "a point apart from frame_point (a lift cylinder of nonzero length)", "frame_point's point");
    pl.lift_cylinder = {cyl.non_negative("stiffness", Quantity::translational_stiffness), cyl.non_negative_or("damping", Quantity::translational_damping, 0.0)};
    // The plow body is the shank (link l2) with what it carries: pins 9 and 10, the blade, the shaker, the bounce tire.
    const std::size_t sizes_before_plow = body_sizes.size();
    read_body_size(plow, "plow", "plow.", {1}, body_sizes);
    if (body_sizes.size() > sizes_before_plow)
      check_box_holds_points(body_sizes.back(),
                             {{"c.g.", pl.cg}, {"upper joint", pl.linkage.upper_joint}, {"lower joint", pl.linkage.lower_joint},
                              {"blade point", pl.blade_point}, {"shaker point", pl.shaker_point}, {"bounce tire point", pl.bounce_tire_point}},
                             root.units());
  }
  if (auto chain = attachment_block(root, "chain", p.attachment == rigid::Attachment::chain, "no chain data unless attachment is chain", "a chain map"))
    read_chain(*chain, p.chain);

  return p;
}

FrameOutputRequest read_frame_output(const YamlMap& fo, const rigid::Machine2DParameters& p, const core::UnitSystem& units) {
  fo.allow_only({"points", "height", "rail"});
  FrameOutputRequest req;
  req.points = fo.numbers("points", Quantity::length);
  if (req.points.empty() || req.points.size() > 24)
    throw fo.error("points", "a list of 1 to 24 X positions (the thesis's limit)", fmt::format("{} points", req.points.size()));
  // The resultants of Eq. 2.47 exist only along the frame tube (FLT from its front end).
  const double front = p.frame.front_end, rear = p.frame.front_end + p.frame.length, slack = 1e-9 * p.frame.length;
  for (double x : req.points)
    if (x < front - slack || x > rear + slack)
      throw fo.error("points", fmt::format("X positions on the frame, from {:g} to {:g} {}", units.from_si(front, Quantity::length),
                                           units.from_si(rear, Quantity::length), units.label(Quantity::length)),
                     fmt::format("{:g}", units.from_si(x, Quantity::length)));
  req.height = fo.number_or("height", Quantity::length, 0.0);
  if (auto rail = fo.optional_map("rail")) {
    rail->allow_only({"area", "second_moment", "top_fiber"});
    req.rail_area = rail->positive("area", Quantity::area);
    req.rail_second_moment = rail->positive("second_moment", Quantity::second_moment_of_area);
    req.rail_top_fiber = rail->positive("top_fiber", Quantity::length);
  }
  return req;
}

}  // namespace framedyn::coupling::internal
