// Four-bar velocity ratios; see plow_linkage.h.
#include "rigid/plow_linkage.h"

#include <cmath>
#include <stdexcept>

namespace framedyn::rigid {

namespace {
// y x r for r in the X-Z plane: (r_z, -r_x).
Eigen::Vector2d turn(const Eigen::Vector2d& r) { return {r.y(), -r.x()}; }
}  // namespace

Eigen::Vector2d four_bar_velocity_ratios(const FourBarGeometry& g) {
  // Frame held, upper arm turns by 1: d9 = y x (r9 - r6); then
  // phi_s y x (r10 - r9) - phi_l y x (r10 - r11) = -d9.
  const Eigen::Vector2d d9 = turn(g.upper_joint - g.upper_pivot);
  Eigen::Matrix2d a;
  a.col(0) = turn(g.lower_joint - g.upper_joint);
  a.col(1) = -turn(g.lower_joint - g.lower_pivot);
  const double scale = (g.lower_joint - g.upper_joint).norm() * (g.lower_joint - g.lower_pivot).norm();
  if (!(scale > 0.0) || std::abs(a.determinant()) < 1e-9 * scale)
    throw std::invalid_argument("the plow linkage is at a toggle position (shank and lower arm in line) or has a zero-length link");
  return a.lu().solve(-d9);
}

}  // namespace framedyn::rigid
