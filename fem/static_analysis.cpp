// Static solve and reactions; mechanism diagnosis by the stiffness matrix's null space.
#include "fem/static_analysis.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "fem/assembly.h"
#include "fem/distributed_loads.h"
#include "fem/modal_analysis.h"
#include "fem/partial_supports.h"
#include "fem/rigid_body_modes.h"
#include "fem/sparse_cholesky.h"

namespace framedyn::fem {

namespace {

// Names the nodes that move in the near-null space of K_ff: the lowest
// eigenvectors of K x = lambda x (identity mass).
std::string describe_mechanism(const FrameModel& model, const DofMap& dofs, const SparseMatrix& k) {
  const int n = dofs.free_count();
  SparseMatrix identity(n, n);
  identity.setIdentity();
  const double scale = k.diagonal().cwiseAbs().maxCoeff();
  EigenOptions o;
  o.count = std::min(6, n - 1);
  o.shift = -1e-6 * scale;
  o.certify = false;  // a diagnosis of a singular K, not a mode set
  try {
    const EigenSolution es = lowest_eigenpairs(k, identity, o);
    std::string out;
    int mechanisms = 0;
    for (Eigen::Index i = 0; i < es.eigenvalues.size(); ++i) {
      if (es.eigenvalues(i) > 1e-9 * scale) continue;
      ++mechanisms;
      // The DOFs with the largest motion in this null vector.
      const Eigen::VectorXd v = es.vectors.col(i).cwiseAbs();
      std::vector<int> order(static_cast<std::size_t>(n));
      for (int j = 0; j < n; ++j) order[static_cast<std::size_t>(j)] = j;
      std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return v(a) > v(b); });
      std::string list;
      for (int j = 0; j < std::min(4, n); ++j)
        list += (j ? ", " : "") + model.describe_dof(dofs.free_dofs[static_cast<std::size_t>(order[static_cast<std::size_t>(j)])]);
      out += fmt::format("\n  free motion {}: largest at {}", mechanisms, list);
    }
    if (mechanisms == 0) return "";
    return fmt::format("{} independent free motion(s):{}", mechanisms, out);
  } catch (const std::exception&) {
    return "";
  }
}

}  // namespace

Eigen::VectorXd applied_loads(const FrameModel& model) { return applied_load_vector(model); }

StaticResult solve_static(const FrameModel& model, const std::function<void(const std::string&)>& progress, const StaticOptions& options) {
  const DofMap dofs = make_dof_map(model);
  const int ndof = model.dof_count();
  StaticResult r;
  r.applied = applied_loads(model);  // nodal loads and the consistent loads of *DLOAD
  Eigen::VectorXd prescribed = Eigen::VectorXd::Zero(ndof);
  for (const Constraint& c : model.constraints) prescribed(kDofsPerNode * c.node + c.dof) = c.value;
  fill_slave_dofs(dofs.links, prescribed);  // slaves of a supported reference node move with it

  if (progress) progress(fmt::format("assembling {} beam elements ({} free DOFs)", model.beams.size(), dofs.free_count()));
  const FreeSystem system = assemble(model, dofs, {MassFormulation::consistent, Storage::lower});
  const SparseMatrix& k = system.stiffness;

  // T^T (f - K u_c) on the free DOFs, with K u_c computed element by element
  // (T: rigid links' slaves, Eq. R.2; the identity without links).
  Eigen::VectorXd rhs = restrict_load(dofs, r.applied - internal_force(model, prescribed));

  // Rigid motions the supports leave free (section 19): the loads must do no
  // work on them (Eq. 19.1), or be relieved by their inertia (Eq. 19.5).
  const FreeRigidMotions motions = free_rigid_motions(model);
  const int p = static_cast<int>(motions.shapes.cols());
  r.free_rigid_motions = p;
  r.free_motions = motions.describe(model);
  r.inertia_relief = options.inertia_relief && p > 0;
  Eigen::MatrixXd rigid, mass_rigid, rigid_gram;
  if (p > 0) {
    rigid = rigid_motions_on_equations(dofs, motions.shapes);
    if (r.inertia_relief) {
      mass_rigid = system.mass.selfadjointView<Eigen::Lower>() * rigid;
      rigid_gram = rigid.transpose() * mass_rigid;
      const Eigen::LLT<Eigen::MatrixXd> llt(rigid_gram);
      if (llt.info() != Eigen::Success)
        throw core::NumericalError("inertia relief needs the mass of the free rigid motions, and it is singular (no *DENSITY and no point mass "
                                   "on a part that can move rigidly?)");
      const Eigen::VectorXd a = llt.solve(rigid.transpose() * rhs);  // R^T M R a = R^T f
      rhs -= mass_rigid * a;                                             // the d'Alembert forces balance the rest
      r.rigid_acceleration = motions.shapes * a;
    } else {
      const std::vector<UnbalancedPart> unbalanced = unbalanced_loads(model, motions, r.applied);
      if (!unbalanced.empty()) throw UnbalancedLoadError(describe(model, motions, unbalanced));
    }
  }
  std::vector<int> auxiliary;
  if (p > 0) {
    auxiliary = auxiliary_supports(rigid);
    for (int e : auxiliary) r.auxiliary_dofs.push_back(dofs.free_dofs[static_cast<std::size_t>(e)]);
  }

  if (progress) progress(fmt::format("factorising K ({} equations)", dofs.free_count()));
  SparseCholesky chol;
  const bool ok = dofs.free_count() > 0 && chol.factorize(p > 0 ? with_auxiliary_supports(k, auxiliary) : k);
  const double rcond = ok ? chol.reciprocal_condition() : 0.0;
  if (!ok || rcond < 1e-12) {
    std::string where = describe_mechanism(model, dofs, k);
    if (where.empty() && !ok && chol.failed_equation() >= 0)
      where = "the factorisation stopped at " + model.describe_dof(dofs.free_dofs[static_cast<std::size_t>(chol.failed_equation())]);
    throw core::NumericalError(fmt::format(
        "the stiffness matrix is singular{}: the frame is a mechanism{}. {}\nAdd supports (*BOUNDARY) or springs, or connect the parts that are loose.",
        ok ? fmt::format(" to working precision (rcond {:.2g})", rcond) : "",
        p > 0 ? fmt::format(" beyond the {} rigid motion(s) its supports leave free ({})", p, r.free_motions) : "",
        where.empty() ? std::string("") : where));
  }
  Eigen::VectorXd rhs_held = rhs;
  for (int e : auxiliary) rhs_held(e) = 0.0;  // a balanced load gives the auxiliary supports no reaction
  Eigen::VectorXd uf = chol.solve(rhs_held);
  // With inertia relief, the elastic part: no rigid motion in the mean, R^T M u = 0 (Eq. 19.6).
  if (r.inertia_relief) uf -= rigid * rigid_gram.llt().solve(mass_rigid.transpose() * uf);
  const Eigen::VectorXd residual = k.selfadjointView<Eigen::Lower>() * uf - rhs;
  r.relative_residual = rhs.norm() > 0 ? residual.norm() / rhs.norm() : residual.norm();

  r.displacement = expand_free(dofs, uf, prescribed);
  // R = T^T (K u - f) at the constrained DOFs: a supported reference node
  // also carries what its slaves transmit (Eq. R.4).
  Eigen::VectorXd residual_all = internal_force(model, r.displacement) - r.applied;
  fold_slave_forces(dofs.links, residual_all);
  r.reaction = Eigen::VectorXd::Zero(ndof);
  for (int g : dofs.constrained_dofs) r.reaction(g) = residual_all(g);
  return r;
}

}  // namespace framedyn::fem
