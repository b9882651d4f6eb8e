// Static condensation of released member-end rotations; see member_releases.h.
#include "fem/member_releases.h"

#include <algorithm>
#include <stdexcept>
#include <vector>

namespace framedyn::fem {

Eigen::Matrix<double, 12, 12> release_transformation(const Eigen::Matrix<double, 12, 12>& k, ReleaseMask released) {
  if (released == 0) return Eigen::Matrix<double, 12, 12>::Identity();
  std::vector<int> r;
  for (int i = 0; i < 12; ++i)
    if ((released >> i) & 1u) r.push_back(i);
  return release_transformation(Eigen::MatrixXd(k), r, released);
}

Eigen::MatrixXd release_transformation(const Eigen::MatrixXd& k, const std::vector<int>& r, ReleaseMask released) {
  const int n = static_cast<int>(k.rows());
  Eigen::MatrixXd t = Eigen::MatrixXd::Identity(n, n);
  if (r.empty()) return t;
  std::vector<int> c;
  for (int i = 0; i < n; ++i)
    if (std::find(r.begin(), r.end(), i) == r.end()) c.push_back(i);
  const int nr = static_cast<int>(r.size()), nc = static_cast<int>(c.size());
  Eigen::MatrixXd krr(nr, nr), krc(nr, nc);
  for (int i = 0; i < nr; ++i) {
    for (int j = 0; j < nr; ++j) krr(i, j) = k(r[static_cast<std::size_t>(i)], r[static_cast<std::size_t>(j)]);
    for (int j = 0; j < nc; ++j) krc(i, j) = k(r[static_cast<std::size_t>(i)], c[static_cast<std::size_t>(j)]);
  }
  // K_rr is symmetric positive semi-definite; it is singular exactly when the
  // released rotations can turn without straining the element (a free twist
  // with torsion released at both ends). Judge by the pivots against the diagonal.
  Eigen::LDLT<Eigen::MatrixXd> ldlt(krr);
  const double scale = krr.diagonal().cwiseAbs().maxCoeff();
  const Eigen::VectorXd pivots = ldlt.vectorD();
  if (ldlt.info() != Eigen::Success || !(scale > 0.0) || !(pivots.minCoeff() > 1e-10 * scale))
    throw std::invalid_argument("the released rotations (" + describe_releases(released) +
                                ") leave the element free to rotate without strain (torsion released at both ends?)");
  const Eigen::MatrixXd follow = -ldlt.solve(krc);  // u_r = follow u_c
  for (int i = 0; i < nr; ++i) {
    const int row = r[static_cast<std::size_t>(i)];
    t(row, row) = 0.0;
    for (int j = 0; j < nc; ++j) t(row, c[static_cast<std::size_t>(j)]) = follow(i, j);
  }
  return t;
}

std::string describe_releases(ReleaseMask released) {
  std::string out;
  for (int end = 0; end < 2; ++end) {
    std::string list;
    const char* names[3] = {"T", "M1", "M2"};
    for (int k = 0; k < 3; ++k)
      if (released & release_bit(end, 3 + k)) list += (list.empty() ? "" : ", ") + std::string(names[k]);
    if (!list.empty()) out += (out.empty() ? "" : "; ") + std::string(end == 0 ? "S1: " : "S2: ") + list;
  }
  return out.empty() ? "none" : out;
}

}  // namespace framedyn::fem
