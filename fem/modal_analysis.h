// Natural frequencies and mass-normalised mode shapes of a frame: the lowest
// N eigenpairs of K phi = lambda M phi by Spectra's shift-invert Lanczos on a
// sparse Cholesky factorisation of K - sigma M (sigma < 0, so the factored
// matrix is positive definite even when K is singular). The rigid-body
// motions the supports leave free are computed from geometry
// (fem/rigid_body_modes.h) and deflated: they are exact zero modes, and the
// Lanczos iteration works on the M-orthogonal complement. Every set is
// certified by a Sturm sequence count: the inertia of K - s M = L D L^T
// (negative pivots = eigenvalues below s), with s in the gap above the
// highest returned eigenvalue; roots the iteration missed (a copy of a
// repeated root) are recovered by a further Lanczos run deflated against the
// pairs already found. Participation factors include the consistent-mass
// coupling to the supports; effective masses are fractions of the model's
// total mass. Theory: docs/theory/fem.md, "Modes" (Eqs. 7.1 to 7.5).
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
  // Optional: n x p, independent vectors with K v = 0 (the free rigid-body
  // motions). They are M-orthonormalised, returned as eigenvalue 0 (counted
  // in `count`), and deflated from the Lanczos iteration.
  Eigen::MatrixXd null_space;
  // Check the set with a Sturm count and recover missed roots (Eq. 7.3).
  bool certify = true;
  int certification_rounds = 4;  // Lanczos runs at most (the first and the recoveries)
};

struct EigenSolution {
  Eigen::VectorXd eigenvalues;   // ascending, rad^2/s^2
  Eigen::MatrixXd vectors;       // M-orthonormal columns on the free DOFs
  int iterations = 0;            // restarts of the Lanczos process (all runs)
  int operator_solves = 0;       // solves with the factorisation
  std::vector<char> null_space;  // per returned pair: 1 if it is one of EigenOptions::null_space's vectors
  // Certification (Eq. 7.3): the number of eigenvalues below sturm_shift,
  // counted from the inertia of K - sturm_shift M; certified when it equals
  // the number of pairs found below it. -1 when not checked.
  long sturm_count = -1;
  double sturm_shift = 0.0;      // rad^2/s^2
  bool certified = false;
  int lanczos_runs = 0;          // 1 + recoveries
  int sturm_factorizations = 0;  // LDL^T factorisations (more than the checks when a pivot vanished)
  double sturm_seconds = 0.0;    // wall time of the Sturm counts
  std::string certification_failure;  // why the set is not certified ("" when it is or was not checked)
};

// Lowest eigenpairs of (K, M) given as lower triangles. Throws NumericalError
// when the factorisation fails (K - sigma M not positive definite) or the
// iteration does not converge (non_convergence_message). A set that could not
// be certified comes back with certified = false and certification_failure
// set (the caller decides: compute_modes throws).
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
  bool certify = true;     // off only to measure the Sturm check's cost
  std::function<void(const std::string&)> progress;
};

struct Mode {
  double eigenvalue = 0.0;      // omega^2, rad^2/s^2
  double frequency_hz = 0.0;    // 0 for rigid-body modes
  bool rigid_body = false;
  // Gamma_d = phi_f^T (M_ff r_f + M_fs r_s), d = x, y, z, rx, ry, rz: the
  // modal force of a unit rigid acceleration of the whole model, supports
  // included (Eq. 7.4).
  Vector6d participation;
  Vector6d effective_mass;      // Gamma_d^2 (kg; kg m^2 for rotations)
};

struct ModalResult {
  std::vector<Mode> modes;
  Eigen::MatrixXd shapes;       // dof_count x modes, zero at constrained DOFs, M-normalised
  // r_d^T M r_d over ALL DOFs, supported ones included: the model's mass in
  // x, y, z (kg) and its rotary inertia about the reference point (kg m^2);
  // effective-mass fractions are of these.
  Vector6d total_mass;
  // r_f^T M_ff r_f: the part of it carried by the free DOFs.
  Vector6d free_mass;
  int free_dofs = 0;
  int rigid_body_modes_expected = 0;  // free rigid motions left by the supports and springs (rigid_body_modes.h)
  int parts = 0;                      // connected parts of the mesh
  int iterations = 0;
  int operator_solves = 0;
  // Certification (Eq. 7.3): eigenvalues below sturm_shift by the Sturm count.
  long sturm_count = -1;
  double sturm_shift_hz = 0.0;        // sqrt(sturm_shift) / 2 pi
  bool certified = false;
  int lanczos_runs = 0;
  double sturm_seconds = 0.0;
};

// Assembles, solves and post-processes. Throws NumericalError for a massless
// DOF, a mechanism (a mode below shift_hz / 100 that is not a free rigid
// motion), a solve that did not converge or a set that could not be
// certified, each with what to check.
ModalResult compute_modes(const FrameModel& model, const ModalOptions& options = {});
// The same on K and M already assembled (lower triangles on `dofs`, with
// options.mass's formulation): a caller that holds the assembled frame
// (fem::FrameDynamics) does not assemble it again. The shift-invert Lanczos
// still factorises K - sigma M (and M): matrices other than K, which a static
// solve's factor cannot stand in for (sigma < 0 keeps the free-free K - sigma M
// positive definite).
ModalResult compute_modes(const FrameModel& model, const DofMap& dofs, const FreeSystem& sys, const ModalOptions& options = {});

}  // namespace framedyn::fem
