// The per-cycle measures of a plowing run (coupling/study_blocks.h): the
// average peak-to-peak blade motion and the thesis's "average peak" plow
// forces of Figures 9-10, and every peak key of the blade force
// (set_plow_force_peaks), on hand-made signals whose cycle peaks are known.
#include <gtest/gtest.h>

#include "coupling/study_blocks.h"

#include <cmath>
#include <vector>

namespace framedyn {
namespace {

constexpr double kPeriod = 0.05;  // s

// Cycle c of four carries a(c) sin(2 pi t / T) + b(c) (sampled on a grid that
// puts samples exactly on the crests and troughs).
struct Signal {
  std::vector<double> time, values;
};
Signal make_signal(const std::vector<double>& a, const std::vector<double>& b) {
  Signal s;
  const int per_cycle = 200;
  for (std::size_t c = 0; c < a.size(); ++c)
    for (int i = (c == 0 ? 0 : 1); i <= per_cycle; ++i) {
      const double tau = kPeriod * i / per_cycle;
      s.time.push_back(c * kPeriod + tau);
      s.values.push_back(a[c] * std::sin(2 * M_PI * tau / kPeriod) + b[c]);
    }
  return s;
}

TEST(CycleMeasures, AveragePeakIsTheMeanOfEachCyclesLargestValue) {
  // Crests a + b: 1.5, 3, 2.5, 4; troughs b - a: -0.5, -1, 0.5 (none below zero), -2.
  const Signal s = make_signal({1.0, 2.0, 1.0, 3.0}, {0.5, 1.0, 1.5, 1.0});
  const double duration = 4 * kPeriod;
  ASSERT_TRUE(coupling::average_cycle_peak(s.time, s.values, kPeriod, duration));
  EXPECT_NEAR(*coupling::average_cycle_peak(s.time, s.values, kPeriod, duration), (1.5 + 3 + 2.5 + 4) / 4, 1e-12);
  // The backing side: the negated signal; the third cycle never goes below zero and is not counted.
  std::vector<double> negated(s.values.size());
  for (std::size_t i = 0; i < negated.size(); ++i) negated[i] = -s.values[i];
  EXPECT_NEAR(*coupling::average_cycle_peak(s.time, negated, kPeriod, duration), (0.5 + 1 + 2) / 3, 1e-12);
  // Peak to peak: 2a per cycle.
  EXPECT_NEAR(*coupling::average_peak_to_peak(s.time, s.values, kPeriod, duration), (2 + 4 + 2 + 6) / 4.0, 1e-12);
}

TEST(CycleMeasures, OnlyWholeCyclesWithinTheDurationCount) {
  const Signal s = make_signal({1.0, 2.0, 1.0, 3.0}, {0.0, 0.0, 0.0, 0.0});
  // 3.5 periods: the fourth, incomplete cycle is left out.
  EXPECT_NEAR(*coupling::average_cycle_peak(s.time, s.values, kPeriod, 3.5 * kPeriod), (1.0 + 2.0 + 1.0) / 3, 1e-12);
  // A signal that never rises above zero has no average peak.
  const std::vector<double> below(s.values.size(), -1.0);
  EXPECT_FALSE(coupling::average_cycle_peak(s.time, below, kPeriod, 4 * kPeriod));
}

// Every peak key of the blade force (set_plow_force_peaks, Eqs. 13.1-13.2),
// the same function in 2-D and 3-D: the samples are split by the soil law's
// state, not by the force's direction. Two shaker periods; |RPF| = A_c |sin|
// with A = 2, 5, exactly 0 at the period ends; the blade cuts only in the
// first half of the first period. Hand values: peak cutting 2 (t = T/4),
// peak backing 5 (t = 5T/4); the cutting average counts the first period only
// (2), the backing one both (max 2 at 3T/4, then 5: 3.5).
TEST(CycleMeasures, PlowForcePeaksSplitTheSamplesByTheSoilLawsState) {
  std::vector<double> time, blade_z, magnitude;
  std::vector<bool> cutting;
  for (int k = 0; k <= 200; ++k) {
    time.push_back(kPeriod * k / 100.0);
    const double s = std::sin(2 * M_PI * k / 100.0);
    blade_z.push_back(s);
    magnitude.push_back(k % 100 == 0 ? 0.0 : (k < 100 ? 2.0 : 5.0) * std::abs(s));
    cutting.push_back(k >= 1 && k <= 50);
  }
  coupling::VehicleResults r;
  coupling::set_plow_force_peaks(time, blade_z, magnitude, cutting, 1.0 / kPeriod, 2 * kPeriod, r);
  ASSERT_TRUE(r.peak_cutting_force && r.peak_backing_force && r.average_peak_cutting_force && r.average_peak_backing_force);
  EXPECT_NEAR(*r.peak_cutting_force, 2.0, 1e-12);
  EXPECT_NEAR(*r.peak_backing_force, 5.0, 1e-12);
  EXPECT_NEAR(*r.average_peak_cutting_force, 2.0, 1e-12);
  EXPECT_NEAR(*r.average_peak_backing_force, (2.0 + 5.0) / 2, 1e-12);
  ASSERT_TRUE(r.plow_vertical_peak_to_peak);
  EXPECT_NEAR(*r.plow_vertical_peak_to_peak, 2.0, 1e-12);
  // Without a shaker (a chain): the peaks, but no per-cycle measures.
  coupling::VehicleResults chain;
  coupling::set_plow_force_peaks(time, blade_z, magnitude, cutting, 0.0, 2 * kPeriod, chain);
  ASSERT_TRUE(chain.peak_cutting_force);
  EXPECT_NEAR(*chain.peak_cutting_force, 2.0, 1e-12);
  EXPECT_FALSE(chain.average_peak_cutting_force || chain.plow_vertical_peak_to_peak);
}

}  // namespace
}  // namespace framedyn
