// Frame transient studies on a mesh that is not the trencher frame: a
// cantilever clamped by the name of its root node set, loaded at its tip,
// with the tip's nodal history and the root element's section forces as
// output sets, checked against the closed-form modal series of an
// Euler-Bernoulli cantilever (Clough & Penzien, Dynamics of Structures,
// ch. 18; Blevins, Formulas for Natural Frequency and Mode Shape, table 8-1).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iostream>

#include "core/error.h"
#include "core/results_folder.h"
#include "coupling/frame_study.h"
#include "report/frame_outputs.h"
#include "tests/support/temp_dir.h"

namespace {

using namespace framedyn;
constexpr double kPi = 3.14159265358979323846;

// Steel cantilever along X: L = 1 m, 20 B33 elements (Euler-Bernoulli, no
// rotary inertia: the theory the closed forms use), 20 mm square section.
constexpr double kL = 1.0, kE = 2.1e11, kRho = 7850.0, kSide = 0.02;
constexpr double kArea = kSide * kSide, kI = kSide * kSide * kSide * kSide / 12.0;
constexpr int kElements = 20;

std::string cantilever_inp(bool with_boundary = false) {
  std::string t = "** units: m-N-s\n*NODE, NSET=ALL_NODES\n";
  for (int i = 0; i <= kElements; ++i) t += std::to_string(i + 1) + ", " + std::to_string(kL * i / kElements) + ", 0, 0\n";
  t += "*ELEMENT, TYPE=B33, ELSET=BEAM\n";
  for (int e = 1; e <= kElements; ++e) t += std::to_string(e) + ", " + std::to_string(e) + ", " + std::to_string(e + 1) + "\n";
  t += "*ELSET, ELSET=ROOT_ELEMENT\n1\n*NSET, NSET=ROOT\n1\n*NSET, NSET=TIP\n" + std::to_string(kElements + 1) + "\n";
  t += "*BEAM SECTION, ELSET=BEAM, MATERIAL=STEEL, SECTION=RECT\n0.02, 0.02\n0, 0, -1\n";
  t += "*MATERIAL, NAME=STEEL\n*ELASTIC\n2.1e11, 0.3\n*DENSITY\n7850\n";
  if (with_boundary) t += "*BOUNDARY\n1, ENCASTRE\n";
  return t;
}

// A load FZ(t) = P f(t) at the tip (point TIP at the tip node), rows every dt to t_end.
std::string tip_load(double p, double dt, double t_end, double (*f)(double)) {
  coupling::LoadHistory h;
  const int n = static_cast<int>(std::lround(t_end / dt)) + 1;
  h.times = Eigen::VectorXd::LinSpaced(n, 0.0, (n - 1) * dt);
  coupling::LoadPointHistory tip;
  tip.name = "TIP";
  tip.location = Eigen::Vector3d(kL, 0.0, 0.0);
  tip.values = Eigen::MatrixXd::Zero(n, 6);
  for (int k = 0; k < n; ++k) tip.values(k, 2) = p * f(h.times(k));
  h.points.push_back(tip);
  return coupling::format_load_history(h, core::UnitSystem::si());
}

std::string study(const std::string& block) {
  return "framedyn_study: 1\nname: cantilever\nunits: m-N-s\nmodel: frame_transient\nframe:\n  mesh: cantilever.inp\n  loads: loads.csv\n" + block;
}

// beta_i L of the clamped-free beam (roots of 1 + cos x cosh x = 0); (2i - 1) pi / 2 beyond the fourth to 1e-7.
double beta_l(int i) {
  static const double roots[4] = {1.875104068711961, 4.694091132974175, 7.854757438237613, 10.99554073487547};
  return i <= 4 ? roots[i - 1] : (2 * i - 1) * kPi / 2;
}
// omega_i = (beta_i L)^2 sqrt(EI / (rho A L^4)).
double omega(int i) { return beta_l(i) * beta_l(i) * std::sqrt(kE * kI / (kRho * kArea)) / (kL * kL); }
// Share of the static tip deflection P L^3 / (3 EI) that mode i carries: with
// the shapes normalised to integral phi^2 = L, phi_i(L) = 2 and the share is
// P phi(L)^2 / (rho A L omega_i^2) / (P L^3 / 3 EI) = 12 / (beta_i L)^4; the shares sum to 1.
double share(int i) { return 12.0 / std::pow(beta_l(i), 4); }

// Response of q'' + w^2 q = w^2 f(t) to the ramped step f = min(t / tau, 1), from rest:
// r(t) and its first two derivatives (Duhamel's integral of the ramp and of the ramp delayed by tau).
struct Ramp {
  double r, dr, ddr;
};
Ramp ramp_response(double w, double tau, double t) {
  if (t <= tau) return {t / tau - std::sin(w * t) / (w * tau), (1.0 - std::cos(w * t)) / tau, w * std::sin(w * t) / tau};
  return {1.0 - (std::sin(w * t) - std::sin(w * (t - tau))) / (w * tau), -(std::cos(w * t) - std::cos(w * (t - tau))) / tau,
          w * (std::sin(w * t) - std::sin(w * (t - tau))) / tau};
}

constexpr double kP = 100.0;                                     // N
const double kStatic = kP * kL * kL * kL / (3.0 * kE * kI);      // PL^3 / 3EI, m
const double kT1 = 2 * kPi / omega(1);                           // s
const double kTau = kT1 / 20;                                    // ramp time of the "step"
double ramped_step(double t) { return std::min(t / kTau, 1.0); }

class CantileverStudy : public ::testing::Test {
 protected:
  framedyn::testing::TempDir dir;
  void SetUp() override {
    dir.write("cantilever.inp", cantilever_inp());
    dir.write("loads.csv", tip_load(kP, kT1 / 120, 2 * kT1, ramped_step));
  }
  coupling::FrameStudyRequest request(const std::string& block) { return coupling::read_frame_study(dir.write("s.yaml", study(block)).string()); }
};

TEST_F(CantileverStudy, StepTipLoadOscillatesAboutStaticDeflectionWithTwiceItsPeakAsTheModalSeries) {
  const auto q = request("  supports: clamped\n  support_set: ROOT\n  modes: all\n  method: mode_acceleration\n  damping: {modal_ratio: 0.0}\n"
                         "  outputs:\n    tip: {node_set: TIP}\n");
  const auto r = coupling::run_frame_study(q);
  ASSERT_EQ(r.nodal.size(), 1u);
  const coupling::NodalHistory& tip = r.nodal[0];
  // Closed form: modes 1-4 as the ramp responses, the rest quasi-static (what
  // they are under mode acceleration). The FE's higher modes respond
  // dynamically: |r_i - f| <= 1 bounds their difference by their summed
  // share, 1 - sum(1..4) = 6.1e-4; allowance 1e-4 for the 20 elements'
  // frequencies and shares of modes 1-4 (cubic elements: errors ~ (beta h)^4).
  double shares = 0.0;
  for (int i = 1; i <= 4; ++i) shares += share(i);
  double tail = 0.0;  // the same remainder summed directly (shares sum to 1)
  for (int i = 5; i < 200000; ++i) tail += share(i);
  EXPECT_NEAR(tail, 1.0 - shares, 1e-6);
  const double tol_u = (1.0 - shares + 1e-4) * kStatic, tol_v = (2.0 * (1.0 - shares) + 1e-4 * omega(4) * kTau) * kStatic / kTau;
  double peak = 0.0, worst_u = 0.0, worst_v = 0.0;
  for (Eigen::Index j = 0; j < r.response.times.size(); ++j) {
    const double t = r.response.times(j);
    double u = (1.0 - shares) * ramped_step(t), v = (1.0 - shares) * (t > 0.0 && t <= kTau ? 1.0 / kTau : 0.0);
    for (int i = 1; i <= 4; ++i) {
      const Ramp x = ramp_response(omega(i), kTau, t);
      u += share(i) * x.r;
      v += share(i) * x.dr;
    }
    const double fe_u = tip.displacement(2, j), fe_v = tip.velocity(2, j);
    worst_u = std::max(worst_u, std::abs(fe_u - u * kStatic));
    worst_v = std::max(worst_v, std::abs(fe_v - v * kStatic));
    EXPECT_NEAR(fe_u, u * kStatic, tol_u) << "t = " << t;
    EXPECT_NEAR(fe_v, v * kStatic, tol_v) << "t = " << t;
    peak = std::max(peak, fe_u);
  }
  std::cout << "[ measured ] static PL^3/3EI " << kStatic << " m; peak " << peak / kStatic << " x static; largest difference from the series: displacement " << worst_u / kStatic << " (allowed " << tol_u / kStatic
            << "), velocity " << worst_v * kTau / kStatic << " P L^3/(3 EI tau) (allowed " << tol_v * kTau / kStatic << ")\n";
  // The peak of an undamped step response: twice static for one mode; the
  // ramp (sin(w tau / 2) / (w tau / 2) = 0.9959 for mode 1) and the higher
  // modes' share bound it from below.
  const double sinc = std::sin(omega(1) * kTau / 2) / (omega(1) * kTau / 2);
  EXPECT_LE(peak, 2.0 * kStatic * (1.0 + 1e-4));
  EXPECT_GE(peak, (1.0 + share(1) * sinc - (1.0 - share(1))) * kStatic);
  // The summary names the peak's node, DOF and time.
  const nlohmann::ordered_json summary = report::frame_summary(r, q);
  const nlohmann::ordered_json& out = summary["outputs"]["tip"];
  EXPECT_EQ(out["kind"], "node_set");
  EXPECT_EQ(out["set"], "TIP");
  EXPECT_EQ(out["nodes"], nlohmann::ordered_json::array({21}));
  EXPECT_EQ(out["peak_displacement"]["node"], 21);
  EXPECT_EQ(tip.peak_displacement.node_id, 21);
  EXPECT_EQ(tip.peak_displacement.dof, 2);
}

TEST_F(CantileverStudy, SingleModeTipDisplacementVelocityAndAccelerationMatchTheClosedFormRampResponse) {
  // The square section's first bending frequency is a pair (bending in Y and
  // in Z): the two modes span both planes, so the Z load drives exactly one mode of Z bending.
  const auto q = request("  supports: clamped\n  support_set: [ROOT]\n  modes: 2\n  method: mode_displacement\n  damping: {modal_ratio: 0.0}\n"
                         "  outputs:\n    tip: {node_set: tip}\n");
  const auto r = coupling::run_frame_study(q);
  const coupling::NodalHistory& tip = r.nodal[0];
  // Mode 1 of 20 cubic elements: frequency within 2 (beta_1 h)^4 / 1440 = 1.1e-7 of
  // (1.8751)^2 sqrt(EI/m)/L^2 (the consistent-mass Hermite error, docs/validation.md V1).
  const double w = 2 * kPi * r.frequencies_hz(0);
  std::cout.precision(10);
  std::cout << "[ measured ] f1 = " << r.frequencies_hz(0) << " and " << r.frequencies_hz(1) << " Hz, closed form " << omega(1) / (2 * kPi) << " Hz\n";
  EXPECT_NEAR(w / omega(1), 1.0, 2 * std::pow(beta_l(1) / kElements, 4) / 1440);
  EXPECT_NEAR(r.frequencies_hz(1) / r.frequencies_hz(0), 1.0, 1e-9);
  // One mode: u = c1 u_st r(t) exactly, v and a its derivatives. The FE share c1 differs from 12 / (beta_1 L)^4
  // by the mode shape's discretisation, allowance 1e-6 of the amplitude.
  const double c1 = share(1) * kStatic;
  double eu = 0.0, ev = 0.0, ea = 0.0;
  for (Eigen::Index j = 0; j < r.response.times.size(); ++j) {
    const Ramp x = ramp_response(w, kTau, r.response.times(j));
    EXPECT_NEAR(tip.displacement(2, j), c1 * x.r, 1e-6 * 2 * c1);
    EXPECT_NEAR(tip.velocity(2, j), c1 * x.dr, 1e-6 * 2 * c1 / kTau);
    EXPECT_NEAR(tip.acceleration(2, j), c1 * x.ddr, 1e-6 * 2 * c1 * w / kTau);
    eu = std::max(eu, std::abs(tip.displacement(2, j) - c1 * x.r) / (2 * c1));
    ev = std::max(ev, std::abs(tip.velocity(2, j) - c1 * x.dr) / (2 * c1 / kTau));
    ea = std::max(ea, std::abs(tip.acceleration(2, j) - c1 * x.ddr) / (2 * c1 * w / kTau));
  }
  std::cout << "[ measured ] one mode, largest differences from the closed form over the amplitude bounds: u " << eu << ", v " << ev << ", a " << ea
            << " (allowed 1e-6 each)\n";
}

TEST_F(CantileverStudy, RootSectionForcesOfAStaticTipLoadArePAndPTimesL) {
  // A constant load from the first time: the study starts in static
  // equilibrium, so every output is the static cantilever: at the root the
  // shear is P and the bending moment P L; at the root element's far end P (L - h).
  dir.write("loads.csv", tip_load(kP, 0.001, 0.01, [](double) { return 1.0; }));
  const auto q = request("  supports: clamped\n  support_set: ROOT\n  modes: 5\n  method: mode_acceleration\n  stations: 3\n"
                         "  outputs:\n    root: {element_set: ROOT_ELEMENT}\n");
  ASSERT_EQ(q.rails.size(), 1u);
  EXPECT_TRUE(q.rails[0].history);
  const auto r = coupling::run_frame_study(q);
  const coupling::SectionHistory& h = r.sections[0];
  ASSERT_EQ(h.element_ids.size(), 3u);
  const double h_el = kL / kElements;
  for (Eigen::Index j = 0; j < r.response.times.size(); ++j) {
    for (int s = 0; s < 3; ++s) {
      const auto v = h.values.row(j * 3 + s);
      const double moment = std::hypot(v(4), v(5)), shear = std::hypot(v(1), v(2));
      EXPECT_NEAR(moment, kP * (kL - h.station_x[static_cast<std::size_t>(s)]), 1e-9 * kP * kL) << s;
      EXPECT_NEAR(shear, kP, 1e-9 * kP);
      EXPECT_NEAR(v(0), 0.0, 1e-9 * kP);
      // Fiber stress M c / I at the corners of the square.
      EXPECT_NEAR(v(6), moment * kSide / 2 / kI, 1e-9 * kP * kL * kSide / 2 / kI);
    }
  }
  EXPECT_NEAR(h.station_x[2], h_el, 1e-12);
  EXPECT_NEAR(std::abs(r.rails[0].peak_bending_moment.value), kP * kL, 1e-9 * kP * kL);
  EXPECT_EQ(r.rails[0].peak_bending_moment.station, 0);
  // Written as frame_sections_root.csv, one row per time and station.
  core::ResultsFolder folder(dir / "out");
  report::write_frame_outputs(r, q, folder);
  folder.commit();
  EXPECT_TRUE(std::filesystem::exists(dir / "out" / "frame_sections_root.csv"));
}

TEST_F(CantileverStudy, ClampingByTheMeshBoundaryOrByTheSetNameGivesTheSameResponse) {
  dir.write("cantilever.inp", cantilever_inp(true));
  const std::string rest = "  modes: 6\n  method: mode_acceleration\n  outputs:\n    tip: {node_set: TIP}\n";
  const auto by_mesh = coupling::run_frame_study(request(rest));  // default: the mesh's *BOUNDARY
  EXPECT_EQ(request(rest).supports, coupling::FrameSupports::mesh_boundary);
  dir.write("cantilever.inp", cantilever_inp(false));
  const auto by_set = coupling::run_frame_study(request("  supports: clamped\n  support_set: ROOT\n" + rest));
  EXPECT_LT((by_mesh.nodal[0].displacement - by_set.nodal[0].displacement).norm(), 1e-12 * by_set.nodal[0].displacement.norm());
  EXPECT_GT(by_set.nodal[0].displacement.norm(), 0.0);
}

TEST_F(CantileverStudy, DirectMethodGivesTheTipDisplacementHistoryWithoutRates) {
  // Newmark gives displacements only (no modal coordinates to take rates
  // from): the CSV has no velocity or acceleration columns, the summary no peaks of them.
  const auto q = request("  supports: clamped\n  support_set: ROOT\n  method: direct\n  damping: {rayleigh: {alpha: 0, beta: 0}}\n"
                         "  outputs:\n    tip: {node_set: TIP}\n");
  const auto r = coupling::run_frame_study(q);
  EXPECT_EQ(r.nodal[0].velocity.size(), 0);
  EXPECT_GT(r.nodal[0].peak_displacement.value, kStatic);  // a step response overshoots the static deflection
  core::ResultsFolder folder(dir / "out");
  report::write_frame_outputs(r, q, folder);
  folder.commit();
  std::ifstream in(dir / "out" / "frame_nodes_tip.csv");
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header, "time [s],node,UX [m],UY [m],UZ [m],URX [rad],URY [rad],URZ [rad]");
  EXPECT_EQ(report::frame_summary_json(r, q).find("peak_velocity"), std::string::npos);
}

