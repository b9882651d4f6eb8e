// Tests of the framedyn program as a user runs it: exit status, the files it
// writes, its messages, the whole-or-absent results folder, and determinism.
// The program is FRAMEDYN_BINARY; every run works in a fresh temp folder.
#include <gtest/gtest.h>

#include "tests/support/run_framedyn.h"
#include "tests/support/temp_dir.h"

#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace {

namespace fs = std::filesystem;

const fs::path kFrame = fs::path(FRAMEDYN_SOURCE_DIR) / "meshes" / "r100_frame.inp";

// A fresh directory per test (tests/support/temp_dir.h).
class TempDir : public framedyn::testing::TempDir {
 public:
  TempDir() : framedyn::testing::TempDir("framedyn_test_cli") {}
};

using framedyn::testing::entries_containing;
using framedyn::testing::framedyn;
using framedyn::testing::quote;
using framedyn::testing::read_file;
using framedyn::testing::RunResult;

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::string cur;
  std::istringstream in(s);
  while (std::getline(in, cur, sep)) out.push_back(cur);
  return out;
}

// A CSV file as header -> column, one map per row.
std::vector<std::map<std::string, std::string>> read_csv(const fs::path& p) {
  const std::vector<std::string> lines = split(read_file(p), '\n');
  std::vector<std::map<std::string, std::string>> rows;
  if (lines.empty()) return rows;
  const std::vector<std::string> header = split(lines[0], ',');
  for (std::size_t i = 1; i < lines.size(); ++i) {
    if (lines[i].empty()) continue;
    const std::vector<std::string> f = split(lines[i], ',');
    EXPECT_EQ(f.size(), header.size()) << p << " line " << i + 1;
    std::map<std::string, std::string> row;
    for (std::size_t k = 0; k < header.size() && k < f.size(); ++k) row[header[k]] = f[k];
    rows.push_back(row);
  }
  return rows;
}

// Every file of a results folder, name -> content.
std::map<std::string, std::string> folder_contents(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& e : fs::directory_iterator(dir)) files[e.path().filename().string()] = read_file(e.path());
  return files;
}

// A cantilever along x, clamped at node 1, tip loads in y and z at node 5.
constexpr double kL = 2.0, kA = 0.05, kB = 0.1, kE = 2.1e11, kNu = 0.3, kPy = 700.0, kPz = 1000.0;

std::string cantilever_deck(const std::string& type = "B31", double pz = kPz) {
  std::ostringstream d;
  d << "** units: m-N-s\n"
       "*HEADING\nCantilever for the CLI test\n"
       "*NODE, NSET=ALL\n"
       "1, 0, 0, 0\n2, 0.5, 0, 0\n3, 1.0, 0, 0\n4, 1.5, 0, 0\n5, 2.0, 0, 0\n"
       "*ELEMENT, TYPE="
    << type
    << ", ELSET=BEAM\n"
       "1, 1, 2\n2, 2, 3\n3, 3, 4\n4, 4, 5\n"
       "*BEAM SECTION, ELSET=BEAM, MATERIAL=STEEL, SECTION=RECT\n"
       "0.05, 0.1\n"
       "*MATERIAL, NAME=STEEL\n*ELASTIC\n2.1e11, 0.3\n*DENSITY\n7850\n"
       "*BOUNDARY\n1, ENCASTRE\n"
       "*STEP\n*STATIC\n"
       "*CLOAD\n5, 2, 700.\n5, 3, "
    << pz
    << "\n"
       "*NODE PRINT, NSET=ALL\nU\n"
       "*END STEP\n";
  return d.str();
}

// With framedyn's manifest of them (core/results_folder.h).
const std::vector<std::string> kStaticFiles = {"displacements.csv", "reactions.csv", "section_forces.csv", "static.vtu", "summary.json", ".framedyn-manifest"};
const std::vector<std::string> kModesFiles = {"summary.json", "modes.csv", "modes.xdmf", "modes.h5", ".framedyn-manifest"};  // the defaults

// ------------------------------------------------------------------ modes

