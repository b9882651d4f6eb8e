// ISO 8608 rough ground (docs/validation.md V14.8): the generated profile's mean square over
// one period against the integral of the standard's PSD over the generated band, the classes'
// ordering (each class doubles the RMS), the rear axle seeing the front's profile one
// wheelbase later, and a seed giving the same ground every time.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "rigid/ground_input.h"
#include "rigid/road_profile.h"

#include <memory>

namespace {

using namespace framedyn::rigid;

RoadProfileOptions options(RoadClass c, double length, std::uint64_t seed = 8608) {
  RoadProfileOptions o;
  o.road_class = c;
  o.length = length;
  o.seed = seed;
  return o;
}

// Mean square of h sampled at M points over one period L.
double sampled_mean_square(const RoadProfile& p, int M) {
  double s = 0.0;
  for (int j = 0; j < M; ++j) {
    const double h = p.height(p.options().length * j / M);
    s += h * h;
  }
  return s / M;
}

TEST(Iso8608RoadProfile, MeanSquareOverOnePeriodIsTheIntegralOfThePsdOverTheBand) {
  // Class C (Gd(n0) = 256e-6 m^3), L = 200 m: lines k/200 from 0.015 to 2.83 cycle/m (564 lines).
  const RoadProfile p(options(RoadClass::C, 200.0));
  ASSERT_EQ(p.lines().size(), 564u);
  EXPECT_EQ(iso8608_gd_n0(RoadClass::C), 256e-6);
  // Sampled at M = 2048 > 2 k_max = 1132 points a period, the cosines are orthogonal: the
  // sampled mean square is sum A_k^2 / 2 to round-off.
  EXPECT_NEAR(sampled_mean_square(p, 2048), p.mean_square(), 1e-10 * p.mean_square());
  // sum A_k^2 / 2 = sum Gd(n_k) dn is the midpoint rule for the integral of Gd = c n^-2 over
  // the band. Gd is convex, so the rule falls short, by at most sum Gd''(n_k - dn/2) dn^3 / 24
  // (2.3 % here, from the lowest lines, where dn / n = 1/3) and to leading order by
  // sum Gd''(n_k) dn^3 / 24 (to within (dn / n_1)^2 = 11 % of itself).
  const double dn = 1.0 / 200.0, c = 256e-6 * 0.01;
  double bound = 0.0, leading = 0.0;
  for (const RoadProfile::Line& l : p.lines()) {
    bound += 6.0 * c * std::pow(l.n - dn / 2, -4) * dn * dn * dn / 24.0;
    leading += 6.0 * c * std::pow(l.n, -4) * dn * dn * dn / 24.0;
  }
  const double shortfall = p.psd_integral() - p.mean_square();
  EXPECT_GE(shortfall, 0.0);
  EXPECT_LE(shortfall, bound);
  EXPECT_LT(bound, 0.03 * p.psd_integral());  // RMS within 1.2 % of the band integral's root
  EXPECT_NEAR(shortfall, leading, 0.11 * leading);
  std::printf("class C, L = 200 m: mean square %.6g m^2, band integral %.6g m^2, shortfall %.4g (bound %.4g, leading order %.4g)\n", p.mean_square(),
              p.psd_integral(), shortfall, bound, leading);
  // The band's integral by hand: c (1/a - 1/b), a = 3/200 - dn/2, b = 566/200 + dn/2.
  EXPECT_NEAR(p.psd_integral(), c * (1.0 / (0.015 - dn / 2) - 1.0 / (2.83 + dn / 2)), 1e-12 * p.psd_integral());
  // The lines' PSD is the standard's at every line: A_k^2 / (2 dn) = Gd(n0) (n_k / n0)^-2.
  for (const RoadProfile::Line& l : p.lines()) EXPECT_NEAR(l.amplitude * l.amplitude / (2 * dn), 256e-6 * std::pow(l.n / 0.1, -2), 1e-12 * 256e-6 * std::pow(l.n / 0.1, -2));
}

// The PSD of the heights themselves, not of the lines' amplitudes: the discrete Fourier transform
// of one period of h sampled at M = 1024 points (more than twice the highest line, k = 283, so no
// line aliases onto another) gives each line's amplitude back, and the one-sided PSD at n_k = k / L,
// |H_k|^2 / (2 dn), is ISO 8608's G_d(n) = G_d(n0) (n / n0)^-2 with class D's G_d(n0) = 1024e-6 m^3
// (the geometric mean of its class band, ISO 8608 Table 1) at every line; the bins outside the band
// 0.011-2.83 cycle/m hold no power. Round-off: each DFT bin sums 1024 terms of size <= the RMS
// (about 1e-13 of the RMS), against the weakest line's amplitude, 7e-3 of the RMS: 1e-9 relative.
TEST(Iso8608RoadProfile, PsdOfTheSampledHeightsIsTheStandardsAtEveryLineAndZeroOutsideTheBand) {
  const double L = 100.0, dn = 1.0 / L, gd_n0 = 1024e-6;
  const RoadProfile p(options(RoadClass::D, L));
  const int M = 1024;
  std::vector<double> h(M);
  for (int j = 0; j < M; ++j) h[static_cast<std::size_t>(j)] = p.height(L * j / M);
  const double rms = std::sqrt(p.mean_square());
  std::vector<bool> is_line(M / 2, false);
  for (const RoadProfile::Line& l : p.lines()) is_line[static_cast<std::size_t>(std::lround(l.n * L))] = true;
  double band_power = 0.0, outside = 0.0;
  int lines = 0;
  for (int k = 1; k < M / 2; ++k) {
    double a = 0.0, b = 0.0;
    for (int j = 0; j < M; ++j) {
      const double w = 2.0 * M_PI * static_cast<double>(k) * j / M;
      a += h[static_cast<std::size_t>(j)] * std::cos(w);
      b += h[static_cast<std::size_t>(j)] * std::sin(w);
    }
    const double amplitude2 = (a * a + b * b) * 4.0 / (static_cast<double>(M) * M);  // |2 H_k / M|^2
    const double n = k * dn;
    if (is_line[static_cast<std::size_t>(k)]) {
      ++lines;
      const double standard = gd_n0 * std::pow(n / kIso8608ReferenceFrequency, -2.0);
      EXPECT_NEAR(amplitude2 / (2.0 * dn), standard, 1e-9 * standard) << "n = " << n << " cycle/m";
      EXPECT_GE(n, 0.011);
      EXPECT_LE(n, 2.83 + 1e-12);
      band_power += amplitude2 / 2.0;
    } else {
      outside = std::max(outside, std::sqrt(amplitude2));
    }
  }
  EXPECT_EQ(lines, 282);  // k = 2 (0.011 L = 1.1 rounded up) to 283 (2.83 L)
  EXPECT_LT(outside, 1e-12 * rms);
  // Parseval: the bins' power is the profile's mean square.
  EXPECT_NEAR(band_power, p.mean_square(), 1e-10 * p.mean_square());
  std::printf("class D, L = 100 m: %d lines, RMS %.6g m (sqrt of the band integral of the standard's PSD: %.6g m), largest bin outside the band %.2g m\n",
              lines, rms, std::sqrt(p.psd_integral()), outside);
}

TEST(Iso8608RoadProfile, EachClassDoublesTheRmsOfTheOneBefore) {
  // Gd(n0) grows by 4 from class to class (A 16e-6 ... H 262144e-6 m^3), so with the same
  // phases the heights, and the RMS, double.
  double previous = 0.0;
  for (char letter = 'A'; letter <= 'H'; ++letter) {
    const RoadProfile p(options(road_class_from_letter(letter), 100.0));
    const double rms = std::sqrt(sampled_mean_square(p, 1024));
    EXPECT_NEAR(iso8608_gd_n0(road_class_from_letter(letter)), 16e-6 * std::pow(4.0, letter - 'A'), 1e-18);
    if (letter > 'A') {
      EXPECT_NEAR(rms / previous, 2.0, 1e-12) << "class " << letter;
    }
    previous = rms;
  }
  EXPECT_THROW(road_class_from_letter('I'), std::invalid_argument);
}

TEST(Iso8608RoadProfile, RearTiresSeeTheFrontProfileOneWheelbaseLater) {
  const double v = 4.0, wheelbase = 2.5;
  const RoughGroundInput input(RoadProfile(options(RoadClass::D, 100.0)), v, wheelbase);
  const double scale = std::sqrt(input.profile().mean_square());
  for (double t : {3.0, 7.25, 11.5}) {
    const AxleGroundInputs now = input.at(t), later = input.at(t + wheelbase / v);
    // x = v (t + wheelbase / v) - wheelbase is v t to round-off (1e-14 m): the same ground.
    EXPECT_NEAR(later.rear_height, now.front_height, 1e-9 * scale);
    EXPECT_NEAR(later.rear_velocity, now.front_velocity, 1e-9 * v);
  }
  // The vertical velocity is v dh/dx: against a central difference of the height over time
  // (step 1e-5 s; truncation (2 pi n_max v)^2 dt^2 / 6 < 1e-6 relative, round-off < 1e-9 / dt).
  const double t = 5.0, dt = 1e-5;
  const double fd = (input.at(t + dt).front_height - input.at(t - dt).front_height) / (2 * dt);
  EXPECT_NEAR(input.at(t).front_velocity, fd, 1e-5 * std::abs(fd) + 1e-9);
  // Lines k / 100 from k = 2 (0.011 * 100 = 1.1 rounds up) to 283: the input's band is n v.
  EXPECT_DOUBLE_EQ(input.lowest_frequency(), 2.0 / 100.0 * v);
  EXPECT_DOUBLE_EQ(input.highest_frequency(), 283.0 / 100.0 * v);
}

TEST(Iso8608RoadProfile, ASeedGivesTheSameGroundAndAnotherSeedAnother) {
  const RoadProfile a(options(RoadClass::B, 50.0, 1)), b(options(RoadClass::B, 50.0, 1)), c(options(RoadClass::B, 50.0, 2));
  for (double x : {0.0, 1.7, 33.3}) {
    EXPECT_EQ(a.height(x), b.height(x));
    EXPECT_NE(a.height(x), c.height(x));
  }
}

}  // namespace

