// `framedyn sweep`: the program writes sweep.csv, summary.json and the
// figures, with the numbers of `framedyn run`; an unknown key is refused with
// the key-path walker's message and leaves no folder. The sweep itself
// (batch::run_one_parameter_sweep, the batch engine's) is tested in
// tests/batch/test_batch.cpp (OneParameterSweep.*).
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "report/plot.h"
#include "coupling/rigid_study.h"
#include "tests/support/temp_dir.h"

namespace framedyn {
namespace {

namespace fs = std::filesystem;

const std::string kPlowStudy = FRAMEDYN_SOURCE_DIR "/examples/r100_plow_2d.yaml";

// ---- the program ----

std::string read_file(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

int framedyn(const testing::TempDir& dir, const std::string& args) {
  const std::string cmd = "cd '" + dir.path().string() + "' && '" + std::string(FRAMEDYN_BINARY) + "' " + args + " >out.txt 2>err.txt";
  const int rc = std::system(cmd.c_str());
  return (rc != -1 && WIFEXITED(rc)) ? WEXITSTATUS(rc) : -1;
}

bool is_png(const fs::path& p) { return read_file(p).substr(0, 8) == std::string("\x89PNG\r\n\x1a\n", 8); }

TEST(SweepCommand, WritesTheTableTheSummaryAndTheFigures) {
  if (!report::gnuplot_available()) GTEST_SKIP() << "gnuplot is not installed (install-deps.sh installs gnuplot-nox)";
  testing::TempDir dir("framedyn_test_sweep");
  ASSERT_EQ(framedyn(dir, "sweep '" + kPlowStudy + "' --parameter soil.damping --values 200,300 --out c5 --jobs 2"), 0)
      << read_file(dir / "err.txt");
  const std::string csv = read_file(dir / "c5" / "sweep.csv");
  std::istringstream lines(csv);
  std::string header, row1, row2, extra;
  std::getline(lines, header);
  std::getline(lines, row1);
  std::getline(lines, row2);
  EXPECT_FALSE(std::getline(lines, extra) && !extra.empty());
  EXPECT_EQ(header.rfind("soil.damping [lbf*s/in],plow_vertical_pp [in],peak_cutting_force [lbf],peak_backing_force [lbf],", 0), 0u) << header;
  EXPECT_NE(header.find("plow_vertical_pp_change [%]"), std::string::npos);
  EXPECT_NE(header.find("frequency_1 [Hz],dominant_1"), std::string::npos);
  EXPECT_EQ(row1.rfind("200,", 0), 0u);
  EXPECT_EQ(row2.rfind("300,", 0), 0u);

  const nlohmann::json j = nlohmann::json::parse(read_file(dir / "c5" / "summary.json"));
  EXPECT_EQ(j["framedyn"]["command"], "sweep");
  EXPECT_EQ(j["sweep"]["parameter"], "soil.damping");
  EXPECT_EQ(j["sweep"]["values"]["unit"], "lbf*s/in");
  EXPECT_EQ(j["sweep"]["reference"]["parameter"]["value"], 300.0);
  EXPECT_EQ(j["sweep"]["reference"]["in_values"], true);
  ASSERT_EQ(j["sweep"]["runs"].size(), 2u);
  EXPECT_EQ(j["sweep"]["runs"][1]["relative_change"]["peak_cutting_force"], 0.0);
  EXPECT_EQ(j["sweep"]["runs"][0]["plow_vertical_pp"]["unit"], "in");

  // The same numbers as `framedyn run` at C5 = 300 (the study file's value).
  const coupling::RigidResults r = coupling::run_rigid_study(coupling::read_rigid_study(kPlowStudy));
  EXPECT_NEAR(j["sweep"]["runs"][1]["plow_vertical_pp"]["value"].get<double>(), *r.plow_vertical_peak_to_peak / 0.0254, 1e-12);

  for (const char* png : {"amplitude.png", "peak_forces.png", "relative_change.png", "frequencies.png"}) {
    EXPECT_TRUE(is_png(dir / "c5" / png)) << png;
    EXPECT_NE(std::find(j["sweep"]["figures"].begin(), j["sweep"]["figures"].end(), png), j["sweep"]["figures"].end()) << png;
  }
}

TEST(SweepCommand, NoFiguresNeedsNoGnuplotAndWritesNoImages) {
  testing::TempDir dir("framedyn_test_sweep");
  ASSERT_EQ(framedyn(dir, "sweep '" + kPlowStudy + "' -p soil.stiffness --values 40000 --out k5 --no-figures -q"), 0) << read_file(dir / "err.txt");
  EXPECT_TRUE(fs::exists(dir / "k5" / "sweep.csv"));
  EXPECT_FALSE(fs::exists(dir / "k5" / "amplitude.png"));
}

TEST(SweepCommand, UnknownParameterFailsWithTheListAndLeavesNoFolder) {
  testing::TempDir dir("framedyn_test_sweep");
  EXPECT_EQ(framedyn(dir, "sweep '" + kPlowStudy + "' -p soil.viscosity --values 1 --out bad --no-figures"), 1);
  const std::string err = read_file(dir / "err.txt");
  // The key-path walker's message (coupling/study_key_path.h): the study's line, the key, what soil has.
  EXPECT_NE(err.find("soil.viscosity: expected a key of the study"), std::string::npos) << err;
  EXPECT_NE(err.find("stiffness, damping"), std::string::npos) << err;
  EXPECT_FALSE(fs::exists(dir / "bad"));
}

}  // namespace
}  // namespace framedyn
