// Hot spots from stress histories (coupling/hot_spots.h, docs/theory/coupling.md
// section 10) on hand-made histories whose answers are known by construction:
//  - the ranking by steady peak von Mises and by normal-stress range, with an
//    exact tie going to the lower station;
//  - the start-up / steady split where the steady report (or frame.steady_from,
//    or half the record) puts it;
//  - static = 0 gives total = dynamic; a static axial force adds N / A;
//  - the yield-strength warning;
//  - the fatigue life map (coupling/frame_fatigue.h): a sine's closed-form Miner damage
//    per hour, fatigue/ applied by hand at a point, FAT classes per element set, and a
//    duty cycle's damages adding with hours.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <vector>

#include "coupling/frame_fatigue.h"
#include "coupling/frame_study.h"
#include "fatigue/miner_damage.h"
#include "fatigue/rainflow.h"
#include "coupling/hot_spots.h"
#include "fem/beam_section.h"
#include "fem/section_stress.h"
#include "report/frame_outputs.h"
#include "tests/support/temp_dir.h"

namespace {

namespace coupling = framedyn::coupling;
namespace fem = framedyn::fem;
namespace report = framedyn::report;

constexpr double kA = 0.05, kB = 0.1;          // RECT, m
const double kI11 = kA * kB * kB * kB / 12;   // bending about 1 by My: sigma = My x2 / I11

// Stations 0..n-1 of one RECT section, times 0, 0.01, ..., with My(station, time) from `moment`.
template <typename F>
coupling::StressHistories histories(int stations, int times, F moment) {
  coupling::StressHistories h;
  h.sections = {fem::rectangle_section(kA, kB, 0.3)};
  h.points = {fem::section_points(h.sections[0])};
  h.times = Eigen::VectorXd::LinSpaced(times, 0.0, 0.01 * (times - 1));
  h.forces = Eigen::MatrixXf::Zero(6 * stations, times);
  for (int s = 0; s < stations; ++s) {
    h.stations.push_back({"rail", 100 + s, 0, Eigen::Vector3d(s, 0, 0), 0});
    for (int j = 0; j < times; ++j) h.forces(6 * s + 4, j) = static_cast<float>(moment(s, h.times(j)));
  }
  return h;
}

// Station 0 swings +-M (range 2 M c / I, peak M c / I); station 1 sits at
// 1.5 M plus a small ripple (the largest peak, a small range); station 2 is
// station 1 exactly (a tie: station 1 ranks first); station 3 is small.
TEST(HotSpots, RankedBySteadyPeakVonMisesAndByNormalStressRangeWithTiesToTheLowerStation) {
  const double m = 1000.0, c = kB / 2;
  const auto moment = [&](int s, double t) {
    const double wave = std::sin(2 * 3.14159265358979 * 5 * t);
    if (s == 0) return m * wave;
    if (s == 1 || s == 2) return 1.5 * m + 0.1 * m * wave;
    return 0.2 * m * wave;
  };
  const coupling::StressHistories h = histories(4, 201, moment);
  const coupling::HotSpotReport r = coupling::find_hot_spots(h, {0.0, "test"}, 3);
  ASSERT_EQ(r.by_von_mises.size(), 3u);
  EXPECT_EQ(r.by_von_mises[0].station, 1u);
  EXPECT_EQ(r.by_von_mises[1].station, 2u);
  EXPECT_EQ(r.by_von_mises[2].station, 0u);
  // Corners carry no shear: von Mises = |sigma| = 1.6 M c / I at the peak of the ripple (float storage: 1e-6).
  EXPECT_NEAR(r.by_von_mises[0].von_mises_total, 1.6 * m * c / kI11, 1e-6 * 1.6 * m * c / kI11);
  // Among the tied corners (+1+2 and -1+2 see the same sigma; -2 corners the same magnitude) the first listed.
  EXPECT_EQ(r.by_von_mises[0].point_name, h.points[0][static_cast<std::size_t>(r.by_von_mises[0].point)].name);
  EXPECT_EQ(r.by_von_mises[0].point, 0);
  ASSERT_EQ(r.by_normal_range.size(), 3u);
  EXPECT_EQ(r.by_normal_range[0].station, 0u);
  EXPECT_NEAR(r.by_normal_range[0].normal_stress_range, 2 * m * c / kI11, 1e-6 * 2 * m * c / kI11);
  EXPECT_EQ(r.by_normal_range[1].station, 3u);  // 0.4 M against the ripple stations' 0.2 M
  // The first of equal peaks in time (the ripple peaks every 0.2 s from t = 0.05 s).
  EXPECT_NEAR(r.by_von_mises[0].time, 0.05, 1e-12);
}

// A start-up spike at t = 0.1 s, then a steady swing: the steady peak ignores
// the spike, the start-up peak is the spike, and the split sits at `from`.
TEST(HotSpots, StartUpAndSteadyPeaksSplitWhereTheSteadyReportSays) {
  const double m = 500.0, c = kB / 2;
  const auto moment = [&](int, double t) { return (std::abs(t - 0.1) < 1e-9 ? 4 * m : 0.0) + m * std::sin(2 * 3.14159265358979 * 5 * t); };  // the swing's peaks at t = 0.05 + 0.1 k, on the samples
  const coupling::StressHistories h = histories(1, 101, moment);  // t = 0 .. 1 s
  // The rigid model's report wins over frame.steady_from, which wins over half the record.
  EXPECT_EQ(coupling::steady_window(0.3, 0.6, h.times).from, 0.3);
  EXPECT_EQ(coupling::steady_window(0.3, 0.6, h.times).source, "rigid-body model's steady report");
  EXPECT_EQ(coupling::steady_window(std::nullopt, 0.6, h.times).from, 0.6);
  EXPECT_EQ(coupling::steady_window(std::nullopt, std::nullopt, h.times).from, 0.5);
  EXPECT_EQ(coupling::steady_window(std::nullopt, std::nullopt, h.times).source, "last half of the record");
  const coupling::HotSpotReport r = coupling::find_hot_spots(h, coupling::steady_window(0.3, std::nullopt, h.times));
  EXPECT_EQ(r.startup_times, 30u);  // t = 0 .. 0.29
  EXPECT_EQ(r.steady_times, 71u);   // t = 0.30 .. 1.00
  EXPECT_NEAR(r.startup_peak.von_mises_total, 4 * m * c / kI11, 1e-6 * 4 * m * c / kI11);
  EXPECT_NEAR(r.startup_peak.time, 0.1, 1e-12);
  EXPECT_NEAR(r.steady_peak.von_mises_total, m * c / kI11, 1e-6 * m * c / kI11);
  EXPECT_GE(r.steady_peak.time, 0.3);
  EXPECT_NEAR(r.peak.time, 0.1, 1e-12);  // the whole record's peak is the spike
  EXPECT_NEAR(r.by_von_mises[0].startup_peak_von_mises, r.startup_peak.von_mises_total, 1e-9 * r.startup_peak.von_mises_total);
}

// Total = static + dynamic: with no static state (or a zero one) the total is
// the dynamic stress; a static axial force N adds N / A at every point.
TEST(HotSpots, ZeroStaticStateGivesTotalEqualToDynamicAndAStaticForceAdds) {
  const double m = 800.0, c = kB / 2, n = 2.0e5;
  const coupling::StressHistories h = histories(2, 51, [&](int s, double t) { return (s + 1) * m * std::cos(7 * t); });
  const coupling::HotSpotReport none = coupling::find_hot_spots(h, {0.2, "test"});
  const std::vector<fem::SectionForces> zero(2);
  const coupling::HotSpotReport zeros = coupling::find_hot_spots(h, {0.2, "test"}, 10, &zero);
  ASSERT_EQ(none.by_von_mises.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_EQ(none.by_von_mises[k].von_mises_total, zeros.by_von_mises[k].von_mises_total);
    EXPECT_EQ(none.by_von_mises[k].von_mises_total, none.by_von_mises[k].von_mises_dynamic);
    EXPECT_EQ(none.by_von_mises[k].von_mises_static, 0.0);
  }
  std::vector<fem::SectionForces> axial(2);
  for (fem::SectionForces& f : axial) f.n = n;
  const coupling::HotSpotReport with = coupling::find_hot_spots(h, {0.2, "test"}, 10, &axial);
  const coupling::HotSpot& top = with.by_von_mises[0];
  EXPECT_EQ(top.station, 1u);
  EXPECT_NEAR(top.von_mises_static, n / (kA * kB), 1e-9 * n / (kA * kB));
  // The worst point is the tension side: N / A + |My| c / I at the largest |My| after t = 0.2 s.
  double peak_moment = 0.0;
  for (Eigen::Index j = 0; j < h.times.size(); ++j)
    if (h.times(j) >= 0.2) peak_moment = std::max(peak_moment, 2 * m * std::abs(std::cos(7 * h.times(j))));
  EXPECT_NEAR(top.von_mises_total, n / (kA * kB) + peak_moment * c / kI11, 1e-6 * top.von_mises_total);
  EXPECT_NEAR(top.von_mises_dynamic, peak_moment * c / kI11, 1e-6 * top.von_mises_total);
  // The range is the dynamic one: the static part cancels.
  EXPECT_NEAR(with.by_normal_range[0].normal_stress_range, none.by_normal_range[0].normal_stress_range, 1e-6 * top.von_mises_total);
}

// The stress history at a hot spot's point (what frame_stress_histories.csv
// writes and the hot-spot figure draws) peaks over steady operation at the
// hot spot's total von Mises stress, at its time; its static part is N / A.
TEST(HotSpots, PointStressHistoryPeaksAtTheHotSpotsTotalAndTime) {
  const double m = 800.0, n = 2.0e5;
  const coupling::StressHistories h = histories(2, 51, [&](int s, double t) { return (s + 1) * m * std::cos(7 * t); });
  std::vector<fem::SectionForces> axial(2);
  for (fem::SectionForces& f : axial) f.n = n;
  const coupling::HotSpotReport r = coupling::find_hot_spots(h, {0.2, "test"}, 10, &axial);
  const coupling::HotSpot& top = r.by_von_mises[0];
  const std::vector<fem::PointStress> history = coupling::point_stress_history(h, top.station, top.point, &axial);
  ASSERT_EQ(history.size(), static_cast<std::size_t>(h.times.size()));
  double peak = 0.0, when = -1.0;
  for (Eigen::Index j = 0; j < h.times.size(); ++j)
    if (h.times(j) >= 0.2 && history[static_cast<std::size_t>(j)].von_mises > peak) peak = history[static_cast<std::size_t>(j)].von_mises, when = h.times(j);
  EXPECT_NEAR(peak, top.von_mises_total, 1e-9 * peak);
  EXPECT_EQ(when, top.time);
  // Without the static forces the history is the dynamic part: N / A less in tension.
  const std::vector<fem::PointStress> dynamic = coupling::point_stress_history(h, top.station, top.point);
  const Eigen::Index j = static_cast<Eigen::Index>(std::lround(top.time / 0.01));
  EXPECT_NEAR(history[static_cast<std::size_t>(j)].normal - dynamic[static_cast<std::size_t>(j)].normal, n / (kA * kB), 1e-6 * n / (kA * kB));
  // The pipeline's figure draws these histories, one series per hot spot, in the study's units.
  coupling::FrameStudyResults results;
  results.stress = h;
  results.hot_spots = r;
  results.static_forces = axial;
  const report::LinePlot figure = report::hot_spot_stress_figure(results, framedyn::core::UnitSystem::si());
  ASSERT_EQ(figure.series.size(), 2u);  // two stations, both hot spots (at most three drawn)
  EXPECT_NO_THROW(report::check_plot(figure));
  EXPECT_NEAR(*std::max_element(figure.series[0].y.begin() + 20, figure.series[0].y.end()), top.von_mises_total, 1e-9 * top.von_mises_total);
  EXPECT_EQ(figure.y_unit, "Pa");
}

// The yield warning: only with frame.yield_strength, only when the peak total von Mises exceeds it.
TEST(HotSpots, AStressAboveTheDeclaredYieldStrengthWarns) {
  coupling::FrameStudyResults r;
  r.stress = histories(1, 11, [](int, double t) { return 1000.0 * t; });
  r.hot_spots = coupling::find_hot_spots(r.stress, {0.0, "test"});
  coupling::FrameStudyRequest q;
  q.supports = coupling::FrameSupports::free_free_inertia_relief;
  const auto codes = [&] {
    std::vector<std::string> c;
    for (const auto& w : coupling::frame_warnings(r, q)) c.push_back(w.code);
    return c;
  };
  EXPECT_TRUE(codes().empty());
  const double peak = r.hot_spots.peak.von_mises_total;  // 100 N m * c / I = 1.2 MPa
  q.yield_strength = 1.01 * peak;
  EXPECT_TRUE(codes().empty());
  q.yield_strength = 0.99 * peak;
  ASSERT_EQ(codes().size(), 1u);
  EXPECT_EQ(codes()[0], "stress_above_yield");
}

}  // namespace

