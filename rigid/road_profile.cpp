// ISO 8608 rough ground; see road_profile.h and docs/theory/fatigue.md section 6.
#include "rigid/road_profile.h"

#include <cmath>
#include <random>
#include <stdexcept>

namespace framedyn::rigid {

namespace {
constexpr double kTwoPi = 6.283185307179586476925;
}  // namespace

double iso8608_gd_n0(RoadClass c) { return 16e-6 * std::pow(4.0, static_cast<int>(c)); }  // F.16

RoadClass road_class_from_letter(char letter) {
  const char u = (letter >= 'a' && letter <= 'h') ? static_cast<char>(letter - 'a' + 'A') : letter;
  if (u < 'A' || u > 'H') throw std::invalid_argument(std::string("ISO 8608 road class must be A to H, found '") + letter + "'");
  return static_cast<RoadClass>(u - 'A');
}

RoadProfile::RoadProfile(const RoadProfileOptions& o) : options_(o) {
  if (!(o.length > 0.0) || !(o.n_min > 0.0) || !(o.n_max > o.n_min) || !std::isfinite(o.length) || !std::isfinite(o.n_max))
    throw std::invalid_argument("road profile: need a positive length and 0 < n_min < n_max");
  const double gd0 = iso8608_gd_n0(o.road_class), n0 = kIso8608ReferenceFrequency, dn = 1.0 / o.length;
  const long k1 = static_cast<long>(std::ceil(o.n_min * o.length)), k2 = static_cast<long>(std::floor(o.n_max * o.length));
  if (k2 < k1 || k2 < 1) throw std::invalid_argument("road profile: no line k / L inside the band (the length is too short)");
  std::mt19937_64 gen(o.seed);
  for (long k = std::max(k1, 1L); k <= k2; ++k) {
    const double n = static_cast<double>(k) * dn;
    const double gd = gd0 * (n0 / n) * (n0 / n);                          // F.15
    const double u = static_cast<double>(gen() >> 11) * 0x1.0p-53;        // uniform in [0, 1), 53 bits
    lines_.push_back({n, std::sqrt(2.0 * gd * dn), kTwoPi * u});          // F.17
  }
}

double RoadProfile::height(double x) const {
  double h = 0.0;
  for (const Line& l : lines_) h += l.amplitude * std::cos(kTwoPi * l.n * x + l.phase);
  return h;
}

double RoadProfile::slope(double x) const {
  double s = 0.0;
  for (const Line& l : lines_) s -= l.amplitude * kTwoPi * l.n * std::sin(kTwoPi * l.n * x + l.phase);
  return s;
}

double RoadProfile::mean_square() const {
  double m = 0.0;
  for (const Line& l : lines_) m += 0.5 * l.amplitude * l.amplitude;  // F.18
  return m;
}

double RoadProfile::psd_integral() const {
  // F.19: integral of Gd(n0) n0^2 n^-2 from a to b = Gd(n0) n0^2 (1/a - 1/b).
  const double half = 0.5 / options_.length, n0 = kIso8608ReferenceFrequency;
  const double a = lines_.front().n - half, b = lines_.back().n + half;
  return iso8608_gd_n0(options_.road_class) * n0 * n0 * (1.0 / a - 1.0 / b);
}

RoughGroundInput::RoughGroundInput(RoadProfile profile, double speed, double wheelbase)
    : profile_(std::move(profile)), speed_(speed), wheelbase_(wheelbase) {
  if (!(speed_ > 0.0) || !(wheelbase_ > 0.0) || !std::isfinite(speed_) || !std::isfinite(wheelbase_))
    throw std::invalid_argument("rough ground input: need a positive speed and wheelbase");
}

AxleGroundInputs RoughGroundInput::at(double t) const {
  const double xf = speed_ * t, xr = xf - wheelbase_;  // the rear axle a wheelbase behind
  return {profile_.height(xf), speed_ * profile_.slope(xf), profile_.height(xr), speed_ * profile_.slope(xr)};
}

double RoughGroundInput::lowest_frequency() const { return profile_.lines().front().n * speed_; }
double RoughGroundInput::highest_frequency() const { return profile_.lines().back().n * speed_; }

}  // namespace framedyn::rigid
