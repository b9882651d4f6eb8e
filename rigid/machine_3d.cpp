// The 3-D machine on the multibody assembly (thesis Chapter III, Eqs.
// 3.1-3.12, Appendices E and F, Table II); see machine_3d.h and
// docs/theory/rigid.md, section 10.
#include "rigid/machine_3d.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace framedyn::rigid {

namespace {

constexpr double kTwoPi = 6.283185307179586;
constexpr int X = 0, Y = 1, Z = 2;

std::vector<std::string> coordinate_names(Attachment a) {
  std::vector<std::string> names{"x", "y", "z", "theta_x", "theta_y", "theta_z", "u", "v", "w", "theta_u", "theta_v", "theta_w", "eta"};
  if (a == Attachment::plow) {
    names.push_back("psi");
    names.push_back("alpha");
  }
  return names;
}

// What each coordinate measures (Chapter III): the frame's and the cab's
// X, Y, Z (x, y, z; u, v, w) translations, every theta, the axle's roll eta,
// the linkage's psi and alpha rotations.
std::vector<core::Quantity> coordinate_quantities(Attachment a) {
  using core::Quantity;
  constexpr Quantity L = Quantity::length, A = Quantity::angle;
  std::vector<Quantity> q{L, L, L, A, A, A, L, L, L, A, A, A, A};
  if (a == Attachment::plow) {
    q.push_back(A);
    q.push_back(A);
  }
  return q;
}

int index_of(const std::vector<std::string>& names, const std::string& n) {
  for (std::size_t i = 0; i < names.size(); ++i)
    if (names[i] == n) return static_cast<int>(i);
  return -1;
}

// Rotation by `angle` about the unit axis `axis` (Rodrigues).
Eigen::Matrix3d rotation(const Eigen::Vector3d& axis, double angle) { return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix(); }

Eigen::Vector3d boom_plane_point(const Eigen::Vector2d& p, double offset) { return {p.x(), offset, p.y()}; }

}  // namespace

Eigen::Matrix3d inertia_tensor(double ixx, double iyy, double izz, double pxy, double pxz, double pyz) {
  Eigen::Matrix3d i;
  i << ixx, -pxy, -pxz, -pxy, iyy, -pyz, -pxz, -pyz, izz;
  return i;
}

RigidPart3D combine(const std::vector<RigidPart3D>& parts, const std::string& name) {
  RigidPart3D c;
  c.name = name;
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();
  for (const RigidPart3D& p : parts) {
    c.mass += p.mass;
    moment += p.mass * p.cg;
  }
  if (!(c.mass > 0.0)) throw std::invalid_argument(name + ": no mass");
  c.cg = moment / c.mass;
  for (const RigidPart3D& p : parts) {
    const Eigen::Vector3d r = p.cg - c.cg;
    // Parallel axes with products: I += I_p + m (|r|^2 1 - r r^T)  (Eqs. F.3, F.5-F.12 as one tensor sum).
    c.inertia += p.inertia + p.mass * (r.squaredNorm() * Eigen::Matrix3d::Identity() - r * r.transpose());
  }
  return c;
}