// ---- The fatigue life map (coupling/frame_fatigue.h, docs/theory/fatigue.md sections 7-9).

namespace fatigue = framedyn::fatigue;

// A request of code IIW with the default FAT71 and the given details.
coupling::FatigueRequest fatigue_request(std::vector<coupling::FatigueDetail> details = {}) {
  coupling::FatigueRequest q;
  q.details = std::move(details);
  q.where = {"study.yaml", 1, "frame.fatigue"};
  for (coupling::FatigueDetail& d : q.details) d.where = {"study.yaml", 2, "frame.fatigue.details"};
  return q;
}

// 1000 samples at 10 ms, steady from 5 s: 500 samples, a block of 5 s holding
// exactly 5 periods of a 1 Hz sine (sampled at its peaks, t = 0.25 + 0.5 k).
// Corner +1+2 sees sigma = My c / I11: amplitude 71 MPa (range 142 MPa = 2 FAT71):
// N = 2e6 (71 / 142)^3 = 2.5e5 on the m = 3 branch, so the block does 5 / 2.5e5 and an
// hour 720 blocks: 0.0144 per hour, a life of 69.4 h (closed form, F.20-F.21).
TEST(FatigueLifeMap, SineAtAStationGivesTheClosedFormMinerDamagePerHour) {
  const double c = kB / 2, sigma = 71e6, m = sigma * kI11 / c;
  const coupling::StressHistories h = histories(2, 1000, [&](int s, double t) { return (s == 0 ? 1.0 : 0.5) * m * std::sin(2 * 3.14159265358979 * t); });
  fem::FrameModel model;
  const coupling::LifeMap life = coupling::frame_life_map(model, h, {}, {5.0, "test"}, fatigue_request());
  EXPECT_EQ(life.block_samples, 500u);
  EXPECT_NEAR(life.block_seconds, 5.0, 1e-12);
  const double expected = 5.0 / 2.5e5 * 3600.0 / 5.0;
  EXPECT_NEAR(life.damage_per_hour[0][0], expected, 1e-5 * expected);  // float storage of the forces: ~1e-7 in stress
  EXPECT_EQ(life.worst_station, 0u);
  // Station 1 at half the amplitude: (1/2)^-3 = 8 times the life on the m = 3 branch (71 MPa range, above the knee's 41.5 MPa).
  EXPECT_NEAR(life.damage_per_hour[1][0], expected / 8.0, 1e-5 * expected);
}

