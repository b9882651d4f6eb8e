// Verification of the 3-D vehicle model (rigid/machine_3d.h; the thesis's
// Chapter III, Appendices E, F, G, Tables IV and V) against references
// written here from the parameters alone:
//   1. M, K, C against central finite-difference Hessians of the kinetic
//      energy, potential energy and dissipation function of the exact,
//      nonlinear geometry (finite rotations, the four-bar loop closed
//      exactly in the boom plane), for an offset plow (alpha', beta, steering
//      not zero) and an offset digging chain;
//   2. products of inertia and steering rotations on hand-made cases;
//   3. the Appendix G formulas for the isolated eta, alpha and psi modes;
//   4. the 2-D model's X-Z frequencies and forced response from a symmetric
//      3-D model of the same machine with the cab stiff in X (Table V case 5);
//   5. the chain variant's 13 coordinates.
// Axes: X rearward, Y right, Z up; SI.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>
#include <type_traits>
#include <vector>

#include "coupling/frame_loads_3d.h"
#include "coupling/rigid_study.h"
#include "rigid/machine_2d.h"
#include "rigid/machine_3d.h"
#include "rigid/rigid_modes.h"
#include "rigid/time_integration.h"
#include "rigid/vehicle_model.h"
#include "rigid/vehicle_run.h"

namespace {

namespace rigid = framedyn::rigid;
namespace coupling = framedyn::coupling;
using Eigen::Matrix3d;
using Eigen::MatrixXd;
using Eigen::Vector2d;
using Eigen::Vector3d;
using Eigen::VectorXd;

constexpr double kPi = 3.14159265358979323846;
constexpr double kInch = 0.0254, kLbf = 4.4482216152605, kLbm = 0.45359237;
constexpr double kStiff = kLbf / kInch;      // lbf/in in N/m
constexpr double kDamp = kLbf / kInch;       // lbf s/in in N s/m
Vector3d in3(double x, double y, double z) { return Vector3d(x, y, z) * kInch; }
double weight(double lb) { return lb * kLbm; }  // mass of a weight in lb

int coordinate(const rigid::VehicleModel& m, const std::string& name) {
  const int i = m.coordinate(name);
  if (i < 0) throw std::logic_error("no coordinate " + name);
  return i;
}

rigid::RigidPart3D part(const std::string& name, double lb, const Vector3d& cg, double rg_in) {
  const double m = weight(lb), i = m * std::pow(rg_in * kInch, 2);
  return {name, m, cg, rigid::inertia_tensor(i, i, i)};
}

// ---------------------------------------------------------------------------
// A 3-D machine from the shipped 2-D data (examples/r100_plow_2d.yaml): the
// frame's parts at Y = 0, the front axle pinned 8 in above its c.g., each
// 2-D tire pair split into a left and a right tire at Y = -/+30 in, four cab
// mounts at Y = -/+12 in whose X springs sit at the cab's c.g. height (so a
// stiff X spring ties the cab's X to the frame's at the cab's c.g., as the
// 2-D model's Eq. 2.8 does). The 2-D inertias are the Iyy's; the Ixx, Izz of
// the parts are the Iyy's (a symmetric choice, irrelevant to X-Z).
rigid::Machine3DParameters from_2d(const rigid::Machine2DParameters& p, double cab_x_stiffness) {
  rigid::Machine3DParameters q;
  q.ground_slope = p.ground_slope;
  q.forward_speed = p.forward_speed;
  q.gravity = p.gravity;
  const rigid::Frame2D& f = p.frame;
  const double tube = f.mass_per_length * f.length;
  q.frame.parts.push_back({"tube", tube, Vector3d(f.front_end + f.length / 2, 0, 0), rigid::inertia_tensor(1.0, tube * f.length * f.length / 12.0, 1.0)});
  for (const rigid::AddedMass& a : f.added_masses) {
    const rigid::RigidPart3D r{a.name, a.mass, Vector3d(a.position.x(), 0, a.position.y()), rigid::inertia_tensor(a.inertia, a.inertia, a.inertia)};
    if (a.name == "reel_and_carrier") {
      q.frame.reel_and_carrier = r;
      q.frame.reel_attachment = Vector3d(a.attachment.x(), 0, a.attachment.y());
    } else if (a.name == "front_axle_and_wheels") {
      q.front_axle.axle = r;
      q.front_axle.pin = r.cg + Vector3d(0, 0, 8 * kInch);
    } else if (a.name == "rear_axle_drive_and_wheels") {
      q.frame.rear_axle = r;
      q.frame.rear_pin = r.cg + Vector3d(0, 0, 8 * kInch);
      q.frame.leveling_cylinder = r.cg + Vector3d(0, 15 * kInch, 8 * kInch);
    } else {
      q.frame.parts.push_back(r);
    }
  }
  const rigid::FrameMassProperties fm = rigid::frame_mass_properties(p.frame, p.cab);
  q.frame.reference = Vector3d(fm.reference.x(), 0, fm.reference.y());
  const rigid::Cab2D& c = p.cab;
  q.cab.body = {"cab", c.mass, Vector3d(c.cg.x(), 0, c.cg.y()), rigid::inertia_tensor(c.inertia, c.inertia, c.inertia)};
  int k = 0;
  for (const rigid::CabMount* m : {&c.front, &c.rear})
    for (double side : {-1.0, 1.0}) {
      rigid::CabMount3D mount;
      mount.name = std::to_string(28 + k++);
      mount.position = Vector3d(m->position.x(), side * 12 * kInch, c.cg.y());
      mount.x = {cab_x_stiffness, 0.0};
      mount.y = {m->vertical.stiffness / 2, m->vertical.damping / 2};
      mount.z = {m->vertical.stiffness / 2, m->vertical.damping / 2};
      q.cab.mounts.push_back(mount);
    }
  auto axle = [&](const rigid::Tire2D& t) {
    rigid::Axle3D a;
    for (double side : {-1.0, 1.0}) {
      rigid::Tire3D& tire = side < 0 ? a.left : a.right;
      tire.contact = Vector3d(t.contact.x(), side * 30 * kInch, t.contact.y());
      tire.vertical = {t.normal.stiffness / 2, t.normal.damping / 2};
      tire.longitudinal = {t.tractive.stiffness / 2, t.tractive.damping / 2};
      tire.lateral = {t.tractive.stiffness / 2, t.tractive.damping / 2};
    }
    return a;
  };
  q.front_tires = axle(p.front_tire);
  q.rear_tires = axle(p.rear_tire);
  q.attachment = p.attachment;
  q.soil = p.soil;
  q.contacts = p.contacts;
  q.soil_lateral = {p.soil.stiffness, p.soil.damping};
  if (p.attachment == rigid::Attachment::plow) {
    const rigid::Plow2D& pl = p.plow;
    rigid::Plow3D& t = q.plow;
    t.swing_pin = Vector3d(pl.linkage.upper_pivot.x() - 4 * kInch, 0, pl.linkage.upper_pivot.y());
    t.mass = pl.mass;
    t.cg = pl.cg;
    t.inertia_boom_axes = rigid::inertia_tensor(pl.inertia, pl.inertia, pl.inertia);
    t.linkage = pl.linkage;
    t.blade_point = pl.blade_point;
    t.shaker_point = pl.shaker_point;
    t.shaker_amplitude = pl.shaker_amplitude;
    t.shaker_frequency = pl.shaker_frequency;
    t.shaker_phase = pl.shaker_phase;
    t.bounce_tire_point = pl.bounce_tire_point;
    t.bounce_tire = pl.bounce_tire;
    t.cylinder_base = pl.cylinder_frame_point;
    t.cylinder_arm_point = pl.cylinder_arm_point;
    t.lift_cylinder = pl.lift_cylinder;
    t.swing_spring = {2.0e6, 2.0e3};
  }
  return q;
}

rigid::Machine2DParameters shipped_2d() {
  return coupling::read_rigid_study(std::string(FRAMEDYN_SOURCE_DIR) + "/examples/r100_plow_2d.yaml").machine_2d();
}

// The offset plow: both axles steered 22 deg right, beta = 22 deg, alpha' = -1 deg, the
// boom 10 in right of the centre line, every part with products of inertia, the
// tires with unequal stiffnesses, so that no term of M, K, C is zero by symmetry.
rigid::Machine3DParameters offset_plow() {
  rigid::Machine3DParameters p = from_2d(shipped_2d(), 200 * kStiff);
  const double d = 22 * kPi / 180;
  p.front_tires.steering_angle = d;
  p.rear_tires.steering_angle = d * 0.8;
  p.travel_angle = d;
  p.front_tires.right.lateral.stiffness *= 1.3;
  p.rear_tires.left.vertical.stiffness *= 0.9;
  p.plow.boom_angle = -1 * kPi / 180;
  p.plow.blade_angle = d;
  p.plow.boom_offset = 10 * kInch;
  p.plow.swing_pin.y() = 10 * kInch;
  p.plow.inertia_boom_axes = rigid::inertia_tensor(60, 80, 50, 5, -7, 3);
  for (auto& part : p.frame.parts) part.inertia += rigid::inertia_tensor(0, 0, 0, 0.3, -0.4, 0.2), part.cg.y() += 0.05;
  p.frame.reel_and_carrier.inertia = rigid::inertia_tensor(20, 25, 22, 1.0, 2.0, -1.5);
  p.front_axle.axle.inertia = rigid::inertia_tensor(30, 12, 31, 0.0, 1.2, 0.0);
  p.cab.body.inertia = rigid::inertia_tensor(90, 110, 95, 0.0, 6.0, 0.0);
  p.cab.mounts[1].position.z() -= 20 * kInch;  // mounts at different heights
  p.ground_slope = 0.05;
  return p;
}

rigid::Machine3DParameters offset_chain() {
  rigid::Machine3DParameters p = offset_plow();
  p.attachment = rigid::Attachment::chain;
  p.frame.parts.push_back(part("chain_boom_and_drive", 1800, in3(108, 35, -16), 20));
  p.chain.boom_point = in3(118, 35, -40);
  p.chain.chain_pin = in3(84, 35, 2);
  p.chain.chain_angle = 30 * kPi / 180;
  p.chain.moment_arm = 12 * kInch;
  p.chain.tooth_static_force = 900 * kLbf;
  p.chain.tooth_damping = 2 * kDamp;
  p.chain.chain_speed = 100 * kInch;
  p.chain.tooth_spacing = 8 * kInch;
  p.chain.length_in_ground = 36 * kInch;
  p.travel_angle = 0.0;
  return p;
}

// ---------------------------------------------------------------------------
// Exact geometry for finite q. Rotations by rotation vectors; the front
// axle turns about the frame's X axis through pin 20 by eta - theta_x
// relative to the frame; the swing carrier about the frame's Z axis through
// pin 19 by alpha - theta_z; the upper arm about the pin axis by psi minus the
// carrier's rotation about it; the shank from the exact loop closure.
Matrix3d rotvec(const Vector3d& v) {
  const double a = v.norm();
  return a > 0 ? Eigen::AngleAxisd(a, v / a).toRotationMatrix() : Matrix3d::Identity();
}

struct Pose {
  Vector3d origin;   // where the body's reference point went
  Vector3d anchor;   // the body's reference point at rest
  Matrix3d rotation;
  Vector3d map(const Vector3d& r) const { return origin + rotation * (r - anchor); }
};

class ExactGeometry {
 public:
  ExactGeometry(const rigid::Machine3DParameters& p, const rigid::VehicleModel& m) : p_(p), m_(m), n_(m.size()) {}