TEST_F(CantileverStudy, FreeFreeBeamHasTheClosedFormFirstElasticFrequency) {
  // Free-free (supports: none): beta_1 L = 4.730041, inertia relief.
  const auto r = coupling::run_frame_study(request("  supports: none\n  modes: 2\n  outputs:\n    tip: {node_set: TIP}\n"));
  const double f1 = 4.730040744862704 * 4.730040744862704 * std::sqrt(kE * kI / (kRho * kArea)) / (kL * kL) / (2 * kPi);
  std::cout << "[ measured ] free-free f1 = " << r.frequencies_hz(0) << " Hz, closed form " << f1 << " Hz\n";
  // 20 cubic elements: within 2 (beta_1 h)^4 / 1440 = 4.3e-6 (docs/validation.md V1).
  const double tol = 2 * std::pow(4.730040744862704 / kElements, 4) / 1440;
  EXPECT_NEAR(r.frequencies_hz(0) / f1, 1.0, tol);
  // Square section: the two bending modes are a pair.
  EXPECT_NEAR(r.frequencies_hz(1) / f1, 1.0, tol);
}

TEST_F(CantileverStudy, MissingOutputAndSupportSetsNameTheStudyLineAndTheMesh) {
  auto error_of = [&](const std::string& block) {
    try {
      coupling::run_frame_study(request(block));
    } catch (const core::InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::string mesh = (dir / "cantilever.inp").string();
  std::string e = error_of("  supports: clamped\n  support_set: ROOT\n  outputs:\n    root: {element_set: ROOTS}\n");
  EXPECT_NE(e.find("s.yaml:11: frame.outputs.root.element_set: expected an element set of the mesh " + mesh + " with beam elements (its element sets: BEAM, ROOT_ELEMENT), found 'ROOTS'"),
            std::string::npos) << e;
  e = error_of("  supports: clamped\n  support_set: ROOT\n  outputs:\n    tip: {node_set: TOP}\n");
  EXPECT_NE(e.find("s.yaml:11: frame.outputs.tip.node_set: expected a node set of the mesh " + mesh + " (its node sets: ALL_NODES, ROOT, TIP), found 'TOP'"),
            std::string::npos) << e;
  e = error_of("  supports: clamped\n  support_set: [ROOT, BASE]\n");
  EXPECT_NE(e.find("s.yaml:9: frame.support_set: expected a node set of the mesh " + mesh), std::string::npos) << e;
  EXPECT_NE(e.find("found 'BASE'"), std::string::npos) << e;
  e = error_of("  modes: 3\n");
  EXPECT_NE(e.find("s.yaml:6: frame.supports: expected supports for the mesh " + mesh), std::string::npos) << e;
  e = error_of("  supports: clamped\n");
  EXPECT_NE(e.find("s.yaml:8: frame.supports: expected supports: clamped with support_set"), std::string::npos) << e;
  e = error_of("  supports: clamped\n  support_set: ROOT\n  outputs:\n    tip: {node_set: TIP, element_set: BEAM}\n");
  EXPECT_NE(e.find("s.yaml:11: frame.outputs.tip: expected exactly one of element_set or node_set, found both"), std::string::npos) << e;
  e = error_of("  supports: clamped\n  support_set: ROOT\n  outputs:\n    tip top: {node_set: TIP}\n");
  EXPECT_NE(e.find("frame.outputs.tip top: expected an output name of letters, digits"), std::string::npos) << e;
}

// An operating study (the pipeline) holds the frame free, relieved by its inertia, as the machine does.
TEST(FrameStudyDefaults, PipelineIsFreeWithInertiaReliefAndKeepsTheTrencherRailsWhileAStudyNamesItsOwn) {
  framedyn::testing::TempDir dir;
  dir.write("frame.inp", cantilever_inp());
  const YAML::Node doc = YAML::Load("mesh: frame.inp\n");
  const core::UnitSystem si = core::UnitSystem::si();
  const coupling::YamlMap block(doc, "frame_response", (dir / "s.yaml").string(), &si);
  const auto pipeline = coupling::read_frame_block(block, dir.path(), coupling::FrameDefaults::pipeline);
  EXPECT_EQ(pipeline.supports, coupling::FrameSupports::free_free_inertia_relief);
  ASSERT_EQ(pipeline.support_sets, std::vector<std::string>{"REAR_END"});
  ASSERT_EQ(pipeline.rails.size(), 2u);
  EXPECT_EQ(pipeline.rails[0].element_set, "LEFT_RAIL");
  EXPECT_EQ(pipeline.rails[1].element_set, "RIGHT_RAIL");
  EXPECT_FALSE(pipeline.rails[0].history);
  const auto standalone = coupling::read_frame_block(block, dir.path(), coupling::FrameDefaults::standalone);
  EXPECT_EQ(standalone.supports, coupling::FrameSupports::mesh_boundary);
  EXPECT_TRUE(standalone.rails.empty());
  EXPECT_TRUE(standalone.node_outputs.empty());
}

}  // namespace

// The mesh's own gravity (*DLOAD GRAV) in frame-response: a constant load
// acting throughout, the response starting from the static equilibrium under
// it. With a zero load history the tip stays at w L^4 / 8 EI (cubic elements
// give it exactly at the nodes), no start-up oscillation; with the step tip
// load added, the response is the gravity deflection plus the step response
// of the test above (superposition, to round-off), so it oscillates about
// the static deflection under both with the closed-form amplitude checked there.
class CantileverUnderGravity : public ::testing::Test {
 protected:
  framedyn::testing::TempDir dir;
  static constexpr double kG = 9.81;
  const double w = kRho * kArea * kG;                               // N/m
  const double static_gravity = -w * std::pow(kL, 4) / (8.0 * kE * kI);  // tip uz, m
  coupling::FrameStudyResults run(double p, const std::string& extra = "") {
    dir.write("cantilever.inp", cantilever_inp(true) + "*DLOAD\nBEAM, GRAV, 9.81, 0, 0, -1\n");
    dir.write("loads.csv", tip_load(p, kT1 / 120, 2 * kT1, ramped_step));
    q = coupling::read_frame_study(
        dir.write("s.yaml", study("  modes: all\n  method: mode_acceleration\n  damping: {modal_ratio: 0.0}\n  outputs:\n    tip: {node_set: TIP}\n" + extra))
            .string());
    return coupling::run_frame_study(q);
  }
  coupling::FrameStudyRequest q;
};

TEST_F(CantileverUnderGravity, ZeroLoadHistoryStaysAtTheStaticDeflectionWL4Over8EI) {
  const auto r = run(0.0);
  double worst = 0.0;
  for (Eigen::Index j = 0; j < r.response.times.size(); ++j) worst = std::max(worst, std::abs(r.nodal[0].displacement(2, j) / static_gravity - 1.0));
  std::cout << "[ measured ] w L^4 / 8EI = " << static_gravity << " m; largest relative departure of the tip over 2 periods " << worst << "\n";
  EXPECT_LT(worst, 1e-9);
  const nlohmann::ordered_json s = report::frame_summary(r, q);
  EXPECT_EQ(s["constant_loads"]["dload_beams"], kElements);
  EXPECT_EQ(s["constant_loads"]["cload_entries"], 0);
  EXPECT_NEAR(s["constant_loads"]["resultant_force"]["value"][2].get<double>(), -w * kL, 1e-9 * w * kL);
  // mesh_loads: none ignores them: the tip does not move.
  const auto none = run(0.0, "  mesh_loads: none\n");
  EXPECT_EQ(none.nodal[0].displacement.cwiseAbs().maxCoeff(), 0.0);
  EXPECT_FALSE(report::frame_summary(none, q).contains("constant_loads"));
}

TEST_F(CantileverUnderGravity, StepLoadOscillatesAboutTheStaticDeflectionUnderGravityAndTheLoad) {
  const auto with = run(kP);
  const auto without = run(kP, "  mesh_loads: none\n");
  double worst = 0.0, low = 0.0, high = 0.0;
  for (Eigen::Index j = 0; j < with.response.times.size(); ++j) {
    const double about = with.nodal[0].displacement(2, j) - static_gravity;
    worst = std::max(worst, std::abs(about - without.nodal[0].displacement(2, j)));
    low = std::min(low, about);
    high = std::max(high, about);
  }
  std::cout << "[ measured ] superposition error " << worst / kStatic << " of PL^3/3EI; excursion about the gravity deflection " << low / kStatic
            << " .. " << high / kStatic << " x PL^3/3EI\n";
  EXPECT_LT(worst, 1e-9 * kStatic);
  // Undamped step: between the gravity deflection and twice the load's static deflection beyond it.
  EXPECT_GE(low, -1e-9 * kStatic);
  EXPECT_LE(high, 2.0 * kStatic * (1.0 + 1e-4));
  EXPECT_GE(high, 1.9 * kStatic);
}