// At another point and with a static force and Goodman, the map's damage is fatigue/
// applied by hand to the point's total stress over the steady window.
TEST(FatigueLifeMap, DamageAtAPointEqualsFatigueModuleAppliedByHandToItsSteadyHistory) {
  const double m = 800.0;
  const coupling::StressHistories h = histories(1, 400, [&](int, double t) {
    return m * (std::sin(2 * 3.14159265358979 * 7 * t) + 0.4 * std::sin(2 * 3.14159265358979 * 23 * t));
  });
  std::vector<fem::SectionForces> statics(1);
  statics[0].n = 2e4;  // N: a tensile mean of 4 MPa
  statics[0].my = 150.0;
  coupling::FatigueRequest q = fatigue_request();
  q.mean_stress = fatigue::MeanStressCorrection::goodman(400e6);
  const coupling::LifeMap life = coupling::frame_life_map(fem::FrameModel{}, h, statics, {1.0, "test"}, q);
  for (int point : {0, 3}) {
    const std::vector<fem::PointStress> all = coupling::point_stress_history(h, 0, point, &statics);
    std::vector<double> steady;
    for (Eigen::Index j = 0; j < h.times.size(); ++j)
      if (h.times(j) >= 1.0 - 1e-12) steady.push_back(all[static_cast<std::size_t>(j)].normal);
    fatigue::MinerDamage by_hand(fatigue::iiw_normal_stress(71.0), 1.0, q.mean_stress);
    fatigue::count_cycles(steady, fatigue::Residue::repeated_block, by_hand);
    const double per_hour = by_hand.damage() * 3600.0 / (0.01 * static_cast<double>(steady.size()));
    ASSERT_GT(per_hour, 0.0);
    EXPECT_NEAR(life.damage_per_hour[0][static_cast<std::size_t>(point)], per_hour, 1e-12 * per_hour) << h.points[0][static_cast<std::size_t>(point)].name;
  }
}