TEST(Cli, ModesOfTheShippedFrame) {
  TempDir dir;
  const fs::path out = dir / "r100";
  const RunResult r = framedyn(dir, "modes " + quote(kFrame.string()) + " --modes 10 --mode-shapes-csv --paraview vtu --out " + quote(out.string()) + " -q");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");  // -q: no progress lines
  for (const char* f : {"summary.json", "modes.csv", "mode_shapes.csv", "modes.vtu", ".framedyn-manifest"}) EXPECT_TRUE(fs::is_regular_file(out / f)) << f;

  const nlohmann::json j = nlohmann::json::parse(read_file(out / "summary.json"));
  EXPECT_EQ(j.at("framedyn").at("command"), "modes");
  EXPECT_EQ(j.at("input").at("units"), "in-lbf-s");
  EXPECT_EQ(j.at("frame").at("nodes"), 51);
  EXPECT_EQ(j.at("frame").at("beam_elements"), 61);
  const auto& modes = j.at("frame").at("modes");
  ASSERT_EQ(modes.size(), 10u);
  double previous = -1.0;
  for (std::size_t i = 0; i < modes.size(); ++i) {
    SCOPED_TRACE("mode " + std::to_string(i + 1));
    const double f = modes[i].at("frequency").at("value").get<double>();
    EXPECT_EQ(modes[i].at("mode"), i + 1);
    if (i < 6) {
      EXPECT_EQ(f, 0.0);  // free-free: six rigid-body modes reported at 0 Hz
      EXPECT_TRUE(modes[i].at("rigid_body").get<bool>());
    } else {
      EXPECT_GT(f, 1.0);
      EXPECT_FALSE(modes[i].at("rigid_body").get<bool>());
      EXPECT_GE(f, previous);
    }
    previous = f;
  }

  const auto table = read_csv(out / "modes.csv");
  ASSERT_EQ(table.size(), 10u);
  for (std::size_t i = 0; i < 10; ++i) {
    EXPECT_EQ(table[i].at("mode"), std::to_string(i + 1));
    EXPECT_EQ(table[i].at("rigid_body"), i < 6 ? "yes" : "no");
    EXPECT_NEAR(std::stod(table[i].at("frequency [Hz]")), modes[i].at("frequency").at("value").get<double>(),
                1e-9 * std::max(1.0, modes[i].at("frequency").at("value").get<double>()));
  }
  EXPECT_EQ(read_csv(out / "mode_shapes.csv").size(), 10u * 51u);
  const std::string vtu = read_file(out / "modes.vtu");
  EXPECT_NE(vtu.find("<VTKFile"), std::string::npos);
  EXPECT_NE(vtu.find("mode_07_"), std::string::npos);
  EXPECT_TRUE(entries_containing(dir.path(), ".partial-").empty());
}

// By default: the ParaView output as XDMF + HDF5 (each mode a time step), no
// text table of the full shapes; --paraview none leaves ParaView out.
TEST(Cli, ModesWritesXdmfAndNoShapeTableByDefault) {
  TempDir dir;
  ASSERT_EQ(framedyn(dir, "modes " + quote(kFrame.string()) + " --modes 3 --out m -q").status, 0);
  std::vector<std::string> files;
  for (const auto& e : fs::directory_iterator(dir / "m")) files.push_back(e.path().filename().string());
  std::sort(files.begin(), files.end());
  EXPECT_EQ(files, (std::vector<std::string>{".framedyn-manifest", "modes.csv", "modes.h5", "modes.xdmf", "summary.json"}));
  const std::string xdmf = read_file(dir / "m" / "modes.xdmf");
  EXPECT_NE(xdmf.find("<Xdmf Version=\"3.0\""), std::string::npos);
  EXPECT_NE(xdmf.find("CollectionType=\"Temporal\""), std::string::npos);
  for (const char* t : {"<Time Value=\"1\" />", "<Time Value=\"2\" />", "<Time Value=\"3\" />"}) EXPECT_NE(xdmf.find(t), std::string::npos) << t;
  EXPECT_EQ(xdmf.find("<Time Value=\"4\" />"), std::string::npos);
  ASSERT_EQ(framedyn(dir, "modes " + quote(kFrame.string()) + " --modes 3 --paraview none --out n -q").status, 0);
  EXPECT_FALSE(fs::exists(dir / "n" / "modes.h5"));
  EXPECT_FALSE(fs::exists(dir / "n" / "modes.xdmf"));
  EXPECT_FALSE(fs::exists(dir / "n" / "modes.vtu"));
}

