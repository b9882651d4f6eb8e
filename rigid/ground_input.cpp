// Ground input profiles; see ground_input.h.
#include "rigid/ground_input.h"

#include <algorithm>
#include <cmath>

namespace framedyn::rigid {

namespace {
constexpr double kTwoPi = 6.283185307179586;
}

double GroundInput::displacement(double t) const {
  switch (kind) {
    case Kind::none: return 0.0;
    case Kind::sine: return amplitude * std::sin(kTwoPi * frequency * t + phase);
    case Kind::bump:
      if (t <= start || t >= start + duration) return 0.0;
      return amplitude * std::sin(M_PI * (t - start) / duration);
    case Kind::table: {
      if (times.empty()) return 0.0;
      if (t <= times.front()) return values.front();
      if (t >= times.back()) return values.back();
      const auto it = std::upper_bound(times.begin(), times.end(), t);
      const std::size_t i = static_cast<std::size_t>(it - times.begin());
      const double w = (t - times[i - 1]) / (times[i] - times[i - 1]);
      return values[i - 1] + w * (values[i] - values[i - 1]);
    }
    case Kind::road: return road ? road->height(speed * t - behind) : 0.0;
  }
  return 0.0;
}

double GroundInput::velocity(double t) const {
  switch (kind) {
    case Kind::none: return 0.0;
    case Kind::sine: return amplitude * kTwoPi * frequency * std::cos(kTwoPi * frequency * t + phase);
    case Kind::bump:
      if (t <= start || t >= start + duration) return 0.0;
      return amplitude * M_PI / duration * std::cos(M_PI * (t - start) / duration);
    case Kind::table: {
      if (times.size() < 2 || t < times.front() || t >= times.back()) return 0.0;
      const auto it = std::upper_bound(times.begin(), times.end(), t);
      const std::size_t i = static_cast<std::size_t>(it - times.begin());
      return (values[i] - values[i - 1]) / (times[i] - times[i - 1]);
    }
    case Kind::road: return road ? speed * road->slope(speed * t - behind) : 0.0;
  }
  return 0.0;
}

std::vector<double> GroundInput::breakpoints() const {
  if (kind == Kind::bump) return {start, start + duration};
  if (kind == Kind::table) return times;
  return {};
}

}  // namespace framedyn::rigid
