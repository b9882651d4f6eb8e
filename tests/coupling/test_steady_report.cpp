// Steady operation and validity warnings as a vehicle run reports them
// (coupling/steady_report.h): on the shipped 2-D plow, which climbs out of the
// cut and never settles (docs/validation.md P1.4), and the shipped digging
// chain, whose soil law chatters after its start-up (§6.4).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "coupling/rigid_study.h"

namespace framedyn::coupling {
namespace {

std::string shipped(const std::string& name) { return std::string(FRAMEDYN_SOURCE_DIR) + "/examples/" + name; }

const core::Warning* find(const std::vector<core::Warning>& w, const std::string& code) {
  auto it = std::find_if(w.begin(), w.end(), [&](const core::Warning& x) { return x.code == code; });
  return it == w.end() ? nullptr : &*it;
}

double figure(const core::Warning& w, const std::string& name) {
  for (const core::WarningFigure& f : w.figures)
    if (f.name == name) return f.value;
  ADD_FAILURE() << "no figure " << name;
  return std::nan("");
}

TEST(SteadyReport, ShippedPlowThatClimbsOutOfTheCutNeverSettlesAndAllItsPeaksAreStartUpPeaks) {
  const RigidStudy study = read_rigid_study(shipped("r100_plow_2d.yaml"));
  const RigidResults r = run_rigid_study(study);
  ASSERT_TRUE(r.steady.assessed);
  EXPECT_FALSE(r.steady.operation.reached_at.has_value());
  EXPECT_NEAR(r.steady.operation.shaker_period, 1.0 / 18.33, 1e-12);
  // Watched: the blade's motion and every frame-load component (computed without frame_output too).
  const std::vector<std::string>& w = r.steady.watched;
  for (const char* name : {"blade_x", "blade_z", "plow_lower_pivot_fx", "lift_cylinder_fz", "rear_tire_my"})
    EXPECT_NE(std::find(w.begin(), w.end(), name), w.end()) << name;
  // The warning carries the detector's remaining change, far above the tolerance.
  const core::Warning* nr = find(r.warnings, "steady_not_reached");
  ASSERT_NE(nr, nullptr);
  EXPECT_EQ(figure(*nr, "remaining_change"), r.steady.operation.remaining_change);
  EXPECT_GT(r.steady.operation.remaining_change, 0.1);
  EXPECT_NEAR(figure(*nr, "shaker_periods"), 0.5 * 18.33, 1e-9);
  // Not reached: every peak is over the start-up, which is the whole run.
  for (const SteadyPeak& p : r.steady.peaks) EXPECT_FALSE(p.split.steady.has_value()) << p.name;
  const auto force = std::find_if(r.steady.peaks.begin(), r.steady.peaks.end(), [](const SteadyPeak& p) { return p.name == "plow_force_signed_magnitude"; });
  ASSERT_NE(force, r.steady.peaks.end());
  ASSERT_TRUE(force->split.start_up.has_value());
  // The start-up peak is the whole run's largest signed magnitude (forward blade travel, Eqs. 2.38-2.39).
  const auto series = std::find_if(r.series.begin(), r.series.end(), [](const Series& s) { return s.name == "plow_force_signed_magnitude"; });
  ASSERT_NE(series, r.series.end());
  EXPECT_EQ(force->split.start_up->value, *std::max_element(series->values.begin(), series->values.end()));
  // Its rotations stay inside the linear range over 0.5 s, and the shaker (18.33 Hz) is far from the modes (<= 11.4 Hz).
  EXPECT_EQ(find(r.warnings, "rotation_beyond_linear_range"), nullptr);
  EXPECT_EQ(find(r.warnings, "shaker_near_mode"), nullptr);
}

TEST(SteadyReport, ShakerMovedOntoAModeWarns) {
  RigidStudy study = read_rigid_study(shipped("r100_plow_2d.yaml"));
  study.response.reset();
  const RigidResults modes = run_rigid_study(study);
  ASSERT_GE(modes.modes.size(), 3u);
  EXPECT_TRUE(modes.warnings.empty());
  // Without a response there is nothing to warn about; with one, 5 % above mode 3 warns about mode 3.
  study = read_rigid_study(shipped("r100_plow_2d.yaml"));
  study.machine_2d().plow.shaker_frequency = 1.05 * modes.modes[2].frequency_hz;
  study.response->duration = 0.05;
  const RigidResults r = run_rigid_study(study);
  bool mode3 = false;
  for (const core::Warning& w : r.warnings)
    if (w.code == "shaker_near_mode" && figure(w, "mode") == 3) {
      mode3 = true;
      EXPECT_NEAR(figure(w, "relative_offset"), 0.05, 1e-12);
    }
  EXPECT_TRUE(mode3);
}

TEST(SteadyReport, ShippedChainChattersInASlidingRegimeAndHasNoShakerToJudgeSteadinessBy) {
  const RigidStudy study = read_rigid_study(shipped("r100_chain_2d.yaml"));
  const RigidResults r = run_rigid_study(study);
  EXPECT_FALSE(r.steady.assessed);
  EXPECT_FALSE(r.steady.not_assessed.empty());
  EXPECT_EQ(find(r.warnings, "steady_not_reached"), nullptr);
  const core::Warning* w = find(r.warnings, "switching_law_chattering");
  ASSERT_NE(w, nullptr);
  // Counts depend on the integrator's tolerance (validation V12.4): bounds, not equalities.
  EXPECT_GT(figure(*w, "switches"), 1000);
  EXPECT_LT(figure(*w, "median_interval"), 1e-4);
  EXPECT_EQ(figure(*w, "period"), 0.1);
  EXPECT_NE(w->message.find("the soil's law"), std::string::npos) << w->message;
}

}  // namespace
}  // namespace framedyn::coupling
