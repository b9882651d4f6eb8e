// Mode superposition with exact piecewise-linear modal integration; see
// modal_transient.h and docs/theory/fem.md, "Transient response by mode superposition".
#include "fem/modal_transient.h"

#include <Eigen/Eigenvalues>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/error.h"
#include "fem/partial_supports.h"
#include "fem/rigid_body_modes.h"

namespace framedyn::fem {

namespace {
constexpr double kTwoPi = 6.283185307179586;
}

double ModalDamping::coefficient(int mode, double omega) const {
  if (rayleigh) return alpha + beta * omega * omega;  // phi^T (alpha M + beta K) phi (Eq. T.3)
  if (ratios.empty()) return 0.0;
  const double zeta = ratios[static_cast<std::size_t>(std::min<int>(mode, static_cast<int>(ratios.size()) - 1))];
  return 2.0 * zeta * omega;
}

double ModalDamping::ratio_of(int mode, double omega) const {
  if (omega <= 0.0) return coefficient(mode, omega) > 0.0 ? std::numeric_limits<double>::infinity() : 0.0;
  return coefficient(mode, omega) / (2.0 * omega);
}

namespace internal {

Eigen::Matrix4d expm(const Eigen::Matrix4d& a) {
  const double norm = a.cwiseAbs().colwise().sum().maxCoeff();
  int squarings = 0;
  if (norm > 0.25) squarings = static_cast<int>(std::ceil(std::log2(norm / 0.25)));
  const Eigen::Matrix4d x = a / std::ldexp(1.0, squarings);
  // ||x|| <= 1/4: the Taylor remainder after the x^18 term is below 0.25^19 / 19! ~ 3e-29.
  Eigen::Matrix4d term = Eigen::Matrix4d::Identity(), sum = Eigen::Matrix4d::Identity();
  for (int n = 1; n <= 18; ++n) {
    term = term * x / n;
    sum += term;
  }
  for (int s = 0; s < squarings; ++s) sum = sum * sum;
  return sum;
}

PiecewiseLinearStep nigam_jennings_step(double w, double z, double h) {
  if (!(w > 0.0) || z < 0.0 || z >= 1.0) throw std::invalid_argument("Nigam-Jennings coefficients need omega > 0 and 0 <= zeta < 1");
  const double k = w * w;
  const double wd = w * std::sqrt(1.0 - z * z);
  const double e = std::exp(-z * w * h);
  const double s = std::sin(wd * h), c = std::cos(wd * h);
  const double r = z / std::sqrt(1.0 - z * z);
  PiecewiseLinearStep p;
  p.a << e * (r * s + c), e * s / wd,
         -e * w / std::sqrt(1.0 - z * z) * s, e * (c - r * s);
  // Displacement: q1 = A q0 + B v0 + C p0 + D p1; velocity: v1 = A' q0 + B' v0 + C' p0 + D' p1.
  const double C = (2.0 * z / (w * h) + e * (((1.0 - 2.0 * z * z) / (wd * h) - r) * s - (1.0 + 2.0 * z / (w * h)) * c)) / k;
  const double D = (1.0 - 2.0 * z / (w * h) + e * ((2.0 * z * z - 1.0) / (wd * h) * s + 2.0 * z / (w * h) * c)) / k;
  const double Cp = (-1.0 / h + e * ((w / std::sqrt(1.0 - z * z) + r / h) * s + c / h)) / k;
  const double Dp = (1.0 - e * (r * s + c)) / (k * h);
  p.b0 << C, Cp;
  p.b1 << D, Dp;
  return p;
}

}  // namespace internal

const PiecewiseLinearStep& StepMemo::step(double k, double c, double h) {
  for (const Entry& e : entries_)
    if (e.k == k && e.c == c && e.h == h) return e.step;
  if (entries_.size() >= kRememberedSteps) {
    last_ = piecewise_linear_step(k, c, h);
    return last_;
  }
  entries_.push_back(Entry{k, c, h, piecewise_linear_step(k, c, h)});
  return entries_.back().step;
}

PiecewiseLinearStep piecewise_linear_step(double k, double c, double h) {
  if (!(h > 0.0) || k < 0.0 || c < 0.0) throw std::invalid_argument("piecewise_linear_step: need h > 0, k >= 0, c >= 0");
  // Augmented state y = (s q, v, p, dp/dt) with y' = G y on [0, h] (Eq. T.5):
  // the load and its slope ride along as states, so exp(h G) is the exact
  // Duhamel integral for a linear load. s balances the matrix (s = omega, or 1/h for k = 0).
  const double s = k > 0.0 ? std::sqrt(k) : 1.0 / h;
  Eigen::Matrix4d g = Eigen::Matrix4d::Zero();
  g(0, 1) = s;
  g(1, 0) = -k / s;
  g(1, 1) = -c;
  g(1, 2) = 1.0;
  g(2, 3) = 1.0;
  const Eigen::Matrix4d e = internal::expm(h * g);
  PiecewiseLinearStep p;
  p.a << e(0, 0), e(0, 1) / s, e(1, 0) * s, e(1, 1);
  p.b1 << e(0, 3) / (s * h), e(1, 3) / h;
  p.b0 << e(0, 2) / s - p.b1(0), e(1, 2) - p.b1(1);
  return p;
}

int ModalBasis::elastic_count() const {
  return static_cast<int>(std::count(rigid_body.begin(), rigid_body.end(), false));
}

ModalBasis modal_basis(const DofMap& dofs, const ModalResult& modes) {
  ModalBasis b;
  const int m = static_cast<int>(modes.modes.size());
  b.eigenvalues.resize(m);
  b.shapes.resize(dofs.free_count(), m);
  for (int i = 0; i < m; ++i) {
    const Mode& mode = modes.modes[static_cast<std::size_t>(i)];
    b.eigenvalues(i) = mode.rigid_body ? 0.0 : mode.eigenvalue;
    b.rigid_body.push_back(mode.rigid_body);
    for (int e = 0; e < dofs.free_count(); ++e) b.shapes(e, i) = modes.shapes(dofs.free_dofs[static_cast<std::size_t>(e)], i);
  }
  return b;
}

// ---------------------------------------------------------------------------
// FrameDynamics

FrameDynamics::FrameDynamics(const FrameModel& model, MassFormulation mass) : model_(model) {
  dofs_ = make_dof_map(model);
  system_ = assemble(model, dofs_, {mass, Storage::lower});
  set_up({});
}

FrameDynamics::FrameDynamics(const FrameModel& model, const std::vector<int>& auxiliary_dofs, MassFormulation mass) : model_(model) {
  if (auxiliary_dofs.size() != 6) throw std::invalid_argument("FrameDynamics: six auxiliary supports are needed");
  dofs_ = make_dof_map(model);
  system_ = assemble(model, dofs_, {mass, Storage::lower});
  set_up(auxiliary_dofs);
  if (!free_free_) throw core::NumericalError("auxiliary supports of the caller's choice are for a free-free frame, and this one is supported");
}

void FrameDynamics::set_up(const std::vector<int>& requested) {
  const FrameModel& model = model_;
  bool grounded = !model.constraints.empty();
  for (const Spring& s : model.springs) grounded = grounded || s.node_b < 0;
  free_free_ = !grounded;
  static_solver_ = std::make_unique<SparseCholesky>();
  const int n = dofs_.free_count();
  // The rigid motions the supports leave free (fem/rigid_body_modes.h): none
  // for a supported frame, six for a free-free one in one piece, any number
  // for a partially supported frame (docs/theory/fem.md, section 19).
  const FreeRigidMotions free_motions = free_rigid_motions(model);
  if (free_motions.shapes.cols() == 0) {
    free_free_ = false;
    if (!static_solver_->factorize(system_.stiffness))
      throw core::NumericalError(fmt::format(
          "the stiffness matrix of the supported frame is singular at {}: the supports leave a mechanism",
          model.describe_dof(dofs_.free_dofs[static_cast<std::size_t>(std::max(0, static_solver_->failed_equation()))])));
    rigid_.resize(n, 0);
    mass_rigid_.resize(n, 0);
    return;
  }
  if (!free_free_ || free_motions.parts > 1 || free_motions.shapes.cols() != 6) {
    free_free_ = false;
    set_up_partial_supports(rigid_motions_on_equations(dofs_, free_motions.shapes));
    return;
  }
  if (model.nodes.size() < 2) throw core::NumericalError("a free-free frame needs at least two nodes");
  // M-orthonormal rigid-body vectors about the nodes' centroid (Eq. T.9).
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const Node& nd : model.nodes) centroid += nd.position;
  centroid /= static_cast<double>(model.nodes.size());
  const Eigen::MatrixXd r_all = rigid_body_vectors(model, centroid);
  Eigen::MatrixXd r(n, 6);
  for (int e = 0; e < n; ++e) r.row(e) = r_all.row(dofs_.free_dofs[static_cast<std::size_t>(e)]);
  Eigen::MatrixXd mr = system_.mass.selfadjointView<Eigen::Lower>() * r;
  const Eigen::Matrix<double, 6, 6> gram = r.transpose() * mr;
  Eigen::LLT<Eigen::Matrix<double, 6, 6>> llt(gram);
  if (llt.info() != Eigen::Success) throw core::NumericalError("the rigid-body mass matrix of the free-free frame is singular");
  const Eigen::Matrix<double, 6, 6> linv_t = llt.matrixL().solve(Eigen::Matrix<double, 6, 6>::Identity()).transpose();
  rigid_ = r * linv_t;
  mass_rigid_ = mr * linv_t;

