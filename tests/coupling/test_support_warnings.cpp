// Which support a frame study used, and the warning when a peak sits on an
// artificial support (issue 17). Physical facts on a straight steel beam
// (1 m, 8 elements) under a slowly ramped load:
//  - clamped at one end and loaded at the other, the bending moment is
//    largest at the clamp (the cantilever's root moment P L): the study warns
//    that the peak is set by a support the machine may not have;
//  - clamped at one end, on a roller at the other (the mesh's *BOUNDARY) and
//    loaded at 3/4 of the span, the moment is largest under the load
//    (R_B b = P a^2 (3L - a) b / (2 L^3) = 0.158 P L, against 0.117 P L at the
//    clamp), two elements from the clamp: no warning;
//  - free-free (inertia relief) there is no support to warn about.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "coupling/frame_study.h"
#include "report/frame_outputs.h"
#include "tests/support/temp_dir.h"

namespace {

using namespace framedyn;

std::string beam_inp(const std::string& boundary) {
  std::string t = "** units: m-N-s\n*NODE, NSET=ALL_NODES\n";
  for (int i = 0; i <= 8; ++i) t += std::to_string(i + 1) + ", " + std::to_string(0.125 * i) + ", 0, 0\n";
  t += "*ELEMENT, TYPE=B33, ELSET=BEAM\n";
  for (int e = 1; e <= 8; ++e) t += std::to_string(e) + ", " + std::to_string(e) + ", " + std::to_string(e + 1) + "\n";
  t += "*NSET, NSET=ROOT\n1\n*NSET, NSET=MID\n5\n*NSET, NSET=END\n9\n";
  t += "*BEAM SECTION, ELSET=BEAM, MATERIAL=STEEL, SECTION=RECT\n0.02, 0.02\n0, 0, -1\n";
  t += "*MATERIAL, NAME=STEEL\n*ELASTIC\n2.1e11, 0.3\n*DENSITY\n7850\n" + boundary;
  return t;
}

// A vertical load ramped from 0 to 100 N over 0.5 s at `set`. The beam's lowest mode is above 15 Hz
// (16.7 Hz for the cantilever): a mode started at rest lags a ramp by at most 1 / (2 pi n) of the
// ramp's final static value, n the periods in the ramp (1.9 % for n = 8.4), and 2 % damping decays
// that lag to about a third by the end: 2 % of the static value bounds the dynamic part.
coupling::LoadHistory ramp_at(const std::string& set, double x) {
  coupling::LoadHistory h;
  h.times = Eigen::VectorXd::LinSpaced(51, 0.0, 0.5);
  coupling::LoadPointHistory p;
  p.name = set;
  p.location = Eigen::Vector3d(x, 0, 0);
  p.values = Eigen::MatrixXd::Zero(51, 6);
  p.values.col(2) = 200.0 * h.times;
  h.points.push_back(p);
  return h;
}

struct Case {
  coupling::FrameStudyResults results;
  coupling::FrameStudyRequest request;
};

Case run_case(const framedyn::testing::TempDir& dir, const std::string& boundary, coupling::FrameSupports supports,
              const std::vector<std::string>& sets, const coupling::LoadHistory& loads) {
  Case c;
  c.request.file = "test";
  c.request.mesh = dir.write("beam_" + std::to_string(static_cast<int>(supports)) + std::to_string(boundary.size()) + ".inp", beam_inp(boundary));
  c.request.supports = supports;
  c.request.support_sets = sets;
  c.request.modes = -1;
  c.request.rails = {{"beam", "BEAM"}};
  c.results = coupling::run_frame_study(c.request, &loads);
  return c;
}

TEST(SupportWarnings, CantileverPeakMomentAtTheClampIsWarnedAndTheSummaryNamesTheSupport) {
  const framedyn::testing::TempDir dir("framedyn_test_support_warnings");
  const Case c = run_case(dir, "", coupling::FrameSupports::clamped, {"ROOT"}, ramp_at("END", 1.0));
  const coupling::RailPeak& peak = c.results.rails[0].peak_bending_moment;
  EXPECT_EQ(peak.element_id, 1);  // the root element
  EXPECT_NEAR(peak.value, 100.0 * 1.0, 0.02 * 100.0);  // P L at the root, within the ramp's dynamic part (below)
  const std::vector<core::Warning> w = coupling::frame_warnings(c.results, c.request);
  ASSERT_EQ(w.size(), 1u);  // the stress and moment peaks share the root element: one warning
  EXPECT_EQ(w[0].code, "peak_at_artificial_support");
  EXPECT_NE(w[0].message.find("beam: the peak normal stress"), std::string::npos) << w[0].message;
  EXPECT_NE(w[0].message.find("the clamp of ROOT (clamped), node 1"), std::string::npos) << w[0].message;
  const auto j = nlohmann::json::parse(report::frame_summary_json(c.results, c.request));
  EXPECT_EQ(j["support"]["kind"], "clamped");
  EXPECT_EQ(j["support"]["artificial"], true);
  EXPECT_EQ(j["support"]["nodes"], nlohmann::json::array({1}));
  ASSERT_EQ(j["load_points"].size(), 1u);
  EXPECT_EQ(j["load_points"][0]["name"], "END");
  EXPECT_EQ(j["load_points"][0]["position"]["value"], nlohmann::json::array({1, 0, 0}));
  EXPECT_NEAR(j["load_points"][0]["peak_force"]["value"].get<double>(), 100.0, 1e-9);
  EXPECT_EQ(j["load_points"][0]["peak_force"]["time"]["value"], 0.5);
}

TEST(SupportWarnings, ProppedCantileverPeakUnderTheLoadAwayFromTheClampIsNotWarned) {
  const framedyn::testing::TempDir dir("framedyn_test_support_warnings");
  // Clamp at node 1 (the study's), roller at node 9 (the mesh's *BOUNDARY), load at node 7 (X = 0.75 m).
  const Case c = run_case(dir, "*NSET, NSET=LOAD\n7\n*BOUNDARY\n9, 2, 3\n", coupling::FrameSupports::clamped, {"ROOT"}, ramp_at("LOAD", 0.75));
  const coupling::RailPeak& peak = c.results.rails[0].peak_bending_moment;
  EXPECT_NEAR(peak.point.x(), 0.75, 1e-12);
  const double a = 0.75, b = 0.25;
  EXPECT_NEAR(peak.value, 100.0 * a * a * (3 - a) * b / 2, 0.02 * 100.0 * a * a * (3 - a) * b / 2);  // R_B b, within the ramp's dynamic part
  EXPECT_TRUE(coupling::frame_warnings(c.results, c.request).empty());
  const auto j = nlohmann::json::parse(report::frame_summary_json(c.results, c.request));
  EXPECT_EQ(j["support"]["kind"], "clamped");
  EXPECT_EQ(j["support"]["nodes"], nlohmann::json::array({1, 9}));  // every supported node, the roller's too
}

TEST(SupportWarnings, FreeFreeFrameHasNoSupportToWarnAbout) {
  const framedyn::testing::TempDir dir("framedyn_test_support_warnings");
  const Case c = run_case(dir, "", coupling::FrameSupports::free_free_inertia_relief, {}, ramp_at("END", 1.0));
  EXPECT_TRUE(coupling::frame_warnings(c.results, c.request).empty());
  const auto j = nlohmann::json::parse(report::frame_summary_json(c.results, c.request));
  EXPECT_EQ(j["support"]["kind"], "free_free_inertia_relief");
  EXPECT_EQ(j["support"]["artificial"], false);
}

}  // namespace
