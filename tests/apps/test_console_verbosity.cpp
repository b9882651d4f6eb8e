// Progress and verbosity are the same on every command (issue 14, item 4):
// each command accepts --quiet/-q and --verbose/-v; a successful run with -q
// writes nothing on stderr and, on stdout, only the line that names the
// results folder; with -v it lists its stages, "writing results" among them,
// each with its time. The commands run as a user runs them: modes, static,
// harmonic, random and frame-response on small frames, and run (2-D, 3-D,
// the pipeline), sweep and batch on the shipped studies cut to 0.05 s.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include "tests/support/run_framedyn.h"
#include "tests/support/temp_dir.h"

namespace {

namespace fs = std::filesystem;
using framedyn::testing::framedyn;
using framedyn::testing::read_file;
using framedyn::testing::RunResult;
using framedyn::testing::TempDir;
using Json = nlohmann::json;

const fs::path kSource = FRAMEDYN_SOURCE_DIR;

std::string cantilever() {
  std::string m = "** units: m-N-s\n*NODE, NSET=ALL\n";
  for (int n = 1; n <= 9; ++n) m += std::to_string(n) + ", " + std::to_string(0.25 * (n - 1)) + ", 0, 0\n";
  m += "*NSET, NSET=TIP\n9\n*ELEMENT, TYPE=B31, ELSET=FRAME\n";
  for (int e = 1; e <= 8; ++e) m += std::to_string(e) + ", " + std::to_string(e) + ", " + std::to_string(e + 1) + "\n";
  return m + "*BEAM SECTION, ELSET=FRAME, MATERIAL=STEEL, SECTION=RECT\n0.05, 0.1\n*MATERIAL, NAME=STEEL\n*ELASTIC\n2.1e11, 0.3\n"
             "*DENSITY\n7850\n*BOUNDARY\n1, ENCASTRE\n*STEP\n*STATIC\n*CLOAD\n9, 3, -1000.\n*END STEP\n";
}

// A shipped example with its mesh and load paths made absolute and its forced response cut to 0.05 s.
std::string shipped(const std::string& name) {
  std::string s = read_file(kSource / "examples" / name);
  // The keys' values, not the comments' mentions of the same files.
  for (const std::string& rel : {std::string("mesh: ../meshes/"), std::string("loads: portal_frame_sway_loads.csv")}) {
    const std::size_t at = s.find(rel);
    if (at == std::string::npos) continue;
    s.replace(at, rel.size(), rel[0] == 'm' ? "mesh: " + (kSource / "meshes").string() + "/" : "loads: " + (kSource / "examples" / rel.substr(7)).string());
  }
  const std::regex duration(R"(duration: [0-9.]+)");
  return std::regex_replace(s, duration, "duration: 0.05", std::regex_constants::format_first_only);
}

struct Case {
  std::string name, args;  // args without --out, -q or -v
};

class EveryCommand : public ::testing::TestWithParam<Case> {
 protected:
  void SetUp() override {
    std::ofstream(dir_ / "frame.inp") << cantilever();
    std::ofstream(dir_ / "psd.csv") << "frequency [Hz],psd [1/Hz]\n1,0.01\n100,0.01\n";
    std::ofstream(dir_ / "plow_2d.yaml") << shipped("r100_plow_2d.yaml");
    std::ofstream(dir_ / "plow_3d.yaml") << shipped("r100_plow_offset.yaml");
    std::ofstream(dir_ / "pipeline.yaml") << shipped("offset_plowing.yaml");
    std::ofstream(dir_ / "portal.yaml") << shipped("portal_frame_sway.yaml");
    std::ofstream(dir_ / "design.yaml") << "framedyn_batch: 1\nstudy: plow_2d.yaml\nsampling: {method: grid}\n"
                                           "parameters:\n  - {key: soil.damping, values: [200, 300]}\noutputs:\n  - rigid.response.peak_cutting_force\n";
  }
  TempDir dir_{"console"};
};

TEST_P(EveryCommand, QuietWritesNothingOnStderrAndOnlyTheResultsFolderOnStdout) {
  const RunResult r = framedyn(dir_, GetParam().args + " --out quiet -q");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_EQ(r.out, "results in quiet/\n");
}

TEST_P(EveryCommand, VerboseListsTheStagesWithTheirTimes) {
  const RunResult r = framedyn(dir_, GetParam().args + " --out verbose -v");
  ASSERT_EQ(r.status, 0) << r.err;
  const std::size_t list = r.err.find("framedyn stages:\n");
  ASSERT_NE(list, std::string::npos) << r.err;
  const std::string stages = r.err.substr(list);
  // "  writing results            0.012 s  12.5 %": every stage with its time and share, the writing among them.
  EXPECT_TRUE(std::regex_search(stages, std::regex(R"(\n  writing results[^\n]* +[0-9]+\.[0-9]{3} s +[0-9]+\.[0-9] %\n)"))) << stages;
  EXPECT_TRUE(std::regex_search(stages, std::regex(R"(\n  reading [^\n]* +[0-9]+\.[0-9]{3} s +[0-9]+\.[0-9] %\n)"))) << stages;
  // The console's tables stay (only -q drops them).
  EXPECT_NE(r.out.find("results in verbose/"), std::string::npos);
}

TEST_P(EveryCommand, HelpListsQuietAndVerbose) {
  const std::string command = GetParam().args.substr(0, GetParam().args.find(' '));
  const RunResult r = framedyn(dir_, command + " --help");
  ASSERT_EQ(r.status, 0);
  EXPECT_NE(r.out.find("--quiet"), std::string::npos) << command;
  EXPECT_NE(r.out.find("--verbose"), std::string::npos) << command;
}

INSTANTIATE_TEST_SUITE_P(
    Commands, EveryCommand,
    ::testing::Values(Case{"modes", "modes frame.inp --modes 4"}, Case{"static", "static frame.inp"},
                      Case{"harmonic", "harmonic frame.inp -f 1:100:20 -z 0.02 --no-figures"},
                      Case{"random", "random frame.inp --psd psd.csv -z 0.02 --no-figures"},
                      Case{"frame_response", "frame-response portal.yaml"}, Case{"run_2d", "run plow_2d.yaml"},
                      Case{"run_3d", "run plow_3d.yaml"}, Case{"pipeline", "run pipeline.yaml"},
                      Case{"sweep", "sweep plow_2d.yaml -p soil.damping --values 100,200 --no-figures"},
                      Case{"batch", "batch design.yaml -j 1"}),
    [](const ::testing::TestParamInfo<Case>& p) { return p.param.name; });

TEST(Verbosity, QuietAndVerboseTogetherAreRefused) {
  TempDir dir("console_both");
  std::ofstream(dir / "frame.inp") << cantilever();
  const RunResult r = framedyn(dir, "modes frame.inp -q -v");
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, "framedyn: error: command line: --quiet: expected at most one of --quiet and --verbose (framedyn modes --help), found both\n");
}

