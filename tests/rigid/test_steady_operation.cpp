// The steady-operation detector (rigid/steady_operation.h; docs/theory/rigid.md,
// section 12) on synthetic signals whose cycle-to-cycle change is known in
// closed form: a decaying transient over a periodic part, a period-2
// subharmonic, a drift; and the start-up / steady peak split (Eq. 12.5).
#include <gtest/gtest.h>

#include <cmath>
#include <algorithm>
#include <functional>
#include <utility>
#include <random>

#include "rigid/steady_operation.h"

namespace framedyn::rigid {
namespace {

constexpr double kPeriod = 0.05;      // s: a 20 Hz shaker
constexpr int kSamplesPerPeriod = 200;

// The smallest and largest value of f on `samples` equal steps over [0, span): a
// periodic part's range from its closed form.
std::pair<double, double> range_on_grid(const std::function<double(double)>& f, double span, int samples) {
  double lo = 1e9, hi = -1e9;
  for (int i = 0; i < samples; ++i) {
    const double p = f(span * i / samples);
    lo = std::min(lo, p);
    hi = std::max(hi, p);
  }
  return {lo, hi};
}

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
  // The periodic part's range, from the closed form on a fine grid over its two periods.
  const auto [lo, hi] = range_on_grid([](double t) { return kB * std::sin(2 * M_PI * t / kPeriod) + 0.5 * std::sin(M_PI * t / kPeriod); },
                                      2 * kPeriod, 200000);
  const double t_star = kTau * std::log(kA * (1 - std::exp(-2 * kPeriod / kTau)) / ((hi - lo) * c.tolerance));
  EXPECT_GE(*op.reached_at, t_star);
  EXPECT_LT(*op.reached_at, t_star + kPeriod);
  // With n = 1 the same signal never settles: the half-frequency part changes by a third of the range.
  const CycleChanges one = cycle_changes(s.time, {{"x", &s.x}}, kPeriod, 1, c);
  EXPECT_GT(one.change.back(), 0.3);
}

TEST(SteadyOperation, FourteenPeriodSubharmonicIsFoundAsFourteenShakerPeriods) {
  // The shipped 3-D offset plow settles on an orbit that repeats every 14
  // shaker periods (docs/theory/rigid.md, section 17). Here: the transient over
  // a periodic part plus a part at 1/14 of the shaker frequency; it repeats
  // every 14 T, so d_14(k) = A e^{-kT/tau} (1 - e^{-14T/tau}) / S with S the
  // periodic part's range over 14 periods, and t* = tau ln(A (1 - e^{-14T/tau}) / (S tol)).
  const auto periodic = [](double t) { return kB * std::sin(2 * M_PI * t / kPeriod) + 0.5 * std::sin(2 * M_PI * t / (14 * kPeriod)); };
  const auto f = [&](double t) { return kA * std::exp(-t / kTau) + periodic(t); };
  const Sampled s = sample(f, 60);
  const SteadyCriterion c;
  const SteadyOperation op = detect_steady_operation(s.time, {{"x", &s.x}}, kPeriod, c);
  ASSERT_TRUE(op.reached_at.has_value());
  EXPECT_EQ(op.period_multiple, 14);
  const auto [lo, hi] = range_on_grid(periodic, 14 * kPeriod, 1400000);
  const double t_star = kTau * std::log(kA * (1 - std::exp(-14 * kPeriod / kTau)) / ((hi - lo) * c.tolerance));
  EXPECT_GE(*op.reached_at, t_star);
  EXPECT_LT(*op.reached_at, t_star + kPeriod);
  // No multiple below 14 passes: over n periods the 1/14 part changes by up to
  // 2 x 0.5 sin(pi n / 14) (at the phase where its cosine is 1), and the scale
  // is at most the range hi - lo; so over the last 14 periods d_n >= sin(pi n / 14) / (hi - lo).
  for (int n = 1; n < 14; ++n) {
    const CycleChanges cc = cycle_changes(s.time, {{"x", &s.x}}, kPeriod, n, c);
    const double largest = *std::max_element(cc.change.end() - 14, cc.change.end());
    EXPECT_GE(largest, std::sin(M_PI * n / 14) / (hi - lo) * (1 - 1e-5)) << n;  // 1e-5: 200 samples per period miss the crest by < 3e-6
  }
}

TEST(SteadyOperation, OrbitOfSevenSlowCyclesInOneHundredTenPeriodsIsFoundAsOneHundredTenShakerPeriods) {
  // The shipped 3-D straight plow settles on an orbit of 7 relaxation cycles
  // in 110 shaker periods (docs/theory/coupling.md, section 19): longer than
  // the 32 periods the detector tried before. Here: the transient over a
  // periodic part plus a part of frequency 7/110 of the shaker's; 7 and 110
  // have no common factor, so it repeats every 110 T and no sooner, and
  // t* = tau ln(A (1 - e^{-110T/tau}) / (S tol)) as for 14 periods.
  const auto periodic = [](double t) { return kB * std::sin(2 * M_PI * t / kPeriod) + std::sin(2 * M_PI * 7 * t / (110 * kPeriod)); };
  const auto f = [&](double t) { return kA * std::exp(-t / kTau) + periodic(t); };
  const Sampled s = sample(f, 130);  // t* is about 10 periods: 130 leaves the 110 + 3 that show it
  const SteadyCriterion c;
  ASSERT_GE(c.max_period_multiple, 110);
  const SteadyOperation op = detect_steady_operation(s.time, {{"x", &s.x}}, kPeriod, c);
  ASSERT_TRUE(op.reached_at.has_value());
  EXPECT_EQ(op.period_multiple, 110);
  const auto [lo, hi] = range_on_grid(periodic, 110 * kPeriod, 2200000);
  const double t_star = kTau * std::log(kA * (1 - std::exp(-110 * kPeriod / kTau)) / ((hi - lo) * c.tolerance));
  EXPECT_GE(*op.reached_at, t_star);
  EXPECT_LT(*op.reached_at, t_star + kPeriod);
  // No multiple below 110 passes: over n periods the slow part changes by up to
  // 2 |sin(7 pi n / 110)| (at the phase where its cosine is 1, which the last 16
  // periods hold: 16 x 7/110 > 1 slow cycle), at least 2 sin(pi / 110) = 0.057,
  // and the scale is at most hi - lo (about 4) plus what is left of the
  // transient at the start of the scale's span (A e^{-17T/tau} = 1e-3, 2.5e-4 relative).
  for (int n = 1; n < 110; ++n) {
    const CycleChanges cc = cycle_changes(s.time, {{"x", &s.x}}, kPeriod, n, c);
    const double largest = *std::max_element(cc.change.end() - 16, cc.change.end());
    EXPECT_GE(largest, 2 * std::abs(std::sin(7 * M_PI * n / 110)) / (hi - lo) * (1 - 1e-3)) << n;
    EXPECT_GT(largest, c.tolerance) << n;
  }
}

TEST(SteadyOperation, RunThatEndsInTheTransientProjectsTheClosedFormSettlingTime) {
  // x = A e^{-t/tau} + B sin(2 pi t / T) with a tolerance the run cannot reach:
  // d_1(k) = C e^{-kT/tau}, C = A (1 - e^{-T/tau}) / 2B, so the change decays at
  // 1/tau and falls under the tolerance at t* = tau ln(C / tol).
  const Sampled s = sample(decaying, 40);
  SteadyCriterion c;
  c.tolerance = 1e-9;
  const SteadyOperation op = detect_steady_operation(s.time, {{"x", &s.x}}, kPeriod, c);
  ASSERT_FALSE(op.reached_at.has_value());
  EXPECT_EQ(op.remaining_period_multiple, 1);
  EXPECT_NEAR(op.change_decay_rate, 1 / kTau, 1e-6 / kTau);
  ASSERT_TRUE(op.projected_reached_at.has_value());
  // The rate to 1e-6 (relative) sets the projection to 1e-6 of t* (41 periods).
  EXPECT_NEAR(*op.projected_reached_at, settling_time(c.tolerance, kPeriod), 1e-6 * settling_time(c.tolerance, kPeriod));
  // A drift does not shrink: no projection.
  const auto drift = [](double t) { return kB * std::sin(2 * M_PI * t / kPeriod) + 0.1 * kB * t / kPeriod; };
  const Sampled d = sample(drift, 40);
  const SteadyOperation never = detect_steady_operation(d.time, {{"x", &d.x}}, kPeriod);
  EXPECT_LE(never.change_decay_rate, 1e-9);
  EXPECT_FALSE(never.projected_reached_at.has_value());
}

TEST(SteadyOperation, ForceThatJumpsAtASwitchIsSteadyWhenTheSwitchesAreGiven) {
  // An orbit that repeats exactly, with a jump of J at phase 0.3 of each
  // period (a damper force at a switch of the soil law), sampled at T / 200.37
  // as an output grid not commensurate with the shaker. Interpolating across
  // the jump reads it part-way: a change of up to J / S that is no change of
  // the motion. With the switch times as breaks those comparisons are left out
  // (Eq. 17.1), and what remains is linear interpolation's error on the sine,
  // at most B (omega dt)^2 / 8 over the scale S = 2B + J.
  constexpr double kJump = 0.5, kDt = kPeriod / 200.37;
  const auto f = [](double t) {
    const double phase = t / kPeriod - std::floor(t / kPeriod);
    return kB * std::sin(2 * M_PI * t / kPeriod) + (phase < 0.3 ? kJump : 0.0);
  };
  Sampled s;
  for (int i = 0; i * kDt <= 20 * kPeriod; ++i) {
    s.time.push_back(i * kDt);
    s.x.push_back(f(i * kDt));
  }
  std::vector<double> breaks;
  for (int k = 0; k <= 20; ++k) {
    breaks.push_back(k * kPeriod);
    breaks.push_back((k + 0.3) * kPeriod);
  }
  const SteadyCriterion c;
  const CycleChanges across = cycle_changes(s.time, {{"x", &s.x}}, kPeriod, 1, c);
  EXPECT_GT(*std::max_element(across.change.begin(), across.change.end()), c.tolerance);  // the artefact
  const SteadyOperation op = detect_steady_operation(s.time, {{"x", &s.x}}, kPeriod, c, breaks);
  ASSERT_TRUE(op.reached_at.has_value());
  EXPECT_EQ(*op.reached_at, 0.0);
  EXPECT_EQ(op.period_multiple, 1);
  const double w_dt = 2 * M_PI * kDt / kPeriod;
  EXPECT_LE(op.remaining_change, kB * w_dt * w_dt / 8 / (2 * kB + kJump));
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
  // Not periodic (a sequence that repeats every 13 samples would be steady with a 13-period cycle).
  std::mt19937 random(7919);
  std::uniform_real_distribution<double> unit(-6.0, 6.0);
  for (double& v : noise) v = 1e-12 * unit(random);
  const SteadyOperation alone = detect_steady_operation(s.time, {{"noise", &noise, 1}}, kPeriod);
  EXPECT_FALSE(alone.reached_at.has_value());
  const SteadyOperation together = detect_steady_operation(s.time, {{"x", &s.x, 1}, {"noise", &noise, 1}}, kPeriod);
  const SteadyOperation x_only = detect_steady_operation(s.time, {{"x", &s.x, 1}}, kPeriod);
  ASSERT_TRUE(together.reached_at.has_value());
  EXPECT_EQ(*together.reached_at, *x_only.reached_at);
}

TEST(SteadyOperation, ComponentThatIsIdenticallyZeroNeitherHoldsBackNorFakesSteadyOperation) {
  // A straight plow's lateral loads are zero throughout (the machine is
  // symmetric): a zero component never changes, so it passes every
  // comparison; beside a settling load of its group it leaves that load's
  // result unchanged, and beside a drift it does not make it steady. A group
  // that is zero throughout has no scale: it is steady from its start.
  const Sampled s = sample(decaying, 40);
  const std::vector<double> zero(s.time.size(), 0.0);
  const SteadyOperation x_only = detect_steady_operation(s.time, {{"x", &s.x, 1}}, kPeriod);
  const SteadyOperation together = detect_steady_operation(s.time, {{"x", &s.x, 1}, {"lateral", &zero, 1}}, kPeriod);
  ASSERT_TRUE(x_only.reached_at.has_value());
  ASSERT_TRUE(together.reached_at.has_value());
  EXPECT_EQ(*together.reached_at, *x_only.reached_at);
  EXPECT_EQ(together.period_multiple, x_only.period_multiple);
  EXPECT_EQ(together.leading_signal, "x");
  const SteadyOperation alone = detect_steady_operation(s.time, {{"lateral", &zero, 2}}, kPeriod);
  ASSERT_TRUE(alone.reached_at.has_value());
  EXPECT_EQ(*alone.reached_at, s.time.front());
  EXPECT_EQ(alone.period_multiple, 1);
  const auto drift = [](double t) { return kB * std::sin(2 * M_PI * t / kPeriod) + 0.1 * kB * t / kPeriod; };
  const Sampled d = sample(drift, 40);
  const std::vector<double> zero_d(d.time.size(), 0.0);
  EXPECT_FALSE(detect_steady_operation(d.time, {{"x", &d.x, 1}, {"lateral", &zero_d, 1}}, kPeriod).reached_at.has_value());
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
