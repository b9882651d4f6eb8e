// Shift-invert Lanczos (Spectra) on a CHOLMOD factorisation; see modal_analysis.h.
#include "fem/modal_analysis.h"

#include <Eigen/SparseCholesky>
#include <Spectra/SymEigsSolver.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <numeric>
#include <chrono>
#include <limits>
#include <random>
#include <thread>

#include "core/error.h"
#include "fem/rigid_body_modes.h"
#include "fem/sparse_cholesky.h"
#include "fem/sturm_count.h"

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
// Pairs already known (orthonormal columns Y, y-space) are deflated: the
// operator is (I - Y Y^T) C (I - Y Y^T), whose eigenvalue for them is 0 (an
// infinite lambda), never among the largest nu.
template <class Solver>
class StandardFormOperator {
 public:
  using Scalar = double;
  StandardFormOperator(const Solver& solver, const MassFactor& mass, const Eigen::MatrixXd& locked)
      : solver_(solver), mass_(mass), locked_(locked), a_(mass.lower.rows()), b_(mass.lower.rows()), c_(mass.lower.rows()) {}
  Eigen::Index rows() const { return mass_.lower.rows(); }
  Eigen::Index cols() const { return mass_.lower.rows(); }
  void perform_op(const Scalar* x, Scalar* y) const {
    const Eigen::Index n = rows();
    Eigen::Map<const Eigen::VectorXd> in(x, n);
    Eigen::Map<Eigen::VectorXd> out(y, n);
    if (locked_.cols() > 0) {
      c_ = in;
      c_.noalias() -= locked_ * (locked_.transpose() * c_);
      a_.noalias() = mass_.lower * c_;                            // L x
    } else {
      a_.noalias() = mass_.lower * in;                            // L x
    }
    for (Eigen::Index i = 0; i < n; ++i) b_(mass_.perm(i)) = a_(i);  // S x = P^T L x
    solve_into(solver_, b_, a_);                                 // A^{-1} S x
    for (Eigen::Index i = 0; i < n; ++i) b_(i) = a_(mass_.perm(i));  // P ...
    out.noalias() = mass_.lower.transpose() * b_;               // S^T ... = L^T P ...
    if (locked_.cols() > 0) out.noalias() -= locked_ * (locked_.transpose() * out);
    ++solves_;
  }
  // phi = S^{-T} y = P^T L^{-T} y.
  Eigen::VectorXd back_transform(const Eigen::VectorXd& y) const {
    const Eigen::VectorXd u = mass_.lower.transpose().triangularView<Eigen::Upper>().solve(y);
    Eigen::VectorXd phi(u.size());
    for (Eigen::Index i = 0; i < u.size(); ++i) phi(mass_.perm(i)) = u(i);
    return phi;
  }
  // y = S^T phi = L^T P phi.
  Eigen::VectorXd to_standard(const Eigen::VectorXd& phi) const {
    Eigen::VectorXd p(phi.size());
    for (Eigen::Index i = 0; i < phi.size(); ++i) p(i) = phi(mass_.perm(i));
    return mass_.lower.transpose() * p;
  }
  int solves() const { return solves_; }

 private:
  const Solver& solver_;
  const MassFactor& mass_;
  const Eigen::MatrixXd& locked_;
  mutable Eigen::VectorXd a_, b_, c_;
  mutable int solves_ = 0;
};

