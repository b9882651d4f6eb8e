// Shift-invert Lanczos (Spectra) on a CHOLMOD factorisation; see modal_analysis.h.
#include "fem/modal_analysis.h"

#include <Eigen/SparseCholesky>
#include <Spectra/SymEigsSolver.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <numeric>
#include <thread>

#include "core/error.h"
#include "fem/sparse_cholesky.h"

namespace framedyn::fem {

namespace {

constexpr double kTwoPi = 6.283185307179586;

bool factorize(SparseCholesky& s, const SparseMatrix& a) { return s.factorize(a); }
bool factorize(Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower>& s, const SparseMatrix& a) {
  s.compute(a);
  return s.info() == Eigen::Success;
}
int failed_equation(const SparseCholesky& s) { return s.failed_equation(); }
int failed_equation(const Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower>&) { return -1; }
void solve_into(const SparseCholesky& s, const Eigen::VectorXd& b, Eigen::VectorXd& x) { s.solve_in_place(b.data(), x.data()); }
void solve_into(const Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower>& s, const Eigen::VectorXd& b, Eigen::VectorXd& x) {
  x = s.solve(b);
}

// The mass matrix as M = S S^T, S = P^T L (L lower triangular, P a
// permutation with (P v)_i = v_perm[i]).
struct MassFactor {
  SparseMatrix lower;
  Eigen::VectorXi perm;
};

// " at node 12, UY" for equation i, or "" without a describer.
std::string at_equation(const EigenOptions& o, int i) {
  if (!o.describe_equation || i < 0) return "";
  return " at " + o.describe_equation(i);
}

MassFactor mass_factor(const SparseMatrix& m, const SparseCholesky&, const EigenOptions& o) {
  SparseCholesky chol;
  if (!chol.factorize(m))
    throw core::NumericalError(fmt::format(
        "the mass matrix is not positive definite: the factorisation stopped{} (a negative density or point mass "
        "there, or a rotation with no rotary inertia?)", at_equation(o, chol.failed_equation())));
  SparseCholesky::ExplicitFactor f = chol.explicit_factor();
  return {std::move(f.lower), std::move(f.perm)};
}

MassFactor mass_factor(const SparseMatrix& m, const Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower>&, const EigenOptions&) {
  Eigen::SimplicialLLT<SparseMatrix, Eigen::Lower> llt(m);
  if (llt.info() != Eigen::Success)
    throw core::NumericalError("the mass matrix is not positive definite (a negative density or point mass?)");
  MassFactor f;
  f.lower = llt.matrixL();
  // Eigen's P moves entry i to indices(i); ours reads perm[i] into i.
  const Eigen::VectorXi& to = llt.permutationP().indices();
  f.perm.resize(to.size());
  for (Eigen::Index i = 0; i < to.size(); ++i) f.perm(to(i)) = static_cast<int>(i);
  return f;
}

// The shift-invert operator in standard form. With M = S S^T and
// A = K - sigma M, the generalised problem K phi = lambda M phi becomes
//     C y = nu y,   C = S^T A^{-1} S,   nu = 1 / (lambda - sigma),   phi = S^{-T} y,
// a symmetric standard problem: Spectra's Lanczos then needs no M-inner
// products (which cost a sparse product each, five to eight per step).
template <class Solver>
class StandardFormOperator {
 public:
  using Scalar = double;
  StandardFormOperator(const Solver& solver, const MassFactor& mass)
      : solver_(solver), mass_(mass), a_(mass.lower.rows()), b_(mass.lower.rows()) {}
  Eigen::Index rows() const { return mass_.lower.rows(); }
  Eigen::Index cols() const { return mass_.lower.rows(); }
  void perform_op(const Scalar* x, Scalar* y) const {
    const Eigen::Index n = rows();
    Eigen::Map<const Eigen::VectorXd> in(x, n);
    Eigen::Map<Eigen::VectorXd> out(y, n);
    a_.noalias() = mass_.lower * in;                           // L x
    for (Eigen::Index i = 0; i < n; ++i) b_(mass_.perm(i)) = a_(i);  // S x = P^T L x
    solve_into(solver_, b_, a_);                                 // A^{-1} S x
    for (Eigen::Index i = 0; i < n; ++i) b_(i) = a_(mass_.perm(i));  // P ...
    out.noalias() = mass_.lower.transpose() * b_;               // S^T ... = L^T P ...
    ++solves_;
  }
  // phi = S^{-T} y = P^T L^{-T} y.
  Eigen::VectorXd back_transform(const Eigen::VectorXd& y) const {
    const Eigen::VectorXd u = mass_.lower.transpose().triangularView<Eigen::Upper>().solve(y);
    Eigen::VectorXd phi(u.size());
    for (Eigen::Index i = 0; i < u.size(); ++i) phi(mass_.perm(i)) = u(i);
    return phi;
  }
  int solves() const { return solves_; }

