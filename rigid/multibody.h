// The linearised multibody assembly that carries every vehicle model
// (docs/theory/rigid.md, section 1; docs/design.md, "rigid/").
//
// For small motions about an equilibrium every displacement is linear in the
// generalised coordinates q (n of them). Each body b has a translational
// Jacobian T_b (velocity of its c.g. = T_b q') and a rotational one R_b
// (angular velocity = R_b q'), both 3 x n in the fixed axes X, Y, Z:
//     M = sum_b m_b T_b^T T_b + R_b^T I_b R_b                      (1.1)
// A point p has a displacement Jacobian J_p (delta_p = J_p q); on a rigid
// body J_p = T_b - [r_p]x R_b (1.2). A spring-damper e acts along a unit
// direction n_e from point a to point b, or from the ground to point a; its
// elongation is G_e q with G_e = n_e^T (J_b - J_a), or G_e = n_e^T J_a for a
// grounded element (1.3), and
//     K = sum_e k_e G_e^T G_e,   C = sum_e c_e G_e^T G_e           (1.4)
// so M, K and C are symmetric by construction. Reference ground inputs
// (the other end of a grounded element moving by xr(t) along n_e) load the
// system with FK = sum k_e G_e^T xr_e(t), FC = sum c_e G_e^T vr_e(t) (1.5);
// an external force F at a point gives Q = J_p^T F (1.6).
// The 2-D model is the same assembly with Y-motions absent (its coordinates
// never produce them); the 3-D model uses all three axes.
#pragma once

#include <Eigen/Dense>

#include <string>
#include <vector>

#include "core/units.h"

namespace framedyn::rigid {

using Jacobian = Eigen::Matrix<double, 3, Eigen::Dynamic>;  // 3 x n

struct Body {
  std::string name;
  double mass = 0.0;                                   // kg
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();   // kg m^2 about the c.g., fixed axes
  Jacobian translation;                                // T_b
  Jacobian rotation;                                   // R_b
};

// A point's displacement Jacobian J_p.
struct Point {
  std::string name;
  Jacobian displacement;
};

// A linear spring and a linear damper in parallel along `direction`, from
// point a to point b: elongation = n . (d_b - d_a). `b < 0` means the ground,
// and then the element runs from the ground to point a (n points from the
// ground towards a): elongation = n . (d_a - d_ground), with d_ground = xr(t) n
// for a moving ground reference, so that FK = k G^T xr (1.5). Element forces
// -k * elongation are then compression positive for every element.
struct SpringDamper {
  std::string name;
  int point_a = -1;
  int point_b = -1;                     // -1: the ground
  Eigen::Vector3d direction{0, 0, 1};   // unit
  double stiffness = 0.0;               // N/m
  double damping = 0.0;                 // N s/m
};

// The assembled model: what the integrators and modal analysis work with.
class Multibody {
 public:
  // Each coordinate by name (the thesis's symbol) and what it measures: a
  // translation (Quantity::length) or a rotation (Quantity::angle), so that
  // every output gives it its unit from this table, never from its name.
  Multibody(std::vector<std::string> coordinate_names, std::vector<core::Quantity> coordinate_quantities);

  int size() const { return static_cast<int>(names_.size()); }
  const std::vector<std::string>& coordinate_names() const { return names_; }
  const std::vector<core::Quantity>& coordinate_quantities() const { return quantities_; }

  int add_body(Body body);
  int add_point(Point point);
  int add_element(SpringDamper element);
  // Point on a body at `offset` from its c.g. (fixed axes): J = T - [r]x R.
  int add_body_point(const std::string& name, int body, const Eigen::Vector3d& offset);

  const std::vector<Body>& bodies() const { return bodies_; }
  const std::vector<Point>& points() const { return points_; }
  const std::vector<SpringDamper>& elements() const { return elements_; }
  SpringDamper& element(int index) { return elements_.at(static_cast<std::size_t>(index)); }
  int element_index(const std::string& name) const;  // -1 if none
  int point_index(const std::string& name) const;

  // G_e: the 1 x n map from q to the element's elongation.
  Eigen::RowVectorXd elongation_map(int element) const;

  Eigen::MatrixXd mass_matrix() const;
  Eigen::MatrixXd stiffness_matrix() const;
  Eigen::MatrixXd damping_matrix() const;
  // Generalised force of a force vector F (N, fixed axes) applied at a point.
  Eigen::VectorXd generalized_force(int point, const Eigen::Vector3d& force) const;

 private:
  std::vector<std::string> names_;
  std::vector<core::Quantity> quantities_;
  std::vector<Body> bodies_;
  std::vector<Point> points_;
  std::vector<SpringDamper> elements_;
};

// Checks M positive definite and K, C positive semi-definite; throws
// core::NumericalError naming the coordinate or body at fault otherwise.
void check_definiteness(const Multibody& model);

// Skew matrix [r]x with [r]x v = r x v.
Eigen::Matrix3d skew(const Eigen::Vector3d& r);

}  // namespace framedyn::rigid