  if (!requested.empty()) {
    // The caller's six supports: statically determinate when the rigid motions' values there determine the motion,
    // i.e. the 6 x 6 rows of R are regular (relative to R's own scale).
    Eigen::Matrix<double, 6, 6> at;
    for (int q = 0; q < 6; ++q) {
      const int g = requested[static_cast<std::size_t>(q)];
      const int e = g >= 0 && g < model.dof_count() ? dofs_.free_index[static_cast<std::size_t>(g)] : -1;
      if (e < 0) throw core::NumericalError(fmt::format("the auxiliary support at {} is not a free DOF of the frame", model.describe_dof(std::max(g, 0))));
      at.row(q) = rigid_.row(e);
      auxiliary_.push_back(e);
    }
    const Eigen::JacobiSVD<Eigen::Matrix<double, 6, 6>> svd(at);
    if (!(svd.singularValues()(5) > 1e-8 * svd.singularValues()(0)))
      throw core::NumericalError("the six auxiliary supports leave a rigid motion of the free-free frame free (not statically determinate)");
    std::sort(auxiliary_.begin(), auxiliary_.end());
    if (std::adjacent_find(auxiliary_.begin(), auxiliary_.end()) != auxiliary_.end())
      throw core::NumericalError("an auxiliary support is given twice");
    if (!static_solver_->factorize(with_auxiliary_supports(system_.stiffness, auxiliary_)))
      throw core::NumericalError("the free-free frame on its auxiliary supports is still a mechanism (disconnected parts?)");
    return;
  }
  // Auxiliary supports, statically determinate (3-2-1, Eq. T.11): the three
  // translations of node A, and the three DOFs of nodes B (farthest from A)
  // and C (farthest from the line AB) that best fix the remaining rotations.
  const auto pos = [&](std::size_t i) { return model.nodes[i].position; };
  // Only nodes whose DOFs are equations can carry them (not the slaves of rigid links).
  std::vector<std::size_t> candidates_nodes;
  for (std::size_t i = 0; i < model.nodes.size(); ++i)
    if (!dofs_.links.is_slave(kDofsPerNode * static_cast<int>(i))) candidates_nodes.push_back(i);
  if (candidates_nodes.size() < 2) throw core::NumericalError("a free-free frame needs at least two nodes that are not tied by rigid links");
  std::size_t a = candidates_nodes[0];
  for (std::size_t i : candidates_nodes)
    if (pos(i).x() < pos(a).x() || (pos(i).x() == pos(a).x() && pos(i).y() < pos(a).y())) a = i;
  std::size_t b = a == candidates_nodes[0] ? candidates_nodes[1] : candidates_nodes[0];
  for (std::size_t i : candidates_nodes)
    if ((pos(i) - pos(a)).norm() > (pos(b) - pos(a)).norm()) b = i;
  const Eigen::Vector3d d = (pos(b) - pos(a)).normalized();
  std::size_t c = b;
  double best_off = -1.0;
  for (std::size_t i : candidates_nodes) {
    if (i == a || i == b) continue;
    const Eigen::Vector3d v = pos(i) - pos(a);
    const double off = (v - v.dot(d) * d).norm();
    if (off > best_off) best_off = off, c = i;
  }
  std::vector<int> fixed = {6 * static_cast<int>(a), 6 * static_cast<int>(a) + 1, 6 * static_cast<int>(a) + 2};
  std::vector<int> candidates;
  for (int k = 0; k < 6; ++k) candidates.push_back(6 * static_cast<int>(b) + k);
  if (c != b)
    for (int k = 0; k < 6; ++k) candidates.push_back(6 * static_cast<int>(c) + k);
  // Rigid vectors about A, rotations scaled by |AB| so that the determinant compares like with like.
  Eigen::MatrixXd ra = rigid_body_vectors(model, pos(a));
  const double scale = std::max((pos(b) - pos(a)).norm(), 1e-12);
  for (int row = 0; row < ra.rows(); ++row)
    if (row % 6 < 3) ra.block<1, 3>(row, 3) /= scale;  // translations from rotations, per unit |AB|
  double best = 0.0;
  std::vector<int> choice;
  const int nc = static_cast<int>(candidates.size());
  for (int i = 0; i < nc; ++i)
    for (int j = i + 1; j < nc; ++j)
      for (int k = j + 1; k < nc; ++k) {
        Eigen::Matrix<double, 6, 6> s;
        const int rows[6] = {fixed[0], fixed[1], fixed[2], candidates[i], candidates[j], candidates[k]};
        for (int q = 0; q < 6; ++q) s.row(q) = ra.row(rows[q]);
        const double det = std::abs(s.determinant());
        if (det > best * (1.0 + 1e-9)) best = det, choice = {candidates[i], candidates[j], candidates[k]};
      }
  if (best < 1e-8) throw core::NumericalError("no statically determinate set of auxiliary supports found for the free-free frame");
  auxiliary_ = fixed;
  auxiliary_.insert(auxiliary_.end(), choice.begin(), choice.end());
  for (int& g : auxiliary_) g = dofs_.free_index[static_cast<std::size_t>(g)];
  std::sort(auxiliary_.begin(), auxiliary_.end());
  // K_s: K with the auxiliary rows and columns replaced by its diagonal (Eq. 19.4).
  const SparseMatrix ks = with_auxiliary_supports(system_.stiffness, auxiliary_);
  if (!static_solver_->factorize(ks))
    throw core::NumericalError("the free-free frame on its auxiliary supports is still a mechanism (disconnected parts?)");
}

