// The frame summary (report::frame_summary, summary.json's "frame") is
// valid JSON whatever its strings hold: a mesh path, load-point and rail names
// with a tab, a line break, a quote, a backslash and every other control
// character parse back with nlohmann and read back exactly as given (issue 14,
// item 6: the hand-built JSON escaped only '"' and '\').
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <string>

#include "coupling/frame_study.h"
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

}  // namespace
