// Frame loads of the 3-D machine by free bodies; see frame_loads_3d.h.
//
// For a body B joined to the frame at load point P, with external element
// forces F_k at points r_k (tires, soil, bounce tire, shaker), Newton and
// Euler about P give the joint's action on B,
//     F_B = m a - sum F_k,   M_B = I alpha + (cg - P) x m a - sum (r_k - P) x F_k,
// and the frame receives -F_B, -M_B (linearised: no gyroscopic terms).
#include "coupling/frame_loads_3d.h"

#include <algorithm>
#include <stdexcept>

namespace framedyn::coupling {

namespace {

LoadPointHistory make_point(const std::string& name, const Eigen::Vector3d& at, std::size_t samples) {
  return {name, at, Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(samples), 6)};
}

// Force of element e on its point a (grounded: the point it acts on), N: a stretched
// element pulls its ends together, so on a of a pair +T n, on a grounded element's point -T n.
Eigen::Vector3d element_force_on_a(const rigid::Machine3D& m, int e, double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v) {
  const rigid::SpringDamper& el = m.model().elements()[static_cast<std::size_t>(e)];
  const double tension = m.element_tension(e, t, q, v);
  return (el.point_b < 0 ? -tension : tension) * el.direction;
}

}  // namespace

std::vector<std::string> frame_load_point_names() {
  return {"P24_REEL",         "P25_FRONT_AXLE_PIN", "P26_REAR_AXLE_PIN", "P27_LEVELING_CYLINDER",
          "P28_CAB_MOUNT_FL", "P29_CAB_MOUNT_FR",   "P30_CAB_MOUNT_RL",  "P31_CAB_MOUNT_RR"};
}

FrameLoads3D frame_loads_3d(const rigid::Machine3D& m, const rigid::Trajectory& tr) {
  const rigid::Machine3DParameters& p = m.parameters();
  const rigid::Multibody& mb = m.model();
  const std::size_t ns = tr.time.size();
  if (p.cab.mounts.size() != 4) throw std::invalid_argument("3-D frame loads need the cab's four mounts (points 28-31)");
  const std::vector<std::string> names = frame_load_point_names();
  FrameLoads3D out;
  out.points.times = Eigen::Map<const Eigen::VectorXd>(tr.time.data(), static_cast<Eigen::Index>(ns));
  out.direct.times = out.points.times;
  const Eigen::Vector3d p24 = p.frame.reel_attachment, p25 = p.front_axle.pin, p26 = p.frame.rear_pin, p27 = p.frame.leveling_cylinder;
  out.points.points = {make_point(names[0], p24, ns), make_point(names[1], p25, ns), make_point(names[2], p26, ns), make_point(names[3], p27, ns)};
  for (std::size_t k = 0; k < 4; ++k) out.points.points.push_back(make_point(names[4 + k], p.cab.mounts[k].position, ns));

  auto body = [&](int b) -> const rigid::Body& { return mb.bodies()[static_cast<std::size_t>(b)]; };
  auto set = [](LoadPointHistory& l, std::size_t i, const Eigen::Vector3d& f, const Eigen::Vector3d& mo) {
    l.values.row(static_cast<Eigen::Index>(i)).head<3>() += f.transpose();
    l.values.row(static_cast<Eigen::Index>(i)).tail<3>() += mo.transpose();
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
  // Joint action on the frame from a body's Newton-Euler equations about P.
  auto joint_on_frame = [&](int b, const Eigen::Vector3d& cg, const Eigen::Vector3d& at, const std::vector<External>& ext,
                            const std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>>& forces_at, std::size_t i,
                            Eigen::Vector3d& f, Eigen::Vector3d& mo) {
    const rigid::Body& bd = body(b);
    const Eigen::Vector3d acc = bd.translation * tr.a[i], alpha = bd.rotation * tr.a[i];
    Eigen::Vector3d fb = bd.mass * acc, mb_ = bd.inertia * alpha + (cg - at).cross(bd.mass * acc);
    for (const External& x : ext) {
      const Eigen::Vector3d fk = element_force_on_a(m, x.element, tr.time[i], tr.q[i], tr.v[i]);
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
  for (std::size_t i = 0; i < ns; ++i) {
    Eigen::Vector3d f, mo;
    // 24: reel and reel carrier, rigid on the frame.
    joint_on_frame(m.reel_body(), p.frame.reel_and_carrier.cg, p24, {}, {}, i, f, mo);
    set(out.points.points[0], i, f, mo);
    // 25: front axle pin; the pin passes no moment about X (the eta equation makes TX vanish).
    joint_on_frame(m.front_axle_body(), p.front_axle.axle.cg, p25, front_tires, {}, i, f, mo);
    set(out.points.points[1], i, f, mo);
    // 26 and 27: the rear axle; the leveling cylinder (vertical, at 27) carries the moment about the pin's X axis.
    joint_on_frame(m.rear_axle_body(), p.frame.rear_axle.cg, p26, rear_tires, {}, i, f, mo);
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
        if (e >= 0) force += element_force_on_a(m, e, tr.time[i], tr.q[i], tr.v[i]);
      }
      set(out.points.points[4 + k], i, force, Eigen::Vector3d::Zero());
    }
  }

  // Direct loads at point 19.
  if (p.attachment == rigid::Attachment::plow) {
    const rigid::Machine3D::PlowPlacement& pp = m.plow_placement();
    out.direct.points.push_back(make_point("P19_PLOW_SWING_PIN", p.plow.swing_pin, ns));
    std::vector<External> ext;
    for (int e : m.soil_elements()) ext.push_back({e, pp.blade});
    const int bounce = mb.element_index("bounce_tire");
    if (bounce >= 0) ext.push_back({bounce, pp.bounce});
    for (std::size_t i = 0; i < ns; ++i) {
      Eigen::Vector3d f, mo;
      joint_on_frame(m.plow_body(), pp.cg, p.plow.swing_pin, ext, {{pp.shaker, m.shaker_force(tr.time[i])}}, i, f, mo);
      set(out.direct.points[0], i, f, mo);
    }
  } else if (p.attachment == rigid::Attachment::chain) {
    out.direct.points.push_back(make_point("P19_CHAIN_PIN", p.chain.chain_pin, ns));
    out.direct.points.push_back(make_point("BOOM_SOIL", p.chain.boom_point, ns));
    for (std::size_t i = 0; i < ns; ++i) {
      set(out.direct.points[0], i, m.chain_force_vector(tr.time[i]), m.chain_moment(tr.time[i]));
      Eigen::Vector3d soil = Eigen::Vector3d::Zero();
      for (int e : m.soil_elements()) soil += element_force_on_a(m, e, tr.time[i], tr.q[i], tr.v[i]);
      set(out.direct.points[1], i, soil, Eigen::Vector3d::Zero());
    }
  }
  return out;
}

LoadHistory all_frame_loads(const FrameLoads3D& loads) {
  LoadHistory all = loads.points;
  all.points.insert(all.points.end(), loads.direct.points.begin(), loads.direct.points.end());
  return all;
}

}  // namespace framedyn::coupling
