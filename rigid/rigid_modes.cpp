// Dense generalised eigenproblem for the vehicle models; see rigid_modes.h.
#include "rigid/rigid_modes.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace framedyn::rigid {

std::vector<RigidMode> rigid_modes(const Eigen::MatrixXd& m, const Eigen::MatrixXd& k, const std::vector<std::string>& names,
                                   const std::vector<std::string>& fixed) {
  const int n = static_cast<int>(names.size());
  std::vector<int> free;
  for (int i = 0; i < n; ++i)
    if (std::find(fixed.begin(), fixed.end(), names[static_cast<std::size_t>(i)]) == fixed.end()) free.push_back(i);
  for (const std::string& f : fixed)
    if (std::find(names.begin(), names.end(), f) == names.end())
      throw std::invalid_argument("cannot fix unknown coordinate '" + f + "'");
  const int nf = static_cast<int>(free.size());
  if (nf == 0) return {};
  Eigen::MatrixXd mf(nf, nf), kf(nf, nf);
  for (int a = 0; a < nf; ++a)
    for (int b = 0; b < nf; ++b) {
      mf(a, b) = m(free[static_cast<std::size_t>(a)], free[static_cast<std::size_t>(b)]);
      kf(a, b) = k(free[static_cast<std::size_t>(a)], free[static_cast<std::size_t>(b)]);
    }
  Eigen::LLT<Eigen::MatrixXd> llt(mf);
  if (llt.info() != Eigen::Success || !mf.allFinite()) {
    // Name the coordinate that leads the motion without inertia.
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> em(mf.allFinite() ? mf : Eigen::MatrixXd::Identity(nf, nf));
    Eigen::Index worst = 0;
    em.eigenvectors().col(0).cwiseAbs().maxCoeff(&worst);
    throw core::NumericalError(fmt::format(
        "the mass matrix of the free coordinates is not positive definite{}: a motion led by coordinate {} has no "
        "inertia (smallest eigenvalue of M {:g}); give the bodies that move with it a mass and inertia, or fix the coordinate",
        mf.allFinite() ? "" : " (it holds a NaN or an infinity)", names[static_cast<std::size_t>(free[static_cast<std::size_t>(worst)])],
        mf.allFinite() ? em.eigenvalues()(0) : std::nan("")));
  }
  if (!kf.allFinite()) throw core::NumericalError("the stiffness matrix of the vehicle holds a NaN or an infinity: check the spring rates");
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(kf, mf);
  if (es.info() != Eigen::Success)
    throw core::NumericalError(
        "the eigenvalue solver for the vehicle modes did not converge (Eigen's QR iteration on the dense problem); "
        "this happens only with extreme values: check the masses and spring rates for values many orders of magnitude "
        "apart, or fix coordinates that do not matter");
  std::vector<RigidMode> modes;
  for (int i = 0; i < nf; ++i) {
    RigidMode mode;
    const double lambda = es.eigenvalues()(i);
    mode.frequency_hz = std::sqrt(std::max(lambda, 0.0)) / (2.0 * M_PI);
    Eigen::VectorXd phi = es.eigenvectors().col(i);
    phi /= std::sqrt(phi.dot(mf * phi));
    Eigen::Index imax = 0;
    phi.cwiseAbs().maxCoeff(&imax);
    if (phi(imax) < 0) phi = -phi;
    const Eigen::VectorXd share = phi.cwiseProduct(mf * phi);
    Eigen::Index dominant = 0;
    share.maxCoeff(&dominant);
    mode.dominant = names[static_cast<std::size_t>(free[static_cast<std::size_t>(dominant)])];
    mode.shape = Eigen::VectorXd::Zero(n);
    mode.energy_share = Eigen::VectorXd::Zero(n);
    for (int a = 0; a < nf; ++a) {
      mode.shape(free[static_cast<std::size_t>(a)]) = phi(a);
      mode.energy_share(free[static_cast<std::size_t>(a)]) = share(a);
    }
    modes.push_back(mode);
  }
  return modes;
}

}  // namespace framedyn::rigid