TEST(Cli, ModesTakesTheCountFromTheFrequencyStep) {
  TempDir dir;
  dir.write("frame.inp", "*INCLUDE, INPUT=" + kFrame.string() + "\n*STEP\n*FREQUENCY\n8\n*END STEP\n");
  const RunResult r = framedyn(dir, "modes frame.inp -q");
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(read_file(dir / "frame_modes" / "summary.json"));  // default folder name
  EXPECT_EQ(j.at("frame").at("modes").size(), 8u);
}

// ------------------------------------------------------------------ static

double cantilever_tip(const fs::path& out, const std::string& column) {
  for (const auto& row : read_csv(out / "displacements.csv"))
    if (row.at("node") == "5") return std::stod(row.at(column));
  ADD_FAILURE() << "no row for node 5";
  return 0.0;
}

TEST(Cli, StaticCantileverTipDeflectionB31) {
  TempDir dir;
  dir.write("cantilever.inp", cantilever_deck("B31"));
  const fs::path out = dir / "results";
  const RunResult r = framedyn(dir, "static cantilever.inp --out " + quote(out.string()) + " -q");
  ASSERT_EQ(r.status, 0) << r.err;
  for (const std::string& f : kStaticFiles) EXPECT_TRUE(fs::is_regular_file(out / f)) << f;

  // Default orientation n1 = -z: a (0.05) lies along z, b (0.1) along y.
  // Load along z bends about y: I = b a^3 / 12; load along y: I = a b^3 / 12.
  const double G = kE / (2 * (1 + kNu));
  const double k = 10 * (1 + kNu) / (12 + 11 * kNu);  // Cowper, rectangle
  const double As = k * kA * kB;
  const double Iz_bending = kB * kA * kA * kA / 12, Iy_bending = kA * kB * kB * kB / 12;
  const double wz = kPz * kL * kL * kL / (3 * kE * Iz_bending) + kPz * kL / (G * As);
  const double wy = kPy * kL * kL * kL / (3 * kE * Iy_bending) + kPy * kL / (G * As);
  EXPECT_NEAR(cantilever_tip(out, "uz [m]"), wz, 1e-9 * wz);
  EXPECT_NEAR(cantilever_tip(out, "uy [m]"), wy, 1e-9 * wy);
  EXPECT_NEAR(cantilever_tip(out, "ux [m]"), 0.0, 1e-12);

  // The support reacts with the opposite force.
  const auto reactions = read_csv(out / "reactions.csv");
  ASSERT_EQ(reactions.size(), 1u);
  EXPECT_EQ(reactions[0].at("node"), "1");
  EXPECT_NEAR(std::stod(reactions[0].at("fz [N]")), -kPz, 1e-6 * kPz);
  EXPECT_NEAR(std::stod(reactions[0].at("fy [N]")), -kPy, 1e-6 * kPy);
  EXPECT_NEAR(std::stod(reactions[0].at("my [N*m]")), kPz * kL, 1e-6 * kPz * kL);

  const auto sections = read_csv(out / "section_forces.csv");
  EXPECT_EQ(sections.size(), 4u * 3u);  // 4 elements, 3 stations
  // At the root (element 1, station 0): Pz bends about local 2 (a along n1 = -z), Py about local 1 (b along n2 = +y).
  // Corners: sigma = Py L (b/2) / I11 + Pz L (a/2) / I22 and no shear; mid-sides: one moment's stress with 1.5 V / A
  // (fem/section_stress.h); von_mises_max is the largest of these, shear_max 1.5 max(Py, Pz) / A.
  {
    const double i11 = kA * kB * kB * kB / 12, i22 = kB * kA * kA * kA / 12, area = kA * kB;
    const double corner = kPy * kL * (kB / 2) / i11 + kPz * kL * (kA / 2) / i22;
    const double side_y = std::hypot(kPz * kL * (kA / 2) / i22, std::sqrt(3.0) * 1.5 * kPy / area);  // sides x1 = +-a/2
    const double side_z = std::hypot(kPy * kL * (kB / 2) / i11, std::sqrt(3.0) * 1.5 * kPz / area);  // sides x2 = +-b/2
    const double von_mises = std::max({corner, side_y, side_z});
    ASSERT_EQ(sections[0].at("element"), "1");
    ASSERT_EQ(sections[0].at("station"), "0");
    EXPECT_NEAR(std::stod(sections[0].at("von_mises_max [Pa]")), von_mises, 1e-6 * von_mises);
    EXPECT_NEAR(std::stod(sections[0].at("shear_max [Pa]")), 1.5 * kPz / area, 1e-6 * 1.5 * kPz / area);
  }
  const nlohmann::json j = nlohmann::json::parse(read_file(out / "summary.json"));
  EXPECT_EQ(j.at("framedyn").at("command"), "static");
  EXPECT_EQ(j.at("frame").at("max_displacement").at("node"), 5);
  EXPECT_NEAR(j.at("frame").at("applied_force_sum").at("value")[2].get<double>(), kPz, 1e-9);
  EXPECT_NE(read_file(out / "static.vtu").find("<VTKFile"), std::string::npos);
}

