// Frame loads of the 3-D machine by free bodies; see frame_loads_3d.h.
//
// For a body B joined to the frame at load point P, with external element
// forces F_k at points r_k (tires, soil, bounce tire, shaker), Newton and
// Euler about P give the joint's action on B,
//     F_B = m a - sum F_k,   M_B = I alpha + (cg - P) x m a - sum (r_k - P) x F_k,
// and the frame receives -F_B, -M_B (linearised: no gyroscopic terms).
#include "coupling/frame_loads_3d.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>

namespace framedyn::coupling {

namespace {

LoadPointHistory make_point(const std::string& name, const Eigen::Vector3d& at, std::size_t samples) {
  return {name, at, Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(samples), 6)};
}

// Force of element e on its point a (grounded: the point it acts on), N: a stretched
// element pulls its ends together, so on a of a pair +T n, on a grounded element's point -T n.
Eigen::Vector3d element_force_on_a(const rigid::VehicleModel& m, const rigid::VehicleRunState& run, int e, double t, const Eigen::VectorXd& q,
                                   const Eigen::VectorXd& v) {
  const rigid::SpringDamper& el = m.multibody.elements()[static_cast<std::size_t>(e)];
  const double tension = rigid::element_tension(m, run, e, t, q, v);
  return (el.point_b < 0 ? -tension : tension) * el.direction;
}

}  // namespace

std::vector<std::string> frame_load_point_names() {
  return {"P24_REEL",         "P25_FRONT_AXLE_PIN", "P26_REAR_AXLE_PIN", "P27_LEVELING_CYLINDER",
          "P28_CAB_MOUNT_FL", "P29_CAB_MOUNT_FR",   "P30_CAB_MOUNT_RL",  "P31_CAB_MOUNT_RR"};
}

