// What a body's declared size allows its radii of gyration to be: a body of
// mass m inside a box has, about an axis through its c.g. with box sides a and
// b across it, k <= sqrt(a^2 + b^2) / 2 (all the mass at the box's corners,
// Eq. 14.3) and, if declared distributed (spread uniformly through the box),
// k >= sqrt((a^2 + b^2) / 12) (the uniform solid, Eq. 14.4; slender: L/sqrt 12).
// A side that is not declared gives no upper limit about the axes it crosses,
// and leaves the lower one from the declared sides alone (docs/theory/rigid.md,
// section 15). Used for stated and fitted inertias alike (coupling/study_blocks.h).
#pragma once

#include <array>
#include <limits>
#include <optional>

namespace framedyn::rigid {

// A body's bounding box: its sides along X, Y, Z (m), each possibly unknown.
struct BodyBox {
  std::array<std::optional<double>, 3> side;
  bool distributed = false;  // mass spread through the box (a tube, a plate, a casting): Eq. 14.4 applies
};

// The radii of gyration a body in `box` can have about its axis `axis` (0 X, 1 Y, 2 Z).
struct GyrationRange {
  double smallest = 0.0;                                   // Eq. 14.4 (0 unless distributed)
  double largest = std::numeric_limits<double>::infinity();  // Eq. 14.3 (infinite unless both sides across the axis are declared)
};
GyrationRange gyration_range(const BodyBox& box, int axis);

// Where a radius of gyration k lies against a range, with a relative slack
// (1e-6) so that a value on a limit (a uniform tube's L/sqrt 12) is inside.
enum class GyrationVerdict { inside, below_uniform_solid, beyond_corners };
GyrationVerdict judge_gyration(double k, const GyrationRange& range);

}  // namespace framedyn::rigid
