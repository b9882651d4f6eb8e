// Newmark average acceleration on the full frame; see direct_integration.h.
#include "fem/direct_integration.h"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "core/error.h"

namespace framedyn::fem {

namespace {
// " at node 12, UY" where a factorisation of a free-DOF matrix stopped, or "".
std::string where_factorisation_stopped(const FrameDynamics& frame, const SparseCholesky& solver) {
  const int e = solver.failed_equation();
  if (e < 0 || e >= frame.dofs().free_count()) return "";
  return " at " + frame.model().describe_dof(frame.dofs().free_dofs[static_cast<std::size_t>(e)]);
}
}  // namespace

TransientResult direct_transient(const FrameDynamics& frame, const TransientInput& in, const NewmarkOptions& o) {
  const Eigen::Index nt = in.times.size();
  if (nt < 2) throw std::invalid_argument("a transient needs at least two times");
  if (in.components.cols() != nt || in.components.rows() != in.distribution.cols())
    throw std::invalid_argument("load components do not match the times and the load distribution");
  if (o.substeps < 1 || o.output_interval < 1) throw std::invalid_argument("substeps and output interval must be at least 1");
  const double gamma = 0.5, beta = 0.25;

  const SparseMatrix& k = frame.system().stiffness;
  const SparseMatrix& m = frame.system().mass;
  const bool rigid = o.include_rigid_motion && frame.rigid_count() > 0;
  const Eigen::MatrixXd b = frame.free_loads(in.distribution, !rigid);
  const Eigen::Index n = b.rows();
  auto load = [&](Eigen::Index step, double s) -> Eigen::VectorXd {  // F at t_step + s (t_{step+1} - t_step), linear
    if (s == 0.0) return b * in.components.col(step);
    return b * ((1.0 - s) * in.components.col(step) + s * in.components.col(step + 1));
  };
  auto damping_times = [&](const Eigen::VectorXd& x) -> Eigen::VectorXd {
    return o.rayleigh_alpha * frame.mass_times(x) + o.rayleigh_beta * frame.stiffness_times(x);
  };

  Eigen::VectorXd u = Eigen::VectorXd::Zero(n), v = Eigen::VectorXd::Zero(n), a(n);
  Eigen::VectorXd f = load(0, 0.0);
  if (o.initial == InitialState::static_equilibrium) u = frame.static_response(rigid ? frame.relieve(f) : f);
  {  // a0 = M^-1 (F0 - C v0 - K u0)
    SparseCholesky mass_solver;
    if (!mass_solver.factorize(m))
      throw core::NumericalError(fmt::format(
          "the mass matrix is not positive definite{}: cannot start Newmark (a massless degree of freedom, or a negative "
          "density or point mass there?)", where_factorisation_stopped(frame, mass_solver)));
    const Eigen::VectorXd rhs = f - frame.stiffness_times(u);
    mass_solver.solve_in_place(rhs.data(), a.data());
  }

  std::vector<Eigen::Index> outputs;
  for (Eigen::Index kk = 0; kk < nt; kk += o.output_interval) outputs.push_back(kk);
  TransientResult r;
  r.times.resize(static_cast<Eigen::Index>(outputs.size()));
  r.displacement.resize(frame.model().dof_count(), static_cast<Eigen::Index>(outputs.size()));
  std::size_t next_out = 0;
  auto record = [&](Eigen::Index kk) {
    if (next_out < outputs.size() && outputs[next_out] == kk) {
      r.times(static_cast<Eigen::Index>(next_out)) = in.times(kk);
      r.displacement.col(static_cast<Eigen::Index>(next_out++)) = frame.expand(rigid ? u : frame.elastic_part(u));
    }
  };
  record(0);

  SparseCholesky solver;
  double h_prev = -1.0;
  Eigen::VectorXd rhs(n), u1(n);
  for (Eigen::Index kk = 0; kk + 1 < nt; ++kk) {
    const double h = (in.times(kk + 1) - in.times(kk)) / o.substeps;
    if (std::abs(h - h_prev) > 1e-12 * h) {
      // K_eff = K + gamma/(beta h) C + 1/(beta h^2) M (Eq. T.14).
      const double cm = 1.0 / (beta * h * h) + gamma / (beta * h) * o.rayleigh_alpha;
      const double ck = 1.0 + gamma / (beta * h) * o.rayleigh_beta;
      const SparseMatrix keff = (ck * k + cm * m).pruned();
      if (!solver.factorize(keff))
        throw core::NumericalError(fmt::format(
            "the effective stiffness of the Newmark step (h = {:g} s) is not positive definite{} (a negative stiffness, "
            "density or damping there?)", h, where_factorisation_stopped(frame, solver)));
      h_prev = h;
    }
    for (int s = 1; s <= o.substeps; ++s) {
      const Eigen::VectorXd f1 = s == o.substeps ? load(kk + 1, 0.0) : load(kk, static_cast<double>(s) / o.substeps);
      // Eq. (T.15): right-hand side from the state at t_n.
      const Eigen::VectorXd mu = u / (beta * h * h) + v / (beta * h) + (0.5 / beta - 1.0) * a;
      const Eigen::VectorXd cu = gamma / (beta * h) * u + (gamma / beta - 1.0) * v + h * (0.5 * gamma / beta - 1.0) * a;
      rhs = f1 + frame.mass_times(mu) + damping_times(cu);
      solver.solve_in_place(rhs.data(), u1.data());
      const Eigen::VectorXd a1 = (u1 - u) / (beta * h * h) - v / (beta * h) - (0.5 / beta - 1.0) * a;
      v += h * ((1.0 - gamma) * a + gamma * a1);
      a = a1;
      u = u1;
    }
    record(kk + 1);
  }
  return r;
}

}  // namespace framedyn::fem