  double c(const VectorXd& q, const char* name) const {
    const int i = m_.coordinate(name);
    return i < 0 ? 0.0 : q[i];
  }
  Pose frame(const VectorXd& q) const {
    const Vector3d ref = m_.reference;
    return {ref + Vector3d(c(q, "x"), c(q, "y"), c(q, "z")), ref, rotvec({c(q, "theta_x"), c(q, "theta_y"), c(q, "theta_z")})};
  }
  Pose front_axle(const VectorXd& q) const {
    const Pose f = frame(q);
    const Vector3d pin = p_.front_axle.pin;
    return {f.map(pin), pin, f.rotation * rotvec(Vector3d(c(q, "eta") - c(q, "theta_x"), 0, 0))};
  }
  Pose cab(const VectorXd& q) const {
    const Vector3d cg = p_.cab.body.cg;
    return {cg + Vector3d(c(q, "u"), c(q, "v"), c(q, "w")), cg, rotvec({c(q, "theta_u"), c(q, "theta_v"), c(q, "theta_w")})};
  }
  // Plow placement from the parameters (Appendix E, as documented in machine_3d.h).
  struct Placed {
    Vector3d p6, p11, p9, p10, cg, blade, shaker, bounce, base, arm, axis;
    Matrix3d inertia;
  };
  Placed placed() const {
    const rigid::Plow3D& pl = p_.plow;
    auto pt = [&](const Vector2d& r) { return Vector3d(r.x(), pl.boom_offset, r.y()); };
    const Matrix3d swing = Eigen::AngleAxisd(pl.boom_angle, Vector3d::UnitZ()).toRotationMatrix();
    auto place = [&](const Vector3d& r) { return Vector3d(pl.swing_pin + swing * (r - pl.swing_pin)); };
    const Vector3d p9 = pt(pl.linkage.upper_joint), p10 = pt(pl.linkage.lower_joint);
    const Matrix3d blade = Eigen::AngleAxisd(-pl.blade_angle, (p9 - p10).normalized()).toRotationMatrix();
    auto bl = [&](const Vector2d& r) { return place(p9 + blade * (pt(r) - p9)); };
    return {place(pt(pl.linkage.upper_pivot)), place(pt(pl.linkage.lower_pivot)), place(p9), place(p10), bl(pl.cg), bl(pl.blade_point),
            bl(pl.shaker_point), bl(pl.bounce_tire_point), place(pt(pl.cylinder_base)), place(pt(pl.cylinder_arm_point)),
            swing * Vector3d::UnitY(), swing * pl.inertia_boom_axes * swing.transpose()};
  }
  Pose carrier(const VectorXd& q) const {
    const Pose f = frame(q);
    const Vector3d pin = p_.plow.swing_pin;
    return {f.map(pin), pin, f.rotation * rotvec(Vector3d(0, 0, c(q, "alpha") - c(q, "theta_z")))};
  }
  // The carrier's rotation about the pin axis to first order (its angular
  // velocity's component): e_p . (theta_x, theta_y, alpha).
  double carrier_about_pin(const VectorXd& q) const {
    return placed().axis.dot(Vector3d(c(q, "theta_x"), c(q, "theta_y"), c(q, "alpha")));
  }
  Pose arm(const VectorXd& q) const {
    const Placed pp = placed();
    const Pose b = carrier(q);
    return {b.map(pp.p6), pp.p6, b.rotation * rotvec(pp.axis * (c(q, "psi") - carrier_about_pin(q)))};
  }
  Pose shank(const VectorXd& q) const {
    const Placed pp = placed();
    const Pose b = carrier(q), a = arm(q);
    // In the carrier's own (rest) frame the linkage is planar: coordinates (s, z) along the boom and up.
    const Vector3d eb = pp.axis.cross(Vector3d::UnitZ());  // e_p x z = boom direction (rearward)
    auto plane = [&](const Vector3d& r) { return Vector2d(eb.dot(r - pp.p6), r.z() - pp.p6.z()); };
    const Vector3d p9_local = b.rotation.transpose() * (a.map(pp.p9) - b.origin) + b.anchor;  // in the carrier's rest frame
    const Vector2d a9 = plane(p9_local), a11 = plane(pp.p11);
    const double shank_len = (pp.p10 - pp.p9).norm(), lower_len = (pp.p10 - pp.p11).norm();
    const Vector2d d = a11 - a9;
    const double dist = d.norm(), along = (shank_len * shank_len - lower_len * lower_len + dist * dist) / (2 * dist);
    const double across = std::sqrt(std::max(0.0, shank_len * shank_len - along * along));
    const Vector2d base = a9 + along / dist * d, nrm(-d.y() / dist, d.x() / dist);
    const Vector2d c1 = base + across * nrm, c2 = base - across * nrm, near = plane(pp.p10);
    const Vector2d a10 = (c1 - near).norm() < (c2 - near).norm() ? c1 : c2;
    // Rotation about +e_p in (s, z): angle = atan2(s, z) (as 2-D's direction_angle about +Y).
    auto dir = [](const Vector2d& v) { return std::atan2(v.x(), v.y()); };
    const Vector2d rest = plane(pp.p10) - plane(pp.p9);
    const double phi = std::remainder(dir(a10 - a9) - dir(rest), 2 * kPi);
    return {a.map(pp.p9), pp.p9, b.rotation * rotvec(pp.axis * phi)};
  }