// One Lanczos run for the `nev` largest nu of the deflated operator.
template <class Op>
void lanczos_run(Op& op, const Eigen::MatrixXd& locked, Eigen::Index nev, Eigen::Index ncv, long wanted, int run, const EigenOptions& o,
                 std::vector<double>& lambdas, Eigen::MatrixXd& ys, int& iterations) {
  const Eigen::Index n = op.rows();
  Spectra::SymEigsSolver<Op> eigs(op, nev, ncv);
  if (o.progress) o.progress(fmt::format("Lanczos iteration for {} modes (subspace {}{})", nev, ncv,
                                         locked.cols() > 0 ? fmt::format(", {} known pairs deflated", locked.cols()) : ""));
  if (locked.cols() == 0 && run == 0) {
    eigs.init();
  } else {
    // A start vector with no component along the known pairs.
    std::mt19937 rng(static_cast<unsigned>(12345 + run));
    std::uniform_real_distribution<double> u(-0.5, 0.5);
    Eigen::VectorXd v0(n);
    for (Eigen::Index i = 0; i < n; ++i) v0(i) = u(rng);
    if (locked.cols() > 0) v0 -= locked * (locked.transpose() * v0);
    eigs.init(v0.data());
  }
  const Eigen::Index converged = eigs.compute(Spectra::SortRule::LargestAlge, o.max_iterations, o.tolerance);
  if (eigs.info() != Spectra::CompInfo::Successful)
    throw core::NumericalError(non_convergence_message(std::min<long>(converged, wanted), wanted, ncv, n, o));
  const Eigen::VectorXd nu = eigs.eigenvalues();
  const Eigen::MatrixXd y = eigs.eigenvectors();
  const Eigen::Index old = ys.cols();
  ys.conservativeResize(n, old + nu.size());
  // lambda = sigma + 1/nu: the largest nu are the lowest lambda, in order.
  for (Eigen::Index i = 0; i < nu.size(); ++i) {
    lambdas.push_back(o.shift + 1.0 / nu(i));
    ys.col(old + i) = y.col(i);
  }
  iterations += static_cast<int>(eigs.num_iterations());
}