namespace {

// What one sample of the frame loads needs: the generalised accelerations, each
// element's force on its point a, the shaker's force and the chain's RCH and
// RMCH, and the acceleration of gravity acting on the attached bodies (zero for
// the dynamic loads, which are measured from the static equilibrium).
struct LoadState {
  Eigen::VectorXd a;
  std::function<Eigen::Vector3d(int)> element_force;
  Eigen::Vector3d shaker = Eigen::Vector3d::Zero(), chain_force = Eigen::Vector3d::Zero(), chain_moment = Eigen::Vector3d::Zero();
  Eigen::Vector3d gravity = Eigen::Vector3d::Zero();
};

// The frame loads' layout (points 24-31; the attachment's at point 19) with `ns` samples at `times`.
FrameLoads3D empty_loads(const rigid::Machine3DParameters& p, const Eigen::VectorXd& times) {
  if (p.cab.mounts.size() != 4) throw std::invalid_argument("3-D frame loads need the cab's four mounts (points 28-31)");
  const std::size_t ns = static_cast<std::size_t>(times.size());
  const std::vector<std::string> names = frame_load_point_names();
  FrameLoads3D out;
  out.points.times = times;
  out.direct.times = times;
  out.points.points = {make_point(names[0], p.frame.reel_attachment, ns), make_point(names[1], p.front_axle.pin, ns),
                       make_point(names[2], p.frame.rear_pin, ns), make_point(names[3], p.frame.leveling_cylinder, ns)};
  for (std::size_t k = 0; k < 4; ++k) out.points.points.push_back(make_point(names[4 + k], p.cab.mounts[k].position, ns));
  if (p.attachment == rigid::Attachment::plow) {
    out.direct.points.push_back(make_point("P19_PLOW_SWING_PIN", p.plow.swing_pin, ns));
  } else if (p.attachment == rigid::Attachment::chain) {
    out.direct.points.push_back(make_point("P19_CHAIN_PIN", p.chain.chain_pin, ns));
    out.direct.points.push_back(make_point("BOOM_SOIL", p.chain.boom_point, ns));
  }
  return out;
}

// Row i of every load point from the state s.
void sample_loads(const rigid::VehicleModel& m, const rigid::Machine3DParameters& p, const LoadState& s, std::size_t i, FrameLoads3D& out) {
  const rigid::Multibody& mb = m.multibody;
  const Eigen::Vector3d p24 = p.frame.reel_attachment, p25 = p.front_axle.pin, p26 = p.frame.rear_pin, p27 = p.frame.leveling_cylinder;
  auto set = [](LoadPointHistory& l, std::size_t row, const Eigen::Vector3d& f, const Eigen::Vector3d& mo) {
    l.values.row(static_cast<Eigen::Index>(row)).head<3>() += f.transpose();
    l.values.row(static_cast<Eigen::Index>(row)).tail<3>() += mo.transpose();
  };
  // Elements whose point a lies on a body, with that point's rest position.
  struct External {
    int element;
    Eigen::Vector3d at;
  };
  auto tire_elements = [&](const std::string& axle, const rigid::Axle3D& a) {
    std::vector<External> list;
    for (const auto& [side, tire] : {std::pair<std::string, const rigid::Tire3D*>{"left", &a.left}, {"right", &a.right}})
      for (const char* dir : {"_vertical", "_longitudinal", "_lateral"}) {
        const int e = mb.element_index(axle + "_" + side + "_tire" + dir);
        if (e >= 0) list.push_back({e, tire->contact});
      }
    return list;
  };
  // Joint action on the frame from a body's Newton-Euler equations about P (its weight among the external forces).
  auto joint_on_frame = [&](int b, const Eigen::Vector3d& cg, const Eigen::Vector3d& at, const std::vector<External>& ext,
                            const std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>>& forces_at, Eigen::Vector3d& f, Eigen::Vector3d& mo) {
    const rigid::Body& bd = mb.bodies()[static_cast<std::size_t>(b)];
    const Eigen::Vector3d acc = bd.translation * s.a - s.gravity, alpha = bd.rotation * s.a;
    Eigen::Vector3d fb = bd.mass * acc, mb_ = bd.inertia * alpha + (cg - at).cross(bd.mass * acc);
    for (const External& x : ext) {
      const Eigen::Vector3d fk = s.element_force(x.element);
      fb -= fk;
      mb_ -= (x.at - at).cross(fk);
    }
    for (const auto& [r, fk] : forces_at) {
      fb -= fk;
      mb_ -= (r - at).cross(fk);
    }
    f = -fb;
    mo = -mb_;
  };

  const std::vector<External> front_tires = tire_elements("front", p.front_tires), rear_tires = tire_elements("rear", p.rear_tires);
  const double lever = p27.y() - p26.y();
  if (!(std::abs(lever) > 0.0)) throw std::invalid_argument("the leveling cylinder (point 27) must be beside the rear axle pin (point 26) in Y");
  Eigen::Vector3d f, mo;
  // 24: reel and reel carrier, rigid on the frame.
  joint_on_frame(m.reel_body, p.frame.reel_and_carrier.cg, p24, {}, {}, f, mo);
  set(out.points.points[0], i, f, mo);
  // 25: front axle pin; the pin passes no moment about X (the eta equation makes TX vanish).
  joint_on_frame(m.front_axle_body, p.front_axle.axle.cg, p25, front_tires, {}, f, mo);
  set(out.points.points[1], i, f, mo);
  // 26 and 27: the rear axle; the leveling cylinder (vertical, at 27) carries the moment about the pin's X axis.
  joint_on_frame(m.rear_axle_body, p.frame.rear_axle.cg, p26, rear_tires, {}, f, mo);
  const Eigen::Vector3d r = p27 - p26;
  // Cylinder force on the frame Fc z at 27: its moment about 26 along X is r_y Fc.
  const double fc = mo.x() / r.y();
  const Eigen::Vector3d cylinder(0, 0, fc);
  set(out.points.points[3], i, cylinder, Eigen::Vector3d::Zero());
  set(out.points.points[2], i, f - cylinder, mo - r.cross(cylinder));
  // 28-31: the mount elements' forces on the frame (point a of each pair, Eq. 3.15).
  for (std::size_t k = 0; k < 4; ++k) {
    const rigid::CabMount3D& mount = p.cab.mounts[k];
    Eigen::Vector3d force = Eigen::Vector3d::Zero();
    for (const char* axis : {"_x", "_y", "_z"}) {
      const int e = mb.element_index("cab_mount_" + mount.name + axis);
      if (e >= 0) force += s.element_force(e);
    }
    set(out.points.points[4 + k], i, force, Eigen::Vector3d::Zero());
  }
  // Direct loads at point 19.
  if (p.attachment == rigid::Attachment::plow) {
    const rigid::PlowPlacement& pp = m.plow_placement;
    std::vector<External> ext;
    for (int e : m.soil_elements) ext.push_back({e, pp.blade});
    const int bounce = mb.element_index("bounce_tire");
    if (bounce >= 0) ext.push_back({bounce, pp.bounce});
    joint_on_frame(m.plow_body, pp.cg, p.plow.swing_pin, ext, {{pp.shaker, s.shaker}}, f, mo);
    set(out.direct.points[0], i, f, mo);
  } else if (p.attachment == rigid::Attachment::chain) {
    set(out.direct.points[0], i, s.chain_force, s.chain_moment);
    Eigen::Vector3d soil = Eigen::Vector3d::Zero();
    for (int e : m.soil_elements) soil += s.element_force(e);
    set(out.direct.points[1], i, soil, Eigen::Vector3d::Zero());
  }
}

}  // namespace