// Each station takes the class of the first listed set holding its element, else the default;
// the same history on every station then scales its damage as FAT^-3 (m = 3 branch).
TEST(FatigueLifeMap, FatClassPerElementSetFirstListedSetWinsElseTheDefault) {
  const double c = kB / 2, m = 60e6 * kI11 / c;  // range 120 MPa: above every knee below
  const coupling::StressHistories h = histories(4, 200, [&](int, double t) { return m * std::sin(2 * 3.14159265358979 * 10 * t); });
  fem::FrameModel model;
  model.element_sets["LEFT"] = {100, 101};
  model.element_sets["BOTH"] = {101, 102};
  const coupling::LifeMap life =
      coupling::frame_life_map(model, h, {}, {0.0, "test"}, fatigue_request({{"left", 90.0, {}}, {"BOTH", 50.0, {}}}));
  ASSERT_EQ(life.curve_of_station.size(), 4u);
  EXPECT_EQ(life.assignment[static_cast<std::size_t>(life.curve_of_station[0])], "left (details[0])");
  EXPECT_EQ(life.assignment[static_cast<std::size_t>(life.curve_of_station[1])], "left (details[0])");
  EXPECT_EQ(life.assignment[static_cast<std::size_t>(life.curve_of_station[2])], "BOTH (details[1])");
  EXPECT_EQ(life.assignment[static_cast<std::size_t>(life.curve_of_station[3])], "default");
  const double d71 = life.damage_per_hour[3][0];
  EXPECT_NEAR(life.damage_per_hour[0][0] / d71, std::pow(71.0 / 90.0, 3), 1e-9);
  EXPECT_NEAR(life.damage_per_hour[1][0] / d71, std::pow(71.0 / 90.0, 3), 1e-9);
  EXPECT_NEAR(life.damage_per_hour[2][0] / d71, std::pow(71.0 / 50.0, 3), 1e-9);
  EXPECT_EQ(life.worst_station, 2u);
  // A set the mesh lacks, and a set none of whose elements carries a station, are refused.
  EXPECT_THROW(coupling::frame_life_map(model, h, {}, {0.0, "test"}, fatigue_request({{"RIGHT", 90.0, {}}})), framedyn::core::InputError);
  model.element_sets["CROSS"] = {7};
  EXPECT_THROW(coupling::frame_life_map(model, h, {}, {0.0, "test"}, fatigue_request({{"CROSS", 90.0, {}}})), framedyn::core::InputError);
  // A detail's own curve (an S-N curve file's, here built in place): Basquin m = 3 through 90 MPa
  // at 2e6 (C = 2e6 * 90^3) gives FAT90's damage at 120 MPa (above its knee), a class being ignored.
  coupling::FatigueDetail own{"left", 1.0, {}};
  own.curve = framedyn::fatigue::basquin_curve(2e6 * 90.0 * 90.0 * 90.0, 3.0, "file curve");
  const coupling::LifeMap with_curve = coupling::frame_life_map(model, h, {}, {0.0, "test"}, fatigue_request({own}));
  EXPECT_NEAR(with_curve.damage_per_hour[0][0] / d71, std::pow(71.0 / 90.0, 3), 1e-9);
  EXPECT_EQ(with_curve.curves[static_cast<std::size_t>(with_curve.curve_of_station[0])], own.curve->name());
}

