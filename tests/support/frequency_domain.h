// The direct frequency-domain solve of a frame, the reference the modal
// frequency-response tests compare with.
#pragma once

#include <Eigen/Dense>

#include <complex>

#include "fem/modal_transient.h"

namespace framedyn::testing {

// (K - omega^2 M + i omega (alpha M + beta K)) u = F on the free DOFs by
// sparse LU (Rayleigh damping: a matrix, and diagonal in the modes); u on all
// DOFs, zero at the constrained ones. F on all DOFs. omega > 0 for a frame
// free to move rigidly (its rigid motions are then finite too). Throws
// std::runtime_error if the factorisation fails.
Eigen::VectorXcd direct_frequency_solve(const fem::FrameDynamics& frame, const Eigen::VectorXd& load, double omega, double alpha, double beta);

}  // namespace framedyn::testing
