// A run of a vehicle model: the switched system over (const model, state) and
// force recovery; see vehicle_run.h and docs/theory/rigid.md, sections 1a, 2, 4, 4a, 10.
//
// The planar and the spatial model share every term. Where the 2-D model
// takes a coordinate of a point (its X along the travel, its Z) the spatial
// one projects on the travel direction; the planar model keeps its own
// sums there (the soil's spring reference and dampers, the soil law's event,
// the chain moment, Eq. 2.37's resultant) so that its results stay those of
// Chapter II's program to the last bit.
#include "rigid/vehicle_run.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace framedyn::rigid {

namespace {

constexpr double kTwoPi = 6.283185307179586;
constexpr int X = 0, Z = 2;

const Jacobian& blade_jacobian(const VehicleModel& m) { return m.multibody.points()[static_cast<std::size_t>(m.blade_point)].displacement; }

int soil_event_count(const VehicleModel& m) { return m.blade_point >= 0 ? 1 : 0; }

// Where the soil law measures the blade: its displacement along the travel
// (2-D: X) and the anchor the soil springs would take there.
std::pair<double, Eigen::Vector3d> blade_position(const VehicleModel& m, const Eigen::VectorXd& q) {
  const Jacobian& j = blade_jacobian(m);
  if (m.dimensions == 2) {
    const double x5 = j.row(X).dot(q);
    return {x5, Eigen::Vector3d(x5, 0.0, j.row(Z).dot(q))};
  }
  const Eigen::Vector3d d = j * q;
  return {m.cut_direction.dot(d), d};
}

// Q(t) + FK(t) + FC(t) without the state-dependent part: ground inputs
// (Eqs. 1.5, 2.20, 2.26), the shaker (Eq. 2.28, 3.12), RCH and RMCH (Eq. 2.33).
Eigen::VectorXd forcing(const VehicleModel& m, const VehicleRunState& s, double t) {
  const Multibody& mb = m.multibody;
  Eigen::VectorXd f = Eigen::VectorXd::Zero(m.size());
  for (int e : m.input_elements) {
    const GroundInput& in = m.ground_inputs[static_cast<std::size_t>(e)];
    const SpringDamper& el = mb.elements()[static_cast<std::size_t>(e)];
    // The ground end moves by xr along the element's direction: elongation = G q - xr.
    f += mb.elongation_map(e).transpose() * (el.stiffness * in.displacement(t) + el.damping * in.velocity(t));
  }
  if (m.attachment == Attachment::plow) {
    f += mb.generalized_force(m.shaker_point, shaker_force(m, t));
  } else if (m.attachment == Attachment::chain) {
    const double rch = s.teeth.law().chain_force(t, s.soil.cutting(), s.teeth.full());
    f += mb.generalized_force(m.chain_point, rch * m.chain_direction);
    if (m.dimensions == 2) {
      f(m.coordinate("theta_y")) -= rch * m.chain_moment_arm;  // -RMCH (Eq. 2.33)
    } else {
      // RMCH about +Y on the frame: Q = R_frame^T M.
      f += mb.bodies()[static_cast<std::size_t>(m.frame_body)].rotation.transpose() * Eigen::Vector3d(0.0, -rch * m.chain_moment_arm, 0.0);
    }
  }
  return f;
}

std::string soil_switch(const VehicleModel& m, VehicleRunState& s, double t, const Eigen::VectorXd& q, int direction) {
  const auto [position, anchor] = blade_position(m, q);
  const char* name = m.dimensions == 2 ? "x5" : "s5";
  switch (s.soil.on_event(t, direction, position, anchor)) {
    case SoilContact<Eigen::Vector3d>::Switch::backs_off: s.last_event_length = {name, position}; return "blade backs off";
    case SoilContact<Eigen::Vector3d>::Switch::cuts_again: s.last_event_length = {name, position}; return "blade cuts again";
    case SoilContact<Eigen::Vector3d>::Switch::none: break;
  }
  return {};
}

}  // namespace