// The fatigue block's details[i].curve: an S-N curve file relative to the study file, its
// curve used instead of a class. Reference 200 MPa at 1e5, m = 3 to 4e5 then m = 5:
// N(100 MPa) = 4e5 (2 * 4^(-1/3))^5 (by hand); class and curve together are refused (STUDY-165).
TEST(FatigueLifeMap, DetailCurveFromAFileBesideTheStudyGivesTheHandCyclesToFailure) {
  const framedyn::testing::TempDir dir;
  dir.write("curves/weld.yaml", "name: weld\nreference: {range: 200, cycles: 1e5}\nslopes: [3, 5]\nknees: [4e5]\n");
  const auto block = [&](const std::string& text) {
    static const framedyn::core::UnitSystem si = framedyn::core::UnitSystem::si();
    return coupling::read_fatigue_block(coupling::YamlMap(YAML::Load(text), "frame.fatigue", (dir / "study.yaml").string(), &si));
  };
  const coupling::FatigueRequest q = block("details: [{element_set: LEFT, curve: curves/weld.yaml}]");
  ASSERT_EQ(q.details.size(), 1u);
  ASSERT_TRUE(q.details[0].curve.has_value());
  const double n = 4e5 * std::pow(2.0 * std::pow(4.0, -1.0 / 3.0), 5);
  EXPECT_NEAR(q.details[0].curve->cycles_to_failure(100e6), n, 1e-12 * n);
  EXPECT_NE(q.details[0].curve->name().find("weld"), std::string::npos);
  EXPECT_THROW(block("details: [{element_set: LEFT, class: FAT80, curve: curves/weld.yaml}]"), framedyn::core::InputError);
}

// Two scenarios' maps with hours: the cycle's damage is sum H_i d_i at every location (Miner),
// the dominant scenario the larger H_i d_i, and one scenario of H hours is that run scaled.
TEST(FatigueLifeMap, DutyCycleDamagesAddWithHoursAndOneScenarioIsTheRunScaled) {
  const double c = kB / 2, m = 60e6 * kI11 / c;
  const coupling::StressHistories a = histories(2, 200, [&](int s, double t) { return (s == 0 ? 1.0 : 0.3) * m * std::sin(2 * 3.14159265358979 * 10 * t); });
  const coupling::StressHistories b = histories(2, 200, [&](int s, double t) { return (s == 0 ? 0.3 : 1.0) * m * std::sin(2 * 3.14159265358979 * 20 * t); });
  const coupling::LifeMap la = coupling::frame_life_map(fem::FrameModel{}, a, {}, {0.0, "test"}, fatigue_request());
  const coupling::LifeMap lb = coupling::frame_life_map(fem::FrameModel{}, b, {}, {0.0, "test"}, fatigue_request());
  const coupling::DutyLife duty = coupling::combine_duty_cycle({{"a", 100.0, &la}, {"b", 50.0, &lb}});
  EXPECT_DOUBLE_EQ(duty.cycle_hours, 150.0);
  for (std::size_t s = 0; s < 2; ++s)
    for (std::size_t p = 0; p < la.damage_per_hour[s].size(); ++p)
      EXPECT_NEAR(duty.damage_per_cycle[s][p], 100.0 * la.damage_per_hour[s][p] + 50.0 * lb.damage_per_hour[s][p], 1e-14 * duty.damage_per_cycle[s][p]);
  EXPECT_EQ(duty.dominant[0][0], 0);  // station 0: a's full swing
  EXPECT_EQ(duty.dominant[1][0], 1);  // station 1: b's, at twice the rate
  EXPECT_NEAR(duty.life_hours(1, 0), 150.0 / duty.damage_per_cycle[1][0], 1e-12 * duty.life_hours(1, 0));
  const double hours = 1234.0;
  const coupling::DutyLife one = coupling::combine_duty_cycle({{"a", hours, &la}});
  EXPECT_NEAR(one.damage_per_cycle[0][0], hours * la.damage_per_hour[0][0], 1e-14 * one.damage_per_cycle[0][0]);
  EXPECT_NEAR(one.life_hours(0, 0), 1.0 / la.damage_per_hour[0][0], 1e-12 * one.life_hours(0, 0));
  EXPECT_EQ(one.worst_station, la.worst_station);
  EXPECT_EQ(one.worst_point, la.worst_point);
}

