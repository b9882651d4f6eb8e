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
// tire positions unless the study gives `behind`. And the one reader of 2-D and 3-D studies
// (issue 15): the common blocks read to the same values in both models, a feature of one
// model refused in the other with the reason.
#include <gtest/gtest.h>

#include <cmath>
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

// One reader for both models (issue 15, "one study reader, one runner, one set of writers"): the
// blocks the two models share are read by the same code into the same fields, so the same text
// gives the same values in a 2-D and a 3-D study. The shipped 2-D plow and 3-D straight plow, each
// given the same ground, contacts, soil and analysis blocks.
TEST(OneStudyReader, TheSameCommonBlocksGiveTheSameValuesIn2DAnd3D) {
  const framedyn::testing::TempDir dir;
  const std::string common =
      "contacts: linear\n"
      "analysis:\n"
      "  modes: false\n"
      "  modal_soil: backing\n"
      "  response: {duration: 0.25, output_interval: 0.002, method: rk4, rk4_step: 0.0001, relative_tolerance: 1e-7}\n";
  const auto with_common = [&](const std::string& example) {
    std::string text = read_text(kSource / "examples" / example);
    text = text.substr(0, text.find("\nanalysis:\n") + 1) + common;  // analysis is each file's last block
    text = replaced(text, "  slope_deg: 0", "  slope_deg: 3");
    return text;
  };
  const coupling::RigidStudy s2 = coupling::read_rigid_study(dir.write("plow2d.yaml", with_common("r100_plow_2d.yaml")).string());
  const coupling::RigidStudy s3 = coupling::read_rigid_study(dir.write("plow3d.yaml", with_common("r100_plow_straight.yaml")).string());
  ASSERT_EQ(s2.dimensions(), 2);
  ASSERT_EQ(s3.dimensions(), 3);
  EXPECT_EQ(s2.units.name(), s3.units.name());
  EXPECT_EQ(s2.attachment(), s3.attachment());
  EXPECT_EQ(s2.machine_2d().contacts, rigid::ContactLaw::linear);
  EXPECT_EQ(s3.machine_3d().contacts, rigid::ContactLaw::linear);
  EXPECT_EQ(s2.machine_2d().ground_slope, s3.machine_3d().ground_slope);
  EXPECT_NEAR(s2.machine_2d().ground_slope, 3 * M_PI / 180, 1e-15);
  EXPECT_EQ(s2.machine_2d().forward_speed, s3.machine_3d().forward_speed);
  EXPECT_EQ(s2.modes, s3.modes);
  EXPECT_FALSE(s2.modes);
  EXPECT_EQ(s2.modal_soil, rigid::ModalSoil::backing);
  EXPECT_EQ(s3.modal_soil, rigid::ModalSoil::backing);
  ASSERT_TRUE(s2.response && s3.response);
  EXPECT_EQ(s2.response->duration, s3.response->duration);
  EXPECT_EQ(s2.response->output_interval, s3.response->output_interval);
  EXPECT_EQ(s2.response->method, coupling::ResponseRequest::Method::rk4);
  EXPECT_EQ(s3.response->method, coupling::ResponseRequest::Method::rk4);
  EXPECT_EQ(s2.response->rk4_step, s3.response->rk4_step);
  EXPECT_EQ(s2.response->relative_tolerance, s3.response->relative_tolerance);
  // The soil law: both files give K5 40000 lbf/in, C5 300 lbf*s/in, REK 0, REC 0.25, cut_face.
  const rigid::SoilLaw& a = s2.machine_2d().soil;
  const rigid::SoilLaw& b = s3.machine_3d().soil;
  EXPECT_EQ(a.stiffness, b.stiffness);
  EXPECT_EQ(a.damping, b.damping);
  EXPECT_EQ(a.stiffness_reduction, b.stiffness_reduction);
  EXPECT_EQ(a.damping_reduction, b.damping_reduction);
  EXPECT_EQ(a.cut_face, b.cut_face);
  EXPECT_EQ(a.spring_from_contact, b.spring_from_contact);
  EXPECT_EQ(s2.shaker_frequency(), s3.shaker_frequency());
}