TEST(Cli, StaticCantileverTipDeflectionB33) {
  TempDir dir;
  dir.write("cantilever.inp", cantilever_deck("B33"));
  const RunResult r = framedyn(dir, "static cantilever.inp --out res -q");
  ASSERT_EQ(r.status, 0) << r.err;
  const double wz = kPz * kL * kL * kL / (3 * kE * (kB * kA * kA * kA / 12));
  EXPECT_NEAR(cantilever_tip(dir / "res", "uz [m]"), wz, 1e-9 * wz);
}

// Two static steps (theory section 18): the second replaces the z load by
// 300 N (OP=MOD on the same DOF) and keeps the y load; each step's files
// carry its number, and each step's tip deflection is the B33 hand formula.
TEST(Cli, StaticWritesEachStepOfAMultiStepDeck) {
  TempDir dir;
  dir.write("cantilever.inp", cantilever_deck("B33") + "*STEP\n*STATIC\n*CLOAD\n5, 3, 300.\n*END STEP\n");
  const RunResult r = framedyn(dir, "static cantilever.inp --out res -q");
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char* f : {"summary_step1.json", "displacements_step2.csv", "reactions_step2.csv", "section_forces_step1.csv", "static_step2.vtu"})
    EXPECT_TRUE(fs::is_regular_file(dir / "res" / f)) << f;
  EXPECT_FALSE(fs::exists(dir / "res" / "summary.json"));
  const double i_z = kB * kA * kA * kA / 12, i_y = kA * kB * kB * kB / 12;
  for (const auto& [step, pz] : std::vector<std::pair<int, double>>{{1, kPz}, {2, 300.0}}) {
    double uz = 0.0, uy = 0.0;
    for (const auto& row : read_csv(dir / "res" / ("displacements_step" + std::to_string(step) + ".csv")))
      if (row.at("node") == "5") uz = std::stod(row.at("uz [m]")), uy = std::stod(row.at("uy [m]"));
    const double wz = pz * kL * kL * kL / (3 * kE * i_z), wy = kPy * kL * kL * kL / (3 * kE * i_y);
    EXPECT_NEAR(uz, wz, 1e-9 * wz) << "step " << step;
    EXPECT_NEAR(uy, wy, 1e-9 * wy) << "step " << step;
    const nlohmann::json j = nlohmann::json::parse(read_file(dir / "res" / ("summary_step" + std::to_string(step) + ".json")));
    EXPECT_EQ(j.at("input").at("step"), step);
  }
}