// One name for one quantity in 2-D and 3-D (issue 15): the blade's soil force,
// the thesis's RPF (Eq. 2.37), is plow_force_* in both models' response.csv;
// the 2-D model has no Y, so it writes X and Z only. (The 3-D columns were
// soil_force_* before docs/validation.md V40.)
std::string header_of(const fs::path& csv) {
  const std::string text = read_file(csv);
  return text.substr(0, text.find('\n'));
}

TEST(BladeForceColumns, OneNameInTwoDAndThreeD) {
  const TempDir dir("blade_columns");
  std::ofstream(dir / "plow_2d.yaml") << shipped("r100_plow_2d.yaml");
  std::ofstream(dir / "plow_3d.yaml") << shipped("r100_plow_offset.yaml");
  ASSERT_EQ(framedyn(dir, "run plow_2d.yaml --out two -q").status, 0);
  ASSERT_EQ(framedyn(dir, "run plow_3d.yaml --out three -q").status, 0);
  const std::string h2 = header_of(dir / "two" / "response.csv"), h3 = header_of(dir / "three" / "response.csv");
  for (const std::string c : {",plow_force_x [lbf]", ",plow_force_z [lbf]"}) {
    EXPECT_NE(h2.find(c), std::string::npos) << c << " in " << h2;
    EXPECT_NE(h3.find(c), std::string::npos) << c << " in " << h3;
  }
  EXPECT_NE(h3.find(",plow_force_y [lbf]"), std::string::npos) << h3;
  EXPECT_EQ(h2.find("plow_force_y"), std::string::npos) << h2;
  EXPECT_EQ(h2.find("soil_force"), std::string::npos) << h2;
  EXPECT_EQ(h3.find("soil_force"), std::string::npos) << h3;
}