Machine3D::Machine3D(const Machine3DParameters& p) : p_(p), model_(coordinate_names(p.attachment), coordinate_quantities(p.attachment)) {
  const std::vector<std::string>& names = model_.coordinate_names();
  const int n = model_.size();
  auto col = [&](const char* c) { return index_of(names, c); };
  const int ix = col("x"), iy = col("y"), iz = col("z"), itx = col("theta_x"), ity = col("theta_y"), itz = col("theta_z");
  const int iu = col("u"), iv = col("v"), iw = col("w"), itu = col("theta_u"), itv = col("theta_v"), itw = col("theta_w");
  const int ieta = col("eta"), ipsi = col("psi"), ialpha = col("alpha");

  // Reference point of x, y, z: the frame assembly's c.g. with the front axle (Eqs. F.1, F.2, F.4) unless given.
  {
    std::vector<RigidPart3D> all = p.frame.parts;
    all.push_back(p.frame.reel_and_carrier);
    all.push_back(p.frame.rear_axle);
    all.push_back(p.front_axle.axle);
    reference_ = p.frame.reference ? *p.frame.reference : combine(all, "frame assembly").cg;
  }

  // Frame: a point p moves by (x, y, z) + theta x (p - ref)  (Eq. 3.3).
  Jacobian frame_rotation = Jacobian::Zero(3, n);
  frame_rotation(X, itx) = frame_rotation(Y, ity) = frame_rotation(Z, itz) = 1.0;
  auto frame_jacobian = [&](const Eigen::Vector3d& point) {
    Jacobian j = Jacobian::Zero(3, n);
    j(X, ix) = j(Y, iy) = j(Z, iz) = 1.0;
    j -= skew(point - reference_) * frame_rotation;
    return j;
  };
  auto rigid_body = [&](const RigidPart3D& part, const Jacobian& translation, const Jacobian& rotation_jacobian) {
    Body b;
    b.name = part.name;
    b.mass = part.mass;
    b.inertia = part.inertia;
    b.translation = translation;
    b.rotation = rotation_jacobian;
    return model_.add_body(b);
  };
  const RigidPart3D frame_part = combine(p.frame.parts, "frame");
  frame_body_ = rigid_body(frame_part, frame_jacobian(frame_part.cg), frame_rotation);
  reel_body_ = rigid_body(p.frame.reel_and_carrier, frame_jacobian(p.frame.reel_and_carrier.cg), frame_rotation);
  rear_axle_body_ = rigid_body(p.frame.rear_axle, frame_jacobian(p.frame.rear_axle.cg), frame_rotation);
  auto frame_point = [&](const std::string& name, const Eigen::Vector3d& point) { return model_.add_point({name, frame_jacobian(point)}); };

  // Front axle: pinned at point 20, angular velocity (eta', theta_y', theta_z') (Table II, Eq. 3.4).
  {
    Jacobian rot = Jacobian::Zero(3, n);
    rot(X, ieta) = 1.0;
    rot(Y, ity) = 1.0;
    rot(Z, itz) = 1.0;
    const Jacobian pin = frame_jacobian(p.front_axle.pin);
    front_axle_body_ = rigid_body(p.front_axle.axle, pin - skew(p.front_axle.axle.cg - p.front_axle.pin) * rot, rot);
  }

  // Cab: six coordinates of its own (Eq. 3.7).
  {
    Jacobian t = Jacobian::Zero(3, n), r = Jacobian::Zero(3, n);
    t(X, iu) = t(Y, iv) = t(Z, iw) = 1.0;
    r(X, itu) = r(Y, itv) = r(Z, itw) = 1.0;
    cab_body_ = rigid_body(p.cab.body, t, r);
  }
  for (const CabMount3D& mount : p.cab.mounts) {
    const int a = frame_point("cab_mount_" + mount.name + "_frame", mount.position);
    const int b = model_.add_body_point("cab_mount_" + mount.name + "_cab", cab_body_, mount.position - p.cab.body.cg);
    const std::pair<const char*, const SpringDamperValues*> axes[] = {{"x", &mount.x}, {"y", &mount.y}, {"z", &mount.z}};
    for (int k = 0; k < 3; ++k)
      model_.add_element({"cab_mount_" + mount.name + "_" + axes[k].first, a, b, Eigen::Vector3d::Unit(k), axes[k].second->stiffness,
                          axes[k].second->damping});
  }

  // Tires: ground axes (slope about Y), wheel axes turned by the steering angle about the normal.
  const double g = p.ground_slope;
  const Eigen::Vector3d normal(std::sin(g), 0.0, std::cos(g)), tangent(std::cos(g), 0.0, -std::sin(g)), side = Eigen::Vector3d::UnitY();
  auto add_tire = [&](const std::string& name, const Tire3D& tire, double delta, bool on_front_axle) {
    const int c = on_front_axle ? model_.add_body_point(name + "_contact", front_axle_body_, tire.contact - p.front_axle.axle.cg)
                                : frame_point(name + "_contact", tire.contact);
    // Rolling direction (rearward sense) and axle direction of a wheel steered by delta to the right:
    // its forward heading -longitudinal = (-cos delta, sin delta) in the ground plane.
    const Eigen::Vector3d longitudinal = std::cos(delta) * tangent - std::sin(delta) * side;
    const Eigen::Vector3d lateral = std::sin(delta) * tangent + std::cos(delta) * side;
    model_.add_element({name + "_vertical", c, -1, normal, tire.vertical.stiffness, tire.vertical.damping});
    model_.add_element({name + "_longitudinal", c, -1, longitudinal, tire.longitudinal.stiffness, tire.longitudinal.damping});
    model_.add_element({name + "_lateral", c, -1, lateral, tire.lateral.stiffness, tire.lateral.damping});
  };
  add_tire("front_left_tire", p.front_tires.left, p.front_tires.steering_angle, true);
  add_tire("front_right_tire", p.front_tires.right, p.front_tires.steering_angle, true);
  add_tire("rear_left_tire", p.rear_tires.left, p.rear_tires.steering_angle, false);
  add_tire("rear_right_tire", p.rear_tires.right, p.rear_tires.steering_angle, false);

  if (p.soil.contact_moves_with_soil && !p.soil.cut_face)
    throw std::invalid_argument("the 3-D model does not yet have the soil law's 'soil_line' spring reference (use equilibrium or contact)");
  // The cut face's anchor stays where the cut ended instead of streaming with the soil: exact only without springs while backing.
  if (p.soil.cut_face && p.soil.stiffness_reduction != 0.0)
    throw std::invalid_argument("the 3-D model has the soil law's 'cut_face' spring reference only with stiffness_reduction 0");
  // Soil directions: along the travel (rearward relative to the ground), across it, vertical.
  cut_direction_ = Eigen::Vector3d(std::cos(p.travel_angle), -std::sin(p.travel_angle), 0.0);
  soil_.configure(p.forward_speed * std::cos(g), p.soil.spring_from_contact, p.soil.cut_face);
  if (p.attachment == Attachment::chain) teeth_ = ToothCount(p.chain);
  soil_flow_ = p.forward_speed * (std::cos(g) * cut_direction_ + Eigen::Vector3d(0.0, 0.0, -std::sin(g)));

  if (p.attachment == Attachment::plow) {
    const Plow3D& pl = p.plow;
    const Eigen::Vector2d ratios = four_bar_velocity_ratios(pl.linkage);
    cb_ = ratios(0);
    // Placement (Appendix E): blade-plane points turned by beta about the shank axis (Eq. E.8), then every
    // plow point by alpha' about the vertical through the swing pin.
    const Eigen::Vector3d p9 = boom_plane_point(pl.linkage.upper_joint, pl.boom_offset);
    const Eigen::Vector3d p10 = boom_plane_point(pl.linkage.lower_joint, pl.boom_offset);
    const Eigen::Matrix3d blade_turn = rotation(p9 - p10, -pl.blade_angle);
    const Eigen::Matrix3d swing = rotation(Eigen::Vector3d::UnitZ(), pl.boom_angle);
    auto place = [&](const Eigen::Vector3d& r) { return Eigen::Vector3d(pl.swing_pin + swing * (r - pl.swing_pin)); };
    auto place_blade = [&](const Eigen::Vector2d& r) { return place(p9 + blade_turn * (boom_plane_point(r, pl.boom_offset) - p9)); };
    PlowPlacement& pp = placement_;
    pp.pin6 = place(boom_plane_point(pl.linkage.upper_pivot, pl.boom_offset));
    pp.pin11 = place(boom_plane_point(pl.linkage.lower_pivot, pl.boom_offset));
    pp.pin9 = place(p9);
    pp.pin10 = place(p10);
    pp.cg = place_blade(pl.cg);
    pp.blade = place_blade(pl.blade_point);
    pp.shaker = place_blade(pl.shaker_point);
    pp.bounce = place_blade(pl.bounce_tire_point);
    pp.cylinder_base = place(boom_plane_point(pl.cylinder_base, pl.boom_offset));
    pp.cylinder_arm = place(boom_plane_point(pl.cylinder_arm_point, pl.boom_offset));
    pp.pin_axis = swing * Eigen::Vector3d::UnitY();
    pp.inertia = swing * pl.inertia_boom_axes * swing.transpose();
    const Eigen::Vector3d& ep = pp.pin_axis;

    // Swing carrier (massless): pinned at 19 about the frame's vertical, yaw alpha absolute (Table II: wZ = alpha').
    Jacobian carrier_rotation = frame_rotation;
    carrier_rotation.row(Z).setZero();
    carrier_rotation(Z, ialpha) = 1.0;
    const Jacobian j19 = frame_jacobian(pl.swing_pin);
    auto carrier_point = [&](const Eigen::Vector3d& r) { return Jacobian(j19 - skew(r - pl.swing_pin) * carrier_rotation); };
    // Upper arm: its rotation about the pin axis is psi (absolute); other components are the carrier's.
    Eigen::RowVectorXd e_psi = Eigen::RowVectorXd::Zero(n);
    e_psi(ipsi) = 1.0;
    const Eigen::RowVectorXd carrier_about_pin = ep.transpose() * carrier_rotation;
    const Jacobian arm_rotation = carrier_rotation + ep * (e_psi - carrier_about_pin);
    const Jacobian j6 = carrier_point(pp.pin6);
    auto arm_point = [&](const Eigen::Vector3d& r) { return Jacobian(j6 - skew(r - pp.pin6) * arm_rotation); };
    // Shank (link l2, the plow): about the pin axis CB psi + (1 - CB) theta (Eqs. E.6, E.7 in the +e_p sense).
    const Jacobian shank_rotation = carrier_rotation + ep * (cb_ * (e_psi - carrier_about_pin));
    const Jacobian j9 = arm_point(pp.pin9);
    auto shank_point = [&](const Eigen::Vector3d& r) { return Jacobian(j9 - skew(r - pp.pin9) * shank_rotation); };

    RigidPart3D plow_part{"plow", pl.mass, pp.cg, pp.inertia};
    plow_body_ = rigid_body(plow_part, shank_point(pp.cg), shank_rotation);
    blade_point_ = model_.add_point({"blade", shank_point(pp.blade)});
    shaker_point_ = model_.add_point({"shaker", shank_point(pp.shaker)});
    const int bounce = model_.add_point({"bounce_tire", shank_point(pp.bounce)});
    model_.add_element({"bounce_tire", bounce, -1, normal, pl.bounce_tire.stiffness, pl.bounce_tire.damping});
    const Eigen::Vector3d axis = pp.cylinder_arm - pp.cylinder_base;
    if (!(axis.norm() > 0.0)) throw std::invalid_argument("the lift cylinder has zero length");
    const int cb = model_.add_point({"lift_cylinder_base", carrier_point(pp.cylinder_base)});
    const int ca = model_.add_point({"lift_cylinder_arm", arm_point(pp.cylinder_arm)});
    model_.add_element({"lift_cylinder", cb, ca, axis, pl.lift_cylinder.stiffness, pl.lift_cylinder.damping});
    // K30 as a tangential spring at unit arm from the swing pin: elongation = 1 m * (alpha - theta_z), so k = K30 / (1 m)^2.
    const Eigen::Vector3d boom_direction = swing * Eigen::Vector3d::UnitX();
    const Eigen::Vector3d arm_end = pl.swing_pin + boom_direction;
    const int sf = frame_point("swing_spring_frame", arm_end);
    const int sc = model_.add_point({"swing_spring_boom", carrier_point(arm_end)});
    model_.add_element({"swing_spring", sf, sc, Eigen::Vector3d::UnitZ().cross(boom_direction), pl.swing_spring.stiffness, pl.swing_spring.damping});
  } else if (p.attachment == Attachment::chain) {
    blade_point_ = frame_point("boom", p.chain.boom_point);
    chain_point_ = frame_point("chain_pin", p.chain.chain_pin);
  }
  if (blade_point_ >= 0) {
    const Eigen::Vector3d across = Eigen::Vector3d::UnitZ().cross(cut_direction_);
    soil_elements_.push_back(model_.add_element({"soil_along", blade_point_, -1, cut_direction_, p.soil.stiffness, p.soil.damping}));
    soil_elements_.push_back(model_.add_element({"soil_across", blade_point_, -1, across, p.soil_lateral.stiffness, p.soil_lateral.damping}));
    soil_elements_.push_back(model_.add_element({"soil_vertical", blade_point_, -1, Eigen::Vector3d::UnitZ(), p.soil.stiffness, p.soil.damping}));
  }
  // Reference ground inputs of the tires and the bounce tire (Eq. 1.5).
  for (int e = 0; e < static_cast<int>(model_.elements().size()); ++e)
    if (ground_input_of(e)) inputs_.push_back(e);

  check_definiteness(model_);
  m_ = model_.mass_matrix();
  k_full_ = model_.stiffness_matrix();
  c_full_ = model_.damping_matrix();
  k_cut_ = k_full_;
  k_back_ = k_full_;
  k_no_soil_ = k_full_;
  c_back_ = c_full_;
  for (int e : soil_elements_) {
    const Eigen::RowVectorXd gmap = model_.elongation_map(e);
    const SpringDamper& el = model_.elements()[static_cast<std::size_t>(e)];
    if (p.soil.cut_face) k_cut_ -= el.stiffness * gmap.transpose() * gmap;
    k_no_soil_ -= el.stiffness * gmap.transpose() * gmap;
    k_back_ -= (1.0 - p.soil.stiffness_reduction) * el.stiffness * gmap.transpose() * gmap;
    c_back_ -= (1.0 - p.soil.damping_reduction) * el.damping * gmap.transpose() * gmap;
  }
  m_solver_.compute(m_);

  // One-sided contacts: each tire's vertical element with its longitudinal and lateral ones, and the bounce tire.
  std::vector<ContactDefinition> contacts;
  for (const char* tire : {"front_left_tire", "front_right_tire", "rear_left_tire", "rear_right_tire"}) {
    const std::string n(tire);
    contacts.push_back({n, model_.element_index(n + "_vertical"), {model_.element_index(n + "_longitudinal"), model_.element_index(n + "_lateral")}});
  }
  if (p.attachment == Attachment::plow) contacts.push_back({"bounce_tire", model_.element_index("bounce_tire"), {}});
  std::vector<GroundInput> inputs;
  for (std::size_t e = 0; e < model_.elements().size(); ++e) {
    const GroundInput* in = ground_input_of(static_cast<int>(e));
    inputs.push_back(in ? *in : GroundInput{});
  }
  statics_ = solve_contact_statics(model_, gravity_force(model_, p.gravity), contacts, soil_elements_, p.contacts);
  contacts_.configure(model_, contacts, statics_.element_forces, inputs, p.contacts);
}

