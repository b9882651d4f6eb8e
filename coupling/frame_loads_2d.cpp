// Frame loads by free bodies, and stress resultants; see frame_loads_2d.h.
#include "coupling/frame_loads_2d.h"

#include <cmath>
#include <stdexcept>

namespace framedyn::coupling {

namespace {

constexpr int X = 0, Z = 2;

Eigen::Vector2d planar(const Eigen::Vector3d& v) { return {v(X), v(Z)}; }
Eigen::Vector3d in_3d(const Eigen::Vector2d& p) { return {p.x(), 0.0, p.y()}; }
// Moment about +Y of a force f at offset r (both in X-Z): r_z f_x - r_x f_z.
double moment_y(const Eigen::Vector2d& r, const Eigen::Vector2d& f) { return r.y() * f.x() - r.x() * f.y(); }

struct Loads {
  std::vector<FrameLoad2D> list;
  int add(const std::string& name, const Eigen::Vector2d& point, std::size_t samples) {
    list.push_back({name, point, std::vector<Eigen::Vector2d>(samples, Eigen::Vector2d::Zero()), std::vector<double>(samples, 0.0)});
    return static_cast<int>(list.size()) - 1;
  }
};

}  // namespace

const std::vector<std::string>& part_load_names_2d() {
  static const std::vector<std::string> names = {"front_tire", "rear_tire",        "cab_mount_front",  "cab_mount_rear", "cab_x_tie",
                                                 "plow_upper_pivot", "plow_lower_pivot", "lift_cylinder", "boom_soil",      "chain"};
  return names;
}

std::vector<FrameLoad2D> frame_loads_2d(const rigid::VehicleModel& model, const rigid::Machine2DParameters& p, const rigid::VehicleRunState& run,
                                        const rigid::Trajectory& tr) {
  const rigid::Multibody& mb = model.multibody;
  const std::size_t ns = tr.time.size();
  const int ity = model.coordinate("theta_y");
  Loads loads;

  // Added masses (Eqs. 2.45-2.46): the inertia force -m a at the mass, moved
  // to its attachment point with the moment it makes there.
  for (const rigid::AddedMass& a : p.frame.added_masses) {
    const int l = loads.add(a.name, a.attachment, ns);
    const rigid::Jacobian j = rigid::frame_point_jacobian(model, in_3d(a.position));
    for (std::size_t i = 0; i < ns; ++i) {
      const Eigen::Vector2d f = -a.mass * planar(j * tr.a[i]);
      loads.list[static_cast<std::size_t>(l)].force[i] = f;
      loads.list[static_cast<std::size_t>(l)].moment[i] = moment_y(a.position - a.attachment, f) - a.inertia * tr.a[i](ity);
    }
  }

  // Elements between the frame and another part, or the ground: the force on the frame's end.
  auto element_on_frame = [&](const std::string& element, const std::string& load, const Eigen::Vector2d& point, bool frame_is_a_of_pair) {
    const int e = mb.element_index(element);
    if (e < 0) return;
    const rigid::SpringDamper& el = mb.elements()[static_cast<std::size_t>(e)];
    int l = -1;
    for (std::size_t k = 0; k < loads.list.size(); ++k)
      if (loads.list[k].name == load) l = static_cast<int>(k);
    if (l < 0) l = loads.add(load, point, ns);
    const Eigen::Vector2d n = planar(el.direction);
    for (std::size_t i = 0; i < ns; ++i) {
      const double tension = rigid::element_tension(model, run, e, tr.time[i], tr.q[i], tr.v[i]);
      // A stretched element pulls its ends together: on a (of a pair) +T n;
      // on the point of a grounded element (which runs from the ground) -T n.
      loads.list[static_cast<std::size_t>(l)].force[i] += (frame_is_a_of_pair ? tension : -tension) * n;
    }
  };
  element_on_frame("front_tire_normal", "front_tire", p.front_tire.contact, false);
  element_on_frame("front_tire_tractive", "front_tire", p.front_tire.contact, false);
  element_on_frame("rear_tire_normal", "rear_tire", p.rear_tire.contact, false);
  element_on_frame("rear_tire_tractive", "rear_tire", p.rear_tire.contact, false);
  element_on_frame("cab_mount_front", "cab_mount_front", p.cab.front.position, true);
  element_on_frame("cab_mount_rear", "cab_mount_rear", p.cab.rear.position, true);

  // The cab's X motion is tied to the frame's at the cab's c.g. (Eq. 2.8): the
  // tie carries the cab's X inertia (Eq. 2.44), here at the c.g. where the
  // kinematic tie acts (the thesis splits it between the two mounts).
  {
    const int l = loads.add("cab_x_tie", p.cab.cg, ns);
    const rigid::Body& cab = mb.bodies()[static_cast<std::size_t>(model.cab_body)];
    for (std::size_t i = 0; i < ns; ++i) loads.list[static_cast<std::size_t>(l)].force[i] = {-p.cab.mass * cab.translation.row(X).dot(tr.a[i]), 0.0};
  }

  if (p.attachment == rigid::Attachment::plow) {
    // The shank (all the plow's mass) is held by the upper arm at pin 9 (force
    // F9, two components) and by the lower arm, a two-force member, at pin 10
    // (force f10 along the arm). Its three equations give F9 and f10; the
    // massless upper arm then passes F9 and the lift cylinder's pull to pin 6.
    const rigid::Plow2D& pl = p.plow;
    const rigid::Body& plow = mb.bodies()[static_cast<std::size_t>(model.plow_body)];
    const Eigen::Vector2d r9 = pl.linkage.upper_joint, r10 = pl.linkage.lower_joint;
    const Eigen::Vector2d lower_axis = (r10 - pl.linkage.lower_pivot).normalized();
    const int bounce = mb.element_index("bounce_tire"), cylinder = mb.element_index("lift_cylinder");
    const Eigen::Vector2d bounce_dir = planar(mb.elements()[static_cast<std::size_t>(bounce)].direction);
    const Eigen::Vector2d cyl_dir = planar(mb.elements()[static_cast<std::size_t>(cylinder)].direction);  // from 7 to 8
    const int l6 = loads.add("plow_upper_pivot", pl.linkage.upper_pivot, ns);
    const int l11 = loads.add("plow_lower_pivot", pl.linkage.lower_pivot, ns);
    const int l7 = loads.add("lift_cylinder", pl.cylinder_frame_point, ns);
    for (std::size_t i = 0; i < ns; ++i) {
      const double t = tr.time[i];
      // External forces on the shank, and its inertia (d'Alembert).
      const Eigen::Vector2d f_shaker = planar(rigid::shaker_force(model, t));
      const Eigen::Vector2d f_soil = -planar(rigid::plow_force(model, run, t, tr.q[i], tr.v[i]));
      const Eigen::Vector2d f_bounce = -rigid::element_tension(model, run, bounce, t, tr.q[i], tr.v[i]) * bounce_dir;
      const Eigen::Vector2d f_inertia = -pl.mass * planar(plow.translation * tr.a[i]);
      const double m_inertia = -pl.inertia * plow.rotation.row(1).dot(tr.a[i]);
      const Eigen::Vector2d f_ext = f_shaker + f_soil + f_bounce + f_inertia;
      const double m_ext = moment_y(pl.shaker_point - r9, f_shaker) + moment_y(pl.blade_point - r9, f_soil) +
                           moment_y(pl.bounce_tire_point - r9, f_bounce) + moment_y(pl.cg - r9, f_inertia) + m_inertia;
      // Unknowns (F9x, F9z, f10): F9 + f10 u + f_ext = 0; (r10 - r9) x f10 u + m_ext = 0.
      const double arm = moment_y(r10 - r9, lower_axis);
      if (std::abs(arm) < 1e-12) throw std::invalid_argument("the plow's lower arm points at pin 9: its force has no lever arm");
      const double f10 = -m_ext / arm;
      const Eigen::Vector2d f9 = -f_ext - f10 * lower_axis;  // on the shank, from the upper arm
      const double tension = rigid::element_tension(model, run, cylinder, t, tr.q[i], tr.v[i]);
      // Upper arm (massless): from the shank -F9, from the cylinder at 8 -T n, from the frame F6.
      const Eigen::Vector2d f6_on_arm = f9 + tension * cyl_dir;
      loads.list[static_cast<std::size_t>(l6)].force[i] = -f6_on_arm;
      loads.list[static_cast<std::size_t>(l11)].force[i] = -f10 * lower_axis;  // the lower arm pushes on pin 11 as on pin 10
      loads.list[static_cast<std::size_t>(l7)].force[i] = tension * cyl_dir;   // the cylinder pulls the frame towards 8
    }
  } else if (p.attachment == rigid::Attachment::chain) {
    const int l5 = loads.add("boom_soil", p.chain.boom_point, ns);
    const int l6 = loads.add("chain", p.chain.chain_pin, ns);
    for (std::size_t i = 0; i < ns; ++i) {
      loads.list[static_cast<std::size_t>(l5)].force[i] = -planar(rigid::plow_force(model, run, tr.time[i], tr.q[i], tr.v[i]));
      const double rch = rigid::chain_force(model, run, tr.time[i]);
      loads.list[static_cast<std::size_t>(l6)].force[i] = rch * Eigen::Vector2d(std::cos(p.chain.chain_angle), -std::sin(p.chain.chain_angle));
      loads.list[static_cast<std::size_t>(l6)].moment[i] = -rch * p.chain.moment_arm;  // -RMCH (Eq. 2.33)
    }
  }
  return loads.list;
}

SectionLoad tube_inertia_in_front(const rigid::VehicleModel& model, const rigid::Frame2D& f, const Eigen::VectorXd& a, double x_cut, double z_cut) {
  SectionLoad s;
  const double x0 = f.front_end, x1 = std::min(x_cut, f.front_end + f.length);
  if (!(x1 > x0) || f.mass_per_length == 0.0) return s;
  // The tube lies on Z = 0 and moves rigidly: its acceleration is linear in X,
  // so the integrals are exact with the segment's end points.
  const rigid::Jacobian j0 = rigid::frame_point_jacobian(model, {x0, 0.0, 0.0}), j1 = rigid::frame_point_jacobian(model, {x1, 0.0, 0.0});
  const Eigen::Vector2d a0 = planar(j0 * a), a1 = planar(j1 * a);
  const double len = x1 - x0, rho = f.mass_per_length;
  // Inertia force -rho a(x) dx over [x0, x1]; its moment about (x_cut, z_cut).
  s.force = -rho * len * 0.5 * (a0 + a1);
  // int (x - x_cut) a(x) dx with a linear: Simpson's rule is exact for the quadratic integrand.
  const double xm = 0.5 * (x0 + x1);
  const Eigen::Vector2d am = 0.5 * (a0 + a1);
  const Eigen::Vector2d first_moment = len / 6.0 * ((x0 - x_cut) * a0 + 4.0 * (xm - x_cut) * am + (x1 - x_cut) * a1);
  // moment_y of -rho a at (x, 0) about (x_cut, z_cut): (0 - z_cut)(-rho a_x) - (x - x_cut)(-rho a_z)
  s.moment = -z_cut * s.force.x() + rho * first_moment.y();
  return s;
}

StressResultants frame_stress_resultants(const rigid::VehicleModel& model, const rigid::Frame2D& frame, const rigid::Trajectory& tr, const std::vector<FrameLoad2D>& loads,
                                         const std::vector<double>& output_x, double output_z) {
  StressResultants r;
  r.output_x = output_x;
  r.output_z = output_z;
  const std::size_t ns = tr.time.size(), np = output_x.size();
  r.srx.assign(ns, std::vector<double>(np, 0.0));
  r.srz = r.srx;
  r.srmy = r.srx;
  for (std::size_t i = 0; i < ns; ++i)
    for (std::size_t k = 0; k < np; ++k) {
      const Eigen::Vector2d op(output_x[k], output_z);
      Eigen::Vector2d f = Eigen::Vector2d::Zero();
      double m = 0.0;
      for (const FrameLoad2D& l : loads) {
        if (!(l.point.x() < op.x())) continue;  // only the loads in front of the output point
        f += l.force[i];
        m += l.moment[i] + moment_y(l.point - op, l.force[i]);
      }
      const SectionLoad d = tube_inertia_in_front(model, frame, tr.a[i], op.x(), op.y());
      // The D terms of Eq. 2.47 are the tube's inertia (SRXD = int rho a_x) with
      // the signs that make the front part's free body balance.
      r.srx[i][k] = -f.x() - d.force.x();
      r.srz[i][k] = -f.y() - d.force.y();
      r.srmy[i][k] = m + d.moment;
    }
  return r;
}

}  // namespace framedyn::coupling