  struct BodyState {
    double mass;
    Matrix3d inertia;
    Vector3d position;
    Matrix3d rotation;
  };
  std::vector<BodyState> bodies(const VectorXd& q) const {
    std::vector<BodyState> out;
    const Pose f = frame(q);
    for (const auto& pt : p_.frame.parts) out.push_back({pt.mass, pt.inertia, f.map(pt.cg), f.rotation});
    for (const auto* pt : {&p_.frame.reel_and_carrier, &p_.frame.rear_axle}) out.push_back({pt->mass, pt->inertia, f.map(pt->cg), f.rotation});
    const Pose fa = front_axle(q);
    out.push_back({p_.front_axle.axle.mass, p_.front_axle.axle.inertia, fa.map(p_.front_axle.axle.cg), fa.rotation});
    const Pose cb = cab(q);
    out.push_back({p_.cab.body.mass, p_.cab.body.inertia, cb.map(p_.cab.body.cg), cb.rotation});
    if (p_.attachment == rigid::Attachment::plow) {
      const Placed pp = placed();
      const Pose s = shank(q);
      out.push_back({p_.plow.mass, pp.inertia, s.map(pp.cg), s.rotation});
    }
    return out;
  }

  struct Spring {
    std::string name;
    double k, c;
    std::function<double(const VectorXd&)> deformation;
  };
  std::vector<Spring> springs() const {
    std::vector<Spring> s;
    const double g = p_.ground_slope;
    const Vector3d normal(std::sin(g), 0, std::cos(g)), tangent(std::cos(g), 0, -std::sin(g)), side(0, 1, 0);
    for (const auto& mount : p_.cab.mounts) {
      const Vector3d r = mount.position;
      const rigid::SpringDamperValues* v[3] = {&mount.x, &mount.y, &mount.z};
      for (int k = 0; k < 3; ++k)
        s.push_back({"mount", v[k]->stiffness, v[k]->damping, [this, r, k](const VectorXd& q) { return cab(q).map(r)[k] - frame(q).map(r)[k]; }});
    }
    auto tires = [&](const rigid::Axle3D& a, bool front) {
      const double d = a.steering_angle;
      const Vector3d lon = std::cos(d) * tangent - std::sin(d) * side, lat = std::sin(d) * tangent + std::cos(d) * side;
      for (const rigid::Tire3D* t : {&a.left, &a.right}) {
        const Vector3d r = t->contact;
        auto moved = [this, r, front](const VectorXd& q) { return Vector3d((front ? front_axle(q) : frame(q)).map(r) - r); };
        s.push_back({"tire_v", t->vertical.stiffness, t->vertical.damping, [moved, normal](const VectorXd& q) { return normal.dot(moved(q)); }});
        s.push_back({"tire_lon", t->longitudinal.stiffness, t->longitudinal.damping, [moved, lon](const VectorXd& q) { return lon.dot(moved(q)); }});
        s.push_back({"tire_lat", t->lateral.stiffness, t->lateral.damping, [moved, lat](const VectorXd& q) { return lat.dot(moved(q)); }});
      }
    };
    tires(p_.front_tires, true);
    tires(p_.rear_tires, false);
    Vector3d soil_rest;
    std::function<Vector3d(const VectorXd&)> soil_point;
    if (p_.attachment == rigid::Attachment::plow) {
      const Placed pp = placed();
      const rigid::Plow3D& pl = p_.plow;
      const Vector3d bounce = pp.bounce, base = pp.base, armp = pp.arm;
      s.push_back({"bounce", pl.bounce_tire.stiffness, pl.bounce_tire.damping,
                   [this, bounce, normal](const VectorXd& q) { return normal.dot(shank(q).map(bounce) - bounce); }});
      s.push_back({"lift", pl.lift_cylinder.stiffness, pl.lift_cylinder.damping,
                   [this, base, armp](const VectorXd& q) { return (arm(q).map(armp) - carrier(q).map(base)).norm() - (armp - base).norm(); }});
      // K30 on the relative yaw: energy 1/2 K30 (alpha - theta_z)^2, as a unit-arm spring.
      s.push_back({"swing", pl.swing_spring.stiffness, pl.swing_spring.damping,
                   [this](const VectorXd& q) { return c(q, "alpha") - c(q, "theta_z"); }});
      soil_rest = pp.blade;
      soil_point = [this, soil_rest](const VectorXd& q) { return shank(q).map(soil_rest); };
    } else {
      soil_rest = p_.chain.boom_point;
      soil_point = [this, soil_rest](const VectorXd& q) { return frame(q).map(soil_rest); };
    }
    const double tau = p_.travel_angle;
    const Vector3d along(std::cos(tau), -std::sin(tau), 0), across(std::sin(tau), std::cos(tau), 0), up(0, 0, 1);
    s.push_back({"soil_along", p_.soil.stiffness, p_.soil.damping, [=](const VectorXd& q) { return along.dot(soil_point(q) - soil_rest); }});
    s.push_back({"soil_across", p_.soil_lateral.stiffness, p_.soil_lateral.damping, [=](const VectorXd& q) { return across.dot(soil_point(q) - soil_rest); }});
    s.push_back({"soil_up", p_.soil.stiffness, p_.soil.damping, [=](const VectorXd& q) { return up.dot(soil_point(q) - soil_rest); }});
    return s;
  }