// A ground input table (piecewise linear heights) reads the same under a 2-D and a 3-D tire: the
// same times and values (SI), the same height and slope at any time (it used to be 2-D only).
TEST(OneStudyReader, AGroundTableReadsTheSameUnderA2DAnd3DTire) {
  const framedyn::testing::TempDir dir;
  const std::string table = "{kind: table, times: [0, 0.1, 0.3], values: [0, 0.5, -0.25]}";
  std::string t2 = read_text(kSource / "examples" / "r100_plow_2d.yaml");
  t2 = replaced(t2, "    contact: [0, -26]\n", "    contact: [0, -26]\n    normal_input: " + table + "\n");
  std::string t3 = read_text(kSource / "examples" / "r100_plow_straight.yaml");
  const std::string left = t3.substr(t3.find("    left:"), t3.find("\n", t3.find("    left:")) - t3.find("    left:"));
  t3 = replaced(t3, left, left.substr(0, left.rfind('}')) + ", vertical_input: " + table + "}");
  const rigid::GroundInput g2 = coupling::read_rigid_study(dir.write("t2.yaml", t2).string()).machine_2d().front_tire.normal_input;
  const rigid::GroundInput g3 = coupling::read_rigid_study(dir.write("t3.yaml", t3).string()).machine_3d().front_tires.left.vertical_input;
  ASSERT_EQ(g2.kind, rigid::GroundInput::Kind::table);
  ASSERT_EQ(g3.kind, rigid::GroundInput::Kind::table);
  EXPECT_EQ(g2.times, g3.times);
  EXPECT_EQ(g2.values, g3.values);
  // 0.05 s: halfway up the first segment, 0.25 in = 0.00635 m, rising 0.5 in / 0.1 s = 0.127 m/s.
  for (double t : {0.05, 0.2, 0.29}) {
    EXPECT_EQ(g2.displacement(t), g3.displacement(t)) << t;
    EXPECT_EQ(g2.velocity(t), g3.velocity(t)) << t;
  }
  EXPECT_NEAR(g3.displacement(0.05), 0.25 * 0.0254, 1e-15);
  EXPECT_NEAR(g3.velocity(0.05), 0.5 * 0.0254 / 0.1, 1e-12);
}

// A feature of one model in a study of the other is refused with the reason (issue 15: "every
// feature works in 2-D and 3-D, or says why not"): frame_output in 3-D (STUDY-139), frame_response
// in 2-D (STUDY-142), calibration.pair_with: symmetric_modes in 2-D (STUDY-137). The soil line,
// once 2-D only (STUDY-140, retired), reads in both.
TEST(OneStudyReader, AFeatureOfOneModelInTheOtherIsRefusedWithTheReason) {
  const framedyn::testing::TempDir dir;
  const std::string plow2d = read_text(kSource / "examples" / "r100_plow_2d.yaml");
  const std::string plow3d = read_text(kSource / "examples" / "r100_plow_straight.yaml");
  const auto error_in = [&](const std::string& text) {
    const fs::path file = dir.write("study.yaml", text);
    return error_of([&] { coupling::read_rigid_study(file.string()); });
  };
  std::string m = error_in(plow3d + "frame_output: {points: [36]}\n");
  EXPECT_NE(m.find("frame_output: expected model: rigid_2d for frame_output (the resultants of Eq. 2.47 along the 2-D model's one frame tube"), std::string::npos) << m;
  EXPECT_NE(m.find("found a frame_output block in a rigid_3d study"), std::string::npos) << m;
  m = error_in(plow2d + "frame_response: {mesh: r100_frame.inp}\n");
  EXPECT_NE(m.find("frame_response: expected model: rigid_3d for the frame pipeline"), std::string::npos) << m;
  m = error_in(plow2d + "calibration: {pair_with: symmetric_modes, parameters: [cab.inertia], targets: [{frequency_hz: 6}]}\n");
  EXPECT_NE(m.find("calibration.pair_with: expected all_modes (symmetric_modes is for 3-D studies)"), std::string::npos) << m;
  // The soil line reads in both models, and so does the cut face with springs while backing off.
  EXPECT_EQ(error_in(replaced(plow2d, "spring_reference: cut_face", "spring_reference: soil_line")), "");
  EXPECT_EQ(error_in(replaced(plow3d, "  spring_reference: cut_face", "  spring_reference: soil_line")), "");
  EXPECT_EQ(error_in(replaced(plow3d, "  stiffness_reduction: 0\n", "  stiffness_reduction: 0.2\n")), "");
}

}  // namespace
