// Study files are read strictly (issue 14, item 3):
//   - a key given twice in one map is an error naming both lines (YAML
//     parsers keep the first silently: `slope_deg: 0` then `slope_deg: 5`
//     ran level);
//   - unit-system names are read in any letter case;
//   - a frame study whose load history (or mesh) is in other units than the
//     study is refused naming both systems, unless the study says
//     frame.convert_units: true; converted, the history gives the same frame
//     response as the same loads written in the study's units.
// And the rear tires' road delay (docs/theory/fatigue.md section 11): derived from the
// tire positions unless the study gives `behind`.
#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <fstream>
#include <sstream>
#include <string>

#include "core/error.h"
#include "core/units.h"
#include "coupling/frame_study.h"
#include "coupling/load_history.h"
#include "coupling/rigid_study.h"
#include "coupling/road_delays.h"
#include "tests/support/temp_dir.h"

namespace {

namespace fs = std::filesystem;
using namespace framedyn;

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  if (at == std::string::npos) throw std::logic_error("no '" + from + "'");
  return text.replace(at, from.size(), to);
}

std::string error_of(const std::function<void()>& run) {
  try {
    run();
  } catch (const core::InputError& e) {
    return e.what();
  }
  return "";
}

const fs::path kSource = FRAMEDYN_SOURCE_DIR;

TEST(StrictStudy, AKeyGivenTwiceNamesBothLines) {
  const framedyn::testing::TempDir dir;
  const std::string study = replaced(read_text(kSource / "examples" / "r100_plow_2d.yaml"), "  slope_deg: 0\n", "  slope_deg: 0\n  slope_deg: 5\n");
  const fs::path file = dir.write("study.yaml", study);
  const std::string m = error_of([&] { coupling::read_rigid_study(file.string()); });
  // The second slope_deg is on the line after the first.
  int first = 0;
  {
    std::istringstream in(study);
    std::string line;
    for (int n = 1; std::getline(in, line); ++n)
      if (line == "  slope_deg: 0") first = n;
  }
  ASSERT_GT(first, 0);
  EXPECT_EQ(m, file.string() + ":" + std::to_string(first + 1) + ": ground.slope_deg: expected each key once in a map, found 'slope_deg' a second time (first on line " +
                   std::to_string(first) + ")");
}

TEST(StrictStudy, AKeyGivenTwiceInsideAListItemIsFoundToo) {
  const framedyn::testing::TempDir dir;
  const std::string study = replaced(read_text(kSource / "examples" / "r100_plow_2d.yaml"), "{name: engine, weight: 850,", "{name: engine, weight: 850, weight: 900,");
  const fs::path file = dir.write("study.yaml", study);
  const std::string m = error_of([&] { coupling::read_rigid_study(file.string()); });
  EXPECT_NE(m.find("frame.added_masses[4].weight: expected each key once in a map, found 'weight' a second time (first on line"), std::string::npos) << m;
}

TEST(StrictStudy, UnitNamesAreReadInAnyLetterCase) {
  EXPECT_EQ(core::UnitSystem::from_name("IN-LBF-S").name(), "in-lbf-s");
  EXPECT_EQ(core::UnitSystem::from_name("si").name(), "m-N-s");
  EXPECT_EQ(core::UnitSystem::from_name("M-n-S").name(), "m-N-s");
  EXPECT_EQ(core::UnitSystem::from_name("MM-N-S").name(), "mm-N-s");
  EXPECT_THROW(core::UnitSystem::from_name("ft-lbf-s"), std::invalid_argument);
  // A study in capitals reads the same machine: the cab's mass, 650 lbf / g.
  const framedyn::testing::TempDir dir;
  const std::string text = read_text(kSource / "examples" / "r100_plow_2d.yaml");
  const auto lower = coupling::read_rigid_study(dir.write("a.yaml", text).string());
  const auto upper = coupling::read_rigid_study(dir.write("b.yaml", replaced(text, "units: in-lbf-s", "units: IN-LBF-S")).string());
  EXPECT_EQ(upper.units.name(), "in-lbf-s");
  EXPECT_EQ(upper.machine_2d().cab.mass, lower.machine_2d().cab.mass);
  EXPECT_NEAR(upper.machine_2d().cab.mass, 650 * 4.4482216152605 / 9.80665, 1e-12 * 300);
}