// Shear in the damage (docs/theory/fatigue.md sections 10 and 12, F.26-F.33): a BOX under a
// constant-amplitude bending moment My and a torque T, 1 Hz, a steady block of 5 cycles in
// 5 s (3600 cycles an hour), the torque in phase with the moment (phase 0) or a quarter
// period behind (phase pi/2). At mid-side +2 (top wall): sigma = My (b/2) / I11 with range
// 120 MPa on IIW FAT71 (m = 3): N_s = 2e6 (71/120)^3 = 414,262; the top wall's Bredt-Batho
// shear tau = T / (2 A_m t) with a range chosen so that N_t = ratio N_s on IIW FAT80 shear
// (m = 5): delta tau = 80 (N_t / 2e6)^(-1/5) MPa.
struct TorsionAndBending {
  coupling::StressHistories h;
  std::size_t top = 0;
  double n_s = 0.0, n_t = 0.0, range_t = 0.0;
};
TorsionAndBending torsion_and_bending(double ratio, double phase) {
  const double a = 0.1, b = 0.1, t = 0.005;
  const fem::SectionProperties box = fem::box_section(a, b, t, t, t, t);
  const double area_m = (a - t) * (b - t);
  TorsionAndBending c;
  c.n_s = 2e6 * std::pow(71.0 / 120.0, 3);
  c.n_t = ratio * c.n_s;
  c.range_t = 80e6 * std::pow(c.n_t / 2e6, -0.2);
  const double moment = 60e6 * box.i11 / (b / 2), torque = 0.5 * c.range_t * 2.0 * area_m * t;
  coupling::StressHistories& h = c.h;
  h.sections = {box};
  h.points = {fem::section_points(box)};
  h.times = Eigen::VectorXd::LinSpaced(1000, 0.0, 9.99);
  h.forces = Eigen::MatrixXf::Zero(6, 1000);
  h.stations.push_back({"rail", 100, 0, Eigen::Vector3d::Zero(), 0});
  for (int j = 0; j < 1000; ++j) {
    const double w = 2 * 3.14159265358979 * h.times(j);
    h.forces(3, j) = static_cast<float>(torque * std::sin(w - phase));
    h.forces(4, j) = static_cast<float>(moment * std::sin(w));
  }
  while (c.top < h.points[0].size() && h.points[0][c.top].name != "mid-side +2") ++c.top;
  return c;
}

// In phase, tau = k sigma: proportional (r = 1), so IIW's CV = 1.0. With N_t = 2 N_s,
// d_t = d_s / 2 and (d_s L)^(2/3) + (d_t L)^(2/5) = 1 holds with both terms 1/2:
// d_s L = 2^(-3/2), L = N_s 2^(-3/2) / 3600 h = 40.69 h (against 115.1 h from sigma alone).
// The CV = 0.5 damage is reported too, and solves F.27 with 0.5.
TEST(FatigueLifeMap, ProportionalTorsionAndBendingTakeIiwCvOneWithTheHandLife) {
  const TorsionAndBending c = torsion_and_bending(2.0, 0.0);
  ASSERT_LT(c.top, c.h.points[0].size());
  const coupling::LifeMap iiw = coupling::frame_life_map(fem::FrameModel{}, c.h, {}, {5.0, "test"}, fatigue_request());
  const std::size_t top = c.top;
  const double d_s = 3600.0 / c.n_s, d_t = 3600.0 / c.n_t;
  EXPECT_NEAR(iiw.normal_damage_per_hour[0][top], d_s, 1e-5 * d_s);
  EXPECT_NEAR(iiw.shear_damage_per_hour[0][top], d_t, 1e-5 * d_t);
  EXPECT_NEAR(iiw.correlation[0][top], 1.0, 1e-6);
  EXPECT_EQ(iiw.comparison_value[0][top], 1.0);
  const double life = c.n_s * std::pow(2.0, -1.5) / 3600.0;
  EXPECT_NEAR(1.0 / iiw.damage_per_hour[0][top], life, 1e-5 * life);
  EXPECT_EQ(iiw.damage_per_hour[0][top], iiw.proportional_damage_per_hour[0][top]);
  // Under CV = 0.5 the same sums last k periods with (d_s k)^(2/3) + (d_t k)^(2/5) = 0.5.
  const double k = 1.0 / iiw.non_proportional_damage_per_hour[0][top];
  const double ds = iiw.normal_damage_per_hour[0][top], dt = iiw.shear_damage_per_hour[0][top];
  EXPECT_NEAR(std::pow(ds * k, 2.0 / 3.0) + std::pow(dt * k, 2.0 / 5.0), 0.5, 1e-12);
  std::cout << "[ measured ] in phase: r " << iiw.correlation[0][top] << ", CV " << iiw.comparison_value[0][top] << ", life "
            << 1.0 / iiw.damage_per_hour[0][top] << " h (hand " << life << "), under CV 0.5 " << k << " h\n";
  // A duty cycle of this one scenario is proportional too.
  const coupling::DutyLife duty = coupling::combine_duty_cycle({{"in phase", 10.0, &iiw}});
  EXPECT_EQ(duty.comparison_value[0][top], 1.0);
  EXPECT_NEAR(duty.life_hours(0, static_cast<int>(top)), life, 1e-5 * life);
}