Eigen::MatrixXd Machine3D::stiffness_matrix(Machine2D::ModalSoil soil) const {
  Eigen::MatrixXd k = soil == Machine2D::ModalSoil::cutting ? k_cut_ : soil == Machine2D::ModalSoil::backing ? k_back_ : k_no_soil_;
  remove_lifted_contacts(model_, statics_, k);  // Eq. 11.7
  return k;
}

int Machine3D::coordinate(const std::string& name) const { return index_of(model_.coordinate_names(), name); }


Jacobian Machine3D::frame_point_jacobian(const Eigen::Vector3d& point) const {
  const Body& frame = model_.bodies()[static_cast<std::size_t>(frame_body_)];
  const Eigen::Vector3d cg = combine(p_.frame.parts, "frame").cg;
  return frame.translation - skew(point - cg) * frame.rotation;
}

const GroundInput* Machine3D::ground_input_of(int element) const {
  const std::string& name = model_.elements().at(static_cast<std::size_t>(element)).name;
  const GroundInput* in = nullptr;
  const std::pair<const char*, const Tire3D*> tires[] = {{"front_left_tire", &p_.front_tires.left},
                                                          {"front_right_tire", &p_.front_tires.right},
                                                          {"rear_left_tire", &p_.rear_tires.left},
                                                          {"rear_right_tire", &p_.rear_tires.right}};
  for (const auto& [prefix, tire] : tires) {
    if (name == std::string(prefix) + "_vertical") in = &tire->vertical_input;
    if (name == std::string(prefix) + "_longitudinal") in = &tire->longitudinal_input;
  }
  if (name == "bounce_tire" && p_.attachment == Attachment::plow) in = &p_.plow.bounce_input;
  return (in && in->kind != GroundInput::Kind::none) ? in : nullptr;
}

