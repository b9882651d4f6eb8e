// `framedyn harmonic` and `framedyn random` as a user runs them: the files,
// their columns and units, and numbers checked against the program's own
// static and modal commands on the same mesh (the harmonic amplitude at a low
// frequency is the static deflection; the resonance is at the first mode and
// amplified by about 1/(2 zeta)) and against the RMS the response PSD table
// integrates to. Bad input is in tests/apps/test_error_table.cpp (CLI-21..32).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
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

// A 2 m steel cantilever of 8 B31 elements along X, clamped at node 1, 1 kN down at the tip (node 9).
std::string cantilever() {
  std::string m = "** units: m-N-s\n*NODE, NSET=ALL\n";
  for (int n = 1; n <= 9; ++n) m += std::to_string(n) + ", " + std::to_string(0.25 * (n - 1)) + ", 0, 0\n";
  m += "*NSET, NSET=TIP\n9\n*ELEMENT, TYPE=B31, ELSET=FRAME\n";
  for (int e = 1; e <= 8; ++e) m += std::to_string(e) + ", " + std::to_string(e) + ", " + std::to_string(e + 1) + "\n";
  return m + R"(*BEAM SECTION, ELSET=FRAME, MATERIAL=STEEL, SECTION=RECT
0.05, 0.1
*MATERIAL, NAME=STEEL
*ELASTIC
2.1e11, 0.3
*DENSITY
7850
*BOUNDARY
1, ENCASTRE
*STEP
*STATIC
*CLOAD
9, 3, -1000.
*END STEP
)";
}

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::string cur;
  std::istringstream in(s);
  while (std::getline(in, cur, sep)) out.push_back(cur);
  return out;
}

struct Csv {
  std::vector<std::string> header;
  std::vector<std::vector<double>> rows;
  int column(const std::string& name) const {
    for (std::size_t i = 0; i < header.size(); ++i)
      if (header[i] == name) return static_cast<int>(i);
    ADD_FAILURE() << "no column " << name;
    return 0;
  }
};

Csv read_csv(const fs::path& p) {
  Csv c;
  const std::vector<std::string> lines = split(read_file(p), '\n');
  c.header = split(lines.at(0), ',');
  for (std::size_t i = 1; i < lines.size(); ++i) {
    if (lines[i].empty()) continue;
    std::vector<double> row;
    for (const std::string& f : split(lines[i], ',')) row.push_back(std::stod(f));
    EXPECT_EQ(row.size(), c.header.size());
    c.rows.push_back(row);
  }
  return c;
}

TEST(HarmonicCli, LowFrequencyAmplitudeIsTheStaticDeflectionAndTheResonanceIsAtTheFirstMode) {
  TempDir dir;
  dir.write("frame.inp", cantilever());
  const RunResult st = framedyn(dir, "static frame.inp --out static -q");
  ASSERT_EQ(st.status, 0) << st.err;
  const RunResult mo = framedyn(dir, "modes frame.inp --modes 4 --out modes -q");
  ASSERT_EQ(mo.status, 0) << mo.err;
  const double u_static = std::abs(nlohmann::json::parse(read_file(dir / "static" / "summary.json"))["frame"]["max_displacement"]["value"].get<double>());
  const double f1 = nlohmann::json::parse(read_file(dir / "modes" / "summary.json"))["frame"]["modes"][0]["frequency"]["value"].get<double>();

  // 0.1 Hz to 2 f1 in steps of f1/500: the first frequency is quasi-static, the grid brackets f1 closely.
  const double step = f1 / 500.0;
  const int n = 1000;
  const double last = 0.1 + step * (n - 1);
  const double zeta = 0.02;
  const RunResult r = framedyn(dir, "harmonic frame.inp -f 0.1:" + std::to_string(last) + ":" + std::to_string(n) +
                                        " -z 0.02 --output-set TIP --out results -q");
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char* file : {"summary.json", "frf.csv", "frf.png", "fiber_stress.png"}) EXPECT_TRUE(fs::exists(dir / "results" / file)) << file;
  const nlohmann::json j = nlohmann::json::parse(read_file(dir / "results" / "summary.json"));
  const nlohmann::json& h = j["frame"]["harmonic"];
  EXPECT_EQ(h["mode_count"], 20);
  EXPECT_EQ(h["static_correction"], true);
  EXPECT_EQ(h["max_displacement"]["unit"], "m");
  EXPECT_EQ(h["max_displacement"]["node"], 9);
  EXPECT_EQ(h["max_displacement"]["dof"], "uz");
  EXPECT_EQ(h["max_fiber_stress"]["unit"], "Pa");
  EXPECT_EQ(h["max_fiber_stress"]["element"], 1);  // the root carries the largest moment
  // The resonance peak of |H| lies at f1 sqrt(1 - 2 zeta^2): within one grid step of it.
  EXPECT_NEAR(h["max_displacement"]["frequency"]["value"].get<double>(), f1 * std::sqrt(1 - 2 * zeta * zeta), step);
  // At resonance the first mode's static share is amplified by 1/(2 zeta); for a tip-loaded
  // cantilever that share is 97 % of the tip deflection (the higher modes add the rest, unamplified),
  // and the grid misses the peak by at most (step / (zeta f1))^2 / 2 = 5e-3.
  const double ratio = h["max_displacement"]["value"].get<double>() / (u_static / (2 * zeta));
  EXPECT_GT(ratio, 0.95);
  EXPECT_LT(ratio, 1.0);

  const Csv frf = read_csv(dir / "results" / "frf.csv");
  EXPECT_EQ(frf.header[0], "node");
  EXPECT_EQ(frf.header[1], "frequency [Hz]");
  EXPECT_EQ(frf.header[6], "uz_amplitude [m]");
  EXPECT_EQ(frf.header[7], "uz_phase [deg]");
  EXPECT_EQ(frf.header[8], "rx_amplitude [rad]");
  ASSERT_EQ(frf.rows.size(), static_cast<std::size_t>(n));  // one node (TIP) x n frequencies
  // 0.1 Hz: (f/f1)^2 ~ 1e-4 from the static deflection. The phase is that of u_z(t) = |u| cos(omega t + phase)
  // against the reference cos(omega t) of the load pattern: the tip moves down with the downward load, phase 180 deg.
  EXPECT_NEAR(frf.rows[0][6], u_static, 2e-4 * u_static);
  EXPECT_GT(std::abs(frf.rows[0][7]), 179.5);
  // At 2 f1 the first mode lags its load by atan2(2 zeta r, 1 - r^2) = 178.5 deg (r = 2): the tip moves up
  // while the load pushes down, phase 180 - 178.5 = 1.5 deg (the higher modes, in phase with their load, shift it a little).
  EXPECT_NEAR(frf.rows.back()[7], 180.0 - std::atan2(2 * zeta * 2.0, 1 - 4.0) * 180.0 / 3.141592653589793, 1.0);
}

