// Sparse Cholesky factorisation of a symmetric positive definite matrix
// given by its lower triangle, on CHOLMOD (fill-reducing ordering; CHOLMOD chooses a simplicial LDL^T
// or a supernodal LL^T factor by the density of the factor). Kept behind this small class so that only one source file sees
// CHOLMOD, and so that a failed factorisation can say which equation failed.
#pragma once

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <memory>

namespace framedyn::fem {

class SparseCholesky {
 public:
  SparseCholesky();
  ~SparseCholesky();
  SparseCholesky(const SparseCholesky&) = delete;
  SparseCholesky& operator=(const SparseCholesky&) = delete;

  // Factorises A (lower triangle of a compressed column-major matrix).
  // Returns false if A is not positive definite; then failed_equation()
  // names the (original) equation at which the factorisation stopped.
  bool factorize(const Eigen::SparseMatrix<double, Eigen::ColMajor, int>& lower);
  int failed_equation() const { return failed_equation_; }
  // min(diag L)^2 / max(diag L)^2: CHOLMOD's cheap reciprocal condition estimate.
  double reciprocal_condition() const;
  Eigen::VectorXd solve(const Eigen::Ref<const Eigen::VectorXd>& b) const;
  // x = A^{-1} b; b and x may not overlap. Reuses the solver's buffers:
  // not for concurrent calls on one object.
  void solve_in_place(const double* b, double* x) const;
  Eigen::Index size() const { return size_; }

  // The factor as A = P^T L L^T P: L lower triangular (a copy, in LL^T form)
  // and the permutation (perm[i] = original index of the i-th pivot).
  struct ExplicitFactor {
    Eigen::SparseMatrix<double, Eigen::ColMajor, int> lower;
    Eigen::VectorXi perm;
  };
  ExplicitFactor explicit_factor() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  int failed_equation_ = -1;
  Eigen::Index size_ = 0;
};

// Inertia of a symmetric, possibly indefinite matrix (lower triangle): the
// signs of the pivots of A = P^T L D L^T P (CHOLMOD's simplicial LDL^T, no
// pivoting; by Sylvester's law of inertia D has as many negative entries as
// A has negative eigenvalues). `breakdown` is set when a pivot was zero or
// not finite: the counts are then not to be trusted and the caller perturbs A.
struct Inertia {
  long negative = 0;
  long positive = 0;
  bool breakdown = false;
};
Inertia ldlt_inertia(const Eigen::SparseMatrix<double, Eigen::ColMajor, int>& lower);

}  // namespace framedyn::fem