VehicleRunState start_run(const VehicleModel& model, double t, const Eigen::VectorXd& q) {
  VehicleRunState s;
  s.soil.configure(model.soil_line_speed, model.soil.spring_from_contact, model.soil.cut_face);
  if (model.blade_point >= 0) {
    const auto [position, anchor] = blade_position(model, q);
    s.soil.reset(t, position, anchor);
  } else {
    s.soil.reset(t, 0.0, Eigen::Vector3d::Zero());
  }
  s.teeth = ToothCount(model.chain);
  s.teeth.reset(t);
  s.contacts = model.contacts;
  s.contacts.reset(t, q, Eigen::VectorXd::Zero(model.size()));
  return s;
}

void VehicleDynamics::acceleration(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v, Eigen::VectorXd& a) const {
  const VehicleModel& m = model_;
  const Multibody& mb = m.multibody;
  const bool cutting = state_.soil.cutting();
  const Eigen::MatrixXd& k = cutting ? m.k_cut : m.k_back;
  const Eigen::MatrixXd& c = cutting ? m.c_cut : m.c_back;
  Eigen::VectorXd f = forcing(m, state_, t) - k * q - c * v;
  if (m.blade_point >= 0 && m.dimensions == 2) {
    // Soil springs unstretched at the anchor (nonzero only with spring_from_contact).
    if (m.soil.spring_from_contact) {
      const double scale = m.soil.stiffness_factor(cutting);
      const Eigen::Vector3d anchor = soil_anchor_at(m, state_.soil.anchor(), state_.soil.anchor_time(), t);
      f += scale * m.soil.stiffness *
           (mb.elongation_map(m.soil_elements[0]).transpose() * anchor.x() + mb.elongation_map(m.soil_elements[1]).transpose() * anchor.z());
    }
    // The soil moves rearward past the machine at VS: the blade dampers see the
    // blade velocity relative to it (Eq. 2.23).
    if (m.soil_flow.x() != 0.0 || m.soil_flow.z() != 0.0)
      f += blade_jacobian(m).transpose() * (m.soil.damping_factor(cutting) * m.soil.damping * m.soil_flow);
  } else if (m.blade_point >= 0) {
    const Eigen::Vector3d anchor = soil_anchor_at(m, state_.soil.anchor(), state_.soil.anchor_time(), t);
    for (int e : m.soil_elements) {
      const SpringDamper& el = mb.elements()[static_cast<std::size_t>(e)];
      const double ks = el.stiffness * m.soil.stiffness_factor(cutting);
      const double cs = el.damping * m.soil.damping_factor(cutting);
      // Soil springs unstretched at the anchor (carried rearward with the soil under soil_line
      // and cut_face); the soil streams past at VS (Eq. 2.23).
      f += mb.elongation_map(e).transpose() * (ks * el.direction.dot(anchor) + cs * el.direction.dot(m.soil_flow));
    }
  }
  f += m.statics.preload;                          // Eq. 11.4: q = 0 is the contact-consistent rest state
  state_.contacts.add_lost_contacts(t, q, v, f);  // Eq. 4a.4
  a = m.m_solver.solve(f);
}

int VehicleDynamics::event_count() const { return soil_event_count(model_) + state_.contacts.event_count(); }

void VehicleDynamics::events(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v, double* g) const {
  state_.contacts.events(t, q, v, g + soil_event_count(model_));  // Eq. 4a.3
  if (model_.blade_point < 0) return;
  const Jacobian& j = blade_jacobian(model_);
  if (model_.dimensions == 2) {
    g[0] = state_.soil.event_value(t, j.row(X).dot(q), j.row(X).dot(v));  // Eq. 2.36 along X
  } else {
    g[0] = state_.soil.event_value(t, model_.cut_direction.dot(j * q), model_.cut_direction.dot(j * v));  // along the travel
  }
}

std::string VehicleDynamics::on_event(double t, const Eigen::VectorXd& q, const Eigen::VectorXd&, const std::vector<int>& fired,
                                      const std::vector<int>& directions) {
  state_.last_event_length = {};
  return state_.contacts.on_events(t, soil_event_count(model_), fired, directions,
                                   [&](int direction) { return soil_switch(model_, state_, t, q, direction); });
}

double VehicleDynamics::next_scheduled_change(double t) const {
  if (model_.attachment != Attachment::chain) return std::numeric_limits<double>::infinity();
  return state_.teeth.law().next_change(t);
}

std::string VehicleDynamics::on_scheduled_change(double t, const Eigen::VectorXd&, const Eigen::VectorXd&) {
  if (model_.attachment != Attachment::chain) return {};
  return state_.teeth.on_scheduled_change(t);
}

