// Reference ground inputs: a displacement xr(t) and velocity vr(t) of the
// ground end of a tire (or blade) element along the element's direction, the
// thesis's function subroutines (XR_i, VR_i of Eqs. 2.5, 2.6, 2.42), or the
// height of ISO 8608 rough ground under a tire driving over it (Kind::road:
// rigid/road_profile.h, docs/theory/fatigue.md section 6): x = v t - behind,
// so a tire `behind` the front axle sees the front's profile behind / v later.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "rigid/road_profile.h"

namespace framedyn::rigid {

struct GroundInput {
  enum class Kind { none, sine, bump, table, road };
  Kind kind = Kind::none;
  double amplitude = 0.0;   // m (sine: amplitude; bump: height)
  double frequency = 0.0;   // Hz (sine)
  double phase = 0.0;       // rad (sine)
  double start = 0.0;       // s (bump: time the tire reaches it)
  double duration = 0.0;    // s (bump: time to cross it; half-sine shape)
  std::vector<double> times, values;  // table: piecewise linear, m
  std::shared_ptr<const RoadProfile> road;  // road: the ground's profile (shared by the tires that drive over it)
  double speed = 0.0;       // m/s (road: forward speed over the ground)
  double behind = 0.0;      // m (road: how far behind the front axle the tire runs; the wheelbase for the rear tires)
  bool behind_given = false;  // road: `behind` set by the study (else derived from the tire positions, coupling/study_machine_3d.cpp)

  double displacement(double t) const;  // m
  double velocity(double t) const;      // m/s
  // Times where the input has a kink or jump (bump ends, table breakpoints).
  std::vector<double> breakpoints() const;
};

}  // namespace framedyn::rigid