// Two load points of the shipped frame, in in-lbf-s, and the same loads written in SI.
const std::string kLoads = R"(# framedyn load history, version 1
# units: in-lbf-s
# point P25_FRONT_AXLE_PIN 0 0 0
# point P28_CAB_MOUNT_FL 20 -15 0
time [s],P25_FRONT_AXLE_PIN.FX [lbf],P25_FRONT_AXLE_PIN.FY [lbf],P25_FRONT_AXLE_PIN.FZ [lbf],P25_FRONT_AXLE_PIN.MX [lbf*in],P25_FRONT_AXLE_PIN.MY [lbf*in],P25_FRONT_AXLE_PIN.MZ [lbf*in],P28_CAB_MOUNT_FL.FX [lbf],P28_CAB_MOUNT_FL.FY [lbf],P28_CAB_MOUNT_FL.FZ [lbf],P28_CAB_MOUNT_FL.MX [lbf*in],P28_CAB_MOUNT_FL.MY [lbf*in],P28_CAB_MOUNT_FL.MZ [lbf*in]
0,0,0,0,0,0,0,0,0,0,0,0,0
0.001,10,0,-300,0,0,0,0,0,50,0,0,0
0.002,20,0,-310,0,0,0,0,0,40,0,0,0
)";

std::string frame_study(const std::string& loads, bool convert) {
  return "framedyn_study: 1\nname: strict units\nunits: in-lbf-s\nmodel: frame_transient\nframe:\n  mesh: " + (kSource / "meshes" / "r100_frame.inp").string() +
         "\n  loads: " + loads + "\n  supports: fixed_rear_end\n  modes: 4\n  method: mode_displacement\n  damping: {modal_ratio: 0.02}\n  stations: 3\n" +
         (convert ? "  convert_units: true\n" : "");
}

TEST(StrictStudy, ALoadHistoryInOtherUnitsIsRefusedUnlessTheStudyConvertsIt) {
  const framedyn::testing::TempDir dir;
  dir.write("inch.csv", kLoads);
  const coupling::LoadHistory inch = coupling::read_load_history(dir / "inch.csv");
  dir.write("si.csv", coupling::format_load_history(inch, core::UnitSystem::si()));
  ASSERT_NE(read_text(dir / "si.csv").find("# units: m-N-s"), std::string::npos);

  const fs::path refused = dir.write("refused.yaml", frame_study("si.csv", false));
  const std::string m = error_of([&] { coupling::run_frame_study(coupling::read_frame_study(refused.string())); });
  EXPECT_NE(m.find("frame.loads: expected a load history in the study's units, in-lbf-s (or frame.convert_units: true to convert it), found "), std::string::npos)
      << m;
  EXPECT_NE(m.find("si.csv in m-N-s"), std::string::npos) << m;

  const auto own = coupling::run_frame_study(coupling::read_frame_study(dir.write("own.yaml", frame_study("inch.csv", false)).string()));
  const auto converted = coupling::run_frame_study(coupling::read_frame_study(dir.write("converted.yaml", frame_study("si.csv", true)).string()));
  ASSERT_EQ(own.rails.size(), converted.rails.size());
  for (std::size_t k = 0; k < own.rails.size(); ++k) {
    const double a = own.rails[k].peak_normal_stress.value, b = converted.rails[k].peak_normal_stress.value;
    EXPECT_NEAR(a, b, 1e-9 * std::abs(a)) << own.rails[k].spec.name;  // the history's 17 digits round-trip
    EXPECT_GT(std::abs(a), 0.0);
  }
}

TEST(StrictStudy, AMeshInOtherUnitsIsRefusedNamingBothSystems) {
  const framedyn::testing::TempDir dir;
  dir.write("inch.csv", kLoads);
  std::string study = replaced(frame_study("inch.csv", false), "units: in-lbf-s", "units: mm-N-s");
  const fs::path file = dir.write("study.yaml", study);
  const std::string m = error_of([&] { coupling::run_frame_study(coupling::read_frame_study(file.string())); });
  EXPECT_NE(m.find("frame.mesh: expected a mesh in the study's units, mm-N-s (or frame.convert_units: true to convert it), found "), std::string::npos) << m;
  EXPECT_NE(m.find("r100_frame.inp in in-lbf-s"), std::string::npos) << m;
}

