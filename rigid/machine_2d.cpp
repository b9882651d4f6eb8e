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

Eigen::Vector3d in_3d(const Eigen::Vector2d& p) { return {p.x(), 0.0, p.y()}; }

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
    : p_(p), frame_(frame_mass_properties(p.frame, p.cab)), model_(build_vehicle_model(p)), state_(start_run(model_, 0.0, Eigen::VectorXd::Zero(model_.size()))) {}

void Machine2D::acceleration(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v, Eigen::VectorXd& a) const {
  VehicleDynamics(model_, state_).acceleration(t, q, v, a);
}
int Machine2D::event_count() const { return VehicleDynamics(model_, state_).event_count(); }
void Machine2D::events(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v, double* g) const {
  VehicleDynamics(model_, state_).events(t, q, v, g);
}
std::string Machine2D::on_event(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v, const std::vector<int>& fired,
                                const std::vector<int>& directions) {
  return VehicleDynamics(model_, state_).on_event(t, q, v, fired, directions);
}
double Machine2D::next_scheduled_change(double t) const {
  return VehicleDynamics(model_, state_).next_scheduled_change(t);
}
std::string Machine2D::on_scheduled_change(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v) {
  return VehicleDynamics(model_, state_).on_scheduled_change(t, q, v);
}

Eigen::Vector2d Machine2D::plow_force(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v) const {
  const Eigen::Vector3d f = rigid::plow_force(model_, state_, t, q, v);
  return {f.x(), f.z()};
}

Jacobian Machine2D::frame_point_jacobian(const Eigen::Vector2d& point) const { return rigid::frame_point_jacobian(model_, in_3d(point)); }

Eigen::Vector2d Machine2D::shaker_force(double t) const {
  const Eigen::Vector3d f = rigid::shaker_force(model_, t);
  return {f.x(), f.z()};
}

}  // namespace framedyn::rigid
