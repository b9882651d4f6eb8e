// The steady-operation detector (rigid/steady_operation.h; docs/theory/rigid.md,
// section 12) on synthetic signals whose cycle-to-cycle change is known in
// closed form: a decaying transient over a periodic part, a period-2
// subharmonic, a drift; and the start-up / steady peak split (Eq. 12.5).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "rigid/steady_operation.h"

namespace framedyn::rigid {
namespace {

constexpr double kPeriod = 0.05;      // s: a 20 Hz shaker
constexpr int kSamplesPerPeriod = 200;

struct Sampled {
  std::vector<double> time, x;
};
Sampled sample(const std::function<double(double)>& f, double periods) {
  Sampled s;
  const int n = static_cast<int>(std::lround(periods * kSamplesPerPeriod));
  for (int i = 0; i <= n; ++i) {
    const double t = i * kPeriod / kSamplesPerPeriod;
    s.time.push_back(t);
    s.x.push_back(f(t));
  }
  return s;
}

// x = A exp(-t/tau) + B sin(2 pi t / T). Over one period the periodic part
// repeats and the transient changes by A exp(-t/tau) (1 - exp(-T/tau)), largest
// at the period's start; the scale is the periodic part's range 2B. So the
// change of period k is under the tolerance from t* = tau ln(A (1 - e^{-T/tau}) / (2 B tol)).
constexpr double kA = 5.0, kB = 1.0, kTau = 2 * kPeriod;
double decaying(double t) { return kA * std::exp(-t / kTau) + kB * std::sin(2 * M_PI * t / kPeriod); }
double settling_time(double tol, double lag) { return kTau * std::log(kA * (1 - std::exp(-lag / kTau)) / (2 * kB * tol)); }

TEST(SteadyOperation, DecayingTransientIsSteadyWithinOnePeriodOfTheClosedFormSettlingTime) {
  const Sampled s = sample(decaying, 40);
  const SteadyCriterion c;
  const SteadyOperation op = detect_steady_operation(s.time, {{"x", &s.x}}, kPeriod, c);
  const double t_star = settling_time(c.tolerance, kPeriod);  // 9.18 periods
  ASSERT_TRUE(op.reached_at.has_value());
  EXPECT_EQ(op.period_multiple, 1);
  EXPECT_GE(*op.reached_at, t_star);
  EXPECT_LT(*op.reached_at, t_star + kPeriod);
  EXPECT_LT(op.remaining_change, c.tolerance);
  EXPECT_EQ(op.leading_signal, "x");
  // The change of each period against the closed form A e^{-kT/tau} (1 - e^{-T/tau}) / 2B.
  const CycleChanges cc = cycle_changes(s.time, {{"x", &s.x}}, kPeriod, 1, c);
  ASSERT_EQ(cc.change.size(), 39u);
  for (std::size_t k = 0; k < 20; ++k)
    EXPECT_NEAR(cc.change[k], kA * std::exp(-(k * kPeriod) / kTau) * (1 - std::exp(-kPeriod / kTau)) / (2 * kB), 1e-6) << k;
}

TEST(SteadyOperation, PeriodTwoSubharmonicIsFoundAsTwoShakerPeriods) {
  // The motion repeats every 2T: over one T the half-frequency part changes by up to 2 x 0.5.
  const auto f = [](double t) { return decaying(t) + 0.5 * std::sin(M_PI * t / kPeriod); };
  const Sampled s = sample(f, 40);
  const SteadyCriterion c;
  const SteadyOperation op = detect_steady_operation(s.time, {{"x", &s.x}}, kPeriod, c);
  ASSERT_TRUE(op.reached_at.has_value());
  EXPECT_EQ(op.period_multiple, 2);
  // The periodic part's range, from the closed form on a fine grid.
  double lo = 1e9, hi = -1e9;
  for (int i = 0; i < 200000; ++i) {
    const double u = 2.0 * i / 200000;  // two periods
    const double p = kB * std::sin(2 * M_PI * u) + 0.5 * std::sin(M_PI * u);
    lo = std::min(lo, p);
    hi = std::max(hi, p);
  }
  const double t_star = kTau * std::log(kA * (1 - std::exp(-2 * kPeriod / kTau)) / ((hi - lo) * c.tolerance));
  EXPECT_GE(*op.reached_at, t_star);
  EXPECT_LT(*op.reached_at, t_star + kPeriod);
  // With n = 1 the same signal never settles: the half-frequency part changes by a third of the range.
  const CycleChanges one = cycle_changes(s.time, {{"x", &s.x}}, kPeriod, 1, c);
  EXPECT_GT(one.change.back(), 0.3);
}

TEST(SteadyOperation, DriftingSignalIsNeverSteadyHoweverLongTheRun) {
  // x = B sin + s t: every period changes it by s T = 0.1 B at every phase.
  const auto f = [](double t) { return kB * std::sin(2 * M_PI * t / kPeriod) + 0.1 * kB * t / kPeriod; };
  for (double periods : {20.0, 200.0}) {
    const Sampled s = sample(f, periods);
    const SteadyOperation op = detect_steady_operation(s.time, {{"x", &s.x}}, kPeriod);
    EXPECT_FALSE(op.reached_at.has_value()) << periods;
    EXPECT_TRUE(op.enough_data);
    // Relative to the range of the last 3 + 1 periods: 2B plus at most the drift over them.
    EXPECT_EQ(op.remaining_period_multiple, 1);
    EXPECT_GE(op.remaining_change, 0.1 / (2.0 + 0.4) - 1e-12) << periods;
    EXPECT_LE(op.remaining_change, 0.1 / 2.0) << periods;
  }
}

TEST(SteadyOperation, RunShorterThanTheWindowCannotBeJudged) {
  const Sampled s = sample(decaying, 3.5);  // 3 whole periods: 2 comparisons with n = 1
  const SteadyOperation op = detect_steady_operation(s.time, {{"x", &s.x}}, kPeriod);
  EXPECT_FALSE(op.reached_at.has_value());
  EXPECT_FALSE(op.enough_data);
}

TEST(SteadyOperation, ComponentThatIsRoundOffIsJudgedAgainstItsGroup) {
  // A steady load beside one that is round-off noise of the same kind: the
  // noise, scaled by its own range, would never settle; scaled by its group's
  // largest magnitude it does not hold steady operation back.
  Sampled s = sample(decaying, 40);
  std::vector<double> noise(s.time.size());
  for (std::size_t i = 0; i < noise.size(); ++i) noise[i] = 1e-12 * ((i * 7919) % 13 - 6.0);
  const SteadyOperation alone = detect_steady_operation(s.time, {{"noise", &noise, 1}}, kPeriod);
  EXPECT_FALSE(alone.reached_at.has_value());
  const SteadyOperation together = detect_steady_operation(s.time, {{"x", &s.x, 1}, {"noise", &noise, 1}}, kPeriod);
  const SteadyOperation x_only = detect_steady_operation(s.time, {{"x", &s.x, 1}}, kPeriod);
  ASSERT_TRUE(together.reached_at.has_value());
  EXPECT_EQ(*together.reached_at, *x_only.reached_at);
}

TEST(SteadyOperation, PeaksSplitAtTheTimeSteadyOperationIsReached) {
  const std::vector<double> t = {0.0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6};
  const std::vector<double> v = {1.0, -5.0, 2.0, 0.5, 3.0, -2.5, 1.0};
  const PeakSplit p = split_peaks(t, v, 0.3);
  ASSERT_TRUE(p.start_up && p.steady);
  EXPECT_EQ(p.start_up->value, -5.0);  // the value of largest magnitude, with its sign
  EXPECT_EQ(p.start_up->time, 0.1);
  EXPECT_EQ(p.steady->value, 3.0);
  EXPECT_EQ(p.steady->time, 0.4);
  const PeakSplit never = split_peaks(t, v, std::nullopt);  // not reached: all of it is start-up
  EXPECT_FALSE(never.steady.has_value());
  EXPECT_EQ(never.start_up->value, -5.0);
}

}  // namespace
}  // namespace framedyn::rigid