double Machine3D::element_tension(int element, double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v) const {
  if (contacts_.contact_of(element) >= 0) return contacts_.static_force(element) - contacts_.transmitted_force(element, t, q, v);
  const SpringDamper& el = model_.elements().at(static_cast<std::size_t>(element));
  const Eigen::RowVectorXd gmap = model_.elongation_map(element);
  double k = el.stiffness, c = el.damping, xr = 0.0, vr = 0.0;
  if (const GroundInput* in = ground_input_of(element)) {
    xr = in->displacement(t);
    vr = in->velocity(t);
  }
  if (std::find(soil_elements_.begin(), soil_elements_.end(), element) != soil_elements_.end()) {
    const SoilState state = soil_state_at(t);
    k *= p_.soil.stiffness_factor(state.cutting);
    c *= p_.soil.damping_factor(state.cutting);
    xr = el.direction.dot(state.anchor);
    vr = el.direction.dot(soil_flow_);
  }
  return k * (gmap.dot(q) - xr) + c * (gmap.dot(v) - vr);
}

Eigen::Vector3d Machine3D::shaker_force(double t) const {
  if (p_.attachment != Attachment::plow) return Eigen::Vector3d::Zero();
  const Plow3D& pl = p_.plow;
  const Eigen::Vector3d shank = (placement_.pin9 - placement_.pin10).normalized();
  return pl.shaker_amplitude * std::sin(kTwoPi * pl.shaker_frequency * t + pl.shaker_phase) * shank;  // Eq. 3.12, along l2
}