FrameDynamics::~FrameDynamics() = default;

void FrameDynamics::set_up_partial_supports(const Eigen::MatrixXd& r) {
  // M-orthonormal free rigid motions (Eq. 19.5) and p auxiliary supports that fix them (Eq. 19.3).
  const Eigen::MatrixXd mr = system_.mass.selfadjointView<Eigen::Lower>() * r;
  const Eigen::MatrixXd gram = r.transpose() * mr;
  Eigen::LLT<Eigen::MatrixXd> llt(gram);
  if (llt.info() != Eigen::Success)
    throw core::NumericalError("the mass of the frame's free rigid motions is singular (a part without mass that can move rigidly?)");
  const Eigen::MatrixXd linv_t = llt.matrixL().solve(Eigen::MatrixXd::Identity(r.cols(), r.cols())).transpose();
  rigid_ = r * linv_t;
  mass_rigid_ = mr * linv_t;
  auxiliary_ = fem::auxiliary_supports(r);
  if (!static_solver_->factorize(with_auxiliary_supports(system_.stiffness, auxiliary_)))
    throw core::NumericalError(fmt::format(
        "the partially supported frame on auxiliary supports against its {} free rigid motions is still a mechanism at {}", r.cols(),
        model_.describe_dof(dofs_.free_dofs[static_cast<std::size_t>(std::max(0, static_solver_->failed_equation()))])));
}