// A quarter period out of phase: r = cos(pi/2) = 0, not proportional, CV = 0.5. With N_t = 4 N_s,
// d_t = d_s / 4 and F.27 holds at d_s L = 1/8 (1/4 + 1/4 = 0.5): L = N_s / (8 * 3600) h = 14.38 h.
// EN 1993-1-9 has no CV (both codes' curves above their knees): L = N_s / (1.25 * 3600) h.
TEST(FatigueLifeMap, TorsionAQuarterPeriodOutOfPhaseTakesIiwCvHalfAndEn1993TheDamageSum) {
  const TorsionAndBending c = torsion_and_bending(4.0, 3.14159265358979 / 2);
  ASSERT_LT(c.top, c.h.points[0].size());
  const std::size_t top = c.top;
  const double d_s = 3600.0 / c.n_s, d_t = 3600.0 / c.n_t;
  const coupling::LifeMap iiw = coupling::frame_life_map(fem::FrameModel{}, c.h, {}, {5.0, "test"}, fatigue_request());
  EXPECT_NEAR(iiw.normal_damage_per_hour[0][top], d_s, 1e-5 * d_s);
  EXPECT_NEAR(iiw.shear_damage_per_hour[0][top], d_t, 1e-5 * d_t);
  EXPECT_NEAR(iiw.normal_max_range[0][top], 120e6, 1e-5 * 120e6);
  EXPECT_NEAR(iiw.shear_max_range[0][top], c.range_t, 1e-5 * c.range_t);
  EXPECT_NEAR(iiw.correlation[0][top], 0.0, 1e-6);
  EXPECT_EQ(iiw.comparison_value[0][top], 0.5);
  const double life_iiw = c.n_s / (8.0 * 3600.0);
  EXPECT_NEAR(1.0 / iiw.damage_per_hour[0][top], life_iiw, 1e-5 * life_iiw);
  EXPECT_EQ(iiw.damage_per_hour[0][top], iiw.non_proportional_damage_per_hour[0][top]);
  EXPECT_LT(iiw.proportional_damage_per_hour[0][top], iiw.damage_per_hour[0][top]);
  std::cout << "[ measured ] a quarter period apart: r " << iiw.correlation[0][top] << ", CV " << iiw.comparison_value[0][top] << ", life "
            << 1.0 / iiw.damage_per_hour[0][top] << " h (hand " << life_iiw << "), under CV 1 " << 1.0 / iiw.proportional_damage_per_hour[0][top]
            << " h, normal alone " << 1.0 / d_s << " h\n";
  coupling::FatigueRequest en = fatigue_request();
  en.code = coupling::FatigueCode::en1993;
  const coupling::LifeMap en_map = coupling::frame_life_map(fem::FrameModel{}, c.h, {}, {5.0, "test"}, en);
  const double life_en = c.n_s / (1.25 * 3600.0);
  EXPECT_NEAR(1.0 / en_map.damage_per_hour[0][top], life_en, 1e-5 * life_en);
  EXPECT_EQ(en_map.proportional_damage_per_hour[0][top], en_map.damage_per_hour[0][top]);
  EXPECT_EQ(en_map.non_proportional_damage_per_hour[0][top], en_map.damage_per_hour[0][top]);
  // A shear range under 15 % of the normal one is neglected under IIW: the normal damage alone.
  EXPECT_DOUBLE_EQ(coupling::combined_damage(coupling::FatigueCode::iiw, 2e-3, 1e-9, 100e6, 14.9e6), 2e-3);
  EXPECT_DOUBLE_EQ(coupling::combined_damage(coupling::FatigueCode::iiw, 1e-9, 2e-3, 14.9e6, 100e6), 2e-3);
  EXPECT_DOUBLE_EQ(coupling::combined_damage(coupling::FatigueCode::en1993, 2e-3, 1e-3, 100e6, 10e6), 3e-3);
  // A duty cycle combines the cycle's damage sums: one scenario of 10 h gives 10 h worth of the same combination.
  const coupling::DutyLife duty = coupling::combine_duty_cycle({{"torsion and bending", 10.0, &iiw}});
  const double life_map = 1.0 / iiw.damage_per_hour[0][top];
  EXPECT_NEAR(duty.life_hours(0, static_cast<int>(top)), life_map, 1e-12 * life_map);
  EXPECT_NEAR(duty.normal_damage_per_cycle[0][top], 10.0 * iiw.normal_damage_per_hour[0][top], 1e-12 * duty.normal_damage_per_cycle[0][top]);
  EXPECT_EQ(duty.comparison_value[0][top], 0.5);
  // The cycle is as proportional as its least proportional damaging scenario.
  const TorsionAndBending in_phase = torsion_and_bending(4.0, 0.0);
  const coupling::LifeMap iiw_in_phase = coupling::frame_life_map(fem::FrameModel{}, in_phase.h, {}, {5.0, "test"}, fatigue_request());
  EXPECT_EQ(iiw_in_phase.comparison_value[0][top], 1.0);
  const coupling::DutyLife mixed = coupling::combine_duty_cycle({{"in phase", 10.0, &iiw_in_phase}, {"out of phase", 1.0, &iiw}});
  EXPECT_EQ(mixed.comparison_value[0][top], 0.5);
  EXPECT_NEAR(mixed.correlation[0][top], iiw.correlation[0][top], 1e-12);
}

