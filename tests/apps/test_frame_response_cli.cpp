// `framedyn frame-response`: a study file and a load history in, a complete
// results folder with summary.json's frame keys out; bad input exits 1.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "tests/support/temp_dir.h"

namespace {

const std::string kBinary = FRAMEDYN_BINARY;

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Vertical loads at the axle pins and the reel: 0.1 s at 1 kHz with a 31 Hz ripple.
std::string loads() {
  std::string t = "# framedyn load history, version 1\n# units: in-lbf-s\n# point P25_FRONT_AXLE_PIN 0 0 0\n# point P26_REAR_AXLE_PIN 72 0 0\n";
  t += "time [s]";
  for (const char* p : {"P25_FRONT_AXLE_PIN", "P26_REAR_AXLE_PIN"})
    for (const char* c : {"FX [lbf]", "FY [lbf]", "FZ [lbf]", "MX [lbf*in]", "MY [lbf*in]", "MZ [lbf*in]"}) t += std::string(",") + p + "." + c;
  t += "\n";
  for (int k = 0; k <= 100; ++k) {
    const double s = k * 0.001, fz = 1000.0 * (1.0 + 0.3 * std::sin(2 * 3.141592653589793 * 31 * s));
    t += std::to_string(s) + ",0,0," + std::to_string(fz) + ",0,0,0,0,0," + std::to_string(-fz) + ",0,0,0\n";
  }
  return t;
}

TEST(FrameResponseCommand, WritesSummaryWithFrameKeysAndParaViewSeries) {
  framedyn::testing::TempDir dir;
  dir.write("loads.csv", loads());
  const auto study = dir.write("s.yaml", "framedyn_study: 1\nname: cli\nunits: in-lbf-s\nmodel: frame_transient\nframe:\n  mesh: " +
                                             std::string(FRAMEDYN_SOURCE_DIR) + "/meshes/r100_frame.inp\n  loads: loads.csv\n  supports: fixed_rear_end\n  modes: 10\n  pvd: true\n"
                                             "  outputs:\n    left_rail: {element_set: LEFT_RAIL}\n    right_rail: {element_set: RIGHT_RAIL}\n");
  const std::string cmd = kBinary + " frame-response " + study.string() + " -o " + (dir / "out").string() + " > " + (dir / "log").string() + " 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << slurp(dir / "log");
  const std::string j = slurp(dir / "out" / "summary.json");
  for (const char* key : {"\"frame\"", "\"frequency\"", "\"Hz\"", "\"peak_bending_moment\"", "\"left_rail\"", "\"right_rail\"", "\"peak_normal_stress\"", "\"psi\""})
    EXPECT_NE(j.find(key), std::string::npos) << key;
  EXPECT_TRUE(std::filesystem::exists(dir / "out" / "frame_response.pvd"));
  EXPECT_TRUE(std::filesystem::exists(dir / "out" / "frame_response_00100.vtu"));
}

TEST(FrameResponseCommand, BadLoadFileExitsOneNamingFileAndLine) {
  framedyn::testing::TempDir dir;
  std::string bad = loads();
  bad.replace(bad.find("[lbf]"), 5, "[N]");
  dir.write("loads.csv", bad);
  const auto study = dir.write("s.yaml", "framedyn_study: 1\nunits: in-lbf-s\nmodel: frame_transient\nframe:\n  mesh: " +
                                             std::string(FRAMEDYN_SOURCE_DIR) + "/meshes/r100_frame.inp\n  loads: loads.csv\n  supports: fixed_rear_end\n");
  const std::string cmd = kBinary + " frame-response " + study.string() + " -o " + (dir / "out").string() + " > " + (dir / "log").string() + " 2>&1";
  const int rc = std::system(cmd.c_str());
  EXPECT_EQ(WEXITSTATUS(rc), 1);
  EXPECT_NE(slurp(dir / "log").find("loads.csv:5: column 2"), std::string::npos) << slurp(dir / "log");
  EXPECT_FALSE(std::filesystem::exists(dir / "out"));
}

// The shipped general example (a portal frame, not the trencher frame):
// nodal histories with units per column, section forces at the column bases,
// and the summary's peak equal to the largest value of the CSV it came from.
TEST(FrameResponseCommand, PortalFrameExampleWritesNodalAndSectionHistoriesWithUnits) {
  framedyn::testing::TempDir dir;
  const std::string cmd = kBinary + " frame-response " + std::string(FRAMEDYN_SOURCE_DIR) + "/examples/portal_frame_sway.yaml -o " +
                          (dir / "out").string() + " > " + (dir / "log").string() + " 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << slurp(dir / "log");
  std::istringstream nodes(slurp(dir / "out" / "frame_nodes_corners.csv"));
  std::string header, line;
  std::getline(nodes, header);
  EXPECT_EQ(header, "time [s],node,UX [m],UY [m],UZ [m],URX [rad],URY [rad],URZ [rad],VX [m/s],VY [m/s],VZ [m/s],VRX [rad/s],VRY [rad/s],VRZ [rad/s],"
                    "AX [m/s^2],AY [m/s^2],AZ [m/s^2],ARX [rad/s^2],ARY [rad/s^2],ARZ [rad/s^2]");
  double largest = 0.0;
  int rows = 0;
  while (std::getline(nodes, line)) {
    std::vector<double> v;
    std::istringstream cells(line);
    for (std::string c; std::getline(cells, c, ',');) v.push_back(std::stod(c));
    ASSERT_EQ(v.size(), 20u) << line;
    for (int d = 2; d < 5; ++d) largest = std::max(largest, std::abs(v[static_cast<std::size_t>(d)]));
    ++rows;
  }
  EXPECT_EQ(rows, 2 * 501);  // two corner nodes, 1 s every 2 ms
  const nlohmann::json j = nlohmann::json::parse(slurp(dir / "out" / "summary.json"))["frame"];
  const nlohmann::json& peak = j["outputs"]["corners"]["peak_displacement"];
  EXPECT_EQ(peak["unit"], "m");
  EXPECT_EQ(peak["dof"], "ux");  // the load is along X: the in-plane sway
  EXPECT_NEAR(std::abs(peak["value"].get<double>()), largest, 1e-9 * largest);
  EXPECT_EQ(j["supports"], "clamped");
  EXPECT_EQ(j["outputs"]["column_bases"]["kind"], "element_set");
  const std::string sections = slurp(dir / "out" / "frame_sections_column_bases.csv");
  EXPECT_EQ(sections.substr(0, sections.find('\n')),
            "time [s],element,station,x [m],N [N],Vy [N],Vz [N],T [N*m],My [N*m],Mz [N*m],max_abs_normal_stress [Pa]");
  EXPECT_FALSE(std::filesystem::exists(dir / "out" / "frame_sections_beam.csv"));  // history: false
}

TEST(FrameResponseCommand, MissingOutputSetExitsOneNamingStudyLineMeshAndSet) {
  framedyn::testing::TempDir dir;
  std::string study = slurp(std::string(FRAMEDYN_SOURCE_DIR) + "/examples/portal_frame_sway.yaml");
  study.replace(study.find("{node_set: MIDSPAN}"), 19, "{node_set: MID_SPAN}");
  study.replace(study.find("../meshes/portal_frame.inp"), 26, std::string(FRAMEDYN_SOURCE_DIR) + "/meshes/portal_frame.inp");
  study.replace(study.find("portal_frame_sway_loads.csv"), 27, std::string(FRAMEDYN_SOURCE_DIR) + "/examples/portal_frame_sway_loads.csv");
  const auto file = dir.write("s.yaml", study);
  const std::string cmd = kBinary + " frame-response " + file.string() + " -o " + (dir / "out").string() + " > " + (dir / "log").string() + " 2>&1";
  EXPECT_EQ(WEXITSTATUS(std::system(cmd.c_str())), 1);
  const std::string log = slurp(dir / "log");
  EXPECT_NE(log.find(file.string() + ":31: frame.outputs.midspan.node_set: expected a node set of the mesh " + std::string(FRAMEDYN_SOURCE_DIR) +
                     "/meshes/portal_frame.inp (its node sets: ALL_NODES, CORNERS, FEET, MIDSPAN, TOP_LEFT), found 'MID_SPAN'"),
            std::string::npos)
      << log;
  EXPECT_FALSE(std::filesystem::exists(dir / "out"));
}

// frame.stress_histories: hot_spots writes frame_stress_histories.csv for the
// hot spots' points (theory/coupling.md section 10): one row per location and
// output time, units in the header; the summary's top hot spot is the largest
// von Mises stress of that CSV over steady operation (the last half of the
// record: the study gives no steady_from); a yield strength below it warns.
TEST(FrameResponseCommand, StressHistoriesOnRequestHoldTheTopHotSpotsPeak) {
  framedyn::testing::TempDir dir;
  std::string study = slurp(std::string(FRAMEDYN_SOURCE_DIR) + "/examples/portal_frame_sway.yaml");
  study.replace(study.find("mesh: ../meshes/portal_frame.inp") + 6, 26, std::string(FRAMEDYN_SOURCE_DIR) + "/meshes/portal_frame.inp");
  study.replace(study.find("loads: portal_frame_sway_loads.csv") + 7, 27, std::string(FRAMEDYN_SOURCE_DIR) + "/examples/portal_frame_sway_loads.csv");
  study.replace(study.find("  stations: 3\n"), 14, "  stations: 3\n  stress_histories: hot_spots\n  yield_strength: 1.0e5\n");
  const auto file = dir.write("s.yaml", study);
  const std::string cmd = kBinary + " frame-response " + file.string() + " -o " + (dir / "out").string() + " > " + (dir / "log").string() + " 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << slurp(dir / "log");
  const nlohmann::json summary = nlohmann::json::parse(slurp(dir / "out" / "summary.json"));
  const nlohmann::json& j = summary["frame"];
  EXPECT_EQ(j["hot_spot_window"]["source"], "last half of the record");
  EXPECT_NEAR(j["hot_spot_window"]["steady_from"]["value"].get<double>(), 0.5, 1e-12);
  ASSERT_EQ(j["hot_spots"].size(), 10u);
  std::vector<std::string> locations;
  for (const char* list : {"hot_spots", "hot_spots_by_normal_stress_range"})
    for (const auto& h : j[list]) {
      const std::string key = h["set"].get<std::string>() + "," + std::to_string(h["element"].get<int>()) + "," + std::to_string(h["station"].get<int>()) +
                              "," + h["point"].get<std::string>();
      if (std::find(locations.begin(), locations.end(), key) == locations.end()) locations.push_back(key);
    }
  std::istringstream csv(slurp(dir / "out" / "frame_stress_histories.csv"));
  std::string header, line;
  std::getline(csv, header);
  EXPECT_EQ(header, "time [s],set,element,station,X [m],Y [m],Z [m],point,normal_stress [Pa],shear_stress [Pa],von_mises [Pa]");
  const nlohmann::json& top = j["hot_spots"][0];
  const std::string top_key = top["set"].get<std::string>() + "," + std::to_string(top["element"].get<int>()) + "," +
                              std::to_string(top["station"].get<int>());
  int rows = 0;
  double steady_max = 0.0;
  while (std::getline(csv, line)) {
    ++rows;
    std::vector<std::string> c;
    std::istringstream cells(line);
    for (std::string x; std::getline(cells, x, ',');) c.push_back(x);
    ASSERT_EQ(c.size(), 11u) << line;
    if (c[1] + "," + c[2] + "," + c[3] == top_key && c[7] == top["point"].get<std::string>() && std::stod(c[0]) >= 0.5 - 1e-9)
      steady_max = std::max(steady_max, std::stod(c[10]));
  }
  EXPECT_EQ(rows, static_cast<int>(locations.size()) * 501);  // 1 s every 2 ms
  const double peak = top["von_mises"]["total"].get<double>();
  EXPECT_NEAR(steady_max, peak, 1e-6 * peak);
  EXPECT_EQ(top["von_mises"]["static"].get<double>(), 0.0);
  bool warned = false;
  for (const auto& w : summary["warnings"]) warned = warned || w["code"] == "stress_above_yield";
  EXPECT_EQ(warned, j["peak_von_mises"]["value"].get<double>() > 1.0e5);
}

// frame.inp_dialect (the study's frame block): a mesh with a CIRC section read
// without it is warned in summary.json's warnings and on the console, the
// message naming the study's key; with inp_dialect: calculix the value is the
// diameter. The cantilever's bending frequencies of Euler-Bernoulli B33
// elements (no rotary inertia), omega = (beta L)^2 sqrt(E I / (rho A)) / L^2
// with I / A = r^2 / 4, are proportional to r: half with the calculix reading.
TEST(FrameResponseCommand, InpDialectReadsCircAsTheStudySaysAndWithoutItTheSummaryWarns) {
  framedyn::testing::TempDir dir;
  std::string mesh = "** units: m-N-s\n*NODE, NSET=ALL\n";
  for (int i = 0; i <= 4; ++i) mesh += std::to_string(i + 1) + ", " + std::to_string(0.5 * i) + ", 0, 0\n";
  mesh += "*NSET, NSET=TIP\n5\n*ELEMENT, TYPE=B33, ELSET=BEAM\n1, 1, 2\n2, 2, 3\n3, 3, 4\n4, 4, 5\n"
          "*BEAM SECTION, ELSET=BEAM, MATERIAL=STEEL, SECTION=CIRC\n0.02\n0, 1, 0\n"
          "*MATERIAL, NAME=STEEL\n*ELASTIC\n2.1e11, 0.3\n*DENSITY\n7850\n*BOUNDARY\n1, ENCASTRE\n";
  dir.write("circ.inp", mesh);
  std::string history = "# framedyn load history, version 1\n# units: m-N-s\n# point TIP 2 0 0\n"
                        "time [s],TIP.FX [N],TIP.FY [N],TIP.FZ [N],TIP.MX [N*m],TIP.MY [N*m],TIP.MZ [N*m]\n";
  for (int k = 0; k <= 10; ++k) history += std::to_string(0.001 * k) + ",0,0,100,0,0,0\n";
  dir.write("loads.csv", history);
  const std::string study = "framedyn_study: 1\nname: circ\nunits: m-N-s\nmodel: frame_transient\nframe:\n  mesh: circ.inp\n  loads: loads.csv\n"
                            "  modes: 2\n  paraview: none\n";
  dir.write("plain.yaml", study);
  dir.write("calculix.yaml", study + "  inp_dialect: calculix\n");
  const auto run = [&](const std::string& name) {
    const std::string cmd = kBinary + " frame-response " + (dir / (name + ".yaml")).string() + " -o " + (dir / name).string() + " > " +
                            (dir / (name + ".log")).string() + " 2>&1";
    EXPECT_EQ(std::system(cmd.c_str()), 0) << slurp(dir / (name + ".log"));
    return nlohmann::json::parse(slurp(dir / name / "summary.json"));
  };
  const nlohmann::json plain = run("plain"), calculix = run("calculix");
  ASSERT_EQ(plain["warnings"].size(), 1u) << plain["warnings"].dump();
  EXPECT_EQ(plain["warnings"][0]["code"], "circ_radius_or_diameter");
  const std::string message = plain["warnings"][0]["message"];
  EXPECT_NE(message.find("ELSET BEAM"), std::string::npos) << message;
  EXPECT_NE(message.find("give frame.inp_dialect abaqus or calculix"), std::string::npos) << message;
  EXPECT_NE(slurp(dir / "plain.log").find("framedyn: warning [circ_radius_or_diameter]"), std::string::npos) << slurp(dir / "plain.log");
  EXPECT_EQ(calculix["warnings"], nlohmann::json::array());
  const double f_radius = plain["frame"]["modes"][0]["frequency"]["value"], f_diameter = calculix["frame"]["modes"][0]["frequency"]["value"];
  EXPECT_NEAR(f_diameter / f_radius, 0.5, 1e-9);
  // Euler-Bernoulli's first root, beta L = 1.8751 (7.2360 Hz for r = 0.02 m): the 4-element cubic mesh with
  // consistent mass is stiff by the discretisation error, 3.3e-5 measured (O(h^4), bounded by 1e-4).
  const double r = 0.02, exact = 1.8751040687 * 1.8751040687 / (2.0 * 3.141592653589793 * 4.0) * std::sqrt(2.1e11 * r * r / 4.0 / 7850.0);
  EXPECT_GT(f_radius, exact);
  EXPECT_NEAR(f_radius / exact, 1.0, 1e-4);
}

// The pipeline (a 3-D study's frame_response block) reads the same key: the
// shipped offset-plowing study on a copy of its frame whose light cross
// members are given as a CIRC section has the warning in its summary.json,
// naming frame_response.inp_dialect; with the key, none.
TEST(FrameResponseCommand, ThePipelinesFrameResponseBlockTakesTheDialectAndWarnsWithoutIt) {
  framedyn::testing::TempDir dir;
  std::string frame = slurp(std::string(FRAMEDYN_SOURCE_DIR) + "/meshes/r100_frame.inp");
  const std::string box = "ELSET=LIGHT_CROSS_MEMBERS, MATERIAL=STEEL, SECTION=BOX\n4.0, 3.0, 0.1875, 0.1875, 0.1875, 0.1875\n";
  ASSERT_NE(frame.find(box), std::string::npos);
  frame.replace(frame.find(box), box.size(), "ELSET=LIGHT_CROSS_MEMBERS, MATERIAL=STEEL, SECTION=CIRC\n1.5\n");
  dir.write("frame.inp", frame);
  std::string study = slurp(std::string(FRAMEDYN_SOURCE_DIR) + "/examples/offset_plowing.yaml");
  for (const auto& [from, to] : {std::pair<std::string, std::string>{"../meshes/r100_frame.inp", "frame.inp"},
                                 {"duration: 10.0", "duration: 0.01"}, {"paraview: xdmf", "paraview: none"}}) {
    ASSERT_NE(study.find(from), std::string::npos) << from;
    study.replace(study.find(from), from.size(), to);
  }
  dir.write("plain.yaml", study);
  const std::string block = "frame_response:\n";
  study.replace(study.find(block), block.size(), block + "  inp_dialect: abaqus\n");
  dir.write("abaqus.yaml", study);
  for (const std::string name : {"plain", "abaqus"}) {
    const std::string cmd = kBinary + " run " + (dir / (name + ".yaml")).string() + " -o " + (dir / name).string() + " > " +
                            (dir / (name + ".log")).string() + " 2>&1";
    ASSERT_EQ(std::system(cmd.c_str()), 0) << slurp(dir / (name + ".log"));
    int circ = 0;
    std::string message;
    const nlohmann::json warnings = nlohmann::json::parse(slurp(dir / name / "summary.json"))["warnings"];
    for (const auto& w : warnings)
      if (w["code"] == "circ_radius_or_diameter") ++circ, message = w["message"];
    EXPECT_EQ(circ, name == "plain" ? 1 : 0) << name << ": " << warnings.dump();
    if (name == "plain") {
      EXPECT_NE(message.find("give frame_response.inp_dialect abaqus or calculix"), std::string::npos) << message;
      EXPECT_NE(slurp(dir / "plain.log").find("framedyn: warning [circ_radius_or_diameter]"), std::string::npos) << slurp(dir / "plain.log");
    }
  }
}

}  // namespace