Eigen::VectorXd FrameDynamics::mass_times(const Eigen::VectorXd& x) const { return system_.mass.selfadjointView<Eigen::Lower>() * x; }
Eigen::VectorXd FrameDynamics::stiffness_times(const Eigen::VectorXd& x) const {
  return system_.stiffness.selfadjointView<Eigen::Lower>() * x;
}

Eigen::VectorXd FrameDynamics::relieve(const Eigen::VectorXd& f) const {
  if (rigid_.cols() == 0) return f;
  return f - mass_rigid_ * (rigid_.transpose() * f);
}

Eigen::VectorXd FrameDynamics::elastic_part(const Eigen::VectorXd& u) const {
  if (rigid_.cols() == 0) return u;
  return u - rigid_ * (mass_rigid_.transpose() * u);
}

Eigen::MatrixXd FrameDynamics::free_loads(const SparseMatrix& distribution, bool relieved) const {
  if (distribution.rows() != model_.dof_count())
    throw std::invalid_argument(fmt::format("load distribution has {} rows, the model {} DOFs", distribution.rows(), model_.dof_count()));
  Eigen::MatrixXd b = Eigen::MatrixXd::Zero(dofs_.free_count(), distribution.cols());
  for (int col = 0; col < distribution.outerSize(); ++col)
    for (SparseMatrix::InnerIterator it(distribution, col); it; ++it) {
      const int g = static_cast<int>(it.row());
      const int e = dofs_.free_index[static_cast<std::size_t>(g)];
      if (e >= 0) {
        b(e, col) += it.value();
      } else if (dofs_.links.is_slave(g)) {  // T^T: a load on a rigid link's slave acts on its reference node (Eq. R.2)
        const SlaveDof& s = dofs_.links.slaves[static_cast<std::size_t>(dofs_.links.slave_of[static_cast<std::size_t>(g)])];
        for (int k = 0; k < s.count; ++k) {
          const int em = dofs_.free_index[static_cast<std::size_t>(s.master[static_cast<std::size_t>(k)])];
          if (em >= 0) b(em, col) += s.coefficient[static_cast<std::size_t>(k)] * it.value();
        }
      }
    }
  if (relieved && rigid_.cols() > 0) b -= mass_rigid_ * (rigid_.transpose() * b);
  return b;
}