// The correlation measure (F.32): sine pairs out of phase by phi give r = cos phi over whole periods;
// a constant history is proportional to anything; the threshold |r| >= 0.95 is the CV's switch.
TEST(FatigueLifeMap, CorrelationOfSinePairsIsTheCosineOfTheirPhaseAndSwitchesTheCvAtPointNineFive) {
  for (double phi_deg : {0.0, 10.0, 18.0, 19.0, 45.0, 90.0, 180.0}) {
    std::vector<double> sigma(400), tau(400);
    for (std::size_t k = 0; k < sigma.size(); ++k) {
      const double w = 2 * 3.14159265358979 * static_cast<double>(k) / 100.0;
      sigma[k] = 50e6 + 80e6 * std::sin(w);  // a mean does not matter
      tau[k] = 30e6 * std::sin(w - phi_deg * 3.14159265358979 / 180.0);
    }
    const double r = coupling::stress_correlation(sigma, tau);
    EXPECT_NEAR(r, std::cos(phi_deg * 3.14159265358979 / 180.0), 1e-12) << phi_deg;
    EXPECT_EQ(coupling::iiw_comparison_value(r), phi_deg <= 18.0 || phi_deg == 180.0 ? 1.0 : 0.5) << phi_deg;
  }
  EXPECT_EQ(coupling::stress_correlation({1.0, 2.0, 3.0}, {4.0, 4.0, 4.0}), 1.0);
}

// The signed shear reverses with the torque (the range the magnitude lost): at a circle's
// surface a torque +-T gives +-T r / J along the surface, a range of 2 T r / J.
TEST(SignedShear, ReversesWithTheTorqueAlongTheSurfaceAndAnOpenWallsFacesDifferByTwiceTheTorsionalShear) {
  const fem::SectionProperties pipe = fem::pipe_section(0.05, 0.004, 0.3);
  const std::vector<fem::SectionPoint> points = fem::section_points(pipe);
  fem::SectionForces f;
  f.t = 1000.0;
  const double tau = 1000.0 * 0.05 / pipe.torsion_constant;
  for (const fem::SectionPoint& p : points) {
    EXPECT_NEAR(fem::signed_shear(p, f).face, tau, 1e-9 * tau) << p.name;
    f.t = -f.t;
    EXPECT_NEAR(fem::signed_shear(p, f).face, -tau, 1e-9 * tau) << p.name;
    f.t = -f.t;
  }
  fem::SectionProperties i = fem::i_section(0.2, 0.1, 0.1, 0.01, 0.01, 0.006);
  const std::vector<fem::SectionPoint> ip = fem::section_points(i);
  f.vz = 5000.0;
  for (const fem::SectionPoint& p : ip) {
    const fem::SignedShear s = fem::signed_shear(p, f);
    const double from_torque = std::abs(fem::shear_direction(p).dot(f.t * p.shear_per_torque));
    EXPECT_NEAR(std::abs(s.face - s.other_face), 2.0 * from_torque, 1e-9 * (1.0 + from_torque)) << p.name;
    EXPECT_NEAR(std::max(std::abs(s.face), std::abs(s.other_face)), fem::point_stress(i, p, f).shear, 1e-6 * (1.0 + fem::point_stress(i, p, f).shear)) << p.name;
  }
}
