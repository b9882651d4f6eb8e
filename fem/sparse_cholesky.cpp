// CHOLMOD behind a narrow interface (see sparse_cholesky.h).
#include "fem/sparse_cholesky.h"

#include "fem/solver_counters.h"

#include <cholmod.h>

#include <cmath>
#include <cstring>
#include <stdexcept>

namespace framedyn::fem {

struct SparseCholesky::Impl {
  mutable cholmod_common common;
  cholmod_factor* factor = nullptr;
  // Solution and workspace reused by every solve (cholmod_solve2): a Lanczos
  // run solves some tens of times, and fresh 8 MB buffers per solve at 10^6
  // DOF cost more in page faults than the triangular solves themselves.
  mutable cholmod_dense* x = nullptr;
  mutable cholmod_dense* y = nullptr;
  mutable cholmod_dense* e = nullptr;
  Impl() {
    cholmod_start(&common);
    common.print = 0;  // CHOLMOD would print warnings on stdout
    // Beam frames fill in little: CHOLMOD's automatic choice (simplicial
    // LDL^T for such sparse factors) factorises and, above all, solves faster
    // than a supernodal LL^T (measured: 26 ms against 59 ms per solve at 10^6 DOF).
    common.supernodal = CHOLMOD_AUTO;
  }
  ~Impl() {
    if (x) cholmod_free_dense(&x, &common);
    if (y) cholmod_free_dense(&y, &common);
    if (e) cholmod_free_dense(&e, &common);
    if (factor) cholmod_free_factor(&factor, &common);
    cholmod_finish(&common);
  }
};

SparseCholesky::SparseCholesky() : impl_(std::make_unique<Impl>()) {}
SparseCholesky::~SparseCholesky() = default;

bool SparseCholesky::factorize(const Eigen::SparseMatrix<double, Eigen::ColMajor, int>& lower) {
  if (!lower.isCompressed()) throw std::invalid_argument("SparseCholesky: matrix must be compressed");
  internal::count_factorisation();
  cholmod_sparse a{};
  a.nrow = static_cast<size_t>(lower.rows());
  a.ncol = static_cast<size_t>(lower.cols());
  a.nzmax = static_cast<size_t>(lower.nonZeros());
  a.p = const_cast<int*>(lower.outerIndexPtr());
  a.i = const_cast<int*>(lower.innerIndexPtr());
  a.x = const_cast<double*>(lower.valuePtr());
  a.stype = -1;  // lower triangle stored
  a.itype = CHOLMOD_INT;
  a.xtype = CHOLMOD_REAL;
  a.dtype = CHOLMOD_DOUBLE;
  a.sorted = 1;
  a.packed = 1;
  cholmod_common& c = impl_->common;
  if (impl_->factor) cholmod_free_factor(&impl_->factor, &c);
  impl_->factor = cholmod_analyze(&a, &c);
  if (!impl_->factor) throw std::runtime_error("CHOLMOD analysis failed (out of memory?)");
  cholmod_factorize(&a, impl_->factor, &c);
  size_ = lower.rows();
  failed_equation_ = -1;
  if (c.status == CHOLMOD_NOT_POSDEF || impl_->factor->minor < impl_->factor->n) {
    const size_t minor = impl_->factor->minor;
    const int* perm = static_cast<const int*>(impl_->factor->Perm);
    failed_equation_ = (perm && minor < impl_->factor->n) ? perm[minor] : static_cast<int>(minor);
    return false;
  }
  if (c.status < CHOLMOD_OK) throw std::runtime_error("CHOLMOD factorisation failed (out of memory?)");
  // A simplicial LDL^T factor of an indefinite matrix does not fail: check
  // that every pivot D_jj (the first entry of column j) is positive.
  const cholmod_factor* f = impl_->factor;
  if (!f->is_super && !f->is_ll) {
    const int* lp = static_cast<const int*>(f->p);
    const double* lx = static_cast<const double*>(f->x);
    const int* perm = static_cast<const int*>(f->Perm);
    for (size_t j = 0; j < f->n; ++j)
      if (!(lx[lp[j]] > 0.0)) {
        failed_equation_ = perm ? perm[j] : static_cast<int>(j);
        return false;
      }
  }
  return true;
}

double SparseCholesky::reciprocal_condition() const {
  if (!impl_->factor) return 0.0;
  return cholmod_rcond(impl_->factor, &impl_->common);
}

void SparseCholesky::solve_in_place(const double* b, double* x) const {
  cholmod_dense rhs{};
  rhs.nrow = static_cast<size_t>(size_);
  rhs.ncol = 1;
  rhs.nzmax = static_cast<size_t>(size_);
  rhs.d = static_cast<size_t>(size_);
  rhs.x = const_cast<double*>(b);
  rhs.xtype = CHOLMOD_REAL;
  rhs.dtype = CHOLMOD_DOUBLE;
  if (!cholmod_solve2(CHOLMOD_A, impl_->factor, &rhs, nullptr, &impl_->x, nullptr, &impl_->y, &impl_->e, &impl_->common))
    throw std::runtime_error("CHOLMOD solve failed");
  std::memcpy(x, impl_->x->x, sizeof(double) * static_cast<size_t>(size_));
}

Eigen::VectorXd SparseCholesky::solve(const Eigen::Ref<const Eigen::VectorXd>& b) const {
  Eigen::VectorXd x(b.size());
  solve_in_place(b.data(), x.data());  // Ref<const VectorXd> is contiguous
  return x;
}

SparseCholesky::ExplicitFactor SparseCholesky::explicit_factor() const {
  if (!impl_->factor) throw std::logic_error("SparseCholesky: no factor");
  cholmod_common& c = impl_->common;
  cholmod_factor* copy = cholmod_copy_factor(impl_->factor, &c);
  if (!copy) throw std::runtime_error("CHOLMOD: cannot copy the factor (out of memory?)");
  // To a simplicial, packed, monotonic LL^T factor, then to a sparse matrix.
  cholmod_change_factor(CHOLMOD_REAL, 1, 0, 1, 1, copy, &c);
  cholmod_sparse* l = cholmod_factor_to_sparse(copy, &c);
  ExplicitFactor out;
  const int n = static_cast<int>(impl_->factor->n);
  out.perm.resize(n);
  const int* perm = static_cast<const int*>(impl_->factor->Perm);
  for (int i = 0; i < n; ++i) out.perm(i) = perm ? perm[i] : i;
  if (!l || l->itype != CHOLMOD_INT) {
    cholmod_free_factor(&copy, &c);
    throw std::runtime_error("CHOLMOD: cannot convert the factor (out of memory?)");
  }
  const int* lp = static_cast<const int*>(l->p);
  const int* li = static_cast<const int*>(l->i);
  const double* lx = static_cast<const double*>(l->x);
  out.lower = Eigen::Map<const Eigen::SparseMatrix<double, Eigen::ColMajor, int>>(n, n, lp[n], lp, li, lx);
  cholmod_free_sparse(&l, &c);
  cholmod_free_factor(&copy, &c);
  return out;
}

Inertia ldlt_inertia(const Eigen::SparseMatrix<double, Eigen::ColMajor, int>& lower) {
  if (!lower.isCompressed()) throw std::invalid_argument("ldlt_inertia: matrix must be compressed");
  internal::count_factorisation();
  cholmod_common c;
  cholmod_start(&c);
  c.print = 0;
  // Simplicial LDL^T, kept as LDL^T: a supernodal or LL^T factor stops at
  // the first negative pivot.
  c.supernodal = CHOLMOD_SIMPLICIAL;
  c.final_ll = 0;
  c.final_asis = 1;
  cholmod_sparse a{};
  a.nrow = static_cast<size_t>(lower.rows());
  a.ncol = static_cast<size_t>(lower.cols());
  a.nzmax = static_cast<size_t>(lower.nonZeros());
  a.p = const_cast<int*>(lower.outerIndexPtr());
  a.i = const_cast<int*>(lower.innerIndexPtr());
  a.x = const_cast<double*>(lower.valuePtr());
  a.stype = -1;
  a.itype = CHOLMOD_INT;
  a.xtype = CHOLMOD_REAL;
  a.dtype = CHOLMOD_DOUBLE;
  a.sorted = 1;
  a.packed = 1;
  Inertia out;
  cholmod_factor* f = cholmod_analyze(&a, &c);
  if (!f) {
    cholmod_finish(&c);
    throw std::runtime_error("CHOLMOD analysis failed (out of memory?)");
  }
  cholmod_factorize(&a, f, &c);
  if (c.status < CHOLMOD_OK) {
    cholmod_free_factor(&f, &c);
    cholmod_finish(&c);
    throw std::runtime_error("CHOLMOD LDL^T factorisation failed (out of memory?)");
  }
  // CHOLMOD stops at a zero pivot (status CHOLMOD_NOT_POSDEF, minor < n).
  out.breakdown = c.status == CHOLMOD_NOT_POSDEF || f->minor < f->n || f->is_ll || f->is_super;
  if (!out.breakdown) {
    const int* lp = static_cast<const int*>(f->p);
    const double* lx = static_cast<const double*>(f->x);
    for (size_t j = 0; j < f->n; ++j) {
      const double d = lx[lp[j]];  // D_jj: the first entry of column j
      if (!std::isfinite(d) || d == 0.0) {
        out.breakdown = true;
        break;
      }
      if (d < 0.0) ++out.negative;
      else ++out.positive;
    }
  }
  cholmod_free_factor(&f, &c);
  cholmod_finish(&c);
  return out;
}

}  // namespace framedyn::fem