 private:
  const Solver& solver_;
  const MassFactor& mass_;
  mutable Eigen::VectorXd a_, b_;
  mutable int solves_ = 0;
};

template <class Solver>
EigenSolution solve_with(Solver& solver, const SparseMatrix& k, const SparseMatrix& m, const EigenOptions& o) {
  const Eigen::Index n = k.rows();
  const Eigen::Index nev = std::min<Eigen::Index>(o.count, n - 1);
  const Eigen::Index ncv = std::min<Eigen::Index>(
      n, o.subspace > nev ? o.subspace : std::max<Eigen::Index>(2 * nev + 1, nev + 20));
  if (o.progress) o.progress(fmt::format("factorising K - sigma M and M ({} equations)", n));
  // The two factorisations are independent: M's on a second thread.
  MassFactor mass;
  std::exception_ptr mass_error;
  std::thread mass_thread([&] {
    try {
      mass = mass_factor(m, solver, o);
    } catch (...) {
      mass_error = std::current_exception();
    }
  });
  const SparseMatrix a = (k - o.shift * m).pruned();
  const bool factorized = factorize(solver, a);
  mass_thread.join();
  if (mass_error) std::rethrow_exception(mass_error);
  if (!factorized)
    throw core::NumericalError(fmt::format(
        "the factorisation of K - sigma M failed{}: the stiffness matrix is not positive semi-definite "
        "or the mass matrix is not positive definite (check for a massless degree of freedom, a negative "
        "stiffness or density)", at_equation(o, failed_equation(solver))));
  using Op = StandardFormOperator<Solver>;
  Op op(solver, mass);
  Spectra::SymEigsSolver<Op> eigs(op, nev, ncv);
  if (o.progress) o.progress(fmt::format("Lanczos iteration for {} modes (subspace {})", nev, ncv));
  eigs.init();
  const Eigen::Index converged = eigs.compute(Spectra::SortRule::LargestAlge, o.max_iterations, o.tolerance);
  if (eigs.info() != Spectra::CompInfo::Successful)
    throw core::NumericalError(non_convergence_message(converged, nev, ncv, n, o));
  EigenSolution s;
  const Eigen::VectorXd nu = eigs.eigenvalues();
  const Eigen::MatrixXd y = eigs.eigenvectors();
  // lambda = sigma + 1/nu: the largest nu are the lowest lambda, in order.
  s.eigenvalues.resize(nu.size());
  s.vectors.resize(n, nu.size());
  for (Eigen::Index i = 0; i < nu.size(); ++i) {
    s.eigenvalues(i) = o.shift + 1.0 / nu(i);
    Eigen::VectorXd v = op.back_transform(y.col(i));
    // Deterministic sign: the largest component positive.
    Eigen::Index imax = 0;
    v.cwiseAbs().maxCoeff(&imax);
    if (v(imax) < 0) v = -v;
    s.vectors.col(i) = v;
  }
  s.iterations = static_cast<int>(eigs.num_iterations());
  s.operator_solves = op.solves();
  return s;
}

}  // namespace

std::string non_convergence_message(long converged, long wanted, long subspace, long equations, const EigenOptions& o) {
  return fmt::format(
      "the eigensolver did not converge: {} of {} modes reached the tolerance {:g} within the limit of {} restarts of "
      "the Lanczos iteration (subspace of {} vectors, {} equations). Try: ask for a few more modes than you need (the "
      "subspace grows with them, and the wanted modes converge faster), a shift nearer the wanted frequencies "
      "(framedyn modes --shift HZ; now {:g} Hz below zero), or fewer modes; near-duplicate frequencies (a symmetric "
      "frame) and a mesh with elements of very different stiffness slow the iteration",
      converged, wanted, o.tolerance, o.max_iterations, subspace, equations, std::sqrt(-o.shift) / kTwoPi);
}

EigenSolution lowest_eigenpairs(const SparseMatrix& k, const SparseMatrix& m, const EigenOptions& o) {
  if (!(o.shift < 0.0)) throw std::invalid_argument("the shift must be negative");
  if (k.rows() < 2) throw std::invalid_argument("the model has fewer than two free degrees of freedom");
  if (o.factorization == Factorization::cholmod) {
    // sigma < 0 and M > 0 make K - sigma M positive definite: supernodal LL^T is safe.
    SparseCholesky solver;
    return solve_with(solver, k, m, o);
  }
  Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower> solver;
  return solve_with(solver, k, m, o);
}

namespace {

// Largest K_ii / M_ii: a lower bound on the largest eigenvalue, the scale of
// the round-off in every computed eigenvalue.
double eigenvalue_scale(const SparseMatrix& k, const SparseMatrix& m) {
  const Eigen::VectorXd kd = k.diagonal(), md = m.diagonal();
  double s = 0.0;
  for (Eigen::Index i = 0; i < kd.size(); ++i)
    if (md(i) > 0.0) s = std::max(s, kd(i) / md(i));
  return s;
}

std::string largest_motion_nodes(const FrameModel& model, const DofMap& dofs, const Eigen::VectorXd& shape) {
  std::vector<std::pair<double, int>> amp(model.nodes.size(), {0.0, 0});
  for (std::size_t i = 0; i < model.nodes.size(); ++i) amp[i].second = model.nodes[i].id;
  for (int e = 0; e < dofs.free_count(); ++e) {
    const int g = dofs.free_dofs[static_cast<std::size_t>(e)];
    amp[static_cast<std::size_t>(g / kDofsPerNode)].first += shape(e) * shape(e);
  }
  std::stable_sort(amp.begin(), amp.end(), [](auto& a, auto& b) { return a.first > b.first; });
  std::string out;
  for (std::size_t i = 0; i < std::min<std::size_t>(5, amp.size()); ++i) out += (i ? ", " : "") + std::to_string(amp[i].second);
  return out;
}

}  // namespace

ModalResult compute_modes(const FrameModel& model, const ModalOptions& options) {
  if (options.mode_count < 1) throw std::invalid_argument("the number of modes must be at least 1");
  const DofMap dofs = make_dof_map(model);
  if (options.progress) options.progress(fmt::format("assembling {} beam elements ({} free DOFs)", model.beams.size(), dofs.free_count()));
  FreeSystem sys = assemble(model, dofs, {options.mass, Storage::lower});

  const std::vector<int> massless = massless_dofs(model, dofs, sys.mass);
  if (!massless.empty()) {
    std::string list;
    for (std::size_t i = 0; i < std::min<std::size_t>(6, massless.size()); ++i) list += (i ? ", " : "") + model.describe_dof(massless[i]);
    throw core::NumericalError(fmt::format(
        "{} degree(s) of freedom have no mass, e.g. {}: the mass matrix is singular. Give the elements "
        "there a density (*DENSITY) or add a point mass, or fix those DOFs", massless.size(), list));
  }
  if (options.mode_count >= dofs.free_count())
    throw std::invalid_argument(fmt::format("{} modes asked for but the model has only {} free DOFs", options.mode_count, dofs.free_count()));

  EigenOptions eo;
  eo.count = options.mode_count;
  eo.shift = -std::pow(kTwoPi * options.shift_hz, 2);
  eo.factorization = options.factorization;
  eo.progress = options.progress;
  eo.describe_equation = [&](int e) { return model.describe_dof(dofs.free_dofs[static_cast<std::size_t>(e)]); };
  EigenSolution es = lowest_eigenpairs(sys.stiffness, sys.mass, eo);
  if (options.progress) options.progress("participation factors and effective masses");

  ModalResult result;
  result.free_dofs = dofs.free_count();
  result.iterations = es.iterations;
  result.operator_solves = es.operator_solves;
  bool grounded = !model.constraints.empty();
  for (const Spring& s : model.springs) grounded = grounded || s.node_b < 0;
  result.rigid_body_modes_expected = grounded ? 0 : 6;

  // Rigid-body vectors restricted to the free DOFs.
  const Eigen::MatrixXd r_all = rigid_body_vectors(model, options.reference_point);
  Eigen::MatrixXd r(dofs.free_count(), 6);
  for (int e = 0; e < dofs.free_count(); ++e) r.row(e) = r_all.row(dofs.free_dofs[static_cast<std::size_t>(e)]);
  const Eigen::MatrixXd mr = sys.mass.selfadjointView<Eigen::Lower>() * r;
  result.total_mass = (r.transpose() * mr).diagonal();

  // A zero eigenvalue comes out with two errors: the iteration's, far below
  // |sigma| (1/(lambda - sigma) converges to `tolerance` relative to
  // 1/|sigma|), and the factorisation's round-off, about eps * lambda_max
  // whatever sigma is (measured up to 7e-17 max_i(K_ii/M_ii) on free-free
  // beams of 40 to 1280 elements: 0.07 rad^2/s^2 for 640 Euler-Bernoulli
  // elements of 3 mm, above 1e-4 |sigma| = 0.004). "Zero" is therefore below
  // the larger of f < shift_hz / 100 and 1e-14 max_i(K_ii/M_ii) (about 45 eps,
  // 150 times the measured round-off). An elastic mode below the latter has
  // lost all but two digits to round-off anyway. (The scale term alone, at
  // 1e-8, took the fundamental of a 40-element cantilever for a mechanism;
  // the shift term alone missed rigid-body modes of fine meshes.)
  const double zero_level = std::max(1e-4 * std::abs(eo.shift), 1e-14 * eigenvalue_scale(sys.stiffness, sys.mass));
  result.shapes = Eigen::MatrixXd::Zero(model.dof_count(), es.eigenvalues.size());
  int near_zero = 0;
  for (Eigen::Index i = 0; i < es.eigenvalues.size(); ++i) {
    Mode mode;
    mode.eigenvalue = es.eigenvalues(i);
    const Eigen::VectorXd phi = es.vectors.col(i);
    const bool zero = std::abs(mode.eigenvalue) <= zero_level;
    if (zero) ++near_zero;
    mode.rigid_body = zero && near_zero <= result.rigid_body_modes_expected;
    mode.frequency_hz = mode.rigid_body ? 0.0 : std::sqrt(std::max(mode.eigenvalue, 0.0)) / kTwoPi;
    mode.participation = mr.transpose() * phi;
    mode.effective_mass = mode.participation.cwiseProduct(mode.participation);
    for (int e = 0; e < dofs.free_count(); ++e) result.shapes(dofs.free_dofs[static_cast<std::size_t>(e)], i) = phi(e);
    if (zero && !mode.rigid_body)
      throw core::NumericalError(fmt::format(
          "mechanism: mode {} has zero frequency ({:.3g} Hz) but is not a rigid-body motion of a {} frame; "
          "part of the frame can move without straining. The motion is largest at nodes {}. Check the "
          "supports (*BOUNDARY), disconnected parts and elements that share no node",
          i + 1, std::sqrt(std::max(mode.eigenvalue, 0.0)) / kTwoPi, grounded ? "supported" : "free-free",
          largest_motion_nodes(model, dofs, phi)));
    result.modes.push_back(mode);
  }
  fill_slave_dofs_columns(dofs.links, result.shapes);  // rigid links' slaves follow their reference nodes (Eq. R.3)
  return result;
}

}  // namespace framedyn::fem
