// `framedyn run --figures`: the response's time histories as PNG images next
// to response.csv (report/response_figures.cpp), the plow's forces (thesis
// Figures 11 and 12) and blade motion; a machine without a chain draws no
// chain force. Skipped only when gnuplot is absent (install-deps.sh installs it).
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

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

TEST(RunFigures, PlowStudyGivesForceMagnitudeAngleAndBladeMotion) {
  if (!framedyn::report::gnuplot_available()) GTEST_SKIP() << "gnuplot is not installed (install-deps.sh installs gnuplot-nox)";
  framedyn::testing::TempDir dir("framedyn_test_run_figures");
  ASSERT_EQ(framedyn(dir, std::string("run '") + FRAMEDYN_SOURCE_DIR + "/examples/r100_plow_2d.yaml' --figures --out plow"), 0)
      << read_file(dir / "err.txt");
  for (const char* png : {"plow_force_magnitude.png", "plow_force_angle.png", "blade_vertical_motion.png"})
    EXPECT_EQ(read_file(dir / "plow" / png).substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8)) << png;
  EXPECT_FALSE(fs::exists(dir / "plow" / "chain_force.png"));
  EXPECT_TRUE(fs::exists(dir / "plow" / "response.csv"));
  EXPECT_NE(read_file(dir / "out.txt").find("figures: plow_force_magnitude.png"), std::string::npos) << read_file(dir / "out.txt");
}

// The digging-chain variant of the shipped machine, as in tests/rigid/test_vehicle_2d.cpp:
// its plow block replaced by a chain block (thesis chain speed 100 in/s,
// reduction factors 0.10 and 0.50, a 0.05 s ramp), the boom added to the frame.
std::string chain_study_text() {
  std::string t = read_file(fs::path(FRAMEDYN_SOURCE_DIR) / "examples" / "r100_plow_2d.yaml");
  const auto replace_once = [&](const std::string& from, const std::string& to) {
    const std::size_t at = t.find(from);
    if (at == std::string::npos) throw std::logic_error("the example has no '" + from + "'");
    t.replace(at, from.size(), to);
  };
  replace_once("attachment: plow", "attachment: chain");
  replace_once("    - {name: hitch_box",
               "    - {name: chain_boom_and_drive, weight: 1800, radius_of_gyration: 20, position: [108, -16], attachment: [84, 0]}\n"
               "    - {name: hitch_box");
  const std::size_t plow = t.find("\nplow:\n"), soil = t.find("\nsoil:");
  if (plow == std::string::npos || soil == std::string::npos || soil < plow) throw std::logic_error("the example has no plow block before soil");
  const std::string chain =
      "chain: {boom_point: [118, -40], chain_pin: [84, 2], chain_angle_deg: 30, moment_arm: 12, tooth_static_force: 900,\n"
      "        tooth_damping: 2, chain_speed: 100, static_reduction: 0.1, damping_reduction: 0.5, tooth_spacing: 8,\n"
      "        length_in_ground: 36, ramp_time: 0.05}\n";
  return t.substr(0, plow + 1) + chain + t.substr(soil);
}

TEST(RunFigures, ChainStudyGivesTheChainForceAndNoPlowFigures) {
  if (!framedyn::report::gnuplot_available()) GTEST_SKIP() << "gnuplot is not installed (install-deps.sh installs gnuplot-nox)";
  framedyn::testing::TempDir dir("framedyn_test_run_figures");
  dir.write("chain.yaml", chain_study_text());
  ASSERT_EQ(framedyn(dir, "run chain.yaml --figures --out chain -q"), 0) << read_file(dir / "err.txt");
  EXPECT_EQ(read_file(dir / "chain" / "chain_force.png").substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  EXPECT_FALSE(fs::exists(dir / "chain" / "plow_force_magnitude.png"));
}

TEST(RunFigures, WithoutTheFlagNoImages) {
  framedyn::testing::TempDir dir("framedyn_test_run_figures");
  ASSERT_EQ(framedyn(dir, std::string("run '") + FRAMEDYN_SOURCE_DIR + "/examples/r100_plow_2d.yaml' --out plow -q"), 0) << read_file(dir / "err.txt");
  EXPECT_FALSE(fs::exists(dir / "plow" / "plow_force_magnitude.png"));
}

}  // namespace
