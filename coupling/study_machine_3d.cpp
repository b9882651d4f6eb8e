// The 3-D machine builder of the one study reader (model: rigid_3d); see study_machine.h.
#include "coupling/study_machine.h"

#include "coupling/frame_mass_source.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "coupling/study_blocks.h"
#include "coupling/yaml_input.h"
#include "fem/frame_model.h"

namespace framedyn::coupling::internal {

namespace {

using core::Quantity;
constexpr double kGravity = 9.80665;
constexpr double kDegree = M_PI / 180.0;

Eigen::Vector3d triple(const YamlMap& m, const std::string& key, Quantity q, bool non_negative) {
  const std::vector<double> v = m.numbers(key, q);
  if (v.size() != 3) throw m.error(key, "three numbers [xx, yy, zz] (or [xy, xz, yz])", fmt::format("{} numbers", v.size()));
  if (non_negative)
    for (double x : v)
      if (x < 0) throw m.error(key, "values >= 0", fmt::format("{:g} {}", m.units().from_si(x, q), m.units().label(q)));
  return {v[0], v[1], v[2]};
}

// Inertia tensor from `inertia: [Ixx, Iyy, Izz]` or `radii_of_gyration: [kx, ky, kz]`, with optional
// `products: [Pxy, Pxz, Pyz]` (integrals of x y dm etc., Eqs. F.7-F.9).
Eigen::Matrix3d inertia3(const YamlMap& m, double mass, const std::string& what) {
  const bool has_i = m.has("inertia"), has_k = m.has("radii_of_gyration");
  if (has_i == has_k) throw m.error("", "exactly one of 'inertia' or 'radii_of_gyration' for the " + what, has_i ? "both" : "neither");
  Eigen::Vector3d d;
  if (has_i) d = triple(m, "inertia", Quantity::rotary_inertia, true);
  else d = mass * triple(m, "radii_of_gyration", Quantity::length, true).cwiseAbs2();
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  if (m.has("products")) p = triple(m, "products", Quantity::rotary_inertia, false);
  return rigid::inertia_tensor(d.x(), d.y(), d.z(), p.x(), p.y(), p.z());
}

rigid::RigidPart3D part(const YamlMap& m, const std::string& name) {
  rigid::RigidPart3D r;
  r.name = name;
  r.mass = m.mass(kGravity);
  r.cg = read_point3(m, "position");
  r.inertia = inertia3(m, r.mass, name);
  return r;
}

rigid::Tire3D tire(const YamlMap& m) {
  m.allow_only({"contact", "vertical", "longitudinal", "lateral", "vertical_input", "longitudinal_input"});
  rigid::Tire3D t;
  t.contact = read_point3(m, "contact");
  t.vertical = read_spring_damper(m.map("vertical"));
  t.longitudinal = read_spring_damper(m.map("longitudinal"));
  t.lateral = read_spring_damper(m.map("lateral"));
  if (auto in = m.optional_map("vertical_input")) t.vertical_input = read_ground_input(*in);
  if (auto in = m.optional_map("longitudinal_input")) t.longitudinal_input = read_ground_input(*in);
  return t;
}

// The four tires with their names and their study keys.
template <typename Machine>
auto named_tires(Machine& p) {
  struct Named {
    const char* name;
    const char* axle;
    const char* side;
    decltype(&p.front_tires.left) tire;
  };
  return std::array<Named, 4>{{{"front left", "front", "left", &p.front_tires.left},
                               {"front right", "front", "right", &p.front_tires.right},
                               {"rear left", "rear", "left", &p.rear_tires.left},
                               {"rear right", "rear", "right", &p.rear_tires.right}}};
}

// F.30: behind = x_tire - x_front for every road input the study gave no `behind`.
void derive_road_delays(rigid::Machine3DParameters& p, const YamlMap& tires) {
  const double x_front = 0.5 * (p.front_tires.left.contact.x() + p.front_tires.right.contact.x());
  const double scale = std::max({1.0, std::abs(p.front_tires.left.contact.x()), std::abs(p.rear_tires.left.contact.x())});
  // A contact's X as the study wrote it (in its units).
  const auto x_text = [&](const char* axle, const char* side) { return tires.map(axle).map(side).node()["contact"][0].Scalar(); };
  for (const auto& t : named_tires(p))
    for (const auto& [key, input] : {std::pair("vertical_input", &t.tire->vertical_input), std::pair("longitudinal_input", &t.tire->longitudinal_input)}) {
      if (input->kind != rigid::GroundInput::Kind::road || input->behind_given) continue;
      const double behind = t.tire->contact.x() - x_front;
      if (behind < -1e-9 * scale) {
        const YamlMap in = tires.map(t.axle).map(t.side).map(key);
        throw in.error("", "a tire on or behind the front axle (contact X >= the front tires' mean X, X growing rearward) to derive its road delay, or 'behind'",
                       fmt::format("contact X {} ahead of the front tires' ({} and {})", x_text(t.axle, t.side), x_text("front", "left"), x_text("front", "right")));
      }
      input->behind = std::max(0.0, behind);
    }
}

rigid::Axle3D axle(const YamlMap& m) {
  m.allow_only({"steering_deg", "left", "right"});
  rigid::Axle3D a;
  a.steering_angle = m.number_or("steering_deg", Quantity::dimensionless, 0.0) * kDegree;
  if (std::abs(a.steering_angle) >= M_PI / 2) throw m.error("steering_deg", "an angle between -90 and 90 degrees", describe(m.node()["steering_deg"]));
  a.left = tire(m.map("left"));
  a.right = tire(m.map("right"));
  return a;
}

// Calibration slots. Scales of all frame parts are handled separately.
double* slot(rigid::Machine3DParameters& p, const std::string& name) {
  if (name == "cab.mass") return &p.cab.body.mass;
  if (name == "cab.inertia.xx") return &p.cab.body.inertia(0, 0);
  if (name == "cab.inertia.yy") return &p.cab.body.inertia(1, 1);
  if (name == "cab.inertia.zz") return &p.cab.body.inertia(2, 2);
  if (name == "front_axle.inertia.xx") return &p.front_axle.axle.inertia(0, 0);
  if (name == "front_axle.mass") return &p.front_axle.axle.mass;
  if (name == "plow.swing_spring.stiffness") return &p.plow.swing_spring.stiffness;
  if (name == "plow.bounce_tire.stiffness") return &p.plow.bounce_tire.stiffness;
  if (name == "plow.lift_cylinder.stiffness") return &p.plow.lift_cylinder.stiffness;
  if (name == "plow.mass") return &p.plow.mass;
  if (name == "soil.stiffness") return &p.soil.stiffness;
  if (name == "soil.lateral.stiffness") return &p.soil_lateral.stiffness;
  return nullptr;
}

rigid::SpringDamperValues* tire_spring(rigid::Tire3D& t, const std::string& dir) {
  if (dir == "vertical") return &t.vertical;
  if (dir == "longitudinal") return &t.longitudinal;
  if (dir == "lateral") return &t.lateral;
  return nullptr;
}

// A frame part's `mounts`: 1 to kMaxCouplingMounts entries, each a node number of the frame
// mesh or a point [X, Y, Z] (the nearest beam node); used by the frame model only
// (coupling/frame_parts.h). Node numbers and lines are checked against the mesh there.
void read_part_mounts(const YamlMap& a, StudyFramePart& sp) {
  const YAML::Node list = a.node()["mounts"];
  const std::string expected = fmt::format("a list of 1 to {} mounts, each a node number of the frame mesh or a point [X, Y, Z]", fem::kMaxCouplingMounts);
  sp.mounts_where = a.location("mounts");
  if (!list.IsSequence() || list.size() == 0 || list.size() > static_cast<std::size_t>(fem::kMaxCouplingMounts))
    throw a.error("mounts", expected, list.IsSequence() ? fmt::format("{} mounts", list.size()) : describe(list));
  for (std::size_t i = 0; i < list.size(); ++i) {
    const YAML::Node item = list[i];
    PartMount m;
    m.where = {a.file(), item.Mark().line + 1, fmt::format("{}.mounts[{}]", a.path(), i)};
    bool ok = false;
    if (item.IsScalar()) {
      const std::string t = item.Scalar();
      ok = !t.empty() && t.size() < 10 && std::all_of(t.begin(), t.end(), [](char c) { return c >= '0' && c <= '9'; }) && std::stoi(t) > 0;
      if (ok) m.node = std::stoi(t);
    } else if (item.IsSequence() && item.size() == 3) {
      ok = true;
      for (std::size_t k = 0; k < 3 && ok; ++k) {
        double v = 0.0;
        ok = item[k].IsScalar() && parse_number(item[k], v) && std::isfinite(v);
        m.point(static_cast<Eigen::Index>(k)) = a.units().to_si(v, Quantity::length);
      }
      m.by_point = true;
    }
    if (!ok) throw core::InputError(m.where, expected, describe(item));
    sp.mounts.push_back(m);
  }
}

}  // namespace

// The mass and the inertias about its own axes of a declared body (DeclaredBodySize::body) of the machine.
BodyInertia body_inertia_3d(const rigid::Machine3DParameters& p, const DeclaredBodySize& b) {
  const auto of = [](const rigid::RigidPart3D& r) { return BodyInertia{r.mass, r.inertia.diagonal()}; };
  if (b.body == "cab") return of(p.cab.body);
  if (b.body == "front_axle") return of(p.front_axle.axle);
  if (b.body == "frame.reel_and_carrier") return of(p.frame.reel_and_carrier);
  if (b.body == "frame.rear_axle") return of(p.frame.rear_axle);
  if (b.body == "plow") return {p.plow.mass, p.plow.inertia_boom_axes.diagonal()};
  for (const rigid::RigidPart3D& part : p.frame.parts)
    if (b.body == "frame.parts[" + part.name + "]") return of(part);
  return {};
}

std::vector<std::string> calibratable_parameters_3d() {
  return {"tires.front.vertical.stiffness", "tires.front.longitudinal.stiffness", "tires.front.lateral.stiffness",
          "tires.rear.vertical.stiffness",  "tires.rear.longitudinal.stiffness",  "tires.rear.lateral.stiffness",
          "tires.contact_depth",
          "cab.mounts.x.stiffness",         "cab.mounts.y.stiffness",             "cab.mounts.z.stiffness",
          "cab.front_mounts.<x|y|z>.stiffness", "cab.rear_mounts.<x|y|z>.stiffness",
          "cab.mass",                       "cab.inertia.xx",                     "cab.inertia.yy",
          "cab.inertia.zz",                 "frame.parts.mass_scale",             "frame.parts.inertia_scale.xx",
          "frame.parts.inertia_scale.yy",   "frame.parts.inertia_scale.zz",       "front_axle.inertia.xx", "front_axle.mass",
          "plow.swing_spring.stiffness",    "plow.bounce_tire.stiffness",         "plow.lift_cylinder.stiffness",
          "plow.mass",                      "soil.stiffness",                     "soil.lateral.stiffness"};
}

core::Quantity parameter_quantity_3d(const std::string& name) {
  if (name == "tires.contact_depth") return Quantity::length;
  if (name.find("stiffness") != std::string::npos) return name == "plow.swing_spring.stiffness" ? Quantity::rotational_stiffness : Quantity::translational_stiffness;
  // frame.parts.mass_scale / inertia_scale.<xx|yy|zz> hold the parts' total
  // mass / inertia (get_parameter_3d): a mass and a rotary inertia, not ratios.
  if (name.find("inertia") != std::string::npos) return Quantity::rotary_inertia;
  if (name.find("mass") != std::string::npos) return Quantity::mass;
  throw std::invalid_argument("unknown parameter '" + name + "'");
}

// The frame-part "scales" are the totals of the parts' masses (or inertias about
// one axis); setting one scales every part by the same factor.
double get_parameter_3d(const rigid::Machine3DParameters& p_in, const std::string& name) {
  rigid::Machine3DParameters p = p_in;
  if (name == "tires.contact_depth") return -0.25 * (p.front_tires.left.contact.z() + p.front_tires.right.contact.z() + p.rear_tires.left.contact.z() + p.rear_tires.right.contact.z());
  if (name.rfind("tires.", 0) == 0) {
    const std::size_t a = name.find('.', 6), b = name.rfind('.');
    const std::string which = name.substr(6, a - 6), dir = name.substr(a + 1, b - a - 1);
    rigid::Axle3D* ax = which == "front" ? &p.front_tires : which == "rear" ? &p.rear_tires : nullptr;
    if (!ax || !tire_spring(ax->left, dir) || name.substr(b + 1) != "stiffness") throw std::invalid_argument("unknown parameter '" + name + "'");
    return tire_spring(ax->left, dir)->stiffness + tire_spring(ax->right, dir)->stiffness;  // the axle's two tires together
  }
  if (name.rfind("cab.mounts.", 0) == 0 || name.rfind("cab.front_mounts.", 0) == 0 || name.rfind("cab.rear_mounts.", 0) == 0) {
    const std::size_t first = name.find('.', 4);
    const std::string group = name.substr(4, first - 4), rest = name.substr(first + 1);
    const std::string dir = rest.substr(0, 1);
    if (p.cab.mounts.empty() || rest.substr(1) != ".stiffness" || (dir != "x" && dir != "y" && dir != "z"))
      throw std::invalid_argument("unknown parameter '" + name + "'");
    double mean_x = 0;
    for (const auto& m : p.cab.mounts) mean_x += m.position.x() / static_cast<double>(p.cab.mounts.size());
    double sum = 0;
    for (const auto& m : p.cab.mounts)
      if (group == "mounts" || (group == "front_mounts") == (m.position.x() < mean_x)) sum += (dir == "x" ? m.x : dir == "y" ? m.y : m.z).stiffness;
    return sum;  // the group's mounts together
  }
  if (name == "frame.parts.mass_scale" || name.rfind("frame.parts.inertia_scale.", 0) == 0) {
    if (p.frame.parts.empty()) throw std::invalid_argument("no frame parts to scale");
    double total = 0;
    const int axis = name == "frame.parts.mass_scale" ? -1 : (name.back() == 'x' ? 0 : name.back() == 'y' ? 1 : 2);
    for (const auto& pt : p.frame.parts) total += axis < 0 ? pt.mass : pt.inertia(axis, axis);
    return total;
  }
  const double* s = slot(p, name);
  if (!s) throw std::invalid_argument("unknown parameter '" + name + "'");
  return *s;
}

void set_parameter_3d(rigid::Machine3DParameters& p, const std::string& name, double value) {
  if (name == "tires.contact_depth") {
    for (rigid::Tire3D* t : {&p.front_tires.left, &p.front_tires.right, &p.rear_tires.left, &p.rear_tires.right}) t->contact.z() = -value;
    return;
  }
  if (name.rfind("tires.", 0) == 0 || (name.rfind("cab.", 0) == 0 && name.find("mounts.") != std::string::npos) || name.rfind("frame.parts.", 0) == 0) {
    const double current = get_parameter_3d(p, name);
    const double f = current > 0 ? value / current : 1.0;
    if (name.rfind("tires.", 0) == 0) {
      const std::size_t a = name.find('.', 6), b = name.rfind('.');
      const std::string which = name.substr(6, a - 6), dir = name.substr(a + 1, b - a - 1);
      rigid::Axle3D& ax = which == "front" ? p.front_tires : p.rear_tires;
      tire_spring(ax.left, dir)->stiffness *= f;
      tire_spring(ax.right, dir)->stiffness *= f;
    } else if (name.rfind("cab.", 0) == 0) {
      const std::size_t first = name.find('.', 4);
      const std::string group = name.substr(4, first - 4), dir = name.substr(first + 1, 1);
      double mean_x = 0;
      for (const auto& m : p.cab.mounts) mean_x += m.position.x() / static_cast<double>(p.cab.mounts.size());
      for (auto& m : p.cab.mounts)
        if (group == "mounts" || (group == "front_mounts") == (m.position.x() < mean_x)) (dir == "x" ? m.x : dir == "y" ? m.y : m.z).stiffness *= f;
    } else {
      const int axis = name == "frame.parts.mass_scale" ? -1 : (name.back() == 'x' ? 0 : name.back() == 'y' ? 1 : 2);
      for (auto& pt : p.frame.parts) (axis < 0 ? pt.mass : pt.inertia(axis, axis)) *= f;
    }
    return;
  }
  double* s = slot(p, name);
  if (!s) throw std::invalid_argument("unknown parameter '" + name + "'");
  *s = value;
}

rigid::Machine3DParameters read_machine_3d(const YamlMap& root, rigid::Attachment attachment, rigid::ContactLaw contacts,
                                           std::vector<DeclaredBodySize>& body_sizes, StudyFrameParts& frame_parts) {
  rigid::Machine3DParameters p;
  p.attachment = attachment;
  p.contacts = contacts;

  const YamlMap tires = root.map("tires");
  tires.allow_only({"front", "rear"});
  p.front_tires = axle(tires.map("front"));
  p.rear_tires = axle(tires.map("rear"));
  derive_road_delays(p, tires);
  p.travel_angle = p.rear_tires.steering_angle;  // crab steering: the machine travels along its wheels
  const GroundBlock ground = read_ground(root, /*with_travel_angle=*/true);
  p.ground_slope = ground.slope;
  p.forward_speed = ground.forward_speed;
  if (ground.travel_angle) p.travel_angle = *ground.travel_angle;

  const YamlMap frame = root.map("frame");
  frame.allow_only({"reference", "parts", "reel_and_carrier", "rear_axle"});
  if (frame.has("reference")) p.frame.reference = read_point3(frame, "reference");
  const std::vector<YamlMap> parts = frame.list_of_maps("parts");
  require_distinct_names(parts, "frame part");
  // `from: frame_mesh`: the part the frame mesh models, its values from the mesh (coupling/frame_mass_source.h).
  std::vector<StudyFramePart>& study_parts = frame_parts.parts;
  frame_parts.entries = parts;
  frame_parts.where = frame.location("parts");
  for (const YamlMap& a : parts) {
    StudyFramePart sp;
    sp.where = a.location("");
    sp.where.key = a.path();
    if (a.has("from")) {
      const std::string from = a.text("from");
      bool second = false;
      for (const StudyFramePart& q : study_parts) second = second || q.from_mesh;
      if (from != "frame_mesh" || second)
        throw a.error("from", "from: frame_mesh on one part only (the frame structure the frame_response mesh models)",
                      second ? "from: frame_mesh on a second part" : "from: " + from);
      sp.from_mesh = true;
      sp.has_values = a.has("mass") || a.has("weight");
    }
    if (sp.has_values) {
      a.allow_only({"name", "mass", "weight", "position", "inertia", "radii_of_gyration", "products", "from", "mounts", "dimensions", "distributed"});
      sp.part = part(a, a.text("name"));
      read_body_size(a, "frame.parts[" + sp.part.name + "]", "frame.parts.", {0, 1, 2}, body_sizes);
      // The part the mesh models is the mesh's own tubes: it has no mounts to join.
      if (sp.from_mesh && a.has("mounts"))
        throw a.error("mounts", "no mounts on the part the frame mesh models (from: frame_mesh: it is the mesh's own tubes)", "mounts");
      if (a.has("mounts")) read_part_mounts(a, sp);
    } else {
      a.allow_only({"name", "from"});
      sp.part.name = a.text("name");
    }
    study_parts.push_back(sp);
    p.frame.parts.push_back(sp.part);
  }
  if (p.frame.parts.empty()) throw frame.error("parts", "a list of the frame's parts", "none");
  const YamlMap reel = frame.map("reel_and_carrier");
  reel.allow_only({"mass", "weight", "position", "inertia", "radii_of_gyration", "products", "attachment", "dimensions", "distributed"});
  p.frame.reel_and_carrier = part(reel, "reel_and_carrier");
  read_body_size(reel, "frame.reel_and_carrier", "frame.reel_and_carrier.", {0, 1, 2}, body_sizes);
  p.frame.reel_attachment = read_point3(reel, "attachment");
  const YamlMap rear = frame.map("rear_axle");
  rear.allow_only({"mass", "weight", "position", "inertia", "radii_of_gyration", "products", "pin", "leveling_cylinder", "dimensions", "distributed"});
  p.frame.rear_axle = part(rear, "rear_axle");
  read_body_size(rear, "frame.rear_axle", "frame.rear_axle.", {0, 1, 2}, body_sizes);
  p.frame.rear_pin = read_point3(rear, "pin");
  p.frame.leveling_cylinder = read_point3(rear, "leveling_cylinder");
  if (p.frame.leveling_cylinder.y() == p.frame.rear_pin.y())
    throw rear.error("leveling_cylinder", "a point beside the pin in Y (the cylinder holds the axle's roll)", "the pin's Y");

  const YamlMap front = root.map("front_axle");
  front.allow_only({"mass", "weight", "position", "inertia", "radii_of_gyration", "products", "pin", "dimensions", "distributed"});
  p.front_axle.axle = part(front, "front_axle");
  read_body_size(front, "front_axle", "front_axle.", {0, 1, 2}, body_sizes);
  p.front_axle.pin = read_point3(front, "pin");
  // The axle rolls (eta) about the pin's X axis: it needs inertia about that axis, its own or its mass's off the axis.
  const Eigen::Vector3d off_pin = p.front_axle.axle.cg - p.front_axle.pin;
  if (!(p.front_axle.axle.inertia(0, 0) + p.front_axle.axle.mass * (off_pin.y() * off_pin.y() + off_pin.z() * off_pin.z()) > 0))
    throw front.error("", "inertia about the pin's X axis for the axle's roll eta (a roll inertia, or a centre of mass off that axis)",
                      "no roll inertia and the centre of mass on the axis");

  const YamlMap cab = root.map("cab");
  cab.allow_only({"mass", "weight", "position", "inertia", "radii_of_gyration", "products", "mounts", "dimensions", "distributed"});
  p.cab.body = part(cab, "cab");
  read_body_size(cab, "cab", "cab.", {0, 1, 2}, body_sizes);
  const std::vector<YamlMap> mounts = cab.list_of_maps("mounts");
  require_distinct_names(mounts, "cab mount");
  for (const YamlMap& m : mounts) {
    m.allow_only({"name", "position", "x", "y", "z"});
    rigid::CabMount3D mount;
    mount.name = m.text("name");
    mount.position = read_point3(m, "position");
    mount.x = read_spring_damper(m.map("x"));
    mount.y = read_spring_damper(m.map("y"));
    mount.z = read_spring_damper(m.map("z"));
    p.cab.mounts.push_back(mount);
  }
  if (p.cab.mounts.size() != 4) throw cab.error("mounts", "four mounts (load points 28-31: FL, FR, RL, RR)", fmt::format("{}", p.cab.mounts.size()));

  if (auto soil = attachment_block(root, "soil", p.attachment != rigid::Attachment::none, "no soil data without an attachment", "a soil map")) {
    soil->allow_only({"stiffness", "damping", "stiffness_reduction", "damping_reduction", "spring_reference", "lateral"});
    read_soil_law(*soil, p.soil);
    p.soil_lateral = read_spring_damper(soil->map("lateral"));
  }

  if (auto plow_block = attachment_block(root, "plow", p.attachment == rigid::Attachment::plow, "no plow data unless attachment is plow", "a plow map")) {
    const YamlMap& plow = *plow_block;
    plow.allow_only({"swing_pin", "boom_angle_deg", "blade_angle_deg", "boom_offset", "mass", "weight", "inertia", "radii_of_gyration", "products",
                     "cg", "linkage", "blade_point", "shaker", "bounce_tire", "lift_cylinder", "swing_spring", "dimensions", "distributed"});
    read_body_size(plow, "plow", "plow.", {0, 1, 2}, body_sizes);  // its box along the boom's axes, as its inertia
    rigid::Plow3D& pl = p.plow;
    pl.swing_pin = read_point3(plow, "swing_pin");
    pl.boom_angle = plow.number_or("boom_angle_deg", Quantity::dimensionless, 0.0) * kDegree;
    pl.blade_angle = plow.number_or("blade_angle_deg", Quantity::dimensionless, 0.0) * kDegree;
    if (std::abs(pl.boom_angle) >= M_PI / 2) throw plow.error("boom_angle_deg", "an angle between -90 and 90 degrees", describe(plow.node()["boom_angle_deg"]));
    if (std::abs(pl.blade_angle) >= M_PI / 2) throw plow.error("blade_angle_deg", "an angle between -90 and 90 degrees", describe(plow.node()["blade_angle_deg"]));
    pl.boom_offset = plow.number_or("boom_offset", Quantity::length, pl.swing_pin.y());
    pl.mass = plow.mass(kGravity);
    pl.inertia_boom_axes = inertia3(plow, pl.mass, "plow");
    pl.cg = plow.point("cg");
    read_plow_linkage_to_bounce_tire(plow, pl);
    const YamlMap cyl = plow.map("lift_cylinder");
    cyl.allow_only({"base", "arm_point", "stiffness", "damping"});
    pl.cylinder_base = cyl.point("base");
    pl.cylinder_arm_point = cyl.point("arm_point");
    // Both ends are [X, Z] in the boom plane: equal points are a cylinder of no length.
    if (pl.cylinder_arm_point == pl.cylinder_base)
      throw cyl.error("arm_point", "a point apart from base (a lift cylinder of nonzero length)", "the base's point");
    pl.lift_cylinder = {cyl.non_negative("stiffness", Quantity::translational_stiffness), cyl.non_negative_or("damping", Quantity::translational_damping, 0.0)};
    const YamlMap swing = plow.map("swing_spring");
    swing.allow_only({"stiffness", "damping"});
    // K30 in moment per radian; C30 in moment * time per radian (time is seconds in every unit system).
    pl.swing_spring = {swing.non_negative("stiffness", Quantity::rotational_stiffness), swing.non_negative_or("damping", Quantity::rotational_stiffness, 0.0)};
  }
  if (auto chain = attachment_block(root, "chain", p.attachment == rigid::Attachment::chain, "no chain data unless attachment is chain", "a chain map"))
    read_chain(*chain, p.chain);

  return p;
}

void read_frame_response(const YamlMap& root, const std::string& file, const StudyFrameParts& parts, RigidStudy& s) {
  rigid::Machine3DParameters& p = s.machine_3d();
  if (root.has("frame_response")) {
    const YamlMap block = root.map("frame_response");
    if (block.has("loads"))
      throw block.error("loads", "no load-history file (the loads are this study's own frame loads at points 24-31)", "loads: " + block.text("loads"));
    if (!s.response) throw root.error("frame_response", "analysis.response as well (the frame loads come from the forced response)", "no response");
    FrameStudyRequest q = read_frame_block(block, std::filesystem::path(file).parent_path());
    q.name = s.name;
    // One source of truth for the frame structure's mass: the mesh (Eq. 9.4); the other parts go onto the frame model.
    const fem::FrameModel mesh = read_frame_mesh(q);
    const FrameMassSources sources = frame_mass_from_mesh(parts.parts, mesh, q.mesh.string(), parts.where, s.units);
    {
      // The parts' mounts against the mesh now (STUDY-111..113), so that a wrong node costs no vehicle run.
      fem::FrameModel probe = mesh;
      (void)mount_frame_parts(probe, sources.mounted, q.mesh.string());
    }
    p.frame.parts = sources.vehicle_parts;
    q.parts = sources.mounted;
    q.structure_part = sources.structure_part;
    q.structure_source = "mesh";
    q.parts_carried_by_mesh = sources.carried_by_mesh;
    q.gravity = Eigen::Vector3d(0.0, 0.0, -p.gravity);  // the vehicle model's axes: Z vertical, the ground (not gravity) sloped
    s.frame_response = q;
  } else {
    for (std::size_t i = 0; i < parts.parts.size(); ++i)
      if (parts.parts[i].from_mesh)
        throw parts.entries[i].error("from", "a frame_response block with the frame mesh (the part's mass, c.g. and inertia come from it)", "no frame_response");
  }
}

}  // namespace framedyn::coupling::internal
