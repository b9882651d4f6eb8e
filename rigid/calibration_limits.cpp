// Radius-of-gyration limits of a body from its declared box; see
// calibration_limits.h and docs/theory/rigid.md, section 15 (Eqs. 14.3, 14.4).
#include "rigid/calibration_limits.h"

#include <cmath>

namespace framedyn::rigid {

GyrationRange gyration_range(const BodyBox& box, int axis) {
  const std::optional<double>& a = box.side[static_cast<std::size_t>((axis + 1) % 3)];
  const std::optional<double>& b = box.side[static_cast<std::size_t>((axis + 2) % 3)];
  GyrationRange r;
  if (a && b) r.largest = 0.5 * std::hypot(*a, *b);  // Eq. 14.3: all the mass at the corners
  // Eq. 14.4 with the declared sides only: an undeclared side can only add to the uniform solid's k.
  if (box.distributed) r.smallest = std::hypot(a.value_or(0.0), b.value_or(0.0)) / std::sqrt(12.0);
  return r;
}

GyrationVerdict judge_gyration(double k, const GyrationRange& range) {
  constexpr double kSlack = 1e-6;
  if (k > range.largest * (1 + kSlack)) return GyrationVerdict::beyond_corners;
  if (k < range.smallest * (1 - kSlack)) return GyrationVerdict::below_uniform_solid;
  return GyrationVerdict::inside;
}

}  // namespace framedyn::rigid