 private:
  rigid::Machine3DParameters p_;
  const rigid::VehicleModel& m_;
  int n_;
};

MatrixXd fd_hessian(const std::function<double(const VectorXd&)>& f, int n, double h) {
  MatrixXd hess(n, n);
  const VectorXd zero = VectorXd::Zero(n);
  const double f0 = f(zero);
  for (int i = 0; i < n; ++i)
    for (int j = i; j < n; ++j) {
      VectorXd ei = zero, ej = zero;
      ei[i] = h;
      ej[j] = h;
      if (i == j) hess(i, i) = (f(ei) - 2.0 * f0 + f(-ei)) / (h * h);
      else hess(i, j) = hess(j, i) = (f(ei + ej) - f(ei - ej) - f(ej - ei) + f(-ei - ej)) / (4.0 * h * h);
    }
  return hess;
}

// Largest |A_ij - B_ij| / sqrt(|B_ii B_jj|).
double scaled_difference(const MatrixXd& a, const MatrixXd& b) {
  double worst = 0.0;
  const double fallback = b.cwiseAbs().maxCoeff();
  for (int i = 0; i < b.rows(); ++i)
    for (int j = 0; j < b.cols(); ++j) {
      double scale = std::sqrt(std::abs(b(i, i) * b(j, j)));
      if (!(scale > 0.0)) scale = fallback;
      worst = std::max(worst, std::abs(a(i, j) - b(i, j)) / scale);
    }
  return worst;
}

// Kinetic energy of the exact motion along q' (velocities by central
// differences with step 1e-5: truncation ~1e-10 relative).
double exact_kinetic_energy(const ExactGeometry& g, const VectorXd& qd) {
  const double eps = 1e-5;
  const auto plus = g.bodies(eps * qd), minus = g.bodies(-eps * qd);
  double t = 0.0;
  for (std::size_t b = 0; b < plus.size(); ++b) {
    const Vector3d v = (plus[b].position - minus[b].position) / (2 * eps);
    const Eigen::AngleAxisd turn(plus[b].rotation * minus[b].rotation.transpose());
    const Vector3d w = turn.angle() * turn.axis() / (2 * eps);
    t += 0.5 * (plus[b].mass * v.squaredNorm() + w.dot(plus[b].inertia * w));
  }
  return t;
}

struct Energies {
  MatrixXd mass, stiffness, damping;
};

Energies exact_hessians(const rigid::Machine3DParameters& p, const rigid::VehicleModel& m) {
  const ExactGeometry g(p, m);
  const auto springs = g.springs();
  const int n = m.size();
  // Step 1e-4 for the Hessians: T, V, D are quadratic to O(h^2) ~ 1e-8 relative (V has the exact geometry's
  // third-order terms; T and D are exactly quadratic in q' up to the 1e-10 of the inner differences).
  auto potential = [&](const VectorXd& q) {
    double v = 0.0;
    for (const auto& s : springs) v += 0.5 * s.k * std::pow(s.deformation(q), 2);
    return v;
  };
  auto dissipation = [&](const VectorXd& qd) {
    const double eps = 1e-5;
    double d = 0.0;
    for (const auto& s : springs) d += 0.5 * s.c * std::pow((s.deformation(eps * qd) - s.deformation(-eps * qd)) / (2 * eps), 2);
    return d;
  };
  return {fd_hessian([&](const VectorXd& qd) { return exact_kinetic_energy(g, qd); }, n, 1.0),
          fd_hessian(potential, n, 1e-4), fd_hessian(dissipation, n, 1.0)};
}

// ===========================================================================
// 1. M, K, C from the exact geometry

void check_against_exact(const rigid::Machine3DParameters& p, const char* label) {
  const rigid::VehicleModel m = rigid::build_vehicle_model(p);
  const Energies e = exact_hessians(p, m);
  const double dm = scaled_difference(m.m, e.mass);
  const double dk = scaled_difference(m.k_full, e.stiffness);
  const double dc = scaled_difference(m.c_full, e.damping);
  std::printf("%s: scaled differences M %.2e, K %.2e, C %.2e\n", label, dm, dk, dc);
  // Finite-difference error: T and D through velocity differences (1e-10
  // relative truncation, round-off eps/1e-5 ~ 1e-11 amplified by the Hessian
  // step 1 -> ~1e-9); V with step 1e-4: O(h^2 * third derivative / second) ~ 1e-8 x geometry ~ 1e-6.
  EXPECT_LT(dm, 1e-7);
  EXPECT_LT(dk, 1e-5);
  EXPECT_LT(dc, 1e-7);
}

TEST(Vehicle3DAssembly, MassStiffnessDampingAreHessiansOfTheExactOffsetPlowGeometry) { check_against_exact(offset_plow(), "offset plow"); }

TEST(Vehicle3DAssembly, MassStiffnessDampingAreHessiansOfTheExactOffsetChainGeometry) { check_against_exact(offset_chain(), "offset chain"); }

TEST(Vehicle3DAssembly, MassIsPositiveDefiniteAndStiffnessDampingSymmetric) {
  for (const auto& p : {offset_plow(), offset_chain()}) {
    const rigid::VehicleModel m = rigid::build_vehicle_model(p);
    EXPECT_LT((m.m - m.m.transpose()).norm(), 1e-12 * m.m.norm());
    EXPECT_LT((m.k_full - m.k_full.transpose()).norm(), 1e-14 * m.k_full.norm());  // round-off of the outer products
    Eigen::SelfAdjointEigenSolver<MatrixXd> es(m.m);
    EXPECT_GT(es.eigenvalues().minCoeff(), 0.0);
  }
}

// ===========================================================================
// 2. Hand-made cases

TEST(ProductsOfInertia, TwoPointMassesCombineWithTheParallelAxisProducts) {
  // Two 1 kg points at (1, 2, 3) and (-1, -2, -3): c.g. at 0, P_xy = sum m x y = 4, P_xz = 6, P_yz = 12.
  const rigid::RigidPart3D a{"a", 1.0, Vector3d(1, 2, 3), Matrix3d::Zero()}, b{"b", 1.0, Vector3d(-1, -2, -3), Matrix3d::Zero()};
  const rigid::RigidPart3D c = rigid::combine({a, b}, "ab");
  EXPECT_NEAR(c.mass, 2.0, 1e-15);
  EXPECT_LT(c.cg.norm(), 1e-15);
  const Matrix3d expected = rigid::inertia_tensor(2 * (4 + 9), 2 * (1 + 9), 2 * (1 + 4), 4, 6, 12);
  EXPECT_LT((c.inertia - expected).norm(), 1e-13);
}

TEST(ProductsOfInertia, CabRotationalMassBlockIsTheInertiaTensorWithItsProducts) {
  rigid::Machine3DParameters p = offset_plow();
  p.cab.body.inertia = rigid::inertia_tensor(90, 110, 95, 3, 6, -2);
  const rigid::VehicleModel m = rigid::build_vehicle_model(p);
  const int tu = coordinate(m, "theta_u");
  const MatrixXd block = m.m.block(tu, tu, 3, 3);
  EXPECT_LT((block - p.cab.body.inertia).norm(), 1e-12 * p.cab.body.inertia.norm());
  EXPECT_NEAR(block(0, 2), -6.0, 1e-12);  // -P_xz couples roll and yaw, as the thesis's IXZ terms of Eq. 3.10
}

TEST(SteeringRotation, TireSpringDirectionsAreTheWheelAxesTurnedExactlyByDelta) {
  rigid::Machine3DParameters p = from_2d(shipped_2d(), 1e6);
  const double d = 22 * kPi / 180;
  p.front_tires.steering_angle = d;
  p.rear_tires.steering_angle = -0.5;  // large, to the left
  const rigid::VehicleModel m = rigid::build_vehicle_model(p);
  auto dir = [&](const std::string& name) { return m.multibody.elements()[static_cast<std::size_t>(m.multibody.element_index(name))].direction; };
  EXPECT_LT((dir("front_right_tire_longitudinal") - Vector3d(std::cos(d), -std::sin(d), 0)).norm(), 1e-15);
  EXPECT_LT((dir("front_right_tire_lateral") - Vector3d(std::sin(d), std::cos(d), 0)).norm(), 1e-15);
  EXPECT_LT((dir("rear_left_tire_longitudinal") - Vector3d(std::cos(0.5), std::sin(0.5), 0)).norm(), 1e-15);
  // A frame translation along the front wheels' heading stretches their longitudinal springs only.
  VectorXd q = VectorXd::Zero(m.size());
  q[coordinate(m, "x")] = -std::cos(d);
  q[coordinate(m, "y")] = std::sin(d);
  const auto g = [&](const std::string& name) { return m.multibody.elongation_map(m.multibody.element_index(name)).dot(q); };
  EXPECT_NEAR(g("front_left_tire_longitudinal"), -1.0, 1e-14);
  EXPECT_NEAR(g("front_left_tire_lateral"), 0.0, 1e-14);
  EXPECT_NEAR(g("front_left_tire_vertical"), 0.0, 1e-14);
}

TEST(FrontAxle, PinnedAxleLockedToTheFrameAddsAppendixFMassAndInertia) {
  // With eta = theta_x (axle locked) the frame and axle are one body with the
  // combined mass, c.g. and inertia of Appendix F (Eqs. F.1-F.12): the rigid-body
  // mass matrix about the reference point of a body of these properties.
  rigid::Machine3DParameters p = offset_plow();
  p.attachment = rigid::Attachment::none;
  const rigid::VehicleModel m = rigid::build_vehicle_model(p);
  std::vector<rigid::RigidPart3D> all = p.frame.parts;
  all.push_back(p.frame.reel_and_carrier);
  all.push_back(p.frame.rear_axle);
  all.push_back(p.front_axle.axle);
  const rigid::RigidPart3D f = rigid::combine(all, "assembly");
  // Map the 6 frame coordinates to the 13 with eta = theta_x.
  MatrixXd lock = MatrixXd::Zero(m.size(), 6);
  for (int i = 0; i < 6; ++i) lock(i, i) = 1.0;
  lock(coordinate(m, "eta"), 3) = 1.0;
  const MatrixXd m6 = lock.transpose() * m.m * lock;
  // Rigid body about the reference: [[m 1, -m [r]x], [m [r]x, I + m([r]x)^T [r]x]] with r = cg - ref.
  const Vector3d r = f.cg - m.reference;
  const Matrix3d s = rigid::skew(r);
  MatrixXd expected(6, 6);
  expected << f.mass * Matrix3d::Identity(), -f.mass * s, f.mass * s, f.inertia + f.mass * s.transpose() * s;
  EXPECT_LT(scaled_difference(m6, expected), 1e-12);
}

// ===========================================================================
// 3. Appendix G: isolated single-freedom modes

double isolated_frequency(const rigid::VehicleModel& m, const std::string& keep) {
  std::vector<std::string> fixed;
  for (const auto& name : m.multibody.coordinate_names())
    if (name != keep) fixed.push_back(name);
  const auto modes = rigid::rigid_modes(m.m, m.k_full, m.multibody.coordinate_names(), fixed);
  return modes.at(0).frequency_hz;
}

// Eq. E.5, Y term of theta_x: the arm's end (point 21, pin 9) moves across by
// -(d19 + TA2 cos alpha') theta_x, the sum of E.1's -d19 theta_x and E.4's
// -TA2 cos alpha' theta_x; the thesis prints -(d19 - TA2 cos alpha')
// (docs/theory/rigid.md, section 10, slips). Derived here twice without the
// model's Jacobians: by central differences of the exact nonlinear geometry
// (ExactGeometry::arm, finite rotations), and from the dimensions with
// TA2 = l1 sin psi' cos alpha' (Appendix E), l1 sin psi' the arm's rise from
// pin 6 to pin 9 and d19 the height of pin 6 above the reference point. The
// boom is swung 25 deg so that the cos alpha' factors matter.
TEST(AppendixE, ArmEndCrossMotionUnderRollIsMinusD19PlusTA2CosAlpha) {
  rigid::Machine3DParameters p = offset_plow();
  const double alpha = 25 * kPi / 180;
  p.plow.boom_angle = alpha;
  const rigid::VehicleModel m = rigid::build_vehicle_model(p);
  const ExactGeometry exact(p, m);
  const auto& pp = m.plow_placement;
  const int itx = coordinate(m, "theta_x");
  // The model's Jacobian of pin 9 (a point of the shank and of the arm).
  const rigid::Body& plow = m.multibody.bodies()[static_cast<std::size_t>(m.plow_body)];
  const rigid::Jacobian j9 = plow.translation - rigid::skew(pp.pin9 - pp.cg) * plow.rotation;
  // Central differences of the exact geometry.
  const double h = 1e-6;
  VectorXd qp = VectorXd::Zero(m.size()), qm = qp;
  qp[itx] = h;
  qm[itx] = -h;
  const Vector3d fd = (exact.arm(qp).map(pp.pin9) - exact.arm(qm).map(pp.pin9)) / (2 * h);
  // Appendix E's dimensions.
  const double d19 = pp.pin6.z() - m.reference.z();
  const double rise = pp.pin9.z() - pp.pin6.z();                      // l1 sin psi'
  const double ta2 = rise * std::cos(alpha);                          // TA2 = l1 sin psi' cos alpha'
  const double corrected = -(d19 + ta2 * std::cos(alpha)), printed = -(d19 - ta2 * std::cos(alpha));
  ASSERT_GT(std::abs(rise), 0.05);                                    // the two readings differ by 2 TA2 cos alpha'
  EXPECT_NEAR(fd.y(), corrected, 1e-8);
  EXPECT_NEAR(j9(1, itx), corrected, 1e-12);
  EXPECT_GT(std::abs(j9(1, itx) - printed), 0.05);
}

TEST(AppendixG, FrontAxleRollMatchesAppendixG) {
  // Eq. G.8 with the errata: w^2 = 2 (K2 dp201^2 + K3 bp201^2) / (I4 + M4 dp200^2),
  // K2 lateral and K3 vertical per tire, contacts at +-bp201 and dp201 below the pin,
  // the axle's c.g. dp200 below the pin.
  rigid::Machine3DParameters p = from_2d(shipped_2d(), 1e6);
  const rigid::VehicleModel m = rigid::build_vehicle_model(p);
  const double dp200 = p.front_axle.pin.z() - p.front_axle.axle.cg.z();
  const double dp201 = p.front_axle.pin.z() - p.front_tires.left.contact.z();
  const double bp201 = p.front_tires.right.contact.y();
  const double k2 = p.front_tires.left.lateral.stiffness, k3 = p.front_tires.left.vertical.stiffness;
  const double i4 = p.front_axle.axle.inertia(0, 0), m4 = p.front_axle.axle.mass;
  const double hand = std::sqrt(2 * (k2 * dp201 * dp201 + k3 * bp201 * bp201) / (i4 + m4 * dp200 * dp200)) / (2 * kPi);
  const double model = isolated_frequency(m, "eta");
  std::printf("eta: model %.9f Hz, Appendix G %.9f Hz\n", model, hand);
  EXPECT_NEAR(model / hand, 1.0, 1e-6);  // the same quadratic forms: round-off of the 1-D eigenproblem
}

TEST(AppendixG, BoomSwingMatchesAppendixG) {
  // Eq. G.16: w^2 = (K15 d^2 + K30) / (IZZ2 + M2 a^2), alpha' = 0, a from the swing pin to the plow's c.g.,
  // d from the swing pin to the blade point (where the lateral soil spring K15 acts).
  rigid::Machine3DParameters p = from_2d(shipped_2d(), 1e6);
  p.plow.inertia_boom_axes = rigid::inertia_tensor(40, 70, 55, 0, 4, 0);
  const rigid::VehicleModel m = rigid::build_vehicle_model(p);
  const double a = m.plow_placement.cg.x() - p.plow.swing_pin.x(), d = m.plow_placement.blade.x() - p.plow.swing_pin.x();
  const double hand = std::sqrt((p.soil_lateral.stiffness * d * d + p.plow.swing_spring.stiffness) / (55 + p.plow.mass * a * a)) / (2 * kPi);
  const double model = isolated_frequency(m, "alpha");
  std::printf("alpha: model %.9f Hz, Appendix G %.9f Hz\n", model, hand);
  EXPECT_NEAR(model / hand, 1.0, 1e-6);
}

TEST(AppendixG, ParallelogramPlowPsiIsSqrtOfK5PlusK8OverM2In3D) {
  // Eq. G.12 (errata: M2): a parallelogram linkage with horizontal arms, lift cylinder off.
  rigid::Machine3DParameters p = from_2d(shipped_2d(), 1e6);
  p.plow.linkage.upper_pivot = Vector2d(82, 6) * kInch;
  p.plow.linkage.lower_pivot = Vector2d(82, -10) * kInch;
  p.plow.linkage.upper_joint = Vector2d(112, 6) * kInch;
  p.plow.linkage.lower_joint = Vector2d(112, -10) * kInch;
  p.plow.lift_cylinder = {0.0, 0.0};
  p.plow.blade_angle = 0.3;  // the blade plane's angle changes nothing for a translating shank
  const rigid::VehicleModel m = rigid::build_vehicle_model(p);
  const double hand = std::sqrt((p.soil.stiffness + p.plow.bounce_tire.stiffness) / p.plow.mass) / (2 * kPi);
  const double model = isolated_frequency(m, "psi");
  std::printf("psi: model %.9f Hz, Appendix G %.9f Hz\n", model, hand);
  EXPECT_NEAR(model / hand, 1.0, 1e-6);
}

// ===========================================================================
// 4. 2-D against 3-D on the same data (Table V, case 5)

TEST(PlanarAgreement, SymmetricModelWithStiffCabXGivesThe2DFrequencies) {
  const rigid::Machine2DParameters p2 = shipped_2d();
  const rigid::VehicleModel m2 = rigid::build_vehicle_model(p2);
  const auto modes2 = rigid::rigid_modes(m2.m, m2.k_full, m2.multibody.coordinate_names());
  // Cab X stiffness 1e13 N/m: the constraint's error (w / w_penalty)^2 ~ 1e-10 relative.
  const rigid::VehicleModel m3 = rigid::build_vehicle_model(from_2d(p2, 1e13));
  const std::vector<std::string> out_of_plane{"y", "theta_x", "theta_z", "v", "theta_u", "theta_w", "eta", "alpha"};
  // The symmetric model decouples exactly: no M or K entry between X-Z and out-of-plane coordinates.
  const std::vector<std::string> in_plane{"x", "z", "theta_y", "u", "w", "theta_v", "psi"};
  double coupling_term = 0.0;
  for (const auto& a : in_plane)
    for (const auto& b : out_of_plane) {
      const int i = coordinate(m3, a), j = coordinate(m3, b);
      coupling_term = std::max({coupling_term, std::abs(m3.m(i, j)) / std::sqrt(m3.m(i, i) * m3.m(j, j)),
                                std::abs(m3.k_full(i, j)) / std::sqrt(m3.k_full(i, i) * m3.k_full(j, j))});
    }
  EXPECT_LT(coupling_term, 1e-14);
  const auto modes3 = rigid::rigid_modes(m3.m, m3.k_full, m3.multibody.coordinate_names(), out_of_plane);
  ASSERT_EQ(modes3.size(), modes2.size() + 1);  // u's penalty mode on top
  for (std::size_t i = 0; i < modes2.size(); ++i) {
    std::printf("X-Z mode %zu: 2-D %.9f Hz (%s), 3-D %.9f Hz (%s)\n", i, modes2[i].frequency_hz, modes2[i].dominant.c_str(),
                modes3[i].frequency_hz, modes3[i].dominant.c_str());
    EXPECT_NEAR(modes3[i].frequency_hz / modes2[i].frequency_hz, 1.0, 1e-6);
  }
}

// The in-plane response of both models to the shaker from rest: frame x, z,
// theta_y, cab w, theta_v, plow psi. `law_active` false sets REK = REC = 1 (the
// soil law switches but changes nothing: a linear response).
// `soil_law`, if given, changes the 2-D soil law (and with it the 3-D one) before
// the build; the runs then also compare the soil resultant RPF (rigid::plow_force).
struct PlanarRun {
  double difference = 0.0, amplitude = 0.0;
  double force_difference = 0.0, force_amplitude = 0.0;
  std::size_t events_2d = 0, events_3d = 0;
  std::vector<rigid::Trajectory::Event> events_2d_log, events_3d_log;
};
PlanarRun planar_run(bool law_active, double duration, double forward_speed,
                     rigid::ContactLaw contacts = rigid::ContactLaw::linear, double shaker_scale = 1.0,
                     const std::function<void(rigid::Machine2DParameters&)>& soil_law = {}) {
  rigid::Machine2DParameters p2 = shipped_2d();
  p2.forward_speed = forward_speed;
  p2.plow.shaker_amplitude *= shaker_scale;
  p2.contacts = contacts;
  if (!law_active) {
    // The printed reading with REK = REC = 1: the switches change nothing. (The shipped
    // cut-face reading drops the springs while cutting whatever REK is.)
    p2.soil.stiffness_reduction = p2.soil.damping_reduction = 1.0;
    p2.soil.cut_face = p2.soil.spring_from_contact = p2.soil.contact_moves_with_soil = false;
  }
  if (soil_law) soil_law(p2);
  const rigid::VehicleModel m2 = rigid::build_vehicle_model(p2);
  // Cab X stiffness 1e13 N/m: the constraint's relative error (w_shaker / w_penalty)^2 = (115 / 1.8e5)^2 ~ 4e-7.
  const rigid::VehicleModel m3 = rigid::build_vehicle_model(from_2d(p2, 1e13));
  VectorXd q2 = VectorXd::Zero(m2.size()), q3 = VectorXd::Zero(m3.size());
  rigid::VehicleRunState m2_run = rigid::start_run(m2, 0.0, q2);
  rigid::VehicleDynamics m2_dyn(m2, m2_run);
  rigid::VehicleRunState m3_run = rigid::start_run(m3, 0.0, q3);
  rigid::VehicleDynamics m3_dyn(m3, m3_run);
  rigid::IntegrationOptions o;
  o.end_time = duration;
  o.output_interval = 1e-3;
  o.relative_tolerance = 1e-10;
  o.absolute_tolerance = 1e-13;
  o.velocity_scale = 100.0;
  const rigid::Trajectory t2 = rigid::integrate_event_located(m2_dyn, q2, q2, o);
  o.method = rigid::MultistepMethod::bdf;  // the stiff cab X penalty
  const rigid::Trajectory t3 = rigid::integrate_event_located(m3_dyn, q3, q3, o);
  PlanarRun r;
  r.events_2d = t2.events.size();
  r.events_3d = t3.events.size();
  for (const auto& e : t2.events) r.events_2d_log.push_back(e);
  for (const auto& e : t3.events) r.events_3d_log.push_back(e);
  if (t2.time.size() != t3.time.size()) throw std::logic_error("different sample counts");
  for (const std::string name : {"x", "z", "theta_y", "psi", "w", "theta_v"}) {
    const int i2 = m2.coordinate(name), i3 = m3.coordinate(name);
    for (std::size_t k = 0; k < t2.time.size(); ++k) {
      r.difference = std::max(r.difference, std::abs(t2.q[k][i2] - t3.q[k][i3]));
      r.amplitude = std::max(r.amplitude, std::abs(t2.q[k][i2]));
    }
  }
  for (std::size_t k = 0; k < t2.time.size(); ++k) {
    const Vector3d f2 = rigid::plow_force(m2, m2_run, t2.time[k], t2.q[k], t2.v[k]);
    const Vector3d f3 = rigid::plow_force(m3, m3_run, t3.time[k], t3.q[k], t3.v[k]);
    r.force_difference = std::max(r.force_difference, (f2 - f3).norm());
    r.force_amplitude = std::max(r.force_amplitude, f2.norm());
  }
  std::printf("in-plane response over %.2f s (soil law %s): max difference %.3e of max amplitude %.3e (%zu / %zu events); "
              "soil resultant differs by %.3e of %.3e N\n", duration, law_active ? "active" : "inert", r.difference, r.amplitude, r.events_2d,
              r.events_3d, r.force_difference, r.force_amplitude);
  return r;
}

TEST(PlanarAgreement, InPlaneLinearForcedResponseAgrees) {
  const PlanarRun r = planar_run(false, 0.3, shipped_2d().forward_speed);
  // Penalty error ~4e-7 relative plus the integrators' rtol 1e-10 over ~1e4 steps (~1e-6).
  EXPECT_LT(r.difference, 2e-6 * r.amplitude);
}

TEST(PlanarAgreement, InPlaneForcedResponseWithSoilSwitchingAgrees) {
  // The shipped plow at its own speed (the cut-face soil law): it backs off at 0.011 s, cuts again
  // at 0.148 s, and from 0.18 s backs off and cuts again once every cycle.
  const PlanarRun r = planar_run(true, 0.21, shipped_2d().forward_speed);
  EXPECT_GE(r.events_2d, 4u);  // two back-offs, two re-cuts
  EXPECT_EQ(r.events_2d, r.events_3d);
  // As above; each located switch restarts both runs at times that differ by the event tolerance.
  EXPECT_LT(r.difference, 2e-6 * r.amplitude);
}

// The soil springs' moving anchor (docs/theory/rigid.md section 18): under
// spring_reference soil_line the springs act from the point where the cut began,
// carried rearward with the soil at VS; under cut_face with REK > 0 they act
// while backing off, from the cut face the blade left, carried the same way. The
// symmetric 3-D model moves its anchor with the same soil flow, so both models
// give the same response and the same soil resultant, through the switches. A
// 2-degree slope puts the flow's vertical component (-VS sin theta_g) in play.
TEST(PlanarAgreement, InPlaneForcedResponseWithTheSoilLineAnchorAgrees) {
  const PlanarRun r = planar_run(true, 0.21, shipped_2d().forward_speed, rigid::ContactLaw::linear, 1.0, [](rigid::Machine2DParameters& p) {
    p.ground_slope = 2.0 * 3.141592653589793 / 180.0;
    p.soil.stiffness_reduction = 0.5;
    p.soil.cut_face = false;
    p.soil.spring_from_contact = p.soil.contact_moves_with_soil = true;
  });
  EXPECT_GE(r.events_2d, 4u);  // two back-offs, two re-cuts
  EXPECT_EQ(r.events_2d, r.events_3d);
  // As the switching test above: the penalty error ~4e-7 and rtol 1e-10 over the steps.
  EXPECT_LT(r.difference, 2e-6 * r.amplitude);
  EXPECT_GT(r.force_amplitude, 0.0);
  EXPECT_LT(r.force_difference, 2e-6 * r.force_amplitude);
}

TEST(PlanarAgreement, InPlaneForcedResponseWithTheCutFaceAnchorAndReducedStiffnessAgrees) {
  const PlanarRun r = planar_run(true, 0.21, shipped_2d().forward_speed, rigid::ContactLaw::linear, 1.0, [](rigid::Machine2DParameters& p) {
    p.ground_slope = 2.0 * 3.141592653589793 / 180.0;
    p.soil.stiffness_reduction = 0.5;  // springs while backing, from the cut face streaming with the soil
    p.soil.cut_face = p.soil.spring_from_contact = p.soil.contact_moves_with_soil = true;
  });
  EXPECT_GE(r.events_2d, 4u);
  EXPECT_EQ(r.events_2d, r.events_3d);
  EXPECT_LT(r.difference, 2e-6 * r.amplitude);
  EXPECT_GT(r.force_amplitude, 0.0);
  EXPECT_LT(r.force_difference, 2e-6 * r.force_amplitude);
}

TEST(PlanarAgreement, InPlaneForcedResponseWithContactsLiftingOffAgrees) {
  // One-sided contacts (Eq. 4a.3): with twice its shaker force the shipped
  // plow's bounce tire lifts off (with the shipped force it carries 2,794 lbf
  // at rest and never less than 746: docs/validation.md P1.3); in 3-D it is
  // the same element, and the 2-D axle's two tires are the 3-D axle's left
  // and right tires, which lift off together or not at all in the symmetric model.
  const PlanarRun r = planar_run(true, 0.21, shipped_2d().forward_speed, rigid::ContactLaw::unilateral, 2.0);
  auto contact_events = [](const std::vector<rigid::Trajectory::Event>& log) {
    std::vector<double> t;
    for (const auto& e : log)
      if (e.what.find("contact") != std::string::npos || e.what.find("touches") != std::string::npos) t.push_back(e.time);
    return t;
  };
  const std::vector<double> c2 = contact_events(r.events_2d_log), c3 = contact_events(r.events_3d_log);
  ASSERT_GE(c2.size(), 1u);  // the bounce tire lifts off
  ASSERT_EQ(c2.size(), c3.size());
  for (std::size_t i = 0; i < c2.size(); ++i) {
    std::printf("contact event %zu: 2-D %.9f s (%s), 3-D %.9f s\n", i, c2[i], r.events_2d_log[i].what.c_str(), c3[i]);
    EXPECT_NEAR(c2[i], c3[i], 1e-6);
  }
  EXPECT_EQ(r.events_2d, r.events_3d);
  EXPECT_LT(r.difference, 2e-6 * r.amplitude);
}

// Both builders give one model type, run and recovered by the same functions:
// the symmetric 3-D model of the shipped 2-D plow, run by run_vehicle, gives
// the 2-D model's in-plane shaker force and soil resultant (Eq. 2.37) through
// rigid::shaker_force and rigid::plow_force. And a 3-D model run at a second
// shaker frequency after set_shaker equals a fresh build, bit for bit.
static_assert(std::is_same_v<decltype(rigid::build_vehicle_model(std::declval<const rigid::Machine2DParameters&>())),
                             decltype(rigid::build_vehicle_model(std::declval<const rigid::Machine3DParameters&>()))>,
              "the 2-D and 3-D builders produce the same model type");

TEST(PlanarAgreement, BothBuildersGiveOneModelTypeRunAndRecoveredByTheSameFunctions) {
  rigid::Machine2DParameters p2 = shipped_2d();
  p2.contacts = rigid::ContactLaw::linear;
  const rigid::VehicleModel m2 = rigid::build_vehicle_model(p2);
  const rigid::VehicleModel m3 = rigid::build_vehicle_model(from_2d(p2, 1e13));
  EXPECT_EQ(m2.dimensions, 2);
  EXPECT_EQ(m3.dimensions, 3);
  rigid::IntegrationOptions o;
  o.end_time = 0.05;
  o.output_interval = 1e-3;
  o.relative_tolerance = 1e-10;
  o.absolute_tolerance = 1e-13;
  o.velocity_scale = 100.0;
  const rigid::VehicleRun r2 = rigid::run_vehicle(m2, VectorXd::Zero(m2.size()), VectorXd::Zero(m2.size()), o);
  o.method = rigid::MultistepMethod::bdf;  // the stiff cab X penalty
  const rigid::VehicleRun r3 = rigid::run_vehicle(m3, VectorXd::Zero(m3.size()), VectorXd::Zero(m3.size()), o);
  ASSERT_EQ(r2.trajectory.time.size(), r3.trajectory.time.size());
  double shaker_difference = 0.0, shaker_amplitude = 0.0, soil_difference = 0.0, soil_amplitude = 0.0;
  for (std::size_t i = 0; i < r2.trajectory.time.size(); ++i) {
    const double t = r2.trajectory.time[i];
    const Vector3d s2 = rigid::shaker_force(m2, t), s3 = rigid::shaker_force(m3, t);
    shaker_difference = std::max(shaker_difference, (s2 - s3).norm());
    shaker_amplitude = std::max(shaker_amplitude, s2.norm());
    const Vector3d f2 = rigid::plow_force(m2, r2.state, t, r2.trajectory.q[i], r2.trajectory.v[i]);
    const Vector3d f3 = rigid::plow_force(m3, r3.state, t, r3.trajectory.q[i], r3.trajectory.v[i]);
    soil_difference = std::max(soil_difference, (f2 - f3).norm());
    soil_amplitude = std::max(soil_amplitude, f2.norm());
  }
  std::printf("one model type: shaker force differs by %.3e of %.3e N, soil resultant by %.3e of %.3e N over %.2f s\n", shaker_difference,
              shaker_amplitude, soil_difference, soil_amplitude, o.end_time);
  EXPECT_LT(shaker_difference, 1e-12 * shaker_amplitude);  // the same shank direction, placed by two builders
  // The penalty error (~4e-7) and rtol 1e-10 over the steps, as the in-plane response above.
  EXPECT_GT(soil_amplitude, 0.0);
  EXPECT_LT(soil_difference, 2e-6 * soil_amplitude);
}

TEST(PlanarAgreement, ThreeDModelRunAtASecondShakerFrequencyEqualsAFreshBuildBitForBit) {
  rigid::Machine3DParameters p = offset_plow();
  rigid::VehicleModel model = rigid::build_vehicle_model(p);
  const VectorXd zero = VectorXd::Zero(model.size());
  rigid::IntegrationOptions o;
  o.end_time = 0.05;
  o.output_interval = 1e-3;
  const rigid::VehicleRun first = rigid::run_vehicle(model, zero, zero, o);
  rigid::set_shaker(model, p.plow.shaker_amplitude, 0.7 * p.plow.shaker_frequency, p.plow.shaker_phase);
  const rigid::VehicleRun second = rigid::run_vehicle(model, zero, zero, o);
  p.plow.shaker_frequency *= 0.7;
  const rigid::VehicleRun fresh = rigid::run_vehicle(rigid::build_vehicle_model(p), zero, zero, o);
  ASSERT_EQ(second.trajectory.time, fresh.trajectory.time);
  ASSERT_EQ(second.trajectory.events.size(), fresh.trajectory.events.size());
  for (std::size_t i = 0; i < fresh.trajectory.time.size(); ++i) {
    EXPECT_EQ(second.trajectory.q[i], fresh.trajectory.q[i]) << "t = " << fresh.trajectory.time[i];
    EXPECT_EQ(second.trajectory.v[i], fresh.trajectory.v[i]) << "t = " << fresh.trajectory.time[i];
  }
  EXPECT_NE(first.trajectory.q.back(), second.trajectory.q.back());  // the frequency did change the run
}

TEST(GroundInput3D, SineUnderOneTireLoadsTheModelThroughThatTireOnly) {
  // Eq. 1.5: FK + FC = G^T (k xr + c vr) for the front left tire's vertical element alone.
  rigid::Machine3DParameters p = offset_plow();
  p.forward_speed = 0.0;
  p.plow.shaker_amplitude = 0.0;
  p.front_tires.left.vertical_input.kind = rigid::GroundInput::Kind::sine;
  p.front_tires.left.vertical_input.amplitude = 0.01;
  p.front_tires.left.vertical_input.frequency = 3.0;
  const rigid::VehicleModel m = rigid::build_vehicle_model(p);
  rigid::VehicleRunState m_run = rigid::start_run(m, 0.0, VectorXd::Zero(m.size()));
  rigid::VehicleDynamics m_dyn(m, m_run);
  const double t = 0.07;
  VectorXd a(m.size());
  m_dyn.acceleration(t, VectorXd::Zero(m.size()), VectorXd::Zero(m.size()), a);
  const int e = m.multibody.element_index("front_left_tire_vertical");
  const rigid::SpringDamper& el = m.multibody.elements()[static_cast<std::size_t>(e)];
  const VectorXd expected = m.multibody.elongation_map(e).transpose() *
                            (el.stiffness * p.front_tires.left.vertical_input.displacement(t) + el.damping * p.front_tires.left.vertical_input.velocity(t));
  EXPECT_LT((m.m * a - expected).norm(), 1e-10 * expected.norm());
  // A copy of the model keeps its inputs (they are looked up, not pointed to).
  const rigid::VehicleModel copy = m;
  rigid::VehicleRunState copy_run = rigid::start_run(copy, 0.0, VectorXd::Zero(copy.size()));
  VectorXd b(m.size());
  rigid::VehicleDynamics(copy, copy_run).acceleration(t, VectorXd::Zero(m.size()), VectorXd::Zero(m.size()), b);
  EXPECT_EQ((a - b).norm(), 0.0);
}

// ===========================================================================
// 5. The chain variant

TEST(ChainVariant, HasThirteenCoordinatesWithoutPsiAndAlpha) {
  const rigid::VehicleModel m = rigid::build_vehicle_model(offset_chain());
  EXPECT_EQ(m.size(), 13);
  EXPECT_LT(m.coordinate("psi"), 0);
  EXPECT_LT(m.coordinate("alpha"), 0);
  EXPECT_EQ(m.multibody.coordinate_names().back(), "eta");
}

TEST(ChainVariant, ChainForceAtPoint19IsRchAlongTheChainAndRmchAboutY) {
  rigid::Machine3DParameters p = offset_chain();
  p.chain.ramp_time = 0.0;
  p.forward_speed = 0.0;
  const rigid::VehicleModel m = rigid::build_vehicle_model(p);
  rigid::VehicleRunState m_run = rigid::start_run(m, 0.0, VectorXd::Zero(m.size()));
  rigid::VehicleDynamics m_dyn(m, m_run);
  const double rch = rigid::chain_force(m, m_run, 0.0);
  const double mtig = std::floor(36.0 / 8.0);  // 4 teeth, the fifth at t=0 within ATCH
  EXPECT_NEAR(rch, (900 * kLbf + 100 * kInch * 2 * kDamp) * mtig, 1e-9 * rch);
  // Virtual work: Q . dq = F . d19 + M . dtheta for any dq.
  VectorXd a(m.size());
  const VectorXd zero = VectorXd::Zero(m.size());
  m_dyn.acceleration(0.0, zero, zero, a);
  const VectorXd q_force = m.m * a;
  const Vector3d f = rch * m.chain_direction, mom(0.0, -rch * m.chain_moment_arm, 0.0);  // RCH along the chain, RMCH about +Y
  VectorXd expected = m.multibody.generalized_force(m.chain_point, f);
  expected += m.multibody.bodies()[static_cast<std::size_t>(m.frame_body)].rotation.transpose() * mom;
  // The soil dampers see the soil flow (VS = 0 here): no other force at rest.
  EXPECT_LT((q_force - expected).norm(), 1e-9 * expected.norm());
  // The offset pin: RCH's X component at Y = 35 in yaws the frame (moment about Z = -Y_rel * F_x).
  const double yaw = expected[coordinate(m, "theta_z")];
  EXPECT_NEAR(yaw, -(p.chain.chain_pin.y() - m.reference.y()) * f.x() + (p.chain.chain_pin.x() - m.reference.x()) * f.y(), 1e-9 * std::abs(yaw));
}

// ===========================================================================
// 6. Frame loads at the eight load points (coupling/frame_loads_3d.h)

void check_frame_balance(rigid::Machine3DParameters p, const char* label) {
  p.forward_speed = 6 * kInch;
  const rigid::VehicleModel m = rigid::build_vehicle_model(p);
  const VectorXd zero = VectorXd::Zero(m.size());
  rigid::VehicleRunState m_run = rigid::start_run(m, 0.0, zero);
  rigid::VehicleDynamics m_dyn(m, m_run);
  rigid::IntegrationOptions o;
  o.end_time = 0.15;
  o.output_interval = 1e-3;
  o.relative_tolerance = 1e-8;
  o.absolute_tolerance = 1e-12;
  o.velocity_scale = 100.0;
  const rigid::Trajectory tr = rigid::integrate_event_located(m_dyn, zero, zero, o);
  const coupling::FrameLoads3D loads = coupling::frame_loads_3d(m, p, m_run, tr);
  ASSERT_EQ(loads.points.points.size(), 8u);
  const rigid::Body& frame = m.multibody.bodies()[static_cast<std::size_t>(m.frame_body)];
  const Vector3d cg = rigid::combine(p.frame.parts, "frame").cg;
  double worst_force = 0.0, worst_moment = 0.0, scale_force = 0.0, scale_moment = 0.0, front_tx = 0.0, rear_tx = 0.0;
  for (std::size_t i = 0; i < tr.time.size(); ++i) {
    const Vector3d acc = frame.translation * tr.a[i], alpha = frame.rotation * tr.a[i];
    Vector3d f = -frame.mass * acc, mo = -frame.inertia * alpha;  // the frame's own inertia force and moment about its c.g.
    for (const auto* set : {&loads.points, &loads.direct})
      for (const coupling::LoadPointHistory& l : set->points) {
        const Vector3d fl = l.values.row(static_cast<Eigen::Index>(i)).head<3>().transpose();
        const Vector3d ml = l.values.row(static_cast<Eigen::Index>(i)).tail<3>().transpose();
        f += fl;
        mo += ml + (l.location - cg).cross(fl);
        scale_force = std::max(scale_force, fl.norm());
        scale_moment = std::max(scale_moment, ml.norm() + (l.location - cg).norm() * fl.norm());
      }
    if (f.norm() > 1e-6 && i < 200 && std::getenv("DEBUG3D")) std::printf("t=%g res %g %g %g\n", tr.time[i], f.x(), f.y(), f.z());
    worst_force = std::max(worst_force, f.norm());
    worst_moment = std::max(worst_moment, mo.norm());
    front_tx = std::max(front_tx, std::abs(loads.points.points[1].values(static_cast<Eigen::Index>(i), 3)));
    rear_tx = std::max(rear_tx, std::abs(loads.points.points[2].values(static_cast<Eigen::Index>(i), 3)));
  }
  std::printf("%s: frame free body over %zu samples: force residual %.2e of %.2e N, moment residual %.2e of %.2e N m; "
              "front pin TX %.2e, rear pin TX %.2e N m\n",
              label, tr.time.size(), worst_force, scale_force, worst_moment, scale_moment, front_tx, rear_tx);
  // Round-off: the loads are sums of ~40 terms of size scale; M a = f is solved to ~1e-15 relative.
  EXPECT_LT(worst_force, 1e-9 * scale_force);
  EXPECT_LT(worst_moment, 1e-9 * scale_moment);
  EXPECT_LT(front_tx, 1e-9 * scale_moment);  // the pin passes no moment about its axis
  EXPECT_LT(rear_tx, 1e-12 * scale_moment);  // the cylinder carries it by construction: round-off
}

TEST(FrameLoads3D, FrameFreeBodyBalancesAtEveryInstantOffsetPlow) { check_frame_balance(offset_plow(), "offset plow"); }
TEST(FrameLoads3D, FrameFreeBodyBalancesAtEveryInstantOffsetChain) {
  // The thesis's bilateral contacts: with one-sided ones, started from their own statics
  // (docs/theory/rigid.md section 11), this chain machine at 6 in/s enters a sliding
  // regime of its soil law at 0.14 s that CVODE cannot pass in 1e6 steps (not handled
  // yet: the chattering warning of issue 15). The balance checked here holds for either law.
  rigid::Machine3DParameters p = offset_chain();
  p.contacts = rigid::ContactLaw::linear;
  check_frame_balance(p, "offset chain");
}

}  // namespace