TEST(HarmonicCli, StaticCorrectionCanBeSwitchedOffAndIsReported) {
  TempDir dir;
  dir.write("frame.inp", cantilever());
  const RunResult r = framedyn(dir, "harmonic frame.inp -f 1:50:50 -z 0.05 --modes 2 --no-static-correction --no-figures --out results -q");
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(read_file(dir / "results" / "summary.json"));
  EXPECT_EQ(j["frame"]["harmonic"]["static_correction"], false);
  EXPECT_EQ(j["frame"]["harmonic"]["mode_count"], 2);
  EXPECT_FALSE(fs::exists(dir / "results" / "frf.png"));
  EXPECT_EQ(read_csv(dir / "results" / "frf.csv").rows.size(), 9u * 50u);  // all nodes without --output-set
}

// A deck with a step per load case: harmonic (and random, which shares the
// input) never takes step 1's loads silently. Without --step the run is
// refused naming the steps; --step 2 gives exactly the response of a deck
// that has step 2's loads alone, and summary.json says which step it was.
TEST(HarmonicCli, MultiStepDeckRunsTheStepItIsToldAndNeverStepOneSilently) {
  TempDir dir;
  const std::string one = cantilever();
  const std::string two = one + "*STEP\n*STATIC\n*CLOAD, OP=NEW\n9, 2, 2000.\n*END STEP\n";
  std::string alone = one;
  alone.replace(alone.find("9, 3, -1000."), 12, "9, 2, 2000.");
  dir.write("two.inp", two);
  dir.write("alone.inp", alone);
  const std::string options = " -f 1:50:5 -z 0.05 --modes 4 --output-set TIP --no-figures -q";
  const RunResult refused = framedyn(dir, "harmonic two.inp" + options + " --out refused");
  EXPECT_EQ(refused.status, 1);
  EXPECT_NE(refused.err.find("two.inp has several steps with loads: 1 (STATIC), 2 (STATIC)"), std::string::npos) << refused.err;
  EXPECT_FALSE(fs::exists(dir / "refused"));
  const RunResult r2 = framedyn(dir, "harmonic two.inp" + options + " --step 2 --out step2");
  ASSERT_EQ(r2.status, 0) << r2.err;
  const RunResult ra = framedyn(dir, "harmonic alone.inp" + options + " --out alone");
  ASSERT_EQ(ra.status, 0) << ra.err;
  const nlohmann::json j2 = nlohmann::json::parse(read_file(dir / "step2" / "summary.json"));
  const nlohmann::json ja = nlohmann::json::parse(read_file(dir / "alone" / "summary.json"));
  EXPECT_EQ(j2["input"]["step"], 2);
  EXPECT_EQ(ja["input"]["step"], 1);  // a deck's only step with loads is used, and named
  const nlohmann::json& h2 = j2["frame"]["harmonic"]["max_displacement"];
  const nlohmann::json& ha = ja["frame"]["harmonic"]["max_displacement"];
  EXPECT_EQ(h2["dof"], "uy");  // step 2's load is along y; step 1's along z
  EXPECT_NEAR(h2["value"].get<double>(), ha["value"].get<double>(), 1e-9 * ha["value"].get<double>());
  EXPECT_NEAR(h2["frequency"]["value"].get<double>(), ha["frequency"]["value"].get<double>(), 1e-9);
}

