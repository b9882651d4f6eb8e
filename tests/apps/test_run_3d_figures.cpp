// `framedyn run STUDY.yaml --figures` for rigid_3d studies (apps/run_3d.cpp):
// every run draws its own Chapter V load-point figures — the front axle pin's
// forces (thesis Figure 22) and the rear axle pin's and leveling cylinder's
// forces (Figure 23 chain, Figure 24 plow) — as PNGs, each with a CSV of the
// plotted series. The CSVs must hold exactly the frame loads of
// frame_loads.csv; the centred chain is symmetric, so its side force at the
// front pin and its leveling-cylinder force vanish, and offsetting the chain
// makes them appear. Skipped only when gnuplot is absent.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "report/plot.h"
#include "tests/support/temp_dir.h"

namespace {

namespace fs = std::filesystem;

std::string read_file(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

int framedyn(const framedyn::testing::TempDir& dir, const std::string& args) {
  const std::string cmd = "cd '" + dir.path().string() + "' && '" + std::string(FRAMEDYN_BINARY) + "' " + args + " >out.txt 2>err.txt";
  const int rc = std::system(cmd.c_str());
  return (rc != -1 && WIFEXITED(rc)) ? WEXITSTATUS(rc) : -1;
}

// Columns of a CSV file (lines starting with '#' skipped), by header.
std::map<std::string, std::vector<double>> read_columns(const fs::path& p) {
  std::ifstream in(p);
  std::string line;
  std::vector<std::string> header;
  std::map<std::string, std::vector<double>> cols;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::stringstream ss(line);
    std::string cell;
    if (header.empty()) {
      while (std::getline(ss, cell, ',')) header.push_back(cell);
      continue;
    }
    for (std::size_t i = 0; std::getline(ss, cell, ','); ++i) cols[header.at(i)].push_back(std::stod(cell));
  }
  return cols;
}

double peak(const std::vector<double>& v) {
  double m = 0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

const std::string kPng("\x89PNG\r\n\x1a\n", 8);

// Runs one shipped 3-D study with --figures; checks both figures and that
// each figure's CSV holds frame_loads.csv's columns (same text, same times);
// the plotted columns by header into `plotted`.
void run_and_check(const std::string& example, std::map<std::string, std::vector<double>>& plotted) {
  framedyn::testing::TempDir dir("framedyn_test_run_3d_figures");
  EXPECT_EQ(framedyn(dir, std::string("run '") + FRAMEDYN_SOURCE_DIR + "/examples/" + example + "' --figures --out run"), 0)
      << read_file(dir / "err.txt");
  const std::string out = read_file(dir / "out.txt");
  EXPECT_NE(out.find("figures: front_pin_forces.png, rear_pin_and_leveling_cylinder_forces.png"), std::string::npos) << out;
  EXPECT_EQ(out.find("not yet drawn"), std::string::npos) << out;
  for (const char* png : {"front_pin_forces.png", "rear_pin_and_leveling_cylinder_forces.png"})
    EXPECT_EQ(read_file(dir / "run" / png).substr(0, 8), kPng) << example << ": " << png;
  const auto loads = read_columns(dir / "run" / "frame_loads.csv");
  plotted.clear();
  for (const char* csv : {"front_pin_forces.csv", "rear_pin_and_leveling_cylinder_forces.csv"})
    for (const auto& [name, values] : read_columns(dir / "run" / csv)) plotted[name] = values;
  const std::vector<std::string> expected = {"time [s]",
                                             "P25_FRONT_AXLE_PIN.FX [lbf]",
                                             "P25_FRONT_AXLE_PIN.FY [lbf]",
                                             "P25_FRONT_AXLE_PIN.FZ [lbf]",
                                             "P26_REAR_AXLE_PIN.FX [lbf]",
                                             "P26_REAR_AXLE_PIN.FY [lbf]",
                                             "P26_REAR_AXLE_PIN.FZ [lbf]",
                                             "P27_LEVELING_CYLINDER.FZ [lbf]"};
  EXPECT_EQ(plotted.size(), expected.size());
  for (const std::string& name : expected) {
    ASSERT_TRUE(plotted.count(name)) << example << ": no plotted column " << name;
    ASSERT_TRUE(loads.count(name)) << example << ": frame_loads.csv has no column " << name;
    const std::vector<double>& a = plotted.at(name);
    const std::vector<double>& b = loads.at(name);
    ASSERT_EQ(a.size(), b.size()) << name;
    ASSERT_GT(a.size(), 100u) << name;
    for (std::size_t i = 0; i < a.size(); ++i) ASSERT_EQ(a[i], b[i]) << example << ": " << name << " row " << i;  // the same numbers, written alike
  }
}

TEST(Run3DFigures, ChainCentredAndOffsetDrawFigures22And23FromTheFrameLoads) {
  if (!framedyn::report::gnuplot_available()) GTEST_SKIP() << "gnuplot is not installed (install-deps.sh installs gnuplot-nox)";
  std::map<std::string, std::vector<double>> centred, offset;
  ASSERT_NO_FATAL_FAILURE(run_and_check("r100_chain_center.yaml", centred));
  ASSERT_NO_FATAL_FAILURE(run_and_check("r100_chain_offset.yaml", offset));
  // Symmetric machine, chain on the centre line: no side force at the pin, the leveling cylinder idle.
  EXPECT_EQ(peak(centred.at("P25_FRONT_AXLE_PIN.FY [lbf]")), 0.0);
  EXPECT_EQ(peak(centred.at("P27_LEVELING_CYLINDER.FZ [lbf]")), 0.0);
  EXPECT_GT(peak(centred.at("P25_FRONT_AXLE_PIN.FX [lbf]")), 0.0);
  // Offset 35 in right: a side force and a cylinder force appear.
  EXPECT_GT(peak(offset.at("P25_FRONT_AXLE_PIN.FY [lbf]")), 0.0);
  EXPECT_GT(peak(offset.at("P27_LEVELING_CYLINDER.FZ [lbf]")), 0.0);
}

TEST(Run3DFigures, StraightAndOffsetPlowingDrawFigure24) {
  if (!framedyn::report::gnuplot_available()) GTEST_SKIP() << "gnuplot is not installed (install-deps.sh installs gnuplot-nox)";
  std::map<std::string, std::vector<double>> straight, offset;
  ASSERT_NO_FATAL_FAILURE(run_and_check("r100_plow_straight.yaml", straight));
  ASSERT_NO_FATAL_FAILURE(run_and_check("r100_plow_offset.yaml", offset));
  EXPECT_EQ(peak(straight.at("P27_LEVELING_CYLINDER.FZ [lbf]")), 0.0);
  EXPECT_GT(peak(offset.at("P27_LEVELING_CYLINDER.FZ [lbf]")), 0.0);
}

TEST(Run3DFigures, WithoutTheFlagNoImages) {
  framedyn::testing::TempDir dir("framedyn_test_run_3d_figures");
  ASSERT_EQ(framedyn(dir, std::string("run '") + FRAMEDYN_SOURCE_DIR + "/examples/r100_chain_offset.yaml' --out run -q"), 0)
      << read_file(dir / "err.txt");
  EXPECT_TRUE(fs::exists(dir / "run" / "frame_loads.csv"));
  EXPECT_FALSE(fs::exists(dir / "run" / "front_pin_forces.png"));
  EXPECT_FALSE(fs::exists(dir / "run" / "front_pin_forces.csv"));
}

}  // namespace
