// Static solve and reactions; mechanism diagnosis by the stiffness matrix's null space.
#include "fem/static_analysis.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <set>

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

namespace {

// K_ff factorised once for a model's supports and rigid links (section 19's
// auxiliary supports included); each load case is then one solve.
struct FactorisedStiffness {
  DofMap dofs;
  FreeSystem system;
  FreeRigidMotions motions;
  int p = 0;
  bool inertia_relief = false;
  Eigen::MatrixXd rigid, mass_rigid, rigid_gram;
  std::vector<int> auxiliary;
  SparseCholesky chol;
};

void factorise(const FrameModel& model, const std::function<void(const std::string&)>& progress, const StaticOptions& options,
               FactorisedStiffness& f) {
  f.dofs = make_dof_map(model);
  if (progress) progress(fmt::format("assembling {} beam elements ({} free DOFs)", model.beams.size(), f.dofs.free_count()));
  f.system = assemble(model, f.dofs, {MassFormulation::consistent, Storage::lower});
  const SparseMatrix& k = f.system.stiffness;
  // Rigid motions the supports leave free (section 19): the loads must do no
  // work on them (Eq. 19.1), or be relieved by their inertia (Eq. 19.5).
  f.motions = free_rigid_motions(model);
  f.p = static_cast<int>(f.motions.shapes.cols());
  f.inertia_relief = options.inertia_relief && f.p > 0;
  if (f.p > 0) {
    f.rigid = rigid_motions_on_equations(f.dofs, f.motions.shapes);
    if (f.inertia_relief) {
      f.mass_rigid = f.system.mass.selfadjointView<Eigen::Lower>() * f.rigid;
      f.rigid_gram = f.rigid.transpose() * f.mass_rigid;
      if (Eigen::LLT<Eigen::MatrixXd>(f.rigid_gram).info() != Eigen::Success)
        throw core::NumericalError("inertia relief needs the mass of the free rigid motions, and it is singular (no *DENSITY and no point mass "
                                   "on a part that can move rigidly?)");
    }
    f.auxiliary = auxiliary_supports(f.rigid);
  }
  if (progress) progress(fmt::format("factorising K ({} equations)", f.dofs.free_count()));
  const bool ok = f.dofs.free_count() > 0 && f.chol.factorize(f.p > 0 ? with_auxiliary_supports(k, f.auxiliary) : k);
  const double rcond = ok ? f.chol.reciprocal_condition() : 0.0;
  if (!ok || rcond < 1e-12) {
    std::string where = describe_mechanism(model, f.dofs, k);
    if (where.empty() && !ok && f.chol.failed_equation() >= 0)
      where = "the factorisation stopped at " + model.describe_dof(f.dofs.free_dofs[static_cast<std::size_t>(f.chol.failed_equation())]);
    throw core::NumericalError(fmt::format(
        "the stiffness matrix is singular{}: the frame is a mechanism{}. {}\nAdd supports (*BOUNDARY) or springs, or connect the parts that are loose.",
        ok ? fmt::format(" to working precision (rcond {:.2g})", rcond) : "",
        f.p > 0 ? fmt::format(" beyond the {} rigid motion(s) its supports leave free ({})", f.p, f.motions.describe(model)) : "",
        where.empty() ? std::string("") : where));
  }
}

// The load case of `model` (its loads and prescribed values) on f, which was
// factorised for a model with the same supports and links.
StaticResult solve_case(const FrameModel& model, const FactorisedStiffness& f) {
  const DofMap& dofs = f.dofs;
  const int ndof = model.dof_count();
  StaticResult r;
  r.applied = applied_loads(model);  // nodal loads and the consistent loads of *DLOAD
  Eigen::VectorXd prescribed = Eigen::VectorXd::Zero(ndof);
  for (const Constraint& c : model.constraints) prescribed(kDofsPerNode * c.node + c.dof) = c.value;
  fill_slave_dofs(dofs.links, prescribed);  // slaves of a supported reference node move with it
  // T^T (f - K u_c) on the free DOFs, with K u_c computed element by element
  // (T: rigid links' slaves, Eq. R.2; the identity without links).
  Eigen::VectorXd rhs = restrict_load(dofs, r.applied - internal_force(model, prescribed));
  r.free_rigid_motions = f.p;
  r.free_motions = f.motions.describe(model);
  r.inertia_relief = f.inertia_relief;
  if (f.p > 0) {
    if (f.inertia_relief) {
      const Eigen::VectorXd a = f.rigid_gram.llt().solve(f.rigid.transpose() * rhs);  // R^T M R a = R^T f
      rhs -= f.mass_rigid * a;                                                         // the d'Alembert forces balance the rest
      r.rigid_acceleration = f.motions.shapes * a;
    } else {
      const std::vector<UnbalancedPart> unbalanced = unbalanced_loads(model, f.motions, r.applied);
      if (!unbalanced.empty()) throw UnbalancedLoadError(describe(model, f.motions, unbalanced));
    }
    for (int e : f.auxiliary) r.auxiliary_dofs.push_back(dofs.free_dofs[static_cast<std::size_t>(e)]);
  }
  Eigen::VectorXd rhs_held = rhs;
  for (int e : f.auxiliary) rhs_held(e) = 0.0;  // a balanced load gives the auxiliary supports no reaction
  Eigen::VectorXd uf = f.chol.solve(rhs_held);
  // With inertia relief, the elastic part: no rigid motion in the mean, R^T M u = 0 (Eq. 19.6).
  if (f.inertia_relief) uf -= f.rigid * f.rigid_gram.llt().solve(f.mass_rigid.transpose() * uf);
  const Eigen::VectorXd residual = f.system.stiffness.selfadjointView<Eigen::Lower>() * uf - rhs;
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

// The supported DOFs, whatever their values: load cases that share them share K_ff.
std::set<std::pair<int, int>> supported_dofs(const FrameModel& model) {
  std::set<std::pair<int, int>> out;
  for (const Constraint& c : model.constraints) out.insert({c.node, c.dof});
  return out;
}

}  // namespace

StaticResult solve_static(const FrameModel& model, const std::function<void(const std::string&)>& progress, const StaticOptions& options) {
  FactorisedStiffness f;
  factorise(model, progress, options, f);
  return solve_case(model, f);
}

std::vector<StaticResult> solve_static_cases(const std::vector<FrameModel>& cases, const std::function<void(const std::string&)>& progress,
                                             const StaticOptions& options, int* factorisations) {
  std::vector<StaticResult> out;
  FactorisedStiffness f;
  std::set<std::pair<int, int>> factorised_for;
  int count = 0;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    std::set<std::pair<int, int>> supports = supported_dofs(cases[i]);
    if (i == 0 || supports != factorised_for) {
      factorise(cases[i], progress, options, f);
      factorised_for = std::move(supports);
      ++count;
    }
    if (progress) progress(fmt::format("solving load case {} of {}", i + 1, cases.size()));
    out.push_back(solve_case(cases[i], f));
  }
  if (factorisations) *factorisations = count;
  return out;
}

std::vector<StaticLoadCase> static_load_cases(const FrameModel& model, const std::string& source) {
  std::vector<StaticLoadCase> cases;
  for (std::size_t i = 0; i < model.steps.size(); ++i)
    if (model.steps[i].procedure == "STATIC") cases.push_back({with_step(model, i), model.steps[i].number});
  const bool several = cases.size() > 1;
  if (!several) cases = {{model, 0}};
  for (const StaticLoadCase& c : cases)
    if (c.model.loads.empty() && c.model.element_loads.empty())
      throw core::InputError({source, 0, "*CLOAD"},
                             "at least one nodal load (*CLOAD) or distributed load (*DLOAD) for a static analysis" +
                                 (several ? std::string(" in every static step") : std::string()),
                             several ? "none in step " + std::to_string(c.step) : std::string("none"));
  return cases;
}

}  // namespace framedyn::fem