TEST(RandomCli, RmsTableIsTheIntegralOfTheResponsePsdTable) {
  TempDir dir;
  dir.write("frame.inp", cantilever());
  dir.write("psd.csv", "# flat from 2 to 400 Hz\nfrequency [Hz],psd [1/Hz]\n2,0.001\n400,0.001\n");
  const RunResult r = framedyn(dir, "random frame.inp --psd psd.csv -z 0.03 --output-set TIP --out results -q");
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char* file : {"summary.json", "response_psd.csv", "rms.csv", "response_psd.png", "stress_psd.png"})
    EXPECT_TRUE(fs::exists(dir / "results" / file)) << file;
  const nlohmann::json j = nlohmann::json::parse(read_file(dir / "results" / "summary.json"));
  const nlohmann::json& h = j["frame"]["random"];
  EXPECT_EQ(h["max_displacement_psd"]["unit"], "m^2/Hz");
  EXPECT_EQ(h["max_displacement_psd"]["node"], 9);
  EXPECT_EQ(h["max_displacement_psd"]["dof"], "uz");
  EXPECT_EQ(h["max_stress_psd"]["unit"], "Pa^2/Hz");
  EXPECT_EQ(h["max_stress_psd"]["element"], 1);
  EXPECT_EQ(h["max_displacement_rms"]["unit"], "m");
  EXPECT_EQ(h["max_stress_rms"]["unit"], "Pa");
  EXPECT_NEAR(j["input"]["load_factor_rms"].get<double>(), std::sqrt(0.001 * 398), 1e-9);

  const Csv psd = read_csv(dir / "results" / "response_psd.csv");
  EXPECT_EQ(psd.header[2], "load_psd [1/Hz]");
  EXPECT_EQ(psd.header[5], "uz_psd [m^2/Hz]");
  const Csv rms = read_csv(dir / "results" / "rms.csv");
  EXPECT_EQ(rms.header[3], "uz_rms [m]");
  // The trapezoidal integral of the tip's uz PSD over the table's rows is the RMS in rms.csv
  // (same grid; the CSV's 10 digits limit the agreement).
  double ms = 0.0;
  const int f = psd.column("frequency [Hz]"), uz = psd.column("uz_psd [m^2/Hz]"), node = psd.column("node");
  for (std::size_t k = 0; k + 1 < psd.rows.size(); ++k)
    if (psd.rows[k][node] == 9 && psd.rows[k + 1][node] == 9) ms += 0.5 * (psd.rows[k][uz] + psd.rows[k + 1][uz]) * (psd.rows[k + 1][f] - psd.rows[k][f]);
  double tip_rms = 0.0;
  for (const auto& row : rms.rows)
    if (row[0] == 9) tip_rms = row[3];
  EXPECT_NEAR(std::sqrt(ms), tip_rms, 1e-7 * tip_rms);
  EXPECT_NEAR(h["max_displacement_rms"]["value"].get<double>(), tip_rms, 1e-9 * tip_rms);
}

TEST(RandomCli, FreeFrameIsRefusedWithoutInertiaReliefAndItsElasticPartReportedWithIt) {
  // The cantilever without its clamp: free-free, 6 free rigid motions.
  std::string mesh = cantilever();
  mesh.replace(mesh.find("*BOUNDARY\n1, ENCASTRE\n"), std::string("*BOUNDARY\n1, ENCASTRE\n").size(), "");
  TempDir dir;
  dir.write("frame.inp", mesh);
  dir.write("psd.csv", "frequency [Hz],psd [1/Hz]\n2,0.001\n400,0.001\n");
  const RunResult refused = framedyn(dir, "random frame.inp --psd psd.csv -z 0.03 --no-figures --out results -q");
  EXPECT_EQ(refused.status, 1);
  EXPECT_NE(refused.err.find("--inertia-relief"), std::string::npos) << refused.err;
  EXPECT_FALSE(fs::exists(dir / "results"));

  const RunResult r = framedyn(dir, "random frame.inp --psd psd.csv -z 0.03 --inertia-relief --no-figures --out results -q");
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(read_file(dir / "results" / "summary.json"));
  const nlohmann::json& h = j["frame"]["random"];
  EXPECT_EQ(h["displacements"].get<std::string>().rfind("elastic part (inertia relief", 0), 0u) << h["displacements"];
  EXPECT_EQ(h["free_rigid_motions"], 6);
  EXPECT_EQ(h["static_correction"], true);
  // A free beam bent by a force at one end: the elastic part moves both ends (no support holds the root).
  const Csv rms = read_csv(dir / "results" / "rms.csv");
  double root = 0.0, tip = 0.0;
  for (const auto& row : rms.rows) {
    if (row[0] == 1) root = row[3];
    if (row[0] == 9) tip = row[3];
  }
  EXPECT_GT(root, 0.0);
  EXPECT_GT(tip, 0.0);
}

}  // namespace