VehicleRun run_vehicle(const VehicleModel& model, const Eigen::VectorXd& q0, const Eigen::VectorXd& v0, const IntegrationOptions& options) {
  VehicleRun run;
  run.state = start_run(model, options.start_time, q0);
  VehicleDynamics system(model, run.state);
  run.trajectory = integrate_event_located(system, q0, v0, options);
  return run;
}

SoilState soil_state_at(const VehicleRunState& state, double t) { return state.soil.state_at(t); }

Eigen::Vector3d soil_anchor_at(const VehicleModel& model, const Eigen::Vector3d& anchor, double anchor_time, double t) {
  if (!(model.soil.spring_from_contact && model.soil.contact_moves_with_soil)) return anchor;
  return anchor + model.soil_flow * (t - anchor_time);
}

double element_tension(const VehicleModel& model, const VehicleRunState& state, int element, double t, const Eigen::VectorXd& q,
                       const Eigen::VectorXd& v) {
  if (state.contacts.contact_of(element) >= 0)
    return state.contacts.static_force(element) - state.contacts.transmitted_force(element, t, q, v);
  const SpringDamper& el = model.multibody.elements().at(static_cast<std::size_t>(element));
  const Eigen::RowVectorXd g = model.multibody.elongation_map(element);
  double k = el.stiffness, c = el.damping, xr = 0.0, vr = 0.0;
  if (const GroundInput* in = ground_input_of(model, element)) {
    xr = in->displacement(t);
    vr = in->velocity(t);
  }
  if (std::find(model.soil_elements.begin(), model.soil_elements.end(), element) != model.soil_elements.end()) {
    const SoilState s = soil_state_at(state, t);
    k *= model.soil.stiffness_factor(s.cutting);
    c *= model.soil.damping_factor(s.cutting);
    // Unstretched at the anchor (zero unless spring_from_contact); the soil streams rearward past the machine (Eq. 2.23).
    xr = el.direction.dot(soil_anchor_at(model, s.anchor, s.anchor_time, t));
    vr = el.direction.dot(model.soil_flow);
  }
  return k * (g.dot(q) - xr) + c * (g.dot(v) - vr);
}

Eigen::Vector3d shaker_force(const VehicleModel& model, double t) {
  if (model.attachment != Attachment::plow) return Eigen::Vector3d::Zero();
  const Shaker& s = model.shaker;
  return s.amplitude * std::sin(kTwoPi * s.frequency * t + s.phase) * s.direction;
}

Eigen::Vector3d plow_force(const VehicleModel& model, const VehicleRunState& state, double t, const Eigen::VectorXd& q,
                           const Eigen::VectorXd& v) {
  if (model.blade_point < 0) return Eigen::Vector3d::Zero();
  if (model.dimensions == 2) {
    const SoilState s = soil_state_at(state, t);
    const Jacobian& j = blade_jacobian(model);
    const Eigen::Vector3d d = j * q, vel = j * v;
    const double rk = model.soil.stiffness * model.soil.stiffness_factor(s.cutting);
    const double rc = model.soil.damping * model.soil.damping_factor(s.cutting);
    const Eigen::Vector3d anchor = soil_anchor_at(model, s.anchor, s.anchor_time, t);
    // Eq. 2.37: RPF = [dX5 RK5 + (VX5 - VS cos) RC5] l + [dZ5 RK5 + (VZ5 + VS sin) RC5] n
    return {(d(X) - anchor.x()) * rk + (vel(X) - model.soil_flow.x()) * rc, 0.0,
            (d(Z) - anchor.z()) * rk + (vel(Z) - model.soil_flow.z()) * rc};
  }
  Eigen::Vector3d f = Eigen::Vector3d::Zero();
  for (int e : model.soil_elements)
    f += model.multibody.elements()[static_cast<std::size_t>(e)].direction * element_tension(model, state, e, t, q, v);
  return f;
}

double chain_force(const VehicleModel& model, const VehicleRunState& state, double t) {
  if (model.attachment != Attachment::chain) return 0.0;
  // The tooth count logged by the run (not the schedule at t): a sample a hair before a
  // scheduled change must see the count in force then, as the equations of motion did.
  return state.teeth.law().chain_force(t, soil_state_at(state, t).cutting, state.teeth.full_at(t));
}

}  // namespace framedyn::rigid
