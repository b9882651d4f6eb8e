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

Machine3D::Machine3D(const Machine3DParameters& p)
    : p_(p), model_(build_vehicle_model(p)), state_(start_run(model_, 0.0, Eigen::VectorXd::Zero(model_.size()))) {}

void Machine3D::acceleration(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v, Eigen::VectorXd& a) const {
  VehicleDynamics(model_, state_).acceleration(t, q, v, a);
}
int Machine3D::event_count() const { return VehicleDynamics(model_, state_).event_count(); }
void Machine3D::events(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v, double* g) const {
  VehicleDynamics(model_, state_).events(t, q, v, g);
}
std::string Machine3D::on_event(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v, const std::vector<int>& fired,
                                const std::vector<int>& directions) {
  return VehicleDynamics(model_, state_).on_event(t, q, v, fired, directions);
}
double Machine3D::next_scheduled_change(double t) const { return VehicleDynamics(model_, state_).next_scheduled_change(t); }
std::string Machine3D::on_scheduled_change(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v) {
  return VehicleDynamics(model_, state_).on_scheduled_change(t, q, v);
}

}  // namespace framedyn::rigid
