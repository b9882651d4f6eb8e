// `framedyn frame-response`: a study file and a load history in, a complete
// results folder with summary.json's frame keys out; bad input exits 1.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

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
  for (const char* key : {"\"frame\"", "\"frequency_hz\"", "\"peak_bending_moment\"", "\"left_rail\"", "\"right_rail\"", "\"peak_normal_stress\"", "\"psi\""})
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

}  // namespace