template <class Solver>
EigenSolution solve_with(Solver& solver, const SparseMatrix& k, const SparseMatrix& m, const EigenOptions& o) {
  const Eigen::Index n = k.rows();
  const Eigen::Index want = std::min<Eigen::Index>(o.count, n - 1);
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

  // Candidates: every pair found so far, as eigenvalues and orthonormal
  // columns in y-space; all are deflated from the next Lanczos run.
  Eigen::MatrixXd ys(n, 0);
  std::vector<double> lambdas;
  using Op = StandardFormOperator<Solver>;
  Op op(solver, mass, ys);
  EigenSolution s;
  const Eigen::Index p = o.null_space.cols();
  if (p > 0) {
    if (o.null_space.rows() != n) throw std::invalid_argument("lowest_eigenpairs: null space of the wrong size");
    Eigen::MatrixXd y0(n, p);
    for (Eigen::Index j = 0; j < p; ++j) y0.col(j) = op.to_standard(o.null_space.col(j));
    // Orthonormal in y-space = M-orthonormal in phi-space.
    Eigen::HouseholderQR<Eigen::MatrixXd> qr(y0);
    const Eigen::VectorXd r = qr.matrixQR().diagonal().head(p).cwiseAbs();
    if (r.minCoeff() <= 1e-10 * r.maxCoeff()) throw std::invalid_argument("lowest_eigenpairs: the null-space vectors are not independent");
    ys = qr.householderQ() * Eigen::MatrixXd::Identity(n, p);
    lambdas.assign(static_cast<std::size_t>(p), 0.0);
  }
  const std::size_t known = lambdas.size();

  // First run: the wanted modes not known, and one more, so that the Sturm
  // shift can be put in the gap above the highest wanted one.
  Eigen::Index nev = std::max<Eigen::Index>(want - p, 0) + 1;
  Eigen::Index first_subspace = o.subspace;
  for (int run = 0;; ++run) {
    const Eigen::Index room = n - static_cast<Eigen::Index>(lambdas.size());  // dimension left after deflation
    nev = std::min(nev, room - 1);
    if (nev >= 1) {
      const Eigen::Index ncv = std::min<Eigen::Index>(
          n, first_subspace > nev ? first_subspace : std::max<Eigen::Index>(2 * nev + 1, nev + 20));
      first_subspace = 0;
      lanczos_run(op, ys, nev, ncv, run == 0 ? static_cast<long>(std::max<Eigen::Index>(want - p, 1)) : static_cast<long>(nev), run, o,
                  lambdas, ys, s.iterations);
      ++s.lanczos_runs;
    }
    if (static_cast<Eigen::Index>(lambdas.size()) < want)
      throw core::NumericalError(fmt::format("the eigensolver found {} of {} modes", lambdas.size(), want));
    if (!o.certify) break;

    // Sturm check (Eq. 7.3). lambda_N's cluster: the values within 1e-6 of
    // it (copies of a repeated root agree far better than that); the shift
    // goes halfway to the next value found, at most 5 % above lambda_N, so
    // that it lies away from every eigenvalue found. Above the zero cluster
    // (rigid-body modes only) it goes halfway to the first elastic mode, far
    // above the round-off of the zero eigenvalues in the LDL^T.
    std::vector<double> sorted = lambdas;
    std::sort(sorted.begin(), sorted.end());
    const double lambda_n = sorted[static_cast<std::size_t>(want - 1)];
    const double cluster = 1e-6 * std::max(std::abs(lambda_n), std::abs(o.shift));
    long found = 0;
    double next = std::numeric_limits<double>::infinity();
    for (double l : sorted) {
      if (l <= lambda_n + cluster) ++found;
      else next = std::min(next, l);
    }
    const bool zero_cluster = std::abs(lambda_n) <= cluster;
    const double window = zero_cluster ? 0.01 * std::abs(o.shift) : 0.05 * std::abs(lambda_n);
    double shift = lambda_n + std::max(window, 2.0 * cluster);
    if (std::isfinite(next)) shift = zero_cluster ? lambda_n + 0.5 * (next - lambda_n) : std::min(shift, lambda_n + 0.5 * (next - lambda_n));
    if (o.progress) o.progress(fmt::format("Sturm count below {:.6g} Hz", std::sqrt(std::max(shift, 0.0)) / kTwoPi));
    const auto t0 = std::chrono::steady_clock::now();
    const SturmCount count = count_eigenvalues_below(k, m, shift, 1e-3 * (shift - lambda_n));
    s.sturm_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    s.sturm_factorizations += count.factorizations;
    s.sturm_count = count.below;
    s.sturm_shift = count.shift;
    if (count.below == found) {
      s.certified = true;
      break;
    }
    if (count.below > found && shift - lambda_n > 2.0 * cluster) {
      // Some eigenvalues between lambda_N's cluster and the shift were not
      // found: if they all lie above the cluster they are not among the N
      // lowest. A second count just above the cluster tells.
      const auto t1 = std::chrono::steady_clock::now();
      const SturmCount tight = count_eigenvalues_below(k, m, lambda_n + 2.0 * cluster, 0.1 * cluster);
      s.sturm_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
      s.sturm_factorizations += tight.factorizations;
      if (tight.below == found) {
        s.sturm_count = tight.below;
        s.sturm_shift = tight.shift;
        s.certified = true;
        break;
      }
    }
    const long missing = count.below - found;
    const std::string figures = fmt::format(
        "the Sturm count (the negative pivots of K - s M = L D L^T) finds {} eigenvalue(s) below s = {:.6g} rad^2/s^2 "
        "({:.6g} Hz) where the Lanczos iteration found {} (asked for {}; {} run(s), {} equations)",
        count.below, count.shift, std::sqrt(std::max(count.shift, 0.0)) / kTwoPi, found, want, s.lanczos_runs, n);
    if (missing < 0) {
      s.certification_failure = "the mode set could not be certified: " + figures +
                                ": the iteration returned pairs that are not eigenpairs (ill-conditioned K or M?)";
      break;
    }
    if (run + 1 >= o.certification_rounds || nev < 1) {
      s.certification_failure = "the mode set could not be certified: " + figures +
                                ", after the recoveries. Try a shift nearer the wanted frequencies (--shift) or more modes";
      break;
    }
    // Recovery: the missed roots are the lowest of the complement of the
    // pairs found; one more than missed, for the gap above them.
    if (o.progress) o.progress(fmt::format("{} eigenvalue(s) missed below {:.6g} Hz: searching again with the {} pairs found deflated",
                                           missing, std::sqrt(std::max(count.shift, 0.0)) / kTwoPi, lambdas.size()));
    nev = missing + 1;
  }

  // The `want` lowest, in order.
  std::vector<std::size_t> order(lambdas.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) { return lambdas[x] < lambdas[y]; });
  s.eigenvalues.resize(want);
  s.vectors.resize(n, want);
  for (Eigen::Index i = 0; i < want; ++i) {
    const std::size_t c = order[static_cast<std::size_t>(i)];
    s.eigenvalues(i) = lambdas[c];
    Eigen::VectorXd v = op.back_transform(ys.col(static_cast<Eigen::Index>(c)));
    // Deterministic sign: the largest component positive.
    Eigen::Index imax = 0;
    v.cwiseAbs().maxCoeff(&imax);
    if (v(imax) < 0) v = -v;
    s.vectors.col(i) = v;
    s.null_space.push_back(c < known ? 1 : 0);
  }
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

