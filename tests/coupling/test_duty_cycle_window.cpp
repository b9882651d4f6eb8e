// The duty cycle's frame transients over their steady windows alone (coupling/duty_cycle.h,
// FrameStudyRequest::window_lead_in_decay; docs/theory/fatigue.md section 15; validation V42):
// the shipped duty cycle run with the shortcut (each scenario's modal transient from a lead-in
// L = ln(1/eps) / (zeta_1 omega_1) before its steady window, eps = 1e-6, the stresses recovered in
// the window alone) against the same cycle run over every scenario's whole record.
//
// Why the damages agree: the modal equations are integrated exactly for piecewise-linear loads on
// the same time grid, so the shortcut differs from the whole run only by its start, the static
// equilibrium under the loads at t_s - L instead of the state the record reached there. The
// difference is a free vibration of the elastic modes, each of amplitude at most that of the
// modal response it replaces, decayed by exp(-zeta_i omega_i L) <= eps by the window's start.
// A stress in the window is then off by at most eps times the dynamic stress amplitude at that
// point, and a range by twice that; a Miner damage sum of ranges to the power m moves by at most
// m times the ranges' relative change. The IIW slopes are m = 3 (normal) and 5 (shear), and
// 22 beyond the knee, whose cycles do little damage. Tolerance per section point: 2 * 5 * eps
// = 1e-5 relative to that point's damage, plus 1e-12 of the cycle's largest damage for points
// whose damage is round-off (the proportionality measure's CV chooses between the same two sums).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "coupling/duty_cycle.h"

namespace {

namespace coupling = framedyn::coupling;

const std::string kSource = FRAMEDYN_SOURCE_DIR;

}  // namespace

TEST(DutyCycleWindowOnly, DamageAtEveryPointEqualsTheWholeRecordsWithinTheLeadInDecayBound) {
  coupling::DutyCycleRequest whole = coupling::read_duty_cycle(kSource + "/examples/duty_cycle.yaml");
  coupling::DutyCycleRequest window = whole;
  whole.lead_in_decay.reset();
  ASSERT_TRUE(window.lead_in_decay.has_value());
  const double eps = *window.lead_in_decay;
  ASSERT_EQ(eps, 1e-6);
  const coupling::DutyCycleResults a = coupling::run_duty_cycle(whole, {}, 2);
  const coupling::DutyCycleResults b = coupling::run_duty_cycle(window, {}, 2);
  ASSERT_EQ(a.scenarios.size(), b.scenarios.size());

  bool shortened = false;
  for (std::size_t i = 0; i < a.scenarios.size(); ++i) {
    const coupling::FrameStudyResults& fa = a.scenarios[i].frame;
    const coupling::FrameStudyResults& fb = b.scenarios[i].frame;
    SCOPED_TRACE(a.scenarios[i].name);
    EXPECT_FALSE(fa.window_only.has_value());
    ASSERT_TRUE(fb.window_only.has_value());  // every shipped scenario has a steady window's start
    const auto& w = *fb.window_only;
    // The lead-in from the lowest elastic mode's decay, zeta omega_1 (all modes at zeta = 0.02,
    // so the lowest decays slowest): L = ln(1/eps) / (0.02 * 2 pi f_1).
    const double rate = 0.02 * 2.0 * M_PI * fa.frequencies_hz(0);
    EXPECT_NEAR(w.decay_rate, rate, 1e-12 * rate);
    EXPECT_NEAR(w.lead_in, std::log(1.0 / eps) / rate, 1e-12 * w.lead_in);
    EXPECT_EQ(w.outputs_from, fb.hot_spots.window.from);
    EXPECT_EQ(fa.hot_spots.window.from, fb.hot_spots.window.from);
    // From the latest output time at or before t_s - L (or the record's start, when the lead-in reaches it).
    EXPECT_LE(w.transient_from, std::max(fa.response.times(0), w.outputs_from - w.lead_in));
    EXPECT_GT(w.transient_from, w.outputs_from - w.lead_in - (fa.response.times(1) - fa.response.times(0)));
    shortened = shortened || w.transient_from > fa.response.times(0);
    // The outputs are the whole run's from the window's start: the same times.
    ASSERT_EQ(fb.response.times.size(), static_cast<Eigen::Index>(fa.life->block_samples));
    const Eigen::Index skip = fa.response.times.size() - fb.response.times.size();
    for (Eigen::Index j = 0; j < fb.response.times.size(); ++j) ASSERT_EQ(fb.response.times(j), fa.response.times(skip + j));
    EXPECT_EQ(fb.life->block_samples, fa.life->block_samples);
    EXPECT_EQ(fb.life->block_seconds, fa.life->block_seconds);

    const double largest = fa.life->max_damage_per_hour();
    ASSERT_GT(largest, 0.0);
    ASSERT_EQ(fa.life->damage_per_hour.size(), fb.life->damage_per_hour.size());
    double worst = 0.0;
    for (std::size_t s = 0; s < fa.life->damage_per_hour.size(); ++s)
      for (std::size_t p = 0; p < fa.life->damage_per_hour[s].size(); ++p) {
        const double da = fa.life->damage_per_hour[s][p], db = fb.life->damage_per_hour[s][p];
        EXPECT_NEAR(db, da, 1e-5 * da + 1e-12 * largest) << "station " << s << " point " << p;
        if (da > 1e-9 * largest) worst = std::max(worst, std::abs(db - da) / da);
      }
    RecordProperty(a.scenarios[i].name + "_worst_relative_damage_difference", std::to_string(worst));
    std::cout << a.scenarios[i].name << ": transient from " << w.transient_from << " s (record from " << fa.response.times(0) << " s), window from "
              << w.outputs_from << " s, lead-in " << w.lead_in << " s; worst relative damage difference " << worst << "\n";
  }
  // Offset plowing's steady window starts 8.73 s into its 10-s record: its transient is shortened.
  EXPECT_TRUE(shortened);
  // The cycle's Miner sum and its shortest life, within the same bound.
  const double la = a.life.life_hours(a.life.worst_station, a.life.worst_point);
  EXPECT_EQ(b.life.worst_station, a.life.worst_station);
  EXPECT_EQ(b.life.worst_point, a.life.worst_point);
  EXPECT_NEAR(b.life.life_hours(b.life.worst_station, b.life.worst_point), la, 1e-5 * la);
}