// The mesh reader's warnings (fem::FrameModel::reader_warnings) reach the
// summary.json of every command that reads a deck, and stderr once: a CIRC
// section read without --inp-dialect is warned (circ_radius_or_diameter,
// naming the set and the option); with a dialect there is nothing to warn.
TEST(Cli, ACircSectionReadWithoutADialectIsWarnedInTheSummaryOfEveryDeckCommand) {
  TempDir dir;
  std::string deck = cantilever_deck("B33");
  const std::string rect = "SECTION=RECT\n0.05, 0.1\n";
  deck.replace(deck.find(rect), rect.size(), "SECTION=CIRC\n0.03\n");
  dir.write("circ.inp", deck);
  dir.write("psd.csv", "frequency [Hz],psd [1/Hz]\n2,0.001\n400,0.001\n");
  const std::vector<std::pair<std::string, std::string>> commands = {{"static", ""},
                                                                     {"modes", " --modes 4"},
                                                                     {"harmonic", " -f 1:100:5 -z 0.02 --no-figures"},
                                                                     {"random", " --psd psd.csv -z 0.02 --no-figures"}};
  for (const auto& [command, options] : commands) {
    const RunResult plain = framedyn(dir, command + " circ.inp" + options + " --out plain_" + command);
    ASSERT_EQ(plain.status, 0) << command << ": " << plain.err;
    const nlohmann::json w = nlohmann::json::parse(read_file(dir / ("plain_" + command) / "summary.json"))["warnings"];
    ASSERT_EQ(w.size(), 1u) << command << ": " << w.dump();
    EXPECT_EQ(w[0]["code"], "circ_radius_or_diameter") << command;
    const std::string message = w[0]["message"];
    EXPECT_NE(message.find("circ.inp:"), std::string::npos) << message;
    EXPECT_NE(message.find("ELSET BEAM"), std::string::npos) << message;
    EXPECT_NE(message.find("give --inp-dialect abaqus or calculix"), std::string::npos) << message;
    EXPECT_EQ(w[0]["figures"]["radius_read"]["value"], 0.03) << command;
    EXPECT_EQ(w[0]["figures"]["radius_calculix"]["value"], 0.015) << command;
    // On stderr once: read, not again when written.
    std::size_t printed = 0;
    for (std::size_t at = plain.err.find("warning [circ_radius_or_diameter]"); at != std::string::npos;
         at = plain.err.find("warning [circ_radius_or_diameter]", at + 1))
      ++printed;
    EXPECT_EQ(printed, 1u) << command << ": " << plain.err;
  }
  // Told the dialect, there is nothing to warn (one command: the reader is the same for all).
  const RunResult told = framedyn(dir, "static circ.inp --inp-dialect calculix --out told");
  ASSERT_EQ(told.status, 0) << told.err;
  EXPECT_EQ(nlohmann::json::parse(read_file(dir / "told" / "summary.json"))["warnings"], nlohmann::json::array());
  EXPECT_EQ(told.err.find("circ_radius_or_diameter"), std::string::npos) << told.err;
}

