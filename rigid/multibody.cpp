// Assembly of M, K, C from bodies, points and spring-dampers; see multibody.h.
#include "rigid/multibody.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/error.h"

namespace framedyn::rigid {

Eigen::Matrix3d skew(const Eigen::Vector3d& r) {
  Eigen::Matrix3d s;
  s << 0, -r.z(), r.y(), r.z(), 0, -r.x(), -r.y(), r.x(), 0;
  return s;
}

Multibody::Multibody(std::vector<std::string> names, std::vector<core::Quantity> quantities)
    : names_(std::move(names)), quantities_(std::move(quantities)) {
  if (quantities_.size() != names_.size()) throw std::invalid_argument("one quantity per coordinate");
  for (core::Quantity q : quantities_)
    if (q != core::Quantity::length && q != core::Quantity::angle) throw std::invalid_argument("a coordinate is a length or an angle");
}

int Multibody::add_body(Body body) {
  if (body.translation.cols() != size() || body.rotation.cols() != size())
    throw std::invalid_argument("body " + body.name + ": Jacobians must have one column per coordinate");
  bodies_.push_back(std::move(body));
  return static_cast<int>(bodies_.size()) - 1;
}

int Multibody::add_point(Point point) {
  if (point.displacement.cols() != size()) throw std::invalid_argument("point " + point.name + ": Jacobian must have one column per coordinate");
  points_.push_back(std::move(point));
  return static_cast<int>(points_.size()) - 1;
}

int Multibody::add_body_point(const std::string& name, int body, const Eigen::Vector3d& offset) {
  const Body& b = bodies_.at(static_cast<std::size_t>(body));
  return add_point({name, b.translation - skew(offset) * b.rotation});
}

int Multibody::add_element(SpringDamper element) {
  if (element.point_a < 0 || element.point_a >= static_cast<int>(points_.size()) || element.point_b >= static_cast<int>(points_.size()))
    throw std::invalid_argument("element " + element.name + ": unknown point");
  const double norm = element.direction.norm();
  if (!(norm > 0.0)) throw std::invalid_argument("element " + element.name + ": zero direction");
  element.direction /= norm;
  elements_.push_back(std::move(element));
  return static_cast<int>(elements_.size()) - 1;
}

int Multibody::element_index(const std::string& name) const {
  for (std::size_t i = 0; i < elements_.size(); ++i)
    if (elements_[i].name == name) return static_cast<int>(i);
  return -1;
}

int Multibody::point_index(const std::string& name) const {
  for (std::size_t i = 0; i < points_.size(); ++i)
    if (points_[i].name == name) return static_cast<int>(i);
  return -1;
}

Eigen::RowVectorXd Multibody::elongation_map(int e) const {
  const SpringDamper& el = elements_.at(static_cast<std::size_t>(e));
  const Jacobian& ja = points_[static_cast<std::size_t>(el.point_a)].displacement;
  // A grounded element runs from the ground to a: elongation n . d_a (multibody.h).
  if (el.point_b < 0) return el.direction.transpose() * ja;
  return el.direction.transpose() * (points_[static_cast<std::size_t>(el.point_b)].displacement - ja);
}

Eigen::MatrixXd Multibody::mass_matrix() const {
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(size(), size());
  for (const Body& b : bodies_) {
    m += b.mass * b.translation.transpose() * b.translation;
    m += b.rotation.transpose() * b.inertia * b.rotation;
  }
  return 0.5 * (m + m.transpose());
}

Eigen::MatrixXd Multibody::stiffness_matrix() const {
  Eigen::MatrixXd k = Eigen::MatrixXd::Zero(size(), size());
  for (std::size_t e = 0; e < elements_.size(); ++e) {
    const Eigen::RowVectorXd g = elongation_map(static_cast<int>(e));
    k += elements_[e].stiffness * g.transpose() * g;
  }
  return k;
}

Eigen::MatrixXd Multibody::damping_matrix() const {
  Eigen::MatrixXd c = Eigen::MatrixXd::Zero(size(), size());
  for (std::size_t e = 0; e < elements_.size(); ++e) {
    const Eigen::RowVectorXd g = elongation_map(static_cast<int>(e));
    c += elements_[e].damping * g.transpose() * g;
  }
  return c;
}

Eigen::VectorXd Multibody::generalized_force(int point, const Eigen::Vector3d& force) const {
  return points_.at(static_cast<std::size_t>(point)).displacement.transpose() * force;
}

namespace {

// The bodies that take part in the motion q = phi, each with what it lacks:
// "cab (translating, mass 0 kg)", for the message of a singular mass matrix.
std::string bodies_in_motion(const Multibody& model, const Eigen::VectorXd& phi) {
  std::string out;
  for (const Body& b : model.bodies()) {
    const Eigen::Vector3d u = b.translation * phi, w = b.rotation * phi;
    const bool translates = u.norm() > 1e-6, rotates = w.norm() > 1e-6;
    if (!translates && !rotates) continue;
    std::string what;
    if (translates) what += fmt::format("translating, mass {:g} kg", b.mass);
    if (rotates) {
      const Eigen::Vector3d axis = w.normalized();
      what += fmt::format("{}rotating, moment of inertia {:g} kg m^2 about its axis of rotation", translates ? "; " : "",
                          axis.dot(b.inertia * axis));
    }
    out += fmt::format("{}{} ({})", out.empty() ? "" : ", ", b.name, what);
  }
  return out;
}

}  // namespace

void check_definiteness(const Multibody& model) {
  // Each body first, so that a wrong input names its body.
  for (const Body& b : model.bodies()) {
    if (!std::isfinite(b.mass) || b.mass < 0.0)
      throw core::NumericalError(fmt::format(
          "the mass matrix is not positive definite: body {} has mass {} kg; a mass must be finite and not negative", b.name, b.mass));
    if (!b.inertia.allFinite())
      throw core::NumericalError(fmt::format("the mass matrix is not positive definite: body {} has a non-finite inertia tensor", b.name));
    const Eigen::Matrix3d inertia = 0.5 * (b.inertia + b.inertia.transpose());
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> ei(inertia);
    const double scale = std::max(1e-300, inertia.cwiseAbs().maxCoeff());
    if (ei.eigenvalues().minCoeff() < -1e-12 * scale)
      throw core::NumericalError(fmt::format(
          "the mass matrix is not positive definite: body {} has an inertia tensor that is not positive semi-definite "
          "(principal moments {:g}, {:g}, {:g} kg m^2; check the signs of its moments and products of inertia)",
          b.name, ei.eigenvalues()(0), ei.eigenvalues()(1), ei.eigenvalues()(2)));
  }
  const Eigen::MatrixXd m = model.mass_matrix();
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> em(m);
  const double scale = std::max(1e-300, m.diagonal().cwiseAbs().maxCoeff());
  if (em.eigenvalues().minCoeff() <= 1e-12 * scale) {
    const Eigen::VectorXd phi = em.eigenvectors().col(0);
    Eigen::Index worst = 0;
    phi.cwiseAbs().maxCoeff(&worst);
    const std::string bodies = bodies_in_motion(model, phi / phi.cwiseAbs().maxCoeff());
    throw core::NumericalError(fmt::format(
        "the mass matrix is not positive definite: coordinate {} has (almost) no inertia; {}. Give the bodies that "
        "move with it a mass and inertia, or remove the coordinate",
        model.coordinate_names()[static_cast<std::size_t>(worst)],
        bodies.empty() ? "no body moves with it" : "the bodies that move with it: " + bodies));
  }
  for (const SpringDamper& e : model.elements())
    if (e.stiffness < 0.0 || e.damping < 0.0)
      throw core::NumericalError(fmt::format("element {} has a negative stiffness or damping ({}, {})", e.name, e.stiffness, e.damping));
}

}  // namespace framedyn::rigid