Eigen::Vector3d Machine3D::plow_force(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v) const {
  Eigen::Vector3d f = Eigen::Vector3d::Zero();
  for (int e : soil_elements_) f += model_.elements()[static_cast<std::size_t>(e)].direction * element_tension(e, t, q, v);
  return f;
}

// --- the digging chain (Appendix D; the tooth law of rigid/soil_contact.h) --------

double Machine3D::chain_force(double t) const {
  if (p_.attachment != Attachment::chain) return 0.0;
  // The tooth count logged by the integration (not the schedule at t): a sample an ulp before a
  // scheduled change must see the count in force then, as the equations of motion did.
  return teeth_.law().chain_force(t, soil_state_at(t).cutting, teeth_.full_at(t));
}

Eigen::Vector3d Machine3D::chain_force_vector(double t) const {
  return chain_force(t) * Eigen::Vector3d(std::cos(p_.chain.chain_angle), 0.0, -std::sin(p_.chain.chain_angle));
}

Eigen::Vector3d Machine3D::chain_moment(double t) const { return Eigen::Vector3d(0.0, -chain_force(t) * p_.chain.moment_arm, 0.0); }

double Machine3D::next_scheduled_change(double t) const {
  if (p_.attachment != Attachment::chain) return std::numeric_limits<double>::infinity();
  return teeth_.law().next_change(t);
}

