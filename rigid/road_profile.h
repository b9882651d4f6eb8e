// Rough ground of an ISO 8608 class (ISO 8608:2016, docs/theory/fatigue.md section 6,
// Eqs. F.15-F.19): the road's vertical displacement PSD
//   Gd(n) = Gd(n0) (n / n0)^-2,  n0 = 0.1 cycle/m,
// with Gd(n0) the class's geometric mean (A: 16e-6 m^3, each class 4 times the one before:
// B 64e-6 ... H 262144e-6), realised as a sum of cosines
//   h(x) = sum_k A_k cos(2 pi n_k x + phi_k),  n_k = k / L,  A_k = sqrt(2 Gd(n_k) / L),
// over the lines k / L inside the band [n_min, n_max] (default ISO 8608's 0.011 to 2.83
// cycle/m), with phases phi_k = 2 pi u_k from std::mt19937_64(seed) and u_k = (bits >> 11) 2^-53
// (not std::uniform_real_distribution, whose output differs between standard libraries), so
// that a seed gives the same ground on every machine. The profile is periodic in L: over one
// length its mean square is sum A_k^2 / 2, the midpoint-rule integral of Gd over the band.
// Both tracks see the same profile (no left-right difference; a roll input is not modelled).
// RoughGroundInput drives the tires: the front axle at x = v t, the rear axle one wheelbase
// behind, so the rear tires see the front's profile wheelbase / v later.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace framedyn::rigid {

enum class RoadClass { A, B, C, D, E, F, G, H };

// Gd(n0) of the class, m^3 (= m^2 / (cycle/m)).
double iso8608_gd_n0(RoadClass c);
// 'A'..'H' (either case); throws std::invalid_argument otherwise.
RoadClass road_class_from_letter(char letter);
inline constexpr double kIso8608ReferenceFrequency = 0.1;  // n0, cycle/m

struct RoadProfileOptions {
  RoadClass road_class = RoadClass::C;
  double length = 1000.0;   // L, m: the period of the profile and 1 / line spacing
  std::uint64_t seed = 8608;
  double n_min = 0.011;     // cycle/m, the band's lower end (ISO 8608's range)
  double n_max = 2.83;      // cycle/m, upper end
};

class RoadProfile {
 public:
  struct Line {
    double n;          // spatial frequency, cycle/m
    double amplitude;  // m
    double phase;      // rad
  };
  // Throws std::invalid_argument on a band or length that leaves no line.
  explicit RoadProfile(const RoadProfileOptions& options);

  double height(double x) const;  // m, at distance x (m) along the path
  double slope(double x) const;   // dh/dx
  // The mean square over one period, sum A_k^2 / 2 (m^2).
  double mean_square() const;
  // The integral of Gd over the lines' band [n_1 - 1/(2L), n_K + 1/(2L)], closed form (m^2).
  double psd_integral() const;
  const std::vector<Line>& lines() const { return lines_; }
  const RoadProfileOptions& options() const { return options_; }

 private:
  RoadProfileOptions options_;
  std::vector<Line> lines_;
};

// The ground under both axles over time (m, m/s).
struct AxleGroundInputs {
  double front_height = 0.0, front_velocity = 0.0;
  double rear_height = 0.0, rear_velocity = 0.0;
};

class RoughGroundInput {
 public:
  // speed: m/s forward (> 0); wheelbase: m from front to rear axle (> 0).
  RoughGroundInput(RoadProfile profile, double speed, double wheelbase);
  AxleGroundInputs at(double t) const;  // t in s; the front axle at x = 0 at t = 0
  // Temporal frequency band of the input, Hz: n v over the profile's lines.
  double lowest_frequency() const;
  double highest_frequency() const;
  const RoadProfile& profile() const { return profile_; }

 private:
  RoadProfile profile_;
  double speed_, wheelbase_;
};

}  // namespace framedyn::rigid