// framedyn transient's section-force history and ParaView series
// (docs/theory/fem.md section 24). A 100 kg tip mass on a 2 m cantilever
// whose beam weighs 7.85e-5 kg (density 7.85e-3 kg/m^3): a one-degree-of-
// freedom oscillator along z, omega^2 = 3 E I / L^3 / (M + 33/140 m_beam).
// Under a tip load P switched on at t = 0 and held, the tip moves u_st (1 -
// cos omega t), and the beam, whose own inertia is 7.85e-7 of the mass's,
// carries k u(t) at its tip: the root's bending moment is P L (1 - cos
// omega t), 2 P L at t = T/2, and the shear at the root P (1 - cos omega t).
TEST(Cli, TransientRootMomentOfAStepLoadedTipMassIsPLTimesOneMinusCosOmegaT) {
  TempDir dir;
  constexpr double kMass = 100.0, kDensity = 7.85e-3, kP = 1000.0;
  const double i_z = kA * kB * kB * kB / 12.0, m_beam = kDensity * kA * kB * kL;
  const double omega = std::sqrt(3.0 * kE * i_z / (kL * kL * kL) / (kMass + 33.0 / 140.0 * m_beam)), period = 2.0 * M_PI / omega;
  std::string deck = cantilever_deck("B33");
  deck = deck.substr(0, deck.find("*STEP"));  // the model data, without its static step
  deck.replace(deck.find("*DENSITY\n7850"), 13, "*DENSITY\n0.00785");
  deck.replace(deck.find("0.05, 0.1\n"), 10, "0.05, 0.1\n0, 1, 0\n");  // n1 = y: local 2 = z, depth b = 0.1
  char steps[512];
  std::snprintf(steps, sizeof steps,
                "*ELEMENT, TYPE=MASS, ELSET=TIPMASS\n100, 5\n*MASS, ELSET=TIPMASS\n%.17g\n*AMPLITUDE, NAME=STEP\n0, 1, 1, 1\n"
                "*STEP\n*FREQUENCY\n2\n*END STEP\n*STEP\n*MODAL DYNAMIC\n%.17g, %.17g\n*CLOAD, AMPLITUDE=STEP\n5, 3, %.17g\n*END STEP\n",
                kMass, period / 100.0, period, kP);
  dir.write("tip_mass.inp", deck + steps);
  const RunResult r = framedyn(dir, "transient tip_mass.inp --element-set beam --out res");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto rows = read_csv(dir / "res" / "section_force_history.csv");
  ASSERT_EQ(rows.size(), 101u * 4 * 2);  // 101 output times, 4 elements, 2 ends
  double worst_moment = 0.0, worst_shear = 0.0;
  int root_rows = 0;
  for (const auto& row : rows) {
    if (row.at("element") != "1" || row.at("end") != "1") continue;
    ++root_rows;
    const double t = std::stod(row.at("time [s]")), exact = 1.0 - std::cos(omega * t);
    worst_moment = std::max(worst_moment, std::abs(std::hypot(std::stod(row.at("My [N*m]")), std::stod(row.at("Mz [N*m]"))) - kP * kL * exact));
    worst_shear = std::max(worst_shear, std::abs(std::hypot(std::stod(row.at("Vy [N]")), std::stod(row.at("Vz [N]"))) - kP * exact));
  }
  EXPECT_EQ(root_rows, 101);
  EXPECT_LT(worst_moment, 1e-6 * kP * kL);
  EXPECT_LT(worst_shear, 1e-6 * kP);
  // The summary's peak: 2 P L at the root at T/2 (the output time 50 of 100).
  const nlohmann::json peak = nlohmann::json::parse(read_file(dir / "res" / "summary.json"))["frame"]["transient"]["max_bending_moment"];
  EXPECT_NEAR(peak["value"].get<double>(), 2.0 * kP * kL, 1e-6 * kP * kL);
  EXPECT_EQ(peak["unit"], "N*m");
  EXPECT_EQ(peak["element"], 1);
  EXPECT_EQ(peak["end"], 1);
  EXPECT_NEAR(peak["time"].get<double>(), period / 2.0, 1e-9 * period);
  // The ParaView series: one grid per output time, the displacement and rotation per node and the twelve end forces per element.
  const std::string xdmf = read_file(dir / "res" / "transient.xdmf");
  EXPECT_NE(xdmf.find("CollectionType=\"Temporal\""), std::string::npos);
  std::size_t grids = 0;
  for (std::size_t at = xdmf.find("<Time Value="); at != std::string::npos; at = xdmf.find("<Time Value=", at + 1)) ++grids;
  EXPECT_EQ(grids, 101u);
  for (const char* field : {"displacement [m]", "rotation [rad]", "N_end1 [N]", "Mz_end2 [N*m]"}) EXPECT_NE(xdmf.find(field), std::string::npos) << field;
  EXPECT_GT(fs::file_size(dir / "res" / "transient.h5"), 8u * 101 * (5 * 6 + 4 * 12));  // every value stored, 8 bytes each
  EXPECT_NE(r.out.find("max bending moment"), std::string::npos) << r.out;
  // --paraview none: no series; an element set without beams is refused.
  ASSERT_EQ(framedyn(dir, "transient tip_mass.inp --paraview none --out bare -q").status, 0);
  EXPECT_FALSE(fs::exists(dir / "bare" / "transient.xdmf"));
  EXPECT_FALSE(fs::exists(dir / "bare" / "transient.h5"));
  const RunResult massless = framedyn(dir, "transient tip_mass.inp --element-set TIPMASS --out none -q");
  EXPECT_EQ(massless.status, 1);
  EXPECT_NE(massless.err.find("found 'TIPMASS' (no beam elements)"), std::string::npos) << massless.err;
}