// The tires' ground input of kind road (rigid/ground_input.h): a rear tire `behind` = the
// wheelbase sees the front tire's height and vertical velocity wheelbase / speed later, and
// both equal RoughGroundInput's axles on the same profile.
TEST(Iso8608RoadProfile, RoadGroundInputsRearDelayIsWheelbaseOverSpeed) {
  const double v = 2.0, wheelbase = 1.8288;  // m/s; 72 in
  auto profile = std::make_shared<const RoadProfile>(options(RoadClass::D, 100.0));
  GroundInput front, rear;
  front.kind = rear.kind = GroundInput::Kind::road;
  front.road = rear.road = profile;
  front.speed = rear.speed = v;
  rear.behind = wheelbase;
  const RoughGroundInput axles(*profile, v, wheelbase);
  const double scale = std::sqrt(profile->mean_square());
  for (double t : {1.0, 2.345, 6.5}) {
    EXPECT_NEAR(rear.displacement(t + wheelbase / v), front.displacement(t), 1e-9 * scale);
    EXPECT_NEAR(rear.velocity(t + wheelbase / v), front.velocity(t), 1e-9 * v);
    EXPECT_NEAR(front.displacement(t), axles.at(t).front_height, 1e-12 * scale);
    EXPECT_NEAR(rear.displacement(t), axles.at(t).rear_height, 1e-12 * scale);
    EXPECT_NEAR(rear.velocity(t), axles.at(t).rear_velocity, 1e-12 * v);
  }
  EXPECT_TRUE(front.breakpoints().empty());  // smooth: no kinks for the integrator to stop at
}