Eigen::VectorXd FrameDynamics::static_response(const Eigen::VectorXd& f) const {
  Eigen::VectorXd rhs = f, u(f.size());
  for (int e : auxiliary_) rhs(e) = 0.0;
  static_solver_->solve_in_place(rhs.data(), u.data());
  return elastic_part(u);
}

Eigen::VectorXd FrameDynamics::auxiliary_reactions(const Eigen::VectorXd& f) const {
  Eigen::VectorXd rhs = f, u(f.size());
  for (int e : auxiliary_) rhs(e) = 0.0;
  static_solver_->solve_in_place(rhs.data(), u.data());
  const Eigen::VectorXd r = stiffness_times(u) - f;
  Eigen::VectorXd out(static_cast<Eigen::Index>(auxiliary_.size()));
  for (std::size_t i = 0; i < auxiliary_.size(); ++i) out(static_cast<Eigen::Index>(i)) = r(auxiliary_[i]);
  return out;
}

Eigen::VectorXd FrameDynamics::expand(const Eigen::VectorXd& u) const {
  Eigen::VectorXd all = Eigen::VectorXd::Zero(model_.dof_count());
  for (int e = 0; e < dofs_.free_count(); ++e) all(dofs_.free_dofs[static_cast<std::size_t>(e)]) = u(e);
  for (const Constraint& c : model_.constraints) all(kDofsPerNode * c.node + c.dof) = c.value;
  fill_slave_dofs(dofs_.links, all);
  return all;
}