TEST(Cli, StaticWithUnitsOption) {
  TempDir dir;
  std::string deck = cantilever_deck();
  deck.erase(0, deck.find('\n') + 1);  // drop the "** units:" line
  dir.write("nounits.inp", deck);
  const RunResult missing = framedyn(dir, "static nounits.inp --out a -q");
  EXPECT_EQ(missing.status, 1);
  EXPECT_NE(missing.err.find("error:"), std::string::npos);
  EXPECT_NE(missing.err.find("nounits.inp: units"), std::string::npos) << missing.err;
  const RunResult given = framedyn(dir, "static nounits.inp --units SI --out b -q");
  ASSERT_EQ(given.status, 0) << given.err;
  const nlohmann::json j = nlohmann::json::parse(read_file(dir / "b" / "summary.json"));
  EXPECT_EQ(j.at("input").at("units"), "m-N-s");
}

// ------------------------------------------------------------------ help

TEST(Cli, HelpOfEachSubcommand) {
  TempDir dir;
  const std::map<std::string, std::vector<std::string>> options = {
      {"modes", {"mesh", "--modes", "--out", "--units", "--lumped", "--shift", "--verbose", "--quiet", "--help"}},
      {"static", {"mesh", "--out", "--stations", "--units", "--verbose", "--quiet", "--help"}},
  };
  for (const auto& [command, names] : options) {
    SCOPED_TRACE(command);
    const RunResult r = framedyn(dir, command + " --help");
    EXPECT_EQ(r.status, 0) << r.err;
    for (const std::string& n : names) EXPECT_NE(r.out.find(n), std::string::npos) << n << " not in:\n" << r.out;
  }
  const RunResult top = framedyn(dir, "--help");
  EXPECT_EQ(top.status, 0);
  EXPECT_NE(top.out.find("modes"), std::string::npos);
  EXPECT_NE(top.out.find("static"), std::string::npos);
  EXPECT_TRUE(fs::is_empty(dir.path()));  // --help writes nothing
}

TEST(Cli, UnknownOptionAndMissingSubcommandFail) {
  TempDir dir;
  EXPECT_NE(framedyn(dir, "").status, 0);
  EXPECT_NE(framedyn(dir, "modes " + quote(kFrame.string()) + " --no-such-option").status, 0);
  EXPECT_NE(framedyn(dir, "static").status, 0);  // mesh is required
  EXPECT_TRUE(fs::is_empty(dir.path()));
}

// ------------------------------------------------------------------ errors and results folders

