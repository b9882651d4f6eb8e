// Reference ground inputs: a displacement xr(t) and velocity vr(t) of the
// ground end of a tire (or blade) element along the element's direction, the
// thesis's function subroutines (XR_i, VR_i of Eqs. 2.5, 2.6, 2.42).
#pragma once

#include <string>
#include <vector>

namespace framedyn::rigid {

struct GroundInput {
  enum class Kind { none, sine, bump, table };
  Kind kind = Kind::none;
  double amplitude = 0.0;   // m (sine: amplitude; bump: height)
  double frequency = 0.0;   // Hz (sine)
  double phase = 0.0;       // rad (sine)
  double start = 0.0;       // s (bump: time the tire reaches it)
  double duration = 0.0;    // s (bump: time to cross it; half-sine shape)
  std::vector<double> times, values;  // table: piecewise linear, m

  double displacement(double t) const;  // m
  double velocity(double t) const;      // m/s
  // Times where the input has a kink or jump (bump ends, table breakpoints).
  std::vector<double> breakpoints() const;
};

}  // namespace framedyn::rigid