ModalBasis FrameDynamics::all_modes() const {
  const SparseMatrix k_full = system_.stiffness.selfadjointView<Eigen::Lower>();
  const SparseMatrix m_full = system_.mass.selfadjointView<Eigen::Lower>();
  const Eigen::MatrixXd k = Eigen::MatrixXd(k_full), m = Eigen::MatrixXd(m_full);
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(k, m);  // eigenvectors with x^T M x = 1
  if (es.info() != Eigen::Success) throw core::NumericalError("the dense eigensolution of the frame failed (is M positive definite?)");
  ModalBasis b;
  b.eigenvalues = es.eigenvalues();
  b.shapes = es.eigenvectors();
  const int rigid = rigid_count();
  for (Eigen::Index i = 0; i < b.eigenvalues.size(); ++i) {
    b.rigid_body.push_back(i < rigid);
    if (i < rigid) b.eigenvalues(i) = 0.0;
  }
  return b;
}

// ---------------------------------------------------------------------------

TransientResult modal_transient(const FrameDynamics& frame, const ModalBasis& basis, const TransientInput& in,
                                const ModalTransientOptions& o) {
  const Eigen::Index nt = in.times.size();
  if (nt < 2) throw std::invalid_argument("a transient needs at least two times");
  if (in.components.cols() != nt || in.components.rows() != in.distribution.cols())
    throw std::invalid_argument(fmt::format("load components are {} x {}, expected {} x {}", in.components.rows(),
                                            in.components.cols(), in.distribution.cols(), nt));
  for (Eigen::Index k = 1; k < nt; ++k)
    if (!(in.times(k) > in.times(k - 1))) throw std::invalid_argument("transient times must increase strictly");
  if (o.output_interval < 1) throw std::invalid_argument("the output interval must be at least 1");
  if (basis.shapes.rows() != frame.dofs().free_count()) throw std::invalid_argument("the modal basis is not on this frame's free DOFs");

  // Elastic modes used, lowest first.
  std::vector<int> used;
  for (int i = 0; i < static_cast<int>(basis.rigid_body.size()); ++i)
    if (!basis.rigid_body[static_cast<std::size_t>(i)]) used.push_back(i);
  if (o.mode_count >= 0) {
    if (o.mode_count > static_cast<int>(used.size()))
      throw std::invalid_argument(fmt::format("{} modes asked for, the basis has {} elastic modes", o.mode_count, used.size()));
    used.resize(static_cast<std::size_t>(o.mode_count));
  }
  const int m = static_cast<int>(used.size());
  Eigen::MatrixXd phi(basis.shapes.rows(), m);
  Eigen::VectorXd w2(m);
  for (int i = 0; i < m; ++i) {
    phi.col(i) = basis.shapes.col(used[static_cast<std::size_t>(i)]);
    w2(i) = basis.eigenvalues(used[static_cast<std::size_t>(i)]);
  }

  const Eigen::MatrixXd b = frame.free_loads(in.distribution);     // free DOFs x components (relieved)
  const Eigen::MatrixXd pm = phi.transpose() * b;                   // modal loads per component (Eq. T.4)
  // The modal loads p = pm C (m x nt) a block of kLoadBlock times at a time, each block the same
  // product shape (the last one padded with zero loads): a long record keeps no m x nt matrix.
  constexpr Eigen::Index kLoadBlock = 256;
  Eigen::MatrixXd p(m, kLoadBlock), c_block = Eigen::MatrixXd::Zero(in.components.rows(), kLoadBlock);
  Eigen::Index p_from = -1;  // the first time of the block in p
  const auto modal_loads_at = [&](Eigen::Index k) -> const double* {
    if (p_from < 0 || k < p_from || k >= p_from + kLoadBlock) {
      p_from = k - k % kLoadBlock;
      const Eigen::Index n = std::min(kLoadBlock, nt - p_from);
      c_block.leftCols(n) = in.components.middleCols(p_from, n);
      if (n < kLoadBlock) c_block.rightCols(kLoadBlock - n).setZero();
      p.noalias() = pm * c_block;
    }
    return p.col(k - p_from).data();
  };
  Eigen::VectorXd p_previous = Eigen::Map<const Eigen::VectorXd>(modal_loads_at(0), m);  // p at the step's start

  // Static correction per component (Eq. T.8): (G - Phi Lambda^-1 Phi^T) B.
  Eigen::MatrixXd correction;
  if (o.method == ResponseMethod::mode_acceleration) {
    correction.resize(b.rows(), b.cols());
    for (Eigen::Index c = 0; c < b.cols(); ++c) correction.col(c) = frame.static_response(b.col(c));  // G B
    correction -= phi * (w2.cwiseInverse().asDiagonal() * pm);
  }

  std::vector<Eigen::Index> outputs;
  for (Eigen::Index k = 0; k < nt; k += o.output_interval)
    if (in.times(k) >= o.outputs_from) outputs.push_back(k);
  const Eigen::Index no = static_cast<Eigen::Index>(outputs.size());

  TransientResult r;
  r.times.resize(no);
  for (Eigen::Index j = 0; j < no; ++j) r.times(j) = in.times(outputs[static_cast<std::size_t>(j)]);
  r.modal_coordinates.resize(m, no);
  r.frequencies_hz.resize(m);
  r.damping_ratios.resize(m);

  // Every mode advances together, time by time: the modal loads at a time (p's column) and the
  // coordinates kept at an output time (a column) are contiguous, and each mode's step is the same
  // arithmetic as on its own (the exact step recomputed for all when the time step changes).
  std::vector<double> damping(static_cast<std::size_t>(m));
  Eigen::VectorXd q = Eigen::VectorXd::Zero(m), v = Eigen::VectorXd::Zero(m);
  for (int i = 0; i < m; ++i) {
    const double omega = std::sqrt(std::max(w2(i), 0.0));
    damping[static_cast<std::size_t>(i)] = o.damping.coefficient(i, omega);
    r.frequencies_hz(i) = omega / kTwoPi;
    r.damping_ratios(i) = o.damping.ratio_of(i, omega);
    if (o.initial == InitialState::static_equilibrium && w2(i) > 0.0) q(i) = p_previous(i) / w2(i);
  }
  // The step's coefficients per mode: q1 = a00 q + a01 v + c0 p0 + d0 p1, v1 = a10 q + a11 v + c1 p0 + d1 p1.
  std::vector<double> a00(static_cast<std::size_t>(m)), a01(a00), a10(a00), a11(a00), c0(a00), c1(a00), d0(a00), d1(a00);
  // The steps already computed, by their exact length h: the grid's steps are differences of rounded
  // times, so past t = 4 s (where an ulp of t exceeds 1e-12 h) consecutive steps differ by an ulp or two
  // and the test below asks for a new step nearly every time, but only a handful of distinct h occur.
  // A step looked up here is the same numbers piecewise_linear_step(w2, c, h) gives (same output).
  struct Remembered {
    double h;
    std::vector<double> coefficients;  // a00, a01, a10, a11, c0, c1, d0, d1, m each
  };
  std::vector<Remembered> remembered;
  std::vector<double>* blocks[8] = {&a00, &a01, &a10, &a11, &c0, &c1, &d0, &d1};
  double h_prev = -1.0;
  std::size_t next_out = 0;
  for (Eigen::Index k = 0; k < nt; ++k) {
    if (k > 0) {
      const double h = in.times(k) - in.times(k - 1);
      if (std::abs(h - h_prev) > 1e-12 * h) {
        const auto known = std::find_if(remembered.begin(), remembered.end(), [h](const Remembered& r) { return r.h == h; });
        if (known != remembered.end()) {
          for (int b = 0; b < 8; ++b)
            std::copy_n(known->coefficients.begin() + b * m, m, blocks[b]->begin());
        } else {
          for (int i = 0; i < m; ++i) {
            const PiecewiseLinearStep step = piecewise_linear_step(w2(i), damping[static_cast<std::size_t>(i)], h);
            const std::size_t u = static_cast<std::size_t>(i);
            a00[u] = step.a(0, 0), a01[u] = step.a(0, 1), a10[u] = step.a(1, 0), a11[u] = step.a(1, 1);
            c0[u] = step.b0(0), c1[u] = step.b0(1), d0[u] = step.b1(0), d1[u] = step.b1(1);
          }
          if (remembered.size() < kRememberedSteps) {
            Remembered r{h, std::vector<double>(static_cast<std::size_t>(8 * m))};
            for (int b = 0; b < 8; ++b) std::copy_n(blocks[b]->begin(), m, r.coefficients.begin() + b * m);
            remembered.push_back(std::move(r));
          }
        }
        h_prev = h;
      }
      const double* p0 = p_previous.data();
      const double* p1 = modal_loads_at(k);
      double* qd = q.data();
      double* vd = v.data();
      for (int i = 0; i < m; ++i) {
        const std::size_t u = static_cast<std::size_t>(i);
        const double q1 = a00[u] * qd[i] + a01[u] * vd[i] + c0[u] * p0[i] + d0[u] * p1[i];
        const double v1 = a10[u] * qd[i] + a11[u] * vd[i] + c1[u] * p0[i] + d1[u] * p1[i];
        qd[i] = q1;
        vd[i] = v1;
      }
      std::copy_n(p1, m, p_previous.data());
    }
    if (next_out < outputs.size() && outputs[next_out] == k) r.modal_coordinates.col(static_cast<Eigen::Index>(next_out++)) = q;
  }

  // The free rigid motions under the unrelieved loads (Eq. 19.7): k = 0,
  // c = alpha of Rayleigh damping (0 for modal ratios), from rest; the same
  // exact step as the elastic modes.
  const bool rigid = o.include_rigid_motion && frame.rigid_count() > 0;
  if (rigid) {
    const Eigen::MatrixXd pr = frame.rigid_vectors().transpose() * frame.free_loads(in.distribution, false) * in.components;
    r.rigid_coordinates.resize(frame.rigid_count(), no);
    const double c = o.damping.rayleigh ? o.damping.alpha : 0.0;
    for (int i = 0; i < frame.rigid_count(); ++i) {
      double q = 0.0, v = 0.0, h_prev = -1.0;
      PiecewiseLinearStep step{};
      StepMemo memo;
      std::size_t next_out = 0;
      for (Eigen::Index k = 0; k < nt; ++k) {
        if (k > 0) {
          const double h = in.times(k) - in.times(k - 1);
          if (std::abs(h - h_prev) > 1e-12 * h) {
            step = memo.step(0.0, c, h);
            h_prev = h;
          }
          const double q1 = step.a(0, 0) * q + step.a(0, 1) * v + step.b0(0) * pr(i, k - 1) + step.b1(0) * pr(i, k);
          v = step.a(1, 0) * q + step.a(1, 1) * v + step.b0(1) * pr(i, k - 1) + step.b1(1) * pr(i, k);
          q = q1;
        }
        if (next_out < outputs.size() && outputs[next_out] == k) r.rigid_coordinates(i, static_cast<Eigen::Index>(next_out++)) = q;
      }
    }
  }

  // Each output's displacement on its own (columns independent: any share of them, the same numbers).
  r.displacement.resize(frame.model().dof_count(), no);
  core::for_ranges(o.share, static_cast<std::size_t>(no), 64, [&](std::size_t begin, std::size_t end) {
    for (Eigen::Index j = static_cast<Eigen::Index>(begin); j < static_cast<Eigen::Index>(end); ++j) {
      Eigen::VectorXd u = phi * r.modal_coordinates.col(j);
      if (rigid) u += frame.rigid_vectors() * r.rigid_coordinates.col(j);
      if (o.method == ResponseMethod::mode_acceleration) u += correction * in.components.col(outputs[static_cast<std::size_t>(j)]);
      r.displacement.col(j) = frame.expand(u);
    }
  });
  return r;
}

}  // namespace framedyn::fem