TEST(Cli, BadMeshFailsWithFileAndLineAndLeavesNoFolder) {
  TempDir dir;
  std::string deck = cantilever_deck();
  const std::string bad = "*ELEMENT, TYPE=C3D8\n";
  deck += bad + "9, 1, 2, 3, 4, 5, 1, 2, 3\n";
  dir.write("bad.inp", deck);
  int line = 0;
  {
    std::istringstream in(deck);
    std::string l;
    for (int n = 1; std::getline(in, l); ++n)
      if (l + "\n" == bad) line = n;
  }
  ASSERT_GT(line, 0);
  for (const std::string command : {"modes", "static"}) {
    SCOPED_TRACE(command);
    const RunResult r = framedyn(dir, command + " bad.inp --out results -q");
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.err.find("error:"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("bad.inp:" + std::to_string(line) + ": *ELEMENT"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("C3D8"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "results"));
    EXPECT_FALSE(fs::exists(dir / "bad_modes"));
    EXPECT_FALSE(fs::exists(dir / "bad_static"));
    EXPECT_TRUE(entries_containing(dir.path(), ".partial-").empty());
  }
  // A missing mesh file too.
  const RunResult missing = framedyn(dir, "modes nothere.inp --out results");
  EXPECT_EQ(missing.status, 1);
  EXPECT_NE(missing.err.find("nothere.inp"), std::string::npos) << missing.err;
  EXPECT_FALSE(fs::exists(dir / "results"));
}

TEST(Cli, SameRunTwiceGivesIdenticalFiles) {
  TempDir dir;
  dir.write("cantilever.inp", cantilever_deck());
  ASSERT_EQ(framedyn(dir, "static cantilever.inp --out s1 -q").status, 0);
  ASSERT_EQ(framedyn(dir, "static cantilever.inp --out s2 -q").status, 0);
  const auto s1 = folder_contents(dir / "s1"), s2 = folder_contents(dir / "s2");
  EXPECT_EQ(s1.size(), kStaticFiles.size());
  EXPECT_TRUE(s1 == s2) << "static results differ between two runs";

  const std::string mesh = quote(kFrame.string());
  ASSERT_EQ(framedyn(dir, "modes " + mesh + " --modes 10 --out m1 -q").status, 0);
  ASSERT_EQ(framedyn(dir, "modes " + mesh + " --modes 10 --out m2 -q").status, 0);
  const auto m1 = folder_contents(dir / "m1"), m2 = folder_contents(dir / "m2");
  EXPECT_EQ(m1.size(), kModesFiles.size());
  for (const auto& [name, content] : m1) {
    ASSERT_EQ(m2.count(name), 1u) << name;
    EXPECT_TRUE(content == m2.at(name)) << name << " differs between two runs";
  }
  // Rerunning into the same folder replaces it with the same bytes.
  ASSERT_EQ(framedyn(dir, "modes " + mesh + " --modes 10 --out m1 -q").status, 0);
  EXPECT_TRUE(folder_contents(dir / "m1") == m1);
}

TEST(Cli, FailingRunLeavesTheOldResultsUntouched) {
  TempDir dir;
  dir.write("good.inp", cantilever_deck());
  ASSERT_EQ(framedyn(dir, "static good.inp --out results -q").status, 0);
  const auto before = folder_contents(dir / "results");

  // Bad input: exit 1.
  dir.write("bad.inp", cantilever_deck() + "*CLOAD\n5, 9, 1.0\n");
  const RunResult bad = framedyn(dir, "static bad.inp --out results -q");
  EXPECT_EQ(bad.status, 1);
  EXPECT_TRUE(folder_contents(dir / "results") == before);

  // No supports and a load that accelerates the frame: refused as bad input
  // (exit 1) naming the rigid motion the load drives (docs/theory/fem.md, Eq. 19.1).
  std::string loose = cantilever_deck();
  loose.replace(loose.find("*BOUNDARY\n1, ENCASTRE\n"), std::string("*BOUNDARY\n1, ENCASTRE\n").size(), "");
  dir.write("loose.inp", loose);
  const RunResult mech = framedyn(dir, "static loose.inp --out results -q");
  EXPECT_EQ(mech.status, 1) << mech.err;
  EXPECT_NE(mech.err.find("6 free rigid motions): the loads drive its"), std::string::npos) << mech.err;
  EXPECT_TRUE(folder_contents(dir / "results") == before);

  // Modes that fail on input into the same folder leave it too.
  EXPECT_EQ(framedyn(dir, "modes bad.inp --out results -q").status, 1);
  EXPECT_TRUE(folder_contents(dir / "results") == before);
  EXPECT_TRUE(entries_containing(dir.path(), ".partial-").empty());

  // A successful run replaces the whole folder.
  dir.write("other.inp", cantilever_deck("B31", 2000.0));
  ASSERT_EQ(framedyn(dir, "static other.inp --out results -q").status, 0);
  const auto after = folder_contents(dir / "results");
  EXPECT_EQ(after.size(), kStaticFiles.size());
  EXPECT_NE(after.at("displacements.csv"), before.at("displacements.csv"));
  EXPECT_TRUE(entries_containing(dir.path(), ".partial-").empty());
  EXPECT_TRUE(entries_containing(dir.path(), ".old-").empty());

  // A file of the user's in the folder: the run is refused, the folder kept whole.
  dir.write("results/my_notes.txt", "never deleted by framedyn\n");
  const auto with_notes = folder_contents(dir / "results");
  const RunResult refused = framedyn(dir, "static good.inp --out results -q");
  EXPECT_EQ(refused.status, 1);
  EXPECT_NE(refused.err.find("my_notes.txt"), std::string::npos) << refused.err;
  EXPECT_TRUE(folder_contents(dir / "results") == with_notes);
}

}  // namespace
