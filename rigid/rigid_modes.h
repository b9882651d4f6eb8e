// Undamped natural frequencies and mode shapes of a rigid-body vehicle
// model, K phi = omega^2 M phi (dense; at most a few tens of coordinates),
// with the dominant coordinate of each mode named as the thesis does in its
// Tables IV and V. docs/theory/rigid.md, section 5.
#pragma once

#include <Eigen/Dense>

#include <string>
#include <vector>

namespace framedyn::rigid {

struct RigidMode {
  double frequency_hz = 0.0;
  std::string dominant;             // the coordinate with the largest share of the mode's kinetic energy
  Eigen::VectorXd shape;            // M-normalised, all coordinates (zero where fixed)
  Eigen::VectorXd energy_share;     // phi_j (M phi)_j, summing to 1 over the coordinates
};

// Modes with the coordinates listed in `fixed` held (the thesis isolates one
// freedom this way for the Appendix G checks). Throws core::NumericalError
// if M restricted to the free coordinates is not positive definite.
std::vector<RigidMode> rigid_modes(const Eigen::MatrixXd& mass, const Eigen::MatrixXd& stiffness,
                                   const std::vector<std::string>& names, const std::vector<std::string>& fixed = {});

}  // namespace framedyn::rigid
