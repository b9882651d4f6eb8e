// The 2-D machine on the multibody assembly; see machine_2d.h and
// docs/theory/rigid.md.
#include "rigid/machine_2d.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/error.h"

namespace framedyn::rigid {

namespace {

constexpr double kTwoPi = 6.283185307179586;
constexpr int X = 0, Y = 1, Z = 2;

Eigen::Vector3d in_3d(const Eigen::Vector2d& p) { return {p.x(), 0.0, p.y()}; }

std::vector<std::string> coordinate_names(Attachment a) {
  if (a == Attachment::plow) return {"x", "z", "theta_y", "psi", "w", "theta_v"};
  return {"x", "z", "theta_y", "w", "theta_v"};
}

// What each coordinate measures (Chapter II): X, Z and W translations; the
// pitch angles theta_y, theta_v and the linkage angle psi rotations.
std::vector<core::Quantity> coordinate_quantities(Attachment a) {
  using core::Quantity;
  if (a == Attachment::plow) return {Quantity::length, Quantity::length, Quantity::angle, Quantity::angle, Quantity::length, Quantity::angle};
  return {Quantity::length, Quantity::length, Quantity::angle, Quantity::length, Quantity::angle};
}

int index_of(const std::vector<std::string>& names, const std::string& n) {
  for (std::size_t i = 0; i < names.size(); ++i)
    if (names[i] == n) return static_cast<int>(i);
  return -1;
}

}  // namespace

FrameMassProperties frame_mass_properties(const Frame2D& frame, const Cab2D& cab) {
  FrameMassProperties f;
  const double tube_mass = frame.mass_per_length * frame.length;  // rho FLT (errata to Eq. C.2)
  const double tube_x = frame.front_end + frame.length / 2.0;
  double sum_m = tube_mass, sum_mx = tube_mass * tube_x, sum_mz = 0.0;  // the tube lies on Z = 0
  for (const AddedMass& a : frame.added_masses) {
    sum_m += a.mass;
    sum_mx += a.mass * a.position.x();
    sum_mz += a.mass * a.position.y();
  }
  if (!(sum_m > 0.0)) throw std::invalid_argument("the frame has no mass");
  f.mass = sum_m;
  f.cg = {sum_mx / sum_m, sum_mz / sum_m};
  f.inertia = tube_mass * (frame.length * frame.length / 12.0 + std::pow(tube_x - f.cg.x(), 2) + f.cg.y() * f.cg.y());
  for (const AddedMass& a : frame.added_masses) f.inertia += a.inertia + a.mass * (a.position - f.cg).squaredNorm();
  // Eq. C.3: the reference height includes the cab, whose X motion the frame carries.
  f.reference = {f.cg.x(), (sum_mz + cab.mass * cab.cg.y()) / (sum_m + cab.mass)};
  return f;
}

Machine2D::Machine2D(const Machine2DParameters& p)
    : p_(p), frame_(frame_mass_properties(p.frame, p.cab)), model_(coordinate_names(p.attachment), coordinate_quantities(p.attachment)) {
  const std::vector<std::string>& names = model_.coordinate_names();
  const int n = model_.size();
  const int ix = index_of(names, "x"), iz = index_of(names, "z"), ity = index_of(names, "theta_y");
  const int iw = index_of(names, "w"), itv = index_of(names, "theta_v"), ipsi = index_of(names, "psi");
  const Eigen::Vector3d ref = in_3d(frame_.reference);

  // Frame: a point p moves by (x, z) + theta_y y x (p - ref).
  auto frame_jacobian = [&](const Eigen::Vector3d& point) {
    Jacobian j = Jacobian::Zero(3, n);
    j(X, ix) = 1.0;
    j(Z, iz) = 1.0;
    const Eigen::Vector3d turn = Eigen::Vector3d::UnitY().cross(point - ref);
    j.col(ity) += turn;
    return j;
  };
  Body frame;
  frame.name = "frame";
  frame.mass = frame_.mass;
  frame.inertia(Y, Y) = frame_.inertia;
  frame.translation = frame_jacobian(in_3d(frame_.cg));
  frame.rotation = Jacobian::Zero(3, n);
  frame.rotation(Y, ity) = 1.0;
  const int frame_body = model_.add_body(frame);

  // Cab: X tied to the frame at the cab's c.g., Z = w, pitch theta_v.
  Body cab;
  cab.name = "cab";
  cab.mass = p.cab.mass;
  cab.inertia(Y, Y) = p.cab.inertia;
  cab.translation = Jacobian::Zero(3, n);
  cab.translation.row(X) = frame_jacobian(in_3d(p.cab.cg)).row(X);
  cab.translation(Z, iw) = 1.0;
  cab.rotation = Jacobian::Zero(3, n);
  cab.rotation(Y, itv) = 1.0;
  const int cab_body = model_.add_body(cab);

  auto frame_point = [&](const std::string& name, const Eigen::Vector2d& p2) { return model_.add_point({name, frame_jacobian(in_3d(p2))}); };
  auto cab_point = [&](const std::string& name, const Eigen::Vector2d& p2) {
    return model_.add_body_point(name, cab_body, in_3d(p2 - p.cab.cg));
  };
  (void)frame_body;

  const Eigen::Vector3d ground_normal(std::sin(p.ground_slope), 0.0, std::cos(p.ground_slope));
  const Eigen::Vector3d ground_tangent(std::cos(p.ground_slope), 0.0, -std::sin(p.ground_slope));  // rearward along the ground
  soil_.configure(p.forward_speed * std::cos(p.ground_slope), p.soil.spring_from_contact, p.soil.cut_face);
  if (p.attachment == Attachment::chain) teeth_ = ToothCount(p.chain);

  // Cab mounts (elements 12 and 14): vertical between frame and cab.
  for (const auto& [name, mount] : {std::pair<std::string, const CabMount*>{"cab_mount_front", &p.cab.front}, {"cab_mount_rear", &p.cab.rear}}) {
    const int a = frame_point(name + "_frame", mount->position);
    const int b = cab_point(name + "_cab", mount->position);
    model_.add_element({name, a, b, Eigen::Vector3d::UnitZ(), mount->vertical.stiffness, mount->vertical.damping});
  }
  // Tires: normal and tractive, at the contact points, to the ground.
  for (const auto& [name, tire] : {std::pair<std::string, const Tire2D*>{"front_tire", &p.front_tire}, {"rear_tire", &p.rear_tire}}) {
    const int c = frame_point(name + "_contact", tire->contact);
    model_.add_element({name + "_normal", c, -1, ground_normal, tire->normal.stiffness, tire->normal.damping});
    model_.add_element({name + "_tractive", c, -1, ground_tangent, tire->tractive.stiffness, tire->tractive.damping});
  }

  if (p.attachment == Attachment::plow) {
    const Plow2D& pl = p.plow;
    const Eigen::Vector2d ratios = four_bar_velocity_ratios(pl.linkage);  // (CB, lower arm)
    const double cb = ratios(0);
    // Upper arm: rotation psi about pin 6 (absolute). Pin 9 moves with it.
    const Jacobian j6 = frame_jacobian(in_3d(pl.linkage.upper_pivot));
    auto arm_point = [&](const Eigen::Vector2d& p2) {
      Jacobian j = j6;
      j.col(ipsi) += Eigen::Vector3d::UnitY().cross(in_3d(p2 - pl.linkage.upper_pivot));
      return j;
    };
    const Jacobian j9 = arm_point(pl.linkage.upper_joint);
    // Shank rotation phi_s = CB psi + (1 - CB) theta_y (Eq. A.10 in the +Y sense).
    Eigen::RowVectorXd shank_rotation = Eigen::RowVectorXd::Zero(n);
    shank_rotation(ipsi) = cb;
    shank_rotation(ity) = 1.0 - cb;
    auto shank_point = [&](const Eigen::Vector2d& p2) {
      Jacobian j = j9;
      j += Eigen::Vector3d::UnitY().cross(in_3d(p2 - pl.linkage.upper_joint)) * shank_rotation;
      return j;
    };
    Body plow;
    plow.name = "plow";
    plow.mass = pl.mass;
    plow.inertia(Y, Y) = pl.inertia;
    plow.translation = shank_point(pl.cg);
    plow.rotation = Jacobian::Zero(3, n);
    plow.rotation.row(Y) = shank_rotation;
    model_.add_body(plow);
    blade_point_ = model_.add_point({"blade", shank_point(pl.blade_point)});
    shaker_point_ = model_.add_point({"shaker", shank_point(pl.shaker_point)});
    const int bounce = model_.add_point({"bounce_tire", shank_point(pl.bounce_tire_point)});
    model_.add_element({"bounce_tire", bounce, -1, ground_normal, pl.bounce_tire.stiffness, pl.bounce_tire.damping});
    const int cyl_frame = frame_point("lift_cylinder_frame", pl.cylinder_frame_point);
    const int cyl_arm = model_.add_point({"lift_cylinder_arm", arm_point(pl.cylinder_arm_point)});
    const Eigen::Vector2d axis = pl.cylinder_arm_point - pl.cylinder_frame_point;
    if (!(axis.norm() > 0.0)) throw std::invalid_argument("the lift cylinder has zero length");
    model_.add_element({"lift_cylinder", cyl_frame, cyl_arm, in_3d(axis), pl.lift_cylinder.stiffness, pl.lift_cylinder.damping});
  } else if (p.attachment == Attachment::chain) {
    blade_point_ = frame_point("boom", p.chain.boom_point);
    chain_point_ = frame_point("chain_pin", p.chain.chain_pin);
  }
  if (blade_point_ >= 0) {
    soil_elements_.push_back(model_.add_element({"soil_x", blade_point_, -1, Eigen::Vector3d::UnitX(), p.soil.stiffness, p.soil.damping}));
    soil_elements_.push_back(model_.add_element({"soil_z", blade_point_, -1, Eigen::Vector3d::UnitZ(), p.soil.stiffness, p.soil.damping}));
  }

  check_definiteness(model_);
  m_ = model_.mass_matrix();
  k_full_ = model_.stiffness_matrix();
  c_full_ = model_.damping_matrix();
  // The soil's share, to switch between full and reduced values.
  Eigen::MatrixXd k_soil = Eigen::MatrixXd::Zero(n, n), c_soil = Eigen::MatrixXd::Zero(n, n);
  for (int e : soil_elements_) {
    const Eigen::RowVectorXd g = model_.elongation_map(e);
    k_soil += p.soil.stiffness * g.transpose() * g;
    c_soil += p.soil.damping * g.transpose() * g;
  }
  k_cut_ = p.soil.cut_face ? Eigen::MatrixXd(k_full_ - k_soil) : k_full_;  // cut-face reading: no spring while cutting
  c_cut_ = c_full_;
  k_back_ = k_full_ - (1.0 - p.soil.stiffness_reduction) * k_soil;
  c_back_ = c_full_ - (1.0 - p.soil.damping_reduction) * c_soil;
  k_no_soil_ = k_full_ - k_soil;
  m_solver_.compute(m_);

  // One-sided contacts: each tire's normal element with its tractive one, and the bounce tire.
  std::vector<ContactDefinition> contacts = {
      {"front_tire", model_.element_index("front_tire_normal"), {model_.element_index("front_tire_tractive")}},
      {"rear_tire", model_.element_index("rear_tire_normal"), {model_.element_index("rear_tire_tractive")}}};
  if (p.attachment == Attachment::plow) contacts.push_back({"bounce_tire", model_.element_index("bounce_tire"), {}});
  std::vector<GroundInput> inputs;
  for (std::size_t e = 0; e < model_.elements().size(); ++e) {
    const GroundInput* in = ground_input_of(static_cast<int>(e));
    inputs.push_back(in ? *in : GroundInput{});
  }
  statics_ = solve_contact_statics(model_, gravity_force(model_, p.gravity), contacts, soil_elements_, p.contacts);
  contacts_.configure(model_, contacts, statics_.element_forces, inputs, p.contacts);
}

Eigen::MatrixXd Machine2D::stiffness_matrix(ModalSoil soil) const {
  Eigen::MatrixXd k = soil == ModalSoil::cutting ? k_cut_ : soil == ModalSoil::backing ? k_back_ : k_no_soil_;
  remove_lifted_contacts(model_, statics_, k);  // Eq. 11.7
  return k;
}

int Machine2D::coordinate(const std::string& name) const { return index_of(model_.coordinate_names(), name); }

double Machine2D::soil_line_at(double t) const { return soil_.line_at(t); }

void Machine2D::reset(double t, const Eigen::VectorXd& q) {
  if (blade_point_ >= 0) {
    const Jacobian& j = model_.points()[static_cast<std::size_t>(blade_point_)].displacement;
    soil_.reset(t, j.row(X).dot(q), {j.row(X).dot(q), j.row(Z).dot(q)});
  } else {
    soil_.reset(t, 0.0, Eigen::Vector2d::Zero());
  }
  teeth_.reset(t);
  contacts_.reset(t, q, Eigen::VectorXd::Zero(size()));
}

Eigen::Vector2d Machine2D::anchor_at(const Eigen::Vector2d& anchor, double anchor_time, double t) const {
  if (!(p_.soil.spring_from_contact && p_.soil.contact_moves_with_soil)) return anchor;
  const Eigen::Vector2d soil_flow(p_.forward_speed * std::cos(p_.ground_slope), -p_.forward_speed * std::sin(p_.ground_slope));
  return anchor + soil_flow * (t - anchor_time);
}

Machine2D::SoilState Machine2D::soil_state_at(double t) const { return soil_.state_at(t); }

double Machine2D::chain_force(double t) const {
  if (p_.attachment != Attachment::chain) return 0.0;
  // The tooth count logged by the integration (not the schedule at t): a sample a hair before a
  // scheduled change must see the count in force then, as the equations of motion did.
  return teeth_.law().chain_force(t, soil_state_at(t).cutting, teeth_.full_at(t));
}

Jacobian Machine2D::frame_point_jacobian(const Eigen::Vector2d& point) const {
  // The frame body's own Jacobian moved to another point of the frame.
  const Body& frame = model_.bodies().front();
  return frame.translation - skew(in_3d(point - frame_.cg)) * frame.rotation;
}

double Machine2D::element_tension(int element, double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v) const {
  if (contacts_.contact_of(element) >= 0) return contacts_.static_force(element) - contacts_.transmitted_force(element, t, q, v);
  const SpringDamper& el = model_.elements().at(static_cast<std::size_t>(element));
  const Eigen::RowVectorXd g = model_.elongation_map(element);
  double k = el.stiffness, c = el.damping, xr = 0.0, vr = 0.0;
  if (const GroundInput* in = ground_input_of(element)) {
    xr = in->displacement(t);
    vr = in->velocity(t);
  }
  if (std::find(soil_elements_.begin(), soil_elements_.end(), element) != soil_elements_.end()) {
    const SoilState state = soil_state_at(t);
    k *= p_.soil.stiffness_factor(state.cutting);
    c *= p_.soil.damping_factor(state.cutting);
    // Unstretched at the anchor (zero unless spring_from_contact), as in plow_force.
    const Eigen::Vector2d anchor = anchor_at(state.anchor, state.anchor_time, t);
    xr = el.direction.dot(Eigen::Vector3d(anchor.x(), 0.0, anchor.y()));
    // The soil streams rearward past the machine at VS (Eq. 2.23).
    vr = el.direction.dot(Eigen::Vector3d(p_.forward_speed * std::cos(p_.ground_slope), 0.0, -p_.forward_speed * std::sin(p_.ground_slope)));
  }
  return k * (g.dot(q) - xr) + c * (g.dot(v) - vr);
}

Eigen::Vector2d Machine2D::shaker_force(double t) const {
  if (p_.attachment != Attachment::plow) return Eigen::Vector2d::Zero();
  const Plow2D& pl = p_.plow;
  const Eigen::Vector2d shank = (pl.linkage.upper_joint - pl.linkage.lower_joint).normalized();
  return pl.shaker_amplitude * std::sin(kTwoPi * pl.shaker_frequency * t + pl.shaker_phase) * shank;
}

const GroundInput* Machine2D::ground_input_of(int element) const {
  const std::string& name = model_.elements().at(static_cast<std::size_t>(element)).name;
  const GroundInput* in = nullptr;
  if (name == "front_tire_normal") in = &p_.front_tire.normal_input;
  else if (name == "front_tire_tractive") in = &p_.front_tire.tractive_input;
  else if (name == "rear_tire_normal") in = &p_.rear_tire.normal_input;
  else if (name == "rear_tire_tractive") in = &p_.rear_tire.tractive_input;
  else if (name == "bounce_tire" && p_.attachment == Attachment::plow) in = &p_.plow.bounce_input;
  return (in && in->kind != GroundInput::Kind::none) ? in : nullptr;
}

Eigen::VectorXd Machine2D::forcing(double t) const {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(size());
  // Reference ground inputs (Eqs. 2.20, 2.26): FK + FC at the tires and bounce tire.
  for (std::size_t e = 0; e < model_.elements().size(); ++e) {
    const GroundInput* in = ground_input_of(static_cast<int>(e));
    if (!in) continue;
    const SpringDamper& el = model_.elements()[e];
    // The ground end moves by xr along the element's direction: elongation = G q - xr.
    f += model_.elongation_map(static_cast<int>(e)).transpose() * (el.stiffness * in->displacement(t) + el.damping * in->velocity(t));
  }
  if (p_.attachment == Attachment::plow) {
    // The shaker's in-plane component acts along the shank (n*, Eq. 2.28).
    f += model_.generalized_force(shaker_point_, in_3d(shaker_force(t)));
  } else if (p_.attachment == Attachment::chain) {
    const double rch = teeth_.law().chain_force(t, soil_.cutting(), teeth_.full());
    const Eigen::Vector3d force = rch * Eigen::Vector3d(std::cos(p_.chain.chain_angle), 0.0, -std::sin(p_.chain.chain_angle));
    f += model_.generalized_force(chain_point_, force);
    f(coordinate("theta_y")) -= rch * p_.chain.moment_arm;  // -RMCH (Eq. 2.33)
  }
  return f;
}

void Machine2D::acceleration(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v, Eigen::VectorXd& a) const {
  const bool cutting = soil_.cutting();
  const Eigen::MatrixXd& k = cutting ? k_cut_ : k_back_;
  const Eigen::MatrixXd& c = cutting ? c_cut_ : c_back_;
  Eigen::VectorXd f = forcing(t) - k * q - c * v;
  // Soil springs unstretched at the anchor (nonzero only with spring_from_contact).
  if (blade_point_ >= 0 && p_.soil.spring_from_contact) {
    const double scale = p_.soil.stiffness_factor(cutting);
    const Eigen::Vector2d anchor = anchor_at(soil_.anchor(), soil_.anchor_time(), t);
    f += scale * p_.soil.stiffness *
         (model_.elongation_map(soil_elements_[0]).transpose() * anchor.x() + model_.elongation_map(soil_elements_[1]).transpose() * anchor.y());
  }
  // The soil moves rearward past the machine at VS: the blade dampers see the
  // blade velocity relative to it (Eq. 2.23), a reference velocity (VS cos, -VS sin).
  if (blade_point_ >= 0 && p_.forward_speed != 0.0) {
    const double scale = p_.soil.damping_factor(cutting);
    const Eigen::Vector3d v_soil(p_.forward_speed * std::cos(p_.ground_slope), 0.0, -p_.forward_speed * std::sin(p_.ground_slope));
    f += model_.points()[static_cast<std::size_t>(blade_point_)].displacement.transpose() * (scale * p_.soil.damping * v_soil);
  }
  f += statics_.preload;                     // Eq. 11.4: q = 0 is the contact-consistent rest state
  contacts_.add_lost_contacts(t, q, v, f);  // Eq. 4a.4
  a = m_solver_.solve(f);
}

Eigen::Vector2d Machine2D::plow_force(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v) const {
  if (blade_point_ < 0) return Eigen::Vector2d::Zero();
  const SoilState state = soil_state_at(t);
  const Jacobian& j = model_.points()[static_cast<std::size_t>(blade_point_)].displacement;
  const Eigen::Vector3d d = j * q, vel = j * v;
  const double rk = p_.soil.stiffness * p_.soil.stiffness_factor(state.cutting);
  const double rc = p_.soil.damping * p_.soil.damping_factor(state.cutting);
  const Eigen::Vector2d anchor = anchor_at(state.anchor, state.anchor_time, t);
  // Eq. 2.37: RPF = [dX5 RK5 + (VX5 - VS cos) RC5] l + [dZ5 RK5 + (VZ5 + VS sin) RC5] n
  return {(d(X) - anchor.x()) * rk + (vel(X) - p_.forward_speed * std::cos(p_.ground_slope)) * rc,
          (d(Z) - anchor.y()) * rk + (vel(Z) + p_.forward_speed * std::sin(p_.ground_slope)) * rc};
}

int Machine2D::event_count() const { return soil_event_count() + contacts_.event_count(); }

void Machine2D::events(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v, double* g) const {
  contacts_.events(t, q, v, g + soil_event_count());  // Eq. 4a.3
  if (blade_point_ < 0) return;
  const Jacobian& j = model_.points()[static_cast<std::size_t>(blade_point_)].displacement;
  g[0] = soil_.event_value(t, j.row(X).dot(q), j.row(X).dot(v));  // Eq. 2.36 along X
}

std::string Machine2D::on_event(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v, const std::vector<int>& fired,
                                const std::vector<int>& directions) {
  (void)v;
  last_event_length_ = {};
  return contacts_.on_events(t, soil_event_count(), fired, directions, [&](int direction) { return soil_switch(t, q, direction); });
}

std::string Machine2D::soil_switch(double t, const Eigen::VectorXd& q, int direction) {
  const Jacobian& j = model_.points()[static_cast<std::size_t>(blade_point_)].displacement;
  const double x5 = j.row(X).dot(q);
  switch (soil_.on_event(t, direction, x5, {x5, j.row(Z).dot(q)})) {
    case SoilContact<Eigen::Vector2d>::Switch::backs_off: last_event_length_ = {"x5", x5}; return "blade backs off";
    case SoilContact<Eigen::Vector2d>::Switch::cuts_again: last_event_length_ = {"x5", x5}; return "blade cuts again";
    case SoilContact<Eigen::Vector2d>::Switch::none: break;
  }
  return {};
}

double Machine2D::next_scheduled_change(double t) const {
  if (p_.attachment != Attachment::chain) return std::numeric_limits<double>::infinity();
  return teeth_.law().next_change(t);
}

std::string Machine2D::on_scheduled_change(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v) {
  (void)q;
  (void)v;
  if (p_.attachment != Attachment::chain) return {};
  return teeth_.on_scheduled_change(t);
}

}  // namespace framedyn::rigid
