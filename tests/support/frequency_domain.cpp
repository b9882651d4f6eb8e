// Direct frequency-domain solve; see frequency_domain.h.
#include "tests/support/frequency_domain.h"

#include <Eigen/SparseLU>

#include <stdexcept>

namespace framedyn::testing {

Eigen::VectorXcd direct_frequency_solve(const fem::FrameDynamics& frame, const Eigen::VectorXd& load, double omega, double alpha, double beta) {
  using cd = std::complex<double>;
  const fem::SparseMatrix k = frame.system().stiffness.selfadjointView<Eigen::Lower>();
  const fem::SparseMatrix m = frame.system().mass.selfadjointView<Eigen::Lower>();
  const Eigen::SparseMatrix<cd> a =
      k.cast<cd>() - cd(omega * omega, 0.0) * m.cast<cd>() + cd(0.0, omega) * (cd(alpha) * m.cast<cd>() + cd(beta) * k.cast<cd>());
  Eigen::SparseLU<Eigen::SparseMatrix<cd>> lu(a);
  if (lu.info() != Eigen::Success) throw std::runtime_error("the direct frequency-domain solve failed to factorise");
  const std::vector<int>& free = frame.dofs().free_dofs;
  Eigen::VectorXcd f(frame.dofs().free_count());
  for (int e = 0; e < f.size(); ++e) f(e) = load(free[static_cast<std::size_t>(e)]);
  const Eigen::VectorXcd u = lu.solve(f);
  Eigen::VectorXcd all = Eigen::VectorXcd::Zero(frame.model().dof_count());
  for (int e = 0; e < f.size(); ++e) all(free[static_cast<std::size_t>(e)]) = u(e);
  return all;
}

}  // namespace framedyn::testing