FrameLoads3D frame_loads_3d(const rigid::VehicleModel& m, const rigid::Machine3DParameters& p, const rigid::VehicleRunState& run,
                            const rigid::Trajectory& tr) {
  const std::size_t ns = tr.time.size();
  FrameLoads3D out = empty_loads(p, Eigen::Map<const Eigen::VectorXd>(tr.time.data(), static_cast<Eigen::Index>(ns)));
  for (std::size_t i = 0; i < ns; ++i) {
    LoadState s;
    s.a = tr.a[i];
    s.element_force = [&](int e) { return element_force_on_a(m, run, e, tr.time[i], tr.q[i], tr.v[i]); };
    s.shaker = rigid::shaker_force(m, tr.time[i]);
    if (p.attachment == rigid::Attachment::chain) {
      // RCH along the chain, RMCH about +Y.
      const double rch = rigid::chain_force(m, run, tr.time[i]);
      s.chain_force = rch * m.chain_direction;
      s.chain_moment = Eigen::Vector3d(0.0, -rch * m.chain_moment_arm, 0.0);
    }
    sample_loads(m, p, s, i, out);
  }
  return out;
}

FrameLoads3D static_frame_loads_3d(const rigid::VehicleModel& m, const rigid::Machine3DParameters& p) {
  FrameLoads3D out = empty_loads(p, Eigen::VectorXd::Zero(1));
  std::vector<double> sf = m.statics.element_forces;
  // A contact the statics released carries nothing (its SF_e is the gap times k, not a force).
  const rigid::ContactStatics& st = m.statics;
  for (std::size_t c = 0; c < st.contacts.size(); ++c) {
    if (st.engaged[c]) continue;
    sf[static_cast<std::size_t>(st.contacts[c].normal)] = 0.0;
    for (int e : st.contacts[c].tangential) sf[static_cast<std::size_t>(e)] = 0.0;
  }
  const rigid::Multibody& mb = m.multibody;
  LoadState s;
  s.a = Eigen::VectorXd::Zero(mb.size());
  // SF_e is compression positive: on point a it pushes along +direction, on a grounded element's point too
  // (element_force_on_a with the tension -SF_e).
  s.element_force = [&](int e) {
    const rigid::SpringDamper& el = mb.elements()[static_cast<std::size_t>(e)];
    const double tension = -sf[static_cast<std::size_t>(e)];
    return Eigen::Vector3d((el.point_b < 0 ? -tension : tension) * el.direction);
  };
  s.gravity = Eigen::Vector3d(0.0, 0.0, -p.gravity);
  sample_loads(m, p, s, 0, out);
  return out;
}

LoadHistory all_frame_loads(const FrameLoads3D& loads) {
  LoadHistory all = loads.points;
  all.points.insert(all.points.end(), loads.direct.points.begin(), loads.direct.points.end());
  return all;
}

LoadHistory all_frame_loads(FrameLoads3D&& loads) {
  LoadHistory all = std::move(loads.points);
  for (LoadPointHistory& p : loads.direct.points) all.points.push_back(std::move(p));
  loads.direct.points.clear();
  return all;
}

std::vector<const LoadPointHistory*> frame_load_points(const FrameLoads3D& loads) {
  std::vector<const LoadPointHistory*> all;
  for (const LoadPointHistory& p : loads.points.points) all.push_back(&p);
  for (const LoadPointHistory& p : loads.direct.points) all.push_back(&p);
  return all;
}

}  // namespace framedyn::coupling
