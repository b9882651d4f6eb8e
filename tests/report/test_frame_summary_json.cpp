// The frame summary (report::frame_summary, summary.json's "frame") is
// valid JSON whatever its strings hold: a mesh path, load-point and rail names
// with a tab, a line break, a quote, a backslash and every other control
// character parse back with nlohmann and read back exactly as given (issue 14,
// item 6: the hand-built JSON escaped only '"' and '\'). The fatigue summary's
// pieces write no null (which the output check refuses as a broken-down
// number): an unlimited life is {unit: h, none: why}, and EN 1993-1-9, which
// has no comparison value, gets none in its proportionality block.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <string>

#include "core/error.h"
#include "core/finite_output.h"
#include "coupling/frame_study.h"
#include "report/fatigue_outputs.h"
#include "report/frame_outputs.h"

namespace {

using namespace framedyn;

// Every control character U+0001..U+001F, a quote, a backslash and DEL.
std::string awkward(const std::string& stem) {
  std::string s = stem + " ";
  for (char c = 1; c < 0x20; ++c) s += c;
  return s + "\"\\\x7f end";
}

TEST(FrameSummaryJson, ControlCharactersInEveryStringParseBackUnchanged) {
  coupling::FrameStudyRequest q;
  q.units = core::UnitSystem::from_name("in-lbf-s");
  q.mesh = awkward("meshes/frame") + ".inp";
  coupling::FrameStudyResults r;
  fem::Node node;
  node.id = 7;
  r.model.nodes.push_back(node);
  coupling::MappedLoadPoint p;
  p.name = awkward("P25_FRONT_AXLE_PIN");
  p.nodes = {0};
  p.spider_length = 0.0254;
  r.mapping.points.push_back(p);
  coupling::RailRecovery rail;
  rail.spec.name = awkward("left_rail");
  rail.peak_bending_moment.value = 1000.0;
  const double psi = 4.4482216152605 / (0.0254 * 0.0254);  // Pa: lbf (exact) per square inch
  rail.peak_normal_stress.value = 1000.0 * psi;
  rail.peak_normal_stress.point = Eigen::Vector3d(0.254, 0, 0);
  r.rails.push_back(rail);

  const std::string text = report::frame_summary(r, q).dump(2);
  nlohmann::json j;
  ASSERT_NO_THROW(j = nlohmann::json::parse(text)) << text;
  EXPECT_EQ(j["mesh"].get<std::string>(), q.mesh.string());
  EXPECT_EQ(j["load_points"][0]["name"].get<std::string>(), p.name);
  EXPECT_EQ(j["peak_bending_moment"][rail.spec.name]["rail"].get<std::string>(), rail.spec.name);
  EXPECT_EQ(j["peak_normal_stress"]["rail"].get<std::string>(), rail.spec.name);
  // The numbers in the study's units, each with its unit: 0.0254 m = 1 in, 1000 psi, 0.254 m = 10 in.
  EXPECT_DOUBLE_EQ(j["load_points"][0]["spider_length"]["value"].get<double>(), 1.0);
  EXPECT_EQ(j["load_points"][0]["spider_length"]["unit"].get<std::string>(), "in");
  EXPECT_NEAR(j["peak_normal_stress"]["value"].get<double>(), 1000.0, 1e-12 * 1000.0);
  EXPECT_EQ(j["peak_normal_stress"]["unit"].get<std::string>(), "psi");
  EXPECT_DOUBLE_EQ(j["peak_normal_stress"]["x"]["value"].get<double>(), 10.0);
}

// A point no cycle damages has an unlimited life: written as {unit, none} (the
// summaries' shape for a quantity without a value), never as null, which the
// check every results file passes refuses (the EN 1993 pipeline run exited 2 on it).
TEST(FatigueSummaryJson, AnUnlimitedLifeAndEn1993sMissingComparisonValueAreWrittenWithoutANull) {
  EXPECT_THROW(core::check_finite_output("summary.json", R"({"comparison_value": null})"), core::NumericalError);  // the old shape
  const nlohmann::ordered_json unlimited = report::life_json(1.0, 0.0);
  EXPECT_EQ(unlimited, nlohmann::ordered_json({{"unit", "h"}, {"none", report::kUnlimitedLifeReason}}));
  EXPECT_EQ(report::life_json(2.0, 0.5), nlohmann::ordered_json({{"value", 4.0}, {"unit", "h"}}));  // 2 h / 0.5 of the damage
  // EN 1993-1-9 (F.29 adds the sums): no comparison value and no lives under IIW's two CVs.
  const nlohmann::ordered_json en = report::proportionality_summary(coupling::FatigueCode::en1993, 0.3, 0.5, 1e-3, 1e-3, 1.0);
  EXPECT_FALSE(en.contains("comparison_value")) << en.dump();
  EXPECT_FALSE(en.contains("life_proportional")) << en.dump();
  EXPECT_NE(en["why"].get<std::string>().find("EN 1993-1-9"), std::string::npos);
  EXPECT_NO_THROW(core::check_finite_output("summary.json", en.dump(2)));
  // IIW at a point no cycle damages: both lives unlimited, each with its CV.
  const nlohmann::ordered_json iiw = report::proportionality_summary(coupling::FatigueCode::iiw, 0.99, 1.0, 0.0, 0.0, 1.0);
  EXPECT_EQ(iiw["comparison_value"], 1.0);
  EXPECT_EQ(iiw["life_proportional"]["none"], report::kUnlimitedLifeReason);
  EXPECT_EQ(iiw["life_non_proportional"]["comparison_value"], 0.5);
  EXPECT_NO_THROW(core::check_finite_output("summary.json", iiw.dump(2)));
}

}  // namespace
