// `framedyn rainflow` as a user runs it (docs/validation.md V14.7): a strain-gauge history in
// MPa and the same history in psi give the same cycles and the same damage, equal to n / N from
// the S-N curve; the outputs carry the series' unit; the repeated-block option closes the count.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
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

}  // namespace