std::string Machine3D::on_scheduled_change(double t, const Eigen::VectorXd&, const Eigen::VectorXd&) {
  if (p_.attachment != Attachment::chain) return {};
  return teeth_.on_scheduled_change(t);
}

// --- the soil law (Eq. 2.36 along the travel; rigid/soil_contact.h) -------------

void Machine3D::reset(double t, const Eigen::VectorXd& q) {
  if (blade_point_ >= 0) {
    const Eigen::Vector3d d = model_.points()[static_cast<std::size_t>(blade_point_)].displacement * q;
    soil_.reset(t, cut_direction_.dot(d), d);
  } else {
    soil_.reset(t, 0.0, Eigen::Vector3d::Zero());
  }
  teeth_.reset(t);
  contacts_.reset(t, q, Eigen::VectorXd::Zero(size()));
}

void Machine3D::events(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v, double* g) const {
  contacts_.events(t, q, v, g + soil_event_count());  // Eq. 4a.3
  if (blade_point_ < 0) return;
  const Jacobian& j = model_.points()[static_cast<std::size_t>(blade_point_)].displacement;
  g[0] = soil_.event_value(t, cut_direction_.dot(j * q), cut_direction_.dot(j * v));
}

std::string Machine3D::on_event(double t, const Eigen::VectorXd& q, const Eigen::VectorXd&, const std::vector<int>& fired,
                                const std::vector<int>& directions) {
  last_event_length_ = {};
  return contacts_.on_events(t, soil_event_count(), fired, directions, [&](int direction) { return soil_switch(t, q, direction); });
}

