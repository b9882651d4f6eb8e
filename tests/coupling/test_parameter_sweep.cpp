// Parameter sweeps (coupling/parameter_sweep.h) and `framedyn sweep`: a sweep
// is nothing but run_rigid_study with one parameter set by hand, whatever the
// number of threads; the soil damping leaves the undamped natural frequencies
// alone but changes the response; bad requests are input errors; the program
// writes sweep.csv, summary.json and the figures.
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

#include "core/error.h"
#include "report/plot.h"
#include "coupling/parameter_sweep.h"
#include "coupling/rigid_study.h"
#include "tests/support/temp_dir.h"

namespace framedyn {
namespace {

namespace fs = std::filesystem;
using core::Quantity;

const std::string kPlowStudy = FRAMEDYN_SOURCE_DIR "/examples/r100_plow_2d.yaml";

// lbf*s/in of the study file into SI, as the reader and `framedyn sweep` convert them.
double damping_si(const coupling::RigidStudy& s, double v) { return s.units.to_si(v, Quantity::translational_damping); }

void expect_same(const coupling::SweepPoint& p, const coupling::RigidResults& r) {
  ASSERT_TRUE(r.plow_vertical_peak_to_peak && r.peak_cutting_force && r.peak_backing_force);
  ASSERT_TRUE(p.plow_vertical_pp && p.peak_cutting_force && p.peak_backing_force);
  // Exact: the same computation on the same data, on whichever thread.
  EXPECT_EQ(*p.plow_vertical_pp, *r.plow_vertical_peak_to_peak);
  EXPECT_EQ(*p.peak_cutting_force, *r.peak_cutting_force);
  EXPECT_EQ(*p.peak_backing_force, *r.peak_backing_force);
  ASSERT_EQ(p.frequencies_hz.size(), r.modes.size());
  for (std::size_t m = 0; m < r.modes.size(); ++m) {
    EXPECT_EQ(p.frequencies_hz[m], r.modes[m].frequency_hz);
    EXPECT_EQ(p.dominant[m], r.modes[m].dominant);
  }
}

TEST(ParameterSweep, SoilDampingSweepEqualsSeparateRunsWithTheParameterSetByHand) {
  const coupling::RigidStudy study = coupling::read_rigid_study(kPlowStudy);
  const std::vector<double> values = {damping_si(study, 200), damping_si(study, 400)};
  const coupling::SweepResult s = coupling::run_parameter_sweep(study, "soil.damping", values, 2);
  EXPECT_EQ(s.parameter, "soil.damping");
  EXPECT_EQ(s.quantity, Quantity::translational_damping);
  ASSERT_EQ(s.points.size(), 2u);
  for (std::size_t i = 0; i < values.size(); ++i) {
    coupling::RigidStudy by_hand = study;
    coupling::set_parameter(by_hand.machine, "soil.damping", values[i]);
    SCOPED_TRACE(i);
    EXPECT_EQ(s.points[i].value, values[i]);
    expect_same(s.points[i], coupling::run_rigid_study(by_hand));
  }
  // The study's own C5 = 300 is not among the values: run on its own as the reference.
  EXPECT_EQ(s.reference_index, -1);
  EXPECT_EQ(s.reference.value, damping_si(study, 300));
  expect_same(s.reference, coupling::run_rigid_study(study));
}

TEST(ParameterSweep, ThreadsGiveTheSameResultsAsASequentialSweep) {
  const coupling::RigidStudy study = coupling::read_rigid_study(kPlowStudy);
  std::vector<double> values;
  for (double c : {100, 200, 300, 400, 500}) values.push_back(damping_si(study, c));
  const coupling::SweepResult one = coupling::run_parameter_sweep(study, "soil.damping", values, 1);
  const coupling::SweepResult two = coupling::run_parameter_sweep(study, "soil.damping", values, 2);
  const coupling::SweepResult many = coupling::run_parameter_sweep(study, "soil.damping", values, 8);
  for (const coupling::SweepResult* other : {&two, &many}) {
    ASSERT_EQ(other->points.size(), one.points.size());
    for (std::size_t i = 0; i < one.points.size(); ++i) {
      EXPECT_EQ(other->points[i].plow_vertical_pp, one.points[i].plow_vertical_pp) << i;
      EXPECT_EQ(other->points[i].peak_cutting_force, one.points[i].peak_cutting_force) << i;
      EXPECT_EQ(other->points[i].peak_backing_force, one.points[i].peak_backing_force) << i;
      EXPECT_EQ(other->points[i].frequencies_hz, one.points[i].frequencies_hz) << i;
    }
  }
}

TEST(ParameterSweep, SoilDampingChangesTheResponseButNotTheNaturalFrequencies) {
  // The modes are those of M and K; C5 is in C only. The response, driven at
  // 18.33 Hz through the soil, does feel C5 (thesis: plowing is mainly
  // velocity-dependent), so the C5 sweep must move the amplitude and forces.
  const coupling::RigidStudy study = coupling::read_rigid_study(kPlowStudy);
  const coupling::SweepResult s =
      coupling::run_parameter_sweep(study, "soil.damping", {damping_si(study, 100), damping_si(study, 300), damping_si(study, 500)}, 2);
  ASSERT_EQ(s.reference_index, 1);
  EXPECT_EQ(s.points[0].frequencies_hz, s.points[1].frequencies_hz);
  EXPECT_EQ(s.points[2].frequencies_hz, s.points[1].frequencies_hz);
  EXPECT_EQ(coupling::relative_change(s.points[1].plow_vertical_pp, s.reference.plow_vertical_pp), 0.0);
  EXPECT_GT(std::abs(*coupling::relative_change(s.points[0].plow_vertical_pp, s.reference.plow_vertical_pp)), 0.01);
  EXPECT_GT(std::abs(*coupling::relative_change(s.points[2].peak_backing_force, s.reference.peak_backing_force)), 0.01);
}

TEST(ParameterSweep, SoilStiffnessRaisesTheSoilModes) {
  // K5 stiffens the plow on the ground: no natural frequency may fall as K5 rises.
  // The modes are those of the state the response cuts in (docs/theory/rigid.md
  // section 11), so the sweep is made in Eq. 2.37's printed reading, where a
  // cutting blade is held by K5 (the shipped cut-face reading has no spring
  // while cutting: SoilReference.CutFaceResponseAndModesAreIndependentOfK5).
  coupling::RigidStudy study = coupling::read_rigid_study(kPlowStudy);
  study.machine.soil.cut_face = false;
  study.machine.soil.spring_from_contact = false;
  study.machine.soil.contact_moves_with_soil = false;
  const double f = study.units.to_si_factor(Quantity::translational_stiffness);
  const coupling::SweepResult s = coupling::run_parameter_sweep(study, "soil.stiffness", {20000 * f, 60000 * f}, 2);
  ASSERT_EQ(s.points[0].frequencies_hz.size(), s.points[1].frequencies_hz.size());
  bool one_rises = false;
  for (std::size_t m = 0; m < s.points[0].frequencies_hz.size(); ++m) {
    EXPECT_GE(s.points[1].frequencies_hz[m], s.points[0].frequencies_hz[m]) << "mode " << m + 1;
    one_rises = one_rises || s.points[1].frequencies_hz[m] > 1.05 * s.points[0].frequencies_hz[m];
  }
  EXPECT_TRUE(one_rises);
}

TEST(ParameterSweep, BadRequestsAreInputErrors) {
  const coupling::RigidStudy study = coupling::read_rigid_study(kPlowStudy);
  const auto expect_error = [&](const std::string& parameter, const std::vector<double>& values, const std::string& text) {
    try {
      (void)coupling::run_parameter_sweep(study, parameter, values);
      ADD_FAILURE() << "no error for " << text;
    } catch (const core::InputError& e) {
      EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
    }
  };
  expect_error("soil.viscosity", {1.0}, "--parameter: expected one of");
  expect_error("soil.viscosity", {1.0}, "soil.damping");  // the list names what can be swept
  expect_error("soil.damping", {}, "--values: expected at least one value");
  expect_error("soil.damping", {-1.0}, "finite non-negative values");
  coupling::RigidStudy no_response = study;
  no_response.response.reset();
  EXPECT_THROW((void)coupling::run_parameter_sweep(no_response, "soil.damping", {1.0}), core::InputError);
}

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
