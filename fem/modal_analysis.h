// Natural frequencies and mass-normalised mode shapes of a frame: the lowest
// N eigenpairs of K phi = lambda M phi by Spectra's shift-invert Lanczos on a
// sparse Cholesky factorisation of K - sigma M (sigma < 0, so the factored
// matrix is positive definite even for a free-free frame, whose six rigid-body
// modes come out at zero frequency). Participation factors and effective
// modal masses per direction. Theory: docs/theory/fem.md, "Modes".
#pragma once

#include <Eigen/Dense>

#include <functional>
#include <string>
#include <vector>

#include "fem/assembly.h"

namespace framedyn::fem {

using Vector6d = Eigen::Matrix<double, 6, 1>;

enum class Factorization {
  cholmod,                // CHOLMOD supernodal LL^T (the default)
  eigen_simplicial_ldlt,  // Eigen's SimplicialLDLT (a baseline for benchmarks)
};

struct EigenOptions {
  int count = 10;
  double shift = -1.0;     // sigma, rad^2/s^2; must be negative
  double tolerance = 1e-10;
  int max_iterations = 1000;
  int subspace = 0;        // Lanczos basis size (ncv); 0 picks one from `count`
  Factorization factorization = Factorization::cholmod;
  std::function<void(const std::string&)> progress;  // optional stage messages
  // Optional: names equation i of K and M ("node 12, UY"), for the messages
  // of a failed factorisation.
  std::function<std::string(int)> describe_equation;
};

struct EigenSolution {
  Eigen::VectorXd eigenvalues;   // ascending, rad^2/s^2
  Eigen::MatrixXd vectors;       // M-orthonormal columns on the free DOFs
  int iterations = 0;            // restarts of the Lanczos process
  int operator_solves = 0;       // solves with the factorisation
};

// Lowest eigenpairs of (K, M) given as lower triangles. Throws NumericalError
// when the factorisation fails (K - sigma M not positive definite) or the
// iteration does not converge (non_convergence_message).
EigenSolution lowest_eigenpairs(const SparseMatrix& stiffness, const SparseMatrix& mass, const EigenOptions& options);

// What lowest_eigenpairs says when the Lanczos iteration stops before all
// `wanted` modes have converged: how far it got and what to try.
std::string non_convergence_message(long converged, long wanted, long subspace, long equations, const EigenOptions& options);

struct ModalOptions {
  int mode_count = 10;
  MassFormulation mass = MassFormulation::consistent;
  double shift_hz = 1.0;   // sigma = -(2 pi shift_hz)^2
  Eigen::Vector3d reference_point = Eigen::Vector3d::Zero();  // for rotational participation
  Factorization factorization = Factorization::cholmod;
  std::function<void(const std::string&)> progress;
};

struct Mode {
  double eigenvalue = 0.0;      // omega^2, rad^2/s^2
  double frequency_hz = 0.0;    // 0 for rigid-body modes
  bool rigid_body = false;
  Vector6d participation;       // Gamma_d = phi^T M r_d, d = x, y, z, rx, ry, rz
  Vector6d effective_mass;      // Gamma_d^2 (kg; kg m^2 for rotations)
};

struct ModalResult {
  std::vector<Mode> modes;
  Eigen::MatrixXd shapes;       // dof_count x modes, zero at constrained DOFs, M-normalised
  Vector6d total_mass;          // r_d^T M r_d on the free DOFs (what the effective masses sum to)
  int free_dofs = 0;
  int rigid_body_modes_expected = 0;  // 6 for a frame with no supports, else 0
  int iterations = 0;
  int operator_solves = 0;
};

// Assembles, solves and post-processes. Throws NumericalError for a massless
// DOF, a mechanism (zero-frequency modes that are not rigid-body motions) or
// a solve that did not converge, each with what to check.
ModalResult compute_modes(const FrameModel& model, const ModalOptions& options = {});

}  // namespace framedyn::fem