// The shipped transport study gives no `behind`: its rear tires run the wheelbase behind, the
// contacts' X 72 - 0 = 72 in = 1.8288 m, and see the front's profile 1.8288 m / (78.74 in/s =
// 1.999996 m/s) = 0.914402 s later; the front tires 0. `behind` overrides; a tire ahead of the
// front axle without `behind` is refused (STUDY-141).
TEST(RoadDelay, RearTiresRunTheWheelbaseBehindFromTheTirePositionsAndBehindOverridesIt) {
  const framedyn::testing::TempDir dir;
  std::string text = read_text(kSource / "examples" / "transport_rough_ground.yaml");
  text = replaced(text, "  mesh: ../meshes/r100_frame.inp", "  mesh: " + (kSource / "meshes" / "r100_frame.inp").string());
  const auto delays_of = [&](const std::string& study) { return coupling::road_delays(coupling::read_rigid_study(dir.write("study.yaml", study).string()).machine_3d()); };
  const std::vector<coupling::RoadDelay> derived = delays_of(text);
  ASSERT_EQ(derived.size(), 4u);
  const double wheelbase = 72 * 0.0254, speed = 78.74 * 0.0254;
  for (std::size_t k = 0; k < 4; ++k) {
    const double behind = k < 2 ? 0.0 : wheelbase;
    EXPECT_EQ(derived[k].tire, (std::vector<std::string>{"front left", "front right", "rear left", "rear right"}[k]));
    EXPECT_NEAR(derived[k].behind, behind, 1e-12);
    EXPECT_NEAR(derived[k].delay, behind / speed, 1e-12);
    EXPECT_FALSE(derived[k].given);
  }
  EXPECT_NEAR(derived[2].delay, 0.914402, 1e-6);
  const std::string rear_left = "left:  {contact: [72, -30, -26], vertical_input: {kind: road,";
  const std::vector<coupling::RoadDelay> given = delays_of(replaced(text, rear_left, "left:  {contact: [72, -30, -26], vertical_input: {behind: 60, kind: road,"));
  EXPECT_NEAR(given[2].behind, 60 * 0.0254, 1e-12);
  EXPECT_TRUE(given[2].given);
  EXPECT_NEAR(given[3].behind, wheelbase, 1e-12);
  const std::string ahead = replaced(text, rear_left, "left:  {contact: [-10, -30, -26], vertical_input: {kind: road,");
  const std::string m = error_of([&] { delays_of(ahead); });
  EXPECT_NE(m.find("tires.rear.left.vertical_input: expected a tire on or behind the front axle"), std::string::npos) << m;
}

// 2-D studies derive the delay the same way (F.30 with one tire per axle): the shipped 2-D plowing
// study's tires at X 0 and 72 in given road inputs at 78.74 in/s without `behind`: the rear runs
// 72 in = 1.8288 m behind and sees the front's profile 0.914402 s later (wheelbase / speed), the
// front 0; `behind` overrides; a rear tire ahead of the front one is refused (STUDY-160).
TEST(RoadDelay, TwoDimensionalRearTireRunsTheWheelbaseBehindFromTheTirePositionsAndBehindOverridesIt) {
  const framedyn::testing::TempDir dir;
  const std::string road = "{kind: road, class: D, speed: 78.74}";
  std::string text = read_text(kSource / "examples" / "r100_plow_2d.yaml");
  text = replaced(text, "    contact: [0, -26]\n", "    contact: [0, -26]\n    normal_input: " + road + "\n");
  text = replaced(text, "    contact: [72, -26]\n", "    contact: [72, -26]\n    normal_input: " + road + "\n");
  const auto machine_of = [&](const std::string& study) { return coupling::read_rigid_study(dir.write("study2d.yaml", study).string()).machine_2d(); };
  const auto derived = machine_of(text);
  const double wheelbase = 72 * 0.0254, speed = 78.74 * 0.0254;
  EXPECT_EQ(derived.front_tire.normal_input.behind, 0.0);
  EXPECT_NEAR(derived.rear_tire.normal_input.behind, wheelbase, 1e-12);
  EXPECT_FALSE(derived.rear_tire.normal_input.behind_given);
  EXPECT_NEAR(derived.rear_tire.normal_input.behind / derived.rear_tire.normal_input.speed, wheelbase / speed, 1e-12);
  EXPECT_NEAR(derived.rear_tire.normal_input.behind / derived.rear_tire.normal_input.speed, 0.914402, 1e-6);
  // The rear tire's ground height is the front's one delay later.
  const double delay = wheelbase / speed;
  for (double t : {1.0, 2.5, 4.0})
    EXPECT_NEAR(derived.rear_tire.normal_input.displacement(t + delay), derived.front_tire.normal_input.displacement(t), 1e-12) << t;
  const std::string given_text = replaced(text, "    contact: [72, -26]\n    normal_input: {kind: road,", "    contact: [72, -26]\n    normal_input: {behind: 60, kind: road,");
  const auto given = machine_of(given_text);
  EXPECT_NEAR(given.rear_tire.normal_input.behind, 60 * 0.0254, 1e-12);
  EXPECT_TRUE(given.rear_tire.normal_input.behind_given);
  const std::string ahead = replaced(text, "    contact: [72, -26]\n    normal_input:", "    contact: [-10, -26]\n    normal_input:");
  const std::string m = error_of([&] { machine_of(ahead); });
  EXPECT_NE(m.find("tires.rear.normal_input: expected a rear tire on or behind the front tire"), std::string::npos) << m;
}

}  // namespace
