// `framedyn rainflow` as a user runs it (docs/validation.md V14.7): a strain-gauge history in
// MPa and the same history in psi give the same cycles and the same damage, equal to n / N from
// the S-N curve; the outputs carry the series' unit; the repeated-block option closes the count;
// the options --mean-stress goodman --ultimate, --thickness and --curve against hand figures.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>

#include "tests/support/run_framedyn.h"
#include "tests/support/temp_dir.h"

namespace {

using framedyn::testing::framedyn;
using framedyn::testing::read_file;
using framedyn::testing::TempDir;
constexpr double kPi = 3.14159265358979323846;
constexpr double kPsi = 4.4482216152605 / (0.0254 * 0.0254);  // Pa per psi (lbf and inch exact)

// 50 periods of 40 + 50 cos(2 pi k / 20) MPa (range 100 MPa), 20 samples a period, peaks sampled
// exactly, with a time column; values divided by `per_mpa`, the unit in MPa (1 for MPa, 6.894757e-3 for psi).
std::string series(const std::string& unit, double per_mpa) {
  std::string text = "# strain gauge SG1, rear rail\ntime [s],sg1 [" + unit + "]\n";
  char line[96];
  for (int k = 0; k <= 1000; ++k) {
    std::snprintf(line, sizeof line, "%.4f,%.17g\n", k * 0.005, (40.0 + 50.0 * std::cos(2.0 * kPi * (k % 20) / 20.0)) / per_mpa);
    text += line;
  }
  return text;
}

nlohmann::json run(const TempDir& dir, const std::string& file, const std::string& extra) {
  const auto r = framedyn(dir, "rainflow " + file + " --sn FAT90 " + extra + " -q");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  return nlohmann::json::parse(read_file(dir / (file.substr(0, file.size() - 4) + "_out") / "summary.json"));
}

TEST(RainflowCommand, SeriesInPsiAndInMpaGiveTheSameDamageAsNOverN) {
  TempDir dir;
  std::ofstream(dir / "mpa.csv") << series("MPa", 1.0);
  std::ofstream(dir / "psi.csv") << series("psi", kPsi / 1e6);
  const nlohmann::json a = run(dir, "mpa.csv", "--out mpa_out"), b = run(dir, "psi.csv", "--out psi_out");
  // 50 periods of 100 MPa: 100 half cycles (each range holds the start) = 50 cycles, and
  // D = 50 / N(100 MPa) with IIW FAT90: N = 2e6 (90/100)^3 = 1.458e6.
  const double expected = 50.0 / (2e6 * std::pow(0.9, 3));
  EXPECT_EQ(a["rainflow"]["cycles"].get<double>(), 50.0);
  EXPECT_EQ(b["rainflow"]["cycles"].get<double>(), 50.0);
  EXPECT_NEAR(a["fatigue"]["damage"].get<double>(), expected, 1e-12 * expected);
  EXPECT_NEAR(b["fatigue"]["damage"].get<double>(), expected, 1e-12 * expected);
  EXPECT_EQ(a["fatigue"]["code"], "IIW 2016 (Hobbacher, IIW-2259-15)");
  // Ranges in the series' unit: 100 MPa and 100e6 / 6894.757 psi = 14503.77 psi.
  EXPECT_EQ(a["rainflow"]["max_range"]["unit"], "MPa");
  EXPECT_EQ(b["rainflow"]["max_range"]["unit"], "psi");
  EXPECT_NEAR(a["rainflow"]["max_range"]["value"].get<double>(), 100.0, 1e-12);
  EXPECT_NEAR(b["rainflow"]["max_range"]["value"].get<double>() * kPsi, 100e6, 1e-12 * 100e6);
  EXPECT_NEAR(b["fatigue"]["equivalent_range"]["value"].get<double>() * kPsi, a["fatigue"]["equivalent_range"]["value"].get<double>() * 1e6,
              1e-9 * a["fatigue"]["equivalent_range"]["value"].get<double>() * 1e6);
  EXPECT_EQ(read_file(dir / "psi_out" / "cycles.csv").substr(0, 33), "range [psi],mean [psi],count\n1450");
}

TEST(RainflowCommand, RepeatedBlockCountsFullCyclesOnly) {
  TempDir dir;
  std::ofstream(dir / "mpa.csv") << series("MPa", 1.0);
  const nlohmann::json s = run(dir, "mpa.csv", "--repeat --out mpa_out");
  EXPECT_EQ(s["rainflow"]["cycles"].get<double>(), 50.0);
  EXPECT_EQ(s["rainflow"]["residue"], "repeated block (history closed at its absolute maximum)");
  const std::string csv = read_file(dir / "mpa_out" / "cycles.csv");
  EXPECT_EQ(csv.find(",0.5\n"), std::string::npos);  // no half cycle
  const auto q = framedyn(dir, "rainflow mpa.csv --out again -q");
  EXPECT_EQ(q.out, "results in again/\n");
}

// The options against hand figures, on the 50 cycles of range 100 MPa and mean 40 MPa above:
//  - Goodman with S_u = 400 MPa: S_eq = 100 / (1 - 40/400) = 111.1 MPa (F.10), D = 50 / (2e6 (90/111.1)^3);
//    the same series in psi with S_u in psi gives the same damage;
//  - IIW thickness 50 mm, n = 0.3: FAT 90 (25/50)^0.3 = 73.11 MPa, D = 50 / (2e6 (73.11/100)^3); n = 0.2 given;
//  - EN 1993-1-9 category 90, 50 mm: k_s = (25/50)^0.2 = 0.8706, 78.35 MPa (above its knee at 5e6), D = 50 / (2e6 (78.35/100)^3);
//  - points 1e5:200,1e7:50 (MPa): m = ln 100 / ln 4, N(100) = 1e5 * 2^m = 1e5 * 10 = 1e6, D = 5e-5;
//  - Basquin C = 2e12 MPa^3, m = 3: N(100) = 2e12 / 100^3 = 2e6, D = 2.5e-5.
TEST(RainflowCommand, MeanStressThicknessAndUserCurvesGiveTheHandDamage) {
  TempDir dir;
  std::ofstream(dir / "mpa.csv") << series("MPa", 1.0);
  std::ofstream(dir / "psi.csv") << series("psi", kPsi / 1e6);
  int k = 0;
  const auto damage = [&](const std::string& file, const std::string& args) {
    const std::string out = "out" + std::to_string(k++);
    const auto r = framedyn(dir, "rainflow " + file + " " + args + " --out " + out + " -q");
    EXPECT_EQ(r.status, 0) << args << ": " << r.err;
    const nlohmann::json j = nlohmann::json::parse(read_file(dir / out / "summary.json"));
    return j["fatigue"]["damage"].get<double>();
  };
  const auto check = [&](double d, double expected, const std::string& what) {
    EXPECT_NEAR(d, expected, 1e-12 * expected) << what;
    std::cout << "[ measured ] " << what << ": D = " << d << " (hand " << expected << ")\n";
  };
  const double s_goodman = 100.0 / (1.0 - 40.0 / 400.0);
  check(damage("mpa.csv", "--sn FAT90 --mean-stress goodman --ultimate 400"), 50.0 / (2e6 * std::pow(90.0 / s_goodman, 3)), "Goodman, MPa");
  char ultimate_psi[32];
  std::snprintf(ultimate_psi, sizeof ultimate_psi, "%.17g", 400e6 / kPsi);
  check(damage("psi.csv", std::string("--sn FAT90 --mean-stress goodman --ultimate ") + ultimate_psi), 50.0 / (2e6 * std::pow(90.0 / s_goodman, 3)),
        "Goodman, psi");
  check(damage("mpa.csv", "--sn FAT90 --mean-stress none"), 50.0 / (2e6 * std::pow(0.9, 3)), "mean stress none");
  check(damage("mpa.csv", "--sn FAT90 --thickness 50"), 50.0 / (2e6 * std::pow(0.9 * std::pow(0.5, 0.3), 3)), "IIW thickness 50 mm");
  check(damage("mpa.csv", "--sn FAT90 --thickness 50 --thickness-exponent 0.2"), 50.0 / (2e6 * std::pow(0.9 * std::pow(0.5, 0.2), 3)), "IIW n = 0.2");
  check(damage("mpa.csv", "--sn FAT90 --thickness 20"), 50.0 / (2e6 * std::pow(0.9, 3)), "IIW 20 mm: no correction");
  check(damage("mpa.csv", "--sn EN90 --thickness 50"), 50.0 / (2e6 * std::pow(0.9 * std::pow(0.5, 0.2), 3)), "EN 1993-1-9 size effect");
  check(damage("mpa.csv", "--curve points:1e5:200,1e7:50"), 5e-5, "points");
  check(damage("mpa.csv", "--curve basquin:2e12:3"), 2.5e-5, "Basquin");
}

// S-N curve files (coupling/sn_curve_file.h) on the same 50 cycles of 100 MPa:
//  - reference 200 MPa at 1e5, m = 3 to the knee at 4e5, then m = 5: the knee's range
//    200 (1/4)^(1/3) = 125.99 MPa, so 100 MPa is on the m = 5 part: N = 4e5 (2 * 4^(-1/3))^5 = 1.26992e6;
//  - the same with one slope and a cut-off at 5e5 cycles (116.96 MPa): 100 MPa does no damage;
//  - the points 1e5:200, 1e7:50 (MPa) written in psi: N(100 MPa) = 1e6, D = 5e-5 as --curve points;
//  - Basquin C = 2e12 MPa^3 written in ksi (C / 6.894757^3): N(100 MPa) = 2e6, D = 2.5e-5;
//  - a point that does not fall: refused naming the file, line and key (STUDY-163).
TEST(RainflowCommand, CurveFilesGiveTheHandDamageInAnyStressUnit) {
  TempDir dir;
  std::ofstream(dir / "mpa.csv") << series("MPa", 1.0);
  int k = 0;
  const auto damage = [&](const std::string& curve_file, const std::string& text) {
    std::ofstream(dir / curve_file) << text;
    const std::string out = "curve_out" + std::to_string(k++);
    const auto r = framedyn(dir, "rainflow mpa.csv --curve " + curve_file + " --out " + out + " -q");
    EXPECT_EQ(r.status, 0) << curve_file << ": " << r.err;
    const nlohmann::json j = nlohmann::json::parse(read_file(dir / out / "summary.json"));
    return j["fatigue"]["damage"].get<double>();
  };
  const auto check = [&](double d, double expected, const std::string& what) {
    EXPECT_NEAR(d, expected, 1e-12 * std::max(expected, 1e-300)) << what;
    std::cout << "[ measured ] curve file, " << what << ": D = " << d << " (hand " << expected << ")\n";
  };
  const double n_knee = 4e5 * std::pow(2.0 * std::pow(4.0, -1.0 / 3.0), 5);
  check(damage("knee.yaml", "name: two slopes\nunits: MPa\nreference: {range: 200, cycles: 1e5}\nslopes: [3, 5]\nknees: [4e5]\ncut_off: 1e9\n"), 50.0 / n_knee,
        "m = 3/5, knee at 4e5");
  EXPECT_EQ(damage("cut.yaml", "name: cut off\nreference: {range: 200, cycles: 1e5}\nslopes: [3]\ncut_off: 5e5\n"), 0.0);
  char psi[160];
  std::snprintf(psi, sizeof psi, "name: in psi\nunits: psi\npoints: [[1e5, %.17g], [1e7, %.17g]]\n", 200e6 / kPsi, 50e6 / kPsi);
  check(damage("psi.yaml", psi), 5e-5, "points in psi");
  char ksi[160];
  std::snprintf(ksi, sizeof ksi, "name: in ksi\nunits: ksi\nbasquin: {C: %.17g, m: 3}\n", 2e12 / std::pow(kPsi * 1e3 / 1e6, 3));
  check(damage("ksi.yaml", ksi), 2.5e-5, "Basquin in ksi");
  std::ofstream(dir / "bad.yaml") << "name: bad\npoints:\n  - [1e5, 200]\n  - [1e7, 250]\n";
  const auto r = framedyn(dir, "rainflow mpa.csv --curve bad.yaml --out bad_out -q");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("bad.yaml:4: points[1]: expected N rising and S falling from the point before, found [1e+07, 250] after [100000, 200]"), std::string::npos) << r.err;
}

}  // namespace