std::string Machine3D::soil_switch(double t, const Eigen::VectorXd& q, int direction) {
  const Eigen::Vector3d d = model_.points()[static_cast<std::size_t>(blade_point_)].displacement * q;
  const double s5 = cut_direction_.dot(d);
  switch (soil_.on_event(t, direction, s5, d)) {
    case SoilContact<Eigen::Vector3d>::Switch::backs_off: last_event_length_ = {"s5", s5}; return "blade backs off";
    case SoilContact<Eigen::Vector3d>::Switch::cuts_again: last_event_length_ = {"s5", s5}; return "blade cuts again";
    case SoilContact<Eigen::Vector3d>::Switch::none: break;
  }
  return {};
}

Eigen::VectorXd Machine3D::forcing(double t) const {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(size());
  for (int e : inputs_) {
    const GroundInput* in = ground_input_of(e);
    const SpringDamper& el = model_.elements()[static_cast<std::size_t>(e)];
    f += model_.elongation_map(e).transpose() * (el.stiffness * in->displacement(t) + el.damping * in->velocity(t));
  }
  if (p_.attachment == Attachment::plow) {
    f += model_.generalized_force(shaker_point_, shaker_force(t));
  } else if (p_.attachment == Attachment::chain) {
    const double rch = teeth_.law().chain_force(t, soil_.cutting(), teeth_.full());
    f += model_.generalized_force(chain_point_, rch * Eigen::Vector3d(std::cos(p_.chain.chain_angle), 0.0, -std::sin(p_.chain.chain_angle)));
    // RMCH about +Y on the frame: Q = R_frame^T M.
    f += model_.bodies()[static_cast<std::size_t>(frame_body_)].rotation.transpose() * Eigen::Vector3d(0.0, -rch * p_.chain.moment_arm, 0.0);
  }
  return f;
}

void Machine3D::acceleration(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v, Eigen::VectorXd& a) const {
  const bool cutting = soil_.cutting();
  const Eigen::MatrixXd& k = cutting ? k_cut_ : k_back_;
  const Eigen::MatrixXd& c = cutting ? c_full_ : c_back_;
  Eigen::VectorXd f = forcing(t) - k * q - c * v;
  for (int e : soil_elements_) {
    const SpringDamper& el = model_.elements()[static_cast<std::size_t>(e)];
    const double ks = el.stiffness * p_.soil.stiffness_factor(cutting);
    const double cs = el.damping * p_.soil.damping_factor(cutting);
    // Soil springs unstretched at the anchor; the soil streams past at VS (Eq. 2.23).
    f += model_.elongation_map(e).transpose() * (ks * el.direction.dot(soil_.anchor()) + cs * el.direction.dot(soil_flow_));
  }
  f += statics_.preload;                     // Eq. 11.4: q = 0 is the contact-consistent rest state
  contacts_.add_lost_contacts(t, q, v, f);  // Eq. 4a.4
  a = m_solver_.solve(f);
}

}  // namespace framedyn::rigid
