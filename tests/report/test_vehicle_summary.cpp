// What summary.json says about a vehicle run that the 2-D and the 3-D model
// must say the same way (issue 15: one meaning per key, every feature in both
// models): the 3-D tires' forces in rigid.steady.peaks, as the 2-D model's
// contacts are there, each equal to the extreme of its own response.csv column
// over its window; and rigid.road_inputs in 2-D, the delay of F.31
// (docs/theory/fatigue.md section 11) by the one coupling::road_delays.
#include <gtest/gtest.h>

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "coupling/road_delays.h"
#include "report/study_run.h"
#include "tests/support/temp_dir.h"

namespace {

using Json = nlohmann::json;
using framedyn::testing::TempDir;

std::string shipped(const std::string& name) {
  std::ifstream in(std::string(FRAMEDYN_SOURCE_DIR) + "/examples/" + name, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}
std::string read_text(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}
std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  if (at == std::string::npos) throw std::runtime_error("no '" + from + "' in the study");
  return text.replace(at, from.size(), to);
}

// response.csv as columns by header.
struct Table {
  std::vector<std::string> names;
  std::vector<std::vector<double>> columns;
  const std::vector<double>& operator[](const std::string& name) const {
    const auto it = std::find(names.begin(), names.end(), name);
    if (it == names.end()) throw std::runtime_error("no column " + name);
    return columns[static_cast<std::size_t>(it - names.begin())];
  }
};
Table read_csv(const std::string& text) {
  Table t;
  std::istringstream in(text);
  std::string line, cell;
  std::getline(in, line);
  for (std::istringstream h(line); std::getline(h, cell, ',');) t.names.push_back(cell);
  t.columns.resize(t.names.size());
  while (std::getline(in, line)) {
    std::istringstream r(line);
    for (std::size_t k = 0; k < t.names.size() && std::getline(r, cell, ','); ++k) t.columns[k].push_back(std::stod(cell));
  }
  return t;
}

// The value of largest magnitude (signed) of `v` over the samples whose time is in [from, to).
double extreme(const std::vector<double>& time, const std::vector<double>& v, double from, double to) {
  double peak = 0.0;
  bool any = false;
  for (std::size_t i = 0; i < time.size(); ++i)
    if (time[i] >= from && time[i] < to && (!any || std::abs(v[i]) > std::abs(peak))) {
      peak = v[i];
      any = true;
    }
  if (!any) throw std::runtime_error("no sample in the window");
  return peak;
}

// The shipped offset plow (3-D, 0.5 s). It does not reach steady operation (docs/validation.md P1.4;
// neither did variants without soil and with ten to thirty times the tire and cab-mount damping over
// 2 s, V29), so its start-up window is the whole run and no peak has a `steady` part; if a run
// reaches it, the steady part is checked over [reached_at, end) the same way.
TEST(VehicleSummary, EachThreeDTireForcePeakIsTheExtremeOfItsResponseColumnOverItsWindow) {
  const TempDir dir;
  const std::filesystem::path study = dir.write("study.yaml", shipped("r100_plow_offset.yaml"));
  framedyn::report::StudyRunOptions options;
  options.out = dir / "results";
  framedyn::report::run_study_file(study, options);
  const Json summary = Json::parse(read_text(dir / "results" / "summary.json"));
  const Table csv = read_csv(read_text(dir / "results" / "response.csv"));
  const Json& steady = summary["rigid"]["steady"];
  const bool reached = !steady["reached_at"].is_null();
  const double from = reached ? steady["reached_at"]["value"].get<double>() : 1e300;
  const std::vector<double>& time = csv["time [s]"];
  int tires = 0;
  for (const char* tire : {"front_left_tire", "front_right_tire", "rear_left_tire", "rear_right_tire"})
    for (const char* direction : {"_vertical", "_longitudinal", "_lateral"}) {
      const std::string name = std::string(tire) + direction + "_force";
      ASSERT_TRUE(steady["peaks"].contains(name)) << name;
      const Json& p = steady["peaks"][name];
      const std::vector<double>& f = csv[name + " [lbf]"];
      // response.csv holds 10 significant digits (core::format_number): 1e-9 of the value.
      const double u = extreme(time, f, -1e300, from);
      EXPECT_EQ(p["start_up"]["unit"], "lbf") << name;
      EXPECT_NEAR(p["start_up"]["value"].get<double>(), u, 1e-9 * std::abs(u)) << name;
      EXPECT_EQ(p.contains("steady"), reached) << name;
      if (reached) {
        const double s = extreme(time, f, from, 1e300);
        EXPECT_NEAR(p["steady"]["value"].get<double>(), s, 1e-9 * std::abs(s)) << name;
      }
      ++tires;
    }
  EXPECT_EQ(tires, 12);
}

// The same shape as the 2-D model's contacts in rigid.steady.peaks (the shipped 2-D plow).
TEST(VehicleSummary, TwoDContactPeaksAndThreeDTirePeaksHaveTheSameShape) {
  const TempDir dir;
  const std::filesystem::path study = dir.write("study.yaml", shipped("r100_plow_2d.yaml"));
  const Json two_d = framedyn::report::run_study_file(study).summary;
  const Json& p = two_d["rigid"]["steady"]["peaks"]["front_tire_normal_force"];
  ASSERT_TRUE(p.contains("start_up")) << two_d["rigid"]["steady"]["peaks"].dump();
  for (const char* key : {"value", "unit", "time"}) EXPECT_TRUE(p["start_up"].contains(key)) << key;
  EXPECT_EQ(p["start_up"]["unit"], "lbf");
}

// F.31 with the 2-D machine's tires at X 0 and 72 in driving at 78.74 in/s over one road: the rear
// sees the front's profile 72 / 78.74 s later; the summary's rigid.road_inputs lists both tires'
// inputs with the keys of the 3-D model's (tire, behind, delay, source).
TEST(VehicleSummary, TwoDRoadInputsRunTheWheelbaseBehindAndSeeTheFrontProfileWheelbaseOverSpeedLater) {
  const std::string road = "{kind: road, class: D, speed: 78.74}";
  std::string text = shipped("r100_plow_2d.yaml");
  text = replaced(text, "    contact: [0, -26]\n", "    contact: [0, -26]\n    normal_input: " + road + "\n");
  text = replaced(text, "    contact: [72, -26]\n", "    contact: [72, -26]\n    normal_input: " + road + "\n    tractive_input: {behind: 60, kind: road, class: D, speed: 78.74}\n");
  text = replaced(text, "  response: {duration: 0.5, output_interval: 0.0005, method: event_located}\n", "");
  const TempDir dir;
  const Json s = framedyn::report::run_study_file(dir.write("study.yaml", text)).summary;
  ASSERT_TRUE(s["rigid"].contains("road_inputs")) << s["rigid"].dump();
  const Json& r = s["rigid"]["road_inputs"];
  ASSERT_EQ(r.size(), 3u);
  const double wheelbase = 72.0, speed = 78.74;  // in, in/s
  const struct {
    const char* tire;
    double behind;
    const char* source;
  } expected[] = {{"front", 0.0, "derived from the tire positions"}, {"rear", wheelbase, "derived from the tire positions"}, {"rear (tractive)", 60.0, "behind (given)"}};
  for (std::size_t k = 0; k < 3; ++k) {
    std::vector<std::string> keys;
    for (const auto& [key, v] : r[k].items()) keys.push_back(key);
    EXPECT_EQ(keys, (std::vector<std::string>{"behind", "delay", "source", "tire"}));  // nlohmann::json lists keys sorted
    EXPECT_EQ(r[k]["tire"], expected[k].tire);
    EXPECT_NEAR(r[k]["behind"]["value"].get<double>(), expected[k].behind, 1e-9);
    EXPECT_EQ(r[k]["behind"]["unit"], "in");
    EXPECT_NEAR(r[k]["delay"]["value"].get<double>(), expected[k].behind / speed, 1e-12);
    EXPECT_EQ(r[k]["delay"]["unit"], "s");
    EXPECT_EQ(r[k]["source"], expected[k].source);
  }
  EXPECT_NEAR(r[1]["delay"]["value"].get<double>(), 0.914402, 1e-6);
}

// One implementation for both models: a road input of each kind at a given behind and speed.
TEST(VehicleSummary, RoadDelayIsBehindOverSpeedAndSkipsInputsThatAreNotRoads) {
  framedyn::rigid::GroundInput road, sine;
  road.kind = framedyn::rigid::GroundInput::Kind::road;
  road.behind = 1.8;
  road.speed = 2.5;
  sine.kind = framedyn::rigid::GroundInput::Kind::sine;
  const std::vector<framedyn::coupling::RoadDelay> d = framedyn::coupling::road_delays({{"a", &sine}, {"b", &road}});
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].tire, "b");
  EXPECT_EQ(d[0].delay, 1.8 / 2.5);
  EXPECT_FALSE(d[0].given);
}

}  // namespace
