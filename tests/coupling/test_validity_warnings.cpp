// The validity warnings (coupling/validity_warnings.h; docs/theory/coupling.md,
// section 8): each fires on a constructed case just beyond its limit and stays
// silent just inside it, and names what it found with its figures.
#include <gtest/gtest.h>

#include <cmath>

#include "coupling/validity_warnings.h"

namespace framedyn::coupling {
namespace {

double figure(const core::Warning& w, const std::string& name) {
  for (const core::WarningFigure& f : w.figures)
    if (f.name == name) return f.value;
  ADD_FAILURE() << "no figure " << name << " in " << w.code;
  return std::nan("");
}

// Two bodies pitching with theta (the second twice as much) on a tiny assembly.
rigid::Multibody pitching_bodies(double second_ratio) {
  rigid::Multibody mb({"z", "theta"}, {core::Quantity::length, core::Quantity::angle});
  for (const auto& [name, ratio] : {std::pair<std::string, double>{"frame", 1.0}, {"plow", second_ratio}}) {
    rigid::Body b;
    b.name = name;
    b.mass = 1.0;
    b.translation = rigid::Jacobian::Zero(3, 2);
    b.translation(2, 0) = 1.0;
    b.rotation = rigid::Jacobian::Zero(3, 2);
    b.rotation(1, 1) = ratio;
    mb.add_body(b);
  }
  return mb;
}

rigid::Trajectory pitching(double amplitude) {
  rigid::Trajectory tr;
  for (int i = 0; i <= 100; ++i) {
    const double t = 0.001 * i;
    Eigen::VectorXd q(2);
    q << 0.01, amplitude * std::sin(2 * M_PI * 10 * t);  // largest at t = 0.025 s
    tr.time.push_back(t);
    tr.q.push_back(q);
  }
  return tr;
}

TEST(ValidityWarnings, RotationBeyondOnePercentLinearisationErrorWarnsWithItsErrorEstimate) {
  const double limit = std::sqrt(2 * kLinearisationErrorLimit);  // x^2/2 = 1 %: 0.1414 rad
  const rigid::Multibody mb = pitching_bodies(2.0);
  const LargestRotation inside = largest_body_rotation(mb, pitching(0.999 * limit / 2));
  EXPECT_EQ(inside.body, "body plow");
  EXPECT_NEAR(inside.angle, 0.999 * limit, 1e-12);
  EXPECT_NEAR(inside.time, 0.025, 1e-12);
  EXPECT_FALSE(rotation_warning(inside).has_value());
  const auto w = rotation_warning(largest_body_rotation(mb, pitching(1.001 * limit / 2)));
  ASSERT_TRUE(w.has_value());
  EXPECT_EQ(w->code, "rotation_beyond_linear_range");
  const double x = 1.001 * limit;
  EXPECT_NEAR(figure(*w, "largest_rotation"), x, 1e-12);
  EXPECT_NEAR(figure(*w, "arm_error_x2_over_2"), x * x / 2, 1e-15);
  EXPECT_NEAR(figure(*w, "sin_error_1_minus_sinx_over_x"), 1 - std::sin(x) / x, 1e-15);  // ~ x^2/6
  EXPECT_NE(w->message.find("body plow rotates by"), std::string::npos) << w->message;
}

TEST(ValidityWarnings, AngleCoordinateOfAMasslessLinkageCountsAsARotation) {
  // psi turns the plow linkage's arms, which are no bodies: its own angle is the rotation.
  rigid::Multibody mb({"z", "psi"}, {core::Quantity::length, core::Quantity::angle});
  rigid::Body b;
  b.name = "plow";
  b.mass = 1.0;
  b.translation = rigid::Jacobian::Zero(3, 2);
  b.translation(2, 1) = 1.0;  // psi lifts the plow without turning it
  b.rotation = rigid::Jacobian::Zero(3, 2);
  mb.add_body(b);
  const LargestRotation r = largest_body_rotation(mb, pitching(0.2));
  EXPECT_EQ(r.body, "coordinate psi");
  EXPECT_NEAR(r.angle, 0.2, 1e-12);
  EXPECT_TRUE(rotation_warning(r).has_value());
}

TEST(ValidityWarnings, EqualRotationsNameTheFirstBodyWhateverTheRoundOff) {
  // Two bodies rotating alike to round-off: the first is named, not whichever wins by an ulp.
  const LargestRotation r = largest_body_rotation(pitching_bodies(1.0 + 1e-12), pitching(0.1));
  EXPECT_EQ(r.body, "body frame");
}

// `count` switches of the soil law inside one 0.05 s period, `interval` apart,
// with a tire's event in the middle (one combined event text).
std::vector<rigid::Trajectory::Event> burst(int count, double interval) {
  std::vector<rigid::Trajectory::Event> ev;
  ev.push_back({0.01, "blade backs off", "", 0.0});  // an ordinary cycle's switches in the period before
  ev.push_back({0.03, "blade cuts again", "", 0.0});
  for (int i = 0; i < count; ++i) {
    std::string what = i % 2 ? "blade cuts again" : "blade backs off";
    if (i == count / 2) what = "front_tire loses contact; " + what;
    ev.push_back({0.06 + i * interval, what, "", 0.0});
  }
  ev.push_back({0.12, "3 teeth digging", "", 0.0});  // a scheduled change: no law's switch
  return ev;
}

TEST(ValidityWarnings, ChatteringNeedsMoreThanTenSwitchesInAPeriodCloserThanOnePercentOfIt) {
  const double T = 0.05;
  const double close = 0.0099 * T, apart = 0.0101 * T;
  // Just inside each limit: silent.
  EXPECT_TRUE(chattering_warnings(switching_activity(burst(10, close), T), T, true, 0).empty());
  EXPECT_TRUE(chattering_warnings(switching_activity(burst(11, apart), T), T, true, 0).empty());
  // Just beyond both: a warning with the counts.
  const std::vector<SwitchingActivity> a = switching_activity(burst(11, close), T);
  ASSERT_EQ(a.size(), 2u);
  EXPECT_EQ(a[0].law, "soil");
  EXPECT_EQ(a[0].switches, 13);
  EXPECT_EQ(a[1].law, "front_tire");
  EXPECT_EQ(a[1].switches, 1);
  const std::vector<core::Warning> w = chattering_warnings(a, T, true, 0);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(w[0].code, "switching_law_chattering");
  EXPECT_EQ(figure(w[0], "switches"), 13);
  EXPECT_EQ(figure(w[0], "chattering_periods"), 1);
  EXPECT_EQ(figure(w[0], "switches_in_chattering_periods"), 11);
  EXPECT_NEAR(figure(w[0], "median_interval"), close, 1e-12);
  EXPECT_NEAR(figure(w[0], "first"), 0.06, 1e-12);
  EXPECT_NE(w[0].message.find("every switch is located"), std::string::npos) << w[0].message;
  // Under RK4 the treatment named is RK4's.
  EXPECT_NE(chattering_warnings(a, T, false, 5e-4)[0].message.find("RK4 at its step"), std::string::npos);
}

TEST(ValidityWarnings, ShakerWithinTenPercentOfAModeWarns) {
  std::vector<rigid::RigidMode> modes(2);
  modes[0].frequency_hz = 3.0;
  modes[0].dominant = "z";
  modes[1].frequency_hz = 10.0;
  modes[1].dominant = "theta_y";
  EXPECT_TRUE(resonance_warnings(11.01, modes, "test").empty());  // +10.1 %
  EXPECT_TRUE(resonance_warnings(8.99, modes, "test").empty());   // -10.1 %
  for (double f : {10.99, 9.01}) {
    const std::vector<core::Warning> w = resonance_warnings(f, modes, "test");
    ASSERT_EQ(w.size(), 1u) << f;
    EXPECT_EQ(w[0].code, "shaker_near_mode");
    EXPECT_EQ(figure(w[0], "mode"), 2);
    EXPECT_NEAR(figure(w[0], "relative_offset"), (f - 10.0) / 10.0, 1e-15);
  }
}

TEST(ValidityWarnings, ShakerWithinTenPercentOfAFrameModeWarnsNamingTheMode) {
  // The shipped free-free frame model's lowest elastic modes (18.63 Hz: the engine rocking on its one-node mount).
  const std::vector<double> frame_hz = {18.63, 31.44, 40.0};
  const std::vector<core::Warning> w = frame_resonance_warnings(18.33, frame_hz, "r100_frame.inp");
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(w[0].code, "shaker_near_frame_mode");
  EXPECT_EQ(figure(w[0], "mode"), 1);
  EXPECT_NEAR(figure(w[0], "relative_offset"), (18.33 - 18.63) / 18.63, 1e-15);
  EXPECT_NE(w[0].message.find("r100_frame.inp"), std::string::npos);
  // The band's edges, as for the vehicle's modes: 10.1 % away is outside, 9.9 % inside.
  EXPECT_TRUE(frame_resonance_warnings(40.0 * 1.101, {40.0}, "m").empty());
  EXPECT_TRUE(frame_resonance_warnings(40.0 * 0.899, {40.0}, "m").empty());
  EXPECT_EQ(frame_resonance_warnings(40.0 * 1.099, {40.0}, "m").size(), 1u);
  EXPECT_EQ(frame_resonance_warnings(40.0 * 0.901, {40.0}, "m").size(), 1u);
  // No shaker (a chain): nothing to warn about.
  EXPECT_TRUE(frame_resonance_warnings(0.0, frame_hz, "m").empty());
}

TEST(ValidityWarnings, SteadyNotReachedWarnsWithTheRemainingChangeAndIsSilentOnceReached) {
  // The decaying transient of test_steady_operation (x = 5 e^{-t/2T} + sin):
  // steady from 10 periods; the last 3 comparisons pass only with 14 periods of data.
  const double T = 0.05;
  const auto run = [&](int periods) {
    std::vector<double> t, x;
    for (int i = 0; i <= periods * 200; ++i) {
      t.push_back(i * T / 200);
      x.push_back(5 * std::exp(-t.back() / (2 * T)) + std::sin(2 * M_PI * t.back() / T));
    }
    return rigid::detect_steady_operation(t, {{"blade_z", &x}}, T);
  };
  const rigid::SteadyCriterion c;
  const rigid::SteadyOperation reached = run(14);
  ASSERT_TRUE(reached.reached_at.has_value());
  EXPECT_NEAR(*reached.reached_at, 10 * T, 1e-12);
  EXPECT_FALSE(steady_warning(reached, c, 14 * T).has_value());
  const rigid::SteadyOperation short_run = run(13);
  const auto w = steady_warning(short_run, c, 13 * T);
  ASSERT_TRUE(w.has_value());
  EXPECT_EQ(w->code, "steady_not_reached");
  // The last window (periods 9-11) is led by period 9: 5 e^{-4.5} (1 - e^{-0.5})
  // over the signal's range in the last 3 + 1 periods (the closed form on a fine grid).
  double lo = 1e9, hi = -1e9;
  for (int i = 0; i <= 400000; ++i) {
    const double t = 9 * T + 4 * T * i / 400000;
    const double v = 5 * std::exp(-t / (2 * T)) + std::sin(2 * M_PI * t / T);
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  EXPECT_NEAR(figure(*w, "remaining_change"), 5 * std::exp(-4.5) * (1 - std::exp(-0.5)) / (hi - lo), 1e-6);
  EXPECT_EQ(figure(*w, "period_multiple"), 1);
  EXPECT_NE(w->message.find("blade_z"), std::string::npos) << w->message;
}

}  // namespace
}  // namespace framedyn::coupling