// "node 12 (ux), node 12 (uz), ..." for the largest components of a shape.
std::string largest_motion_dofs(const FrameModel& model, const DofMap& dofs, const Eigen::VectorXd& shape) {
  std::vector<int> order(static_cast<std::size_t>(dofs.free_count()));
  std::iota(order.begin(), order.end(), 0);
  const std::size_t shown = std::min<std::size_t>(6, order.size());
  std::partial_sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(shown), order.end(),
                    [&](int a, int b) { return std::abs(shape(a)) > std::abs(shape(b)); });
  std::string out;
  for (std::size_t i = 0; i < shown; ++i)
    out += (i ? ", " : "") + model.describe_dof(dofs.free_dofs[static_cast<std::size_t>(order[i])]);
  return out;
}

}  // namespace

ModalResult compute_modes(const FrameModel& model, const ModalOptions& options) {
  if (options.mode_count < 1) throw std::invalid_argument("the number of modes must be at least 1");
  const DofMap dofs = make_dof_map(model);
  if (options.progress) options.progress(fmt::format("assembling {} beam elements ({} free DOFs)", model.beams.size(), dofs.free_count()));
  const FreeSystem sys = assemble(model, dofs, {options.mass, Storage::lower});
  return compute_modes(model, dofs, sys, options);
}

