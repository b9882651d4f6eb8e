// Numerical faults of a study reach the user as explanations, with exit
// status 2 and no results folder: here the shipped 2-D plow study, integrated
// by RK4 with a step far beyond its stability limit (h omega_max > 2.8), so
// that the motion grows without bound. The message says which integrator,
// when, which coordinate and the whole state there, by coordinate name, and
// that the step is the thing to change.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include "tests/support/temp_dir.h"

namespace framedyn {
namespace {

namespace fs = std::filesystem;

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

struct RunOutcome {
  int status = -1;
  std::string err;
};

RunOutcome run_framedyn(const testing::TempDir& dir, const std::string& args) {
  const fs::path err = dir / "stderr.txt";
  const std::string cmd = "cd '" + dir.path().string() + "' && '" + FRAMEDYN_BINARY + "' " + args + " >/dev/null 2>'" + err.string() + "'";
  const int rc = std::system(cmd.c_str());
  RunOutcome r;
  r.status = (rc != -1 && WIFEXITED(rc)) ? WEXITSTATUS(rc) : -1;
  r.err = read_text(err);
  fs::remove(err);
  return r;
}

TEST(NumericalFaultsCli, DivergingRk4StudyNamesTimeCoordinateAndStateAndWritesNothing) {
  testing::TempDir dir;
  std::string study = read_text(fs::path(FRAMEDYN_SOURCE_DIR) / "examples/r100_plow_2d.yaml");
  const std::string response = "response: {duration: 0.5, output_interval: 0.0005, method: event_located}";
  const std::size_t at = study.find(response);
  ASSERT_NE(at, std::string::npos) << "the shipped study's response line changed";
  // 0.1 s steps: h omega = 7.2 for the highest mode (11.4 Hz), far above
  // RK4's limit of 2.8; the motion grows by about 100 a step until it overflows.
  study.replace(at, response.size(), "response: {duration: 60, output_interval: 0.1, method: rk4, rk4_step: 0.1}");
  std::ofstream(dir / "diverging.yaml") << study;

  const RunOutcome r = run_framedyn(dir, "run diverging.yaml --out results");
  std::printf("%s\n", r.err.c_str());
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("framedyn: numerical failure: RK4: the motion is unbounded: by t = "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("reduce the step (RK4 is unstable for h omega_max > 2.8)"), std::string::npos) << r.err;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.err, m, std::regex(R"(by t = ([0-9.eE+-]+) s the state has grown to [qv] of ([a-z_0-9]+) \(coordinate [0-9]+\) = )")))
      << r.err;
  EXPECT_GT(std::stod(m[1]), 0.0);
  EXPECT_LT(std::stod(m[1]), 60.0);
  // The whole state, by the model's coordinate names (x, z, theta_y, psi, w, theta_v).
  EXPECT_NE(r.err.find("The state there: q: x "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(", theta_v "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("; v: x "), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "results"));
  for (const auto& e : fs::directory_iterator(dir.path()))
    EXPECT_EQ(e.path().filename().string().find(".partial-"), std::string::npos) << e.path();
}

}  // namespace
}  // namespace framedyn