// The console of `framedyn run` prints the same blade lines for a 2-D and a
// 3-D study (issue 15; it printed them for 2-D only before docs/validation.md
// V40), each figure the one summary.json reports, to the 4 or 5 significant
// digits the console prints.
double console_number(const std::string& out, const std::string& pattern) {
  std::smatch m;
  if (!std::regex_search(out, m, std::regex(pattern))) return std::nan("");
  return std::stod(m[1].str());
}

TEST(RunConsole, TwoDAndThreeDPrintTheSameBladeLinesAsTheSummary) {
  const TempDir dir("blade_console");
  // 0.2 s: a few shaker cycles (18.33 Hz), so that the cycle measures exist.
  const auto cut = [](std::string s) { return s.replace(s.find("duration: 0.05"), 14, "duration: 0.2"); };
  std::ofstream(dir / "plow_2d.yaml") << cut(shipped("r100_plow_2d.yaml"));
  std::ofstream(dir / "plow_3d.yaml") << cut(shipped("r100_plow_offset.yaml"));
  for (const std::string model : {"2d", "3d"}) {
    const RunResult r = framedyn(dir, "run plow_" + model + ".yaml --out out_" + model);
    ASSERT_EQ(r.status, 0) << r.err;
    const Json summary = Json::parse(read_file(dir / ("out_" + model) / "summary.json"));
    const Json& response = summary["rigid"]["response"];
    const auto expect_line = [&](const std::string& pattern, const std::string& key, double digits) {
      // A force the run never reached (no backing off in 0.05 s) is absent from the summary and printed 0.
      const double printed = console_number(r.out, pattern);
      const double reported = response.contains(key) ? response[key]["value"].get<double>() : 0.0;
      if (response.contains(key)) EXPECT_EQ(response[key]["unit"].get<std::string>(), key == "plow_vertical_pp" ? "in" : "lbf") << key;
      // The console prints `digits` significant digits: half a unit of the last one.
      const double half_unit = reported == 0.0 ? 0.0 : 0.5 * std::pow(10.0, std::floor(std::log10(std::abs(reported))) - digits + 1);
      EXPECT_NEAR(printed, reported, half_unit) << model << " " << key << "\n" << r.out;
    };
    expect_line(R"(blade vertical motion, average peak to peak: ([-0-9.e+]+) in\n)", "plow_vertical_pp", 4);
    expect_line(R"(peak cutting force ([-0-9.e+]+) lbf, )", "peak_cutting_force", 5);
    expect_line(R"(, peak backing force ([-0-9.e+]+) lbf\n)", "peak_backing_force", 5);
    expect_line(R"(shaker cycles' peaks: cutting ([-0-9.e+]+) lbf, )", "average_peak_cutting_force", 5);
    expect_line(R"(, backing ([-0-9.e+]+) lbf\n)", "average_peak_backing_force", 5);
  }
}

}  // namespace