ModalResult compute_modes(const FrameModel& model, const DofMap& dofs, const FreeSystem& sys, const ModalOptions& options) {
  if (options.mode_count < 1) throw std::invalid_argument("the number of modes must be at least 1");

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

  // The rigid motions the supports and springs leave free (Eq. 7.2): exact
  // zero modes, deflated from the iteration.
  const FreeRigidMotions rigid = free_rigid_motions(model);
  const int nf = dofs.free_count();
  Eigen::MatrixXd rigid_free(nf, rigid.shapes.cols());
  for (int e = 0; e < nf; ++e) rigid_free.row(e) = rigid.shapes.row(dofs.free_dofs[static_cast<std::size_t>(e)]);

  EigenOptions eo;
  eo.count = options.mode_count;
  eo.shift = -std::pow(kTwoPi * options.shift_hz, 2);
  eo.factorization = options.factorization;
  eo.progress = options.progress;
  eo.certify = options.certify;
  eo.null_space = std::move(rigid_free);
  eo.describe_equation = [&](int e) { return model.describe_dof(dofs.free_dofs[static_cast<std::size_t>(e)]); };
  const EigenSolution es = lowest_eigenpairs(sys.stiffness, sys.mass, eo);
  if (options.progress) options.progress("participation factors and effective masses");

  ModalResult result;
  result.free_dofs = nf;
  result.iterations = es.iterations;
  result.operator_solves = es.operator_solves;
  result.rigid_body_modes_expected = static_cast<int>(rigid.shapes.cols());
  result.parts = rigid.parts;
  result.sturm_count = es.sturm_count;
  result.sturm_shift_hz = std::sqrt(std::max(es.sturm_shift, 0.0)) / kTwoPi;
  result.certified = es.certified;
  result.lanczos_runs = es.lanczos_runs;
  result.sturm_seconds = es.sturm_seconds;

  // Mass bookkeeping over all DOFs (Eqs. 7.4, 7.5): M assembled with every
  // DOF free gives the model's total mass and, in the rows of the free DOFs,
  // M_ff r_f + M_fs r_s, the inertia force of a rigid acceleration of the
  // whole model (supports included) on the free DOFs.
  DofMap all;
  all.free_index.resize(static_cast<std::size_t>(model.dof_count()));
  std::iota(all.free_index.begin(), all.free_index.end(), 0);
  all.free_dofs = all.free_index;
  const SparseMatrix mass_all = assemble_mass(model, all, {options.mass, Storage::lower});
  const Eigen::MatrixXd r_all = rigid_body_vectors(model, options.reference_point);
  const Eigen::MatrixXd mr_all = mass_all.selfadjointView<Eigen::Lower>() * r_all;
  result.total_mass = (r_all.transpose() * mr_all).diagonal();
  Eigen::MatrixXd r(nf, 6), mr(nf, 6);
  for (int e = 0; e < nf; ++e) {
    r.row(e) = r_all.row(dofs.free_dofs[static_cast<std::size_t>(e)]);
    mr.row(e) = mr_all.row(dofs.free_dofs[static_cast<std::size_t>(e)]);
  }
  result.free_mass = (r.transpose() * (sys.mass.selfadjointView<Eigen::Lower>() * r)).diagonal();

  // A mode that is not a free rigid motion but has a frequency below a
  // hundredth of the shift (0.01 Hz by default) is a mechanism: a motion the
  // beams do not resist (a section with no stiffness), which no rigid motion
  // of a part explains. The threshold is relative to the frequencies the
  // user asks about, not to the stiffest DOF: the rigid motions no longer
  // need telling apart by their (round-off) eigenvalue.
  const double zero_level = 1e-4 * std::abs(eo.shift);
  result.shapes = Eigen::MatrixXd::Zero(model.dof_count(), es.eigenvalues.size());
  for (Eigen::Index i = 0; i < es.eigenvalues.size(); ++i) {
    Mode mode;
    const Eigen::VectorXd phi = es.vectors.col(i);
    mode.rigid_body = es.null_space[static_cast<std::size_t>(i)] != 0;
    mode.eigenvalue = mode.rigid_body ? 0.0 : es.eigenvalues(i);
    mode.frequency_hz = mode.rigid_body ? 0.0 : std::sqrt(std::max(mode.eigenvalue, 0.0)) / kTwoPi;
    if (!mode.rigid_body && mode.eigenvalue <= zero_level)
      throw core::NumericalError(fmt::format(
          "mechanism: mode {} has zero frequency ({:.3g} Hz, below {:.3g} Hz = shift / 100) but is not a rigid motion of "
          "the parts the supports leave free ({} expected: {}); part of the frame can move without straining. The motion "
          "is largest at {}. Check the sections (a zero area, moment of inertia or torsion constant), the supports "
          "(*BOUNDARY) and the springs",
          i + 1, std::sqrt(std::max(es.eigenvalues(i), 0.0)) / kTwoPi, std::sqrt(zero_level) / kTwoPi,
          result.rigid_body_modes_expected, rigid.describe(model), largest_motion_dofs(model, dofs, phi)));
    mode.participation = mr.transpose() * phi;
    mode.effective_mass = mode.participation.cwiseProduct(mode.participation);
    for (int e = 0; e < nf; ++e) result.shapes(dofs.free_dofs[static_cast<std::size_t>(e)], i) = phi(e);
    result.modes.push_back(mode);
  }
  fill_slave_dofs_columns(dofs.links, result.shapes);  // rigid links' slaves follow their reference nodes (Eq. R.3)
  if (options.certify && !es.certified) throw core::NumericalError(es.certification_failure);
  return result;
}

}  // namespace framedyn::fem
