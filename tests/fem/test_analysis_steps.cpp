// Multi-step decks (docs/theory/fem.md section 18): loads carried over from
// step to step or replaced (OP=MOD, OP=NEW), one factorisation for the static
// steps, the *FREQUENCY step's supports for modes; checked against the
// cantilever's hand formulas, not against the reader's own bookkeeping.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "fem/frame_model.h"
#include "fem/inp_reader.h"
#include "fem/modal_analysis.h"
#include "fem/static_analysis.h"
#include "fem/transient_step.h"

namespace {

namespace fem = framedyn::fem;

constexpr double kE = 2.1e11, kA = 0.05, kB = 0.1, kL = 2.0;  // RECT a (local 1) x b (local 2), m
constexpr int kElements = 4;

// A cantilever along x of B33 elements, n1 = y, clamped at node 1; `steps` appended.
std::string cantilever(const std::string& steps) {
  std::string s = "** units: m-N-s\n*NODE, NSET=ALL\n";
  for (int i = 0; i <= kElements; ++i) s += std::to_string(i + 1) + ", " + std::to_string(kL * i / kElements) + ", 0, 0\n";
  s += "*ELEMENT, TYPE=B33, ELSET=FRAME\n";
  for (int i = 1; i <= kElements; ++i) s += std::to_string(i) + ", " + std::to_string(i) + ", " + std::to_string(i + 1) + "\n";
  s += "*BEAM SECTION, ELSET=FRAME, MATERIAL=STEEL, SECTION=RECT\n0.05, 0.1\n0, 1, 0\n*MATERIAL, NAME=STEEL\n*ELASTIC\n2.1e11, 0.3\n"
       "*DENSITY\n7850\n*NSET, NSET=TIP\n5\n";
  return s + steps;
}

// Tip deflection of an Euler-Bernoulli cantilever under a tip force P: P L^3 / (3 E I).
double tip_deflection(double force, double i) { return force * kL * kL * kL / (3.0 * kE * i); }
const double kI_y = kB * kA * kA * kA / 12.0;  // bending along y (local 1 = y, depth a)
const double kI_z = kA * kB * kB * kB / 12.0;  // bending along z (depth b)

const std::string kThreeSteps =
    "*BOUNDARY\n1, 1, 6\n"
    "*STEP\n*STATIC\n*CLOAD\n5, 3, 1000.\n*END STEP\n"           // 1: tip load along z
    "*STEP\n*STATIC\n*CLOAD\nTIP, 2, 500.\n*END STEP\n"          // 2: adds y, z carried over
    "*STEP\n*STATIC\n*CLOAD, OP=NEW\n5, 3, -200.\n*END STEP\n"   // 3: only the new z load
    "*STEP\n*FREQUENCY\n3\n*BOUNDARY\n5, 1, 3\n*END STEP\n";     // 4: modes with the tip pinned too

TEST(AnalysisSteps, LoadsCarryOverFromStepToStepUnlessOpNew) {
  const fem::FrameModel m = fem::read_inp_text(cantilever(kThreeSteps), "deck.inp", ".");
  ASSERT_EQ(m.steps.size(), 4u);
  EXPECT_EQ(m.steps[0].procedure, "STATIC");
  EXPECT_EQ(m.steps[3].procedure, "FREQUENCY");
  EXPECT_EQ(m.steps[3].requested_modes, 3);
  EXPECT_EQ(m.requested_modes, 3);
  std::vector<fem::FrameModel> cases;
  for (std::size_t i = 0; i < 3; ++i) cases.push_back(fem::with_step(m, i));
  int factorisations = 0;
  const std::vector<fem::StaticResult> r = fem::solve_static_cases(cases, {}, {}, &factorisations);
  EXPECT_EQ(factorisations, 1);  // the three static steps support the same DOFs
  const int tip = 6 * m.node_index(5);
  // Step 1: 1000 N along z; step 2: and 500 N along y; step 3: -200 N along z alone.
  const double uz1 = tip_deflection(1000.0, kI_z), uy2 = tip_deflection(500.0, kI_y), uz3 = tip_deflection(-200.0, kI_z);
  EXPECT_NEAR(r[0].displacement(tip + 2), uz1, 1e-9 * std::abs(uz1));
  EXPECT_NEAR(r[0].displacement(tip + 1), 0.0, 1e-9 * std::abs(uz1));
  EXPECT_NEAR(r[1].displacement(tip + 2), uz1, 1e-9 * std::abs(uz1));
  EXPECT_NEAR(r[1].displacement(tip + 1), uy2, 1e-9 * std::abs(uy2));
  EXPECT_NEAR(r[2].displacement(tip + 2), uz3, 1e-9 * std::abs(uz3));
  EXPECT_NEAR(r[2].displacement(tip + 1), 0.0, 1e-9 * std::abs(uz3));
  // The root carries each step's load.
  EXPECT_NEAR(r[1].reaction(1), -500.0, 1e-6);
  EXPECT_NEAR(r[2].reaction(2), 200.0, 1e-6);
}

TEST(AnalysisSteps, ALoadRedefinedInALaterStepReplacesTheEarlierValue) {
  // CalculiX's OP=MOD: the same node and DOF loaded again takes the new value (not the sum).
  const fem::FrameModel m = fem::read_inp_text(
      cantilever("*BOUNDARY\n1, 1, 6\n*STEP\n*STATIC\n*CLOAD\n5, 3, 1000.\n*END STEP\n*STEP\n*STATIC\n*CLOAD\n5, 3, 300.\n*END STEP\n"),
      "deck.inp", ".");
  ASSERT_EQ(m.steps.size(), 2u);
  const fem::StaticResult r = fem::solve_static(fem::with_step(m, 1));
  const double uz = tip_deflection(300.0, kI_z);
  EXPECT_NEAR(r.displacement(6 * m.node_index(5) + 2), uz, 1e-9 * uz);
}

TEST(AnalysisSteps, ModesUseTheFrequencyStepsSupports) {
  // Step 4 pins the tip as well: a propped cantilever (clamped-pinned), whose
  // first bending frequency has beta L = 3.9266 (against 1.8751 clamped-free).
  const fem::FrameModel m = fem::with_frequency_step(fem::read_inp_text(cantilever(kThreeSteps), "deck.inp", "."));
  EXPECT_EQ(m.constraints.size(), 9u);  // 6 at the root, 3 at the tip
  fem::ModalOptions o;
  o.mode_count = 1;
  const fem::ModalResult r = fem::compute_modes(m, o);
  // Euler-Bernoulli, bending along y (the softer plane), 4 elements: within 0.5 % of beta L = 3.9266.
  const double rho_a = 7850.0 * kA * kB, beta = 3.92660231 / kL;
  const double f = beta * beta * std::sqrt(kE * kI_y / rho_a) / (2.0 * 3.14159265358979323846);
  EXPECT_NEAR(r.modes.at(0).frequency_hz / f, 1.0, 5e-3);
}

// *BOUNDARY, OP=NEW (CalculiX, docs/theory/fem.md section 21): the step's
// first *BOUNDARY card removes every support prescribed before the step, the
// model data's clamp included; later cards of the step add to it; a later
// step without *BOUNDARY keeps them. As CalculiX's test deck rot1: the clamp
// moves from the root to mid-span, the tip load carried over.
TEST(AnalysisSteps, BoundaryOpNewReplacesTheModelDataClampByTheStepsSupports) {
  const fem::FrameModel m = fem::read_inp_text(cantilever("*BOUNDARY\n1, 1, 6\n"
                                                          "*STEP\n*STATIC\n*CLOAD\n5, 3, 1000.\n*END STEP\n"
                                                          "*STEP\n*STATIC\n*BOUNDARY, OP=NEW\n3, 1, 6\n*END STEP\n"
                                                          "*STEP\n*STATIC\n*END STEP\n"),
                                               "deck.inp", ".");
  ASSERT_EQ(m.steps.size(), 3u);
  for (std::size_t s : {1u, 2u}) {
    ASSERT_EQ(m.steps[s].constraints.size(), 6u) << s;
    for (const fem::Constraint& c : m.steps[s].constraints) EXPECT_EQ(c.node, m.node_index(3)) << s;
  }
  std::vector<fem::FrameModel> cases = {fem::with_step(m, 0), fem::with_step(m, 1)};
  const std::vector<fem::StaticResult> r = fem::solve_static_cases(cases);
  const int tip = 6 * m.node_index(5), root = 6 * m.node_index(1), mid = 6 * m.node_index(3);
  const double uz1 = tip_deflection(1000.0, kI_z), uz2 = uz1 / 8.0;  // the free length halved: (L/2)^3
  EXPECT_NEAR(r[0].displacement(tip + 2), uz1, 1e-9 * uz1);
  EXPECT_NEAR(r[1].displacement(tip + 2), uz2, 1e-9 * uz2);
  // Step 2: the unloaded half between the old root and the new clamp does not move, and the old root carries nothing.
  for (int d = 0; d < 6; ++d) {
    EXPECT_NEAR(r[1].displacement(root + d), 0.0, 1e-12) << d;
    EXPECT_EQ(r[1].reaction(root + d), 0.0) << d;
  }
  EXPECT_NEAR(r[1].reaction(mid + 2), -1000.0, 1e-6);
}

TEST(AnalysisSteps, BoundaryOpNewInAFrequencyStepGivesItsOwnSupports) {
  // Step 2 clamps the tip (OP=NEW, so the root is free) and its second card pins the root again:
  // a propped cantilever mirrored, beta L = 3.9266; had the root clamp survived, it would be
  // clamped-clamped (beta L = 4.7300).
  const fem::FrameModel m = fem::with_frequency_step(fem::read_inp_text(
      cantilever("*BOUNDARY\n1, 1, 6\n*STEP\n*STATIC\n*CLOAD\n5, 3, 1000.\n*END STEP\n"
                 "*STEP\n*FREQUENCY\n1\n*BOUNDARY, OP=NEW\n5, 1, 6\n*BOUNDARY\n1, 1, 3\n*END STEP\n"),
      "deck.inp", "."));
  EXPECT_EQ(m.constraints.size(), 9u);  // 6 at the tip, 3 at the root
  fem::ModalOptions o;
  o.mode_count = 1;
  const fem::ModalResult r = fem::compute_modes(m, o);
  const double rho_a = 7850.0 * kA * kB, beta = 3.92660231 / kL;
  const double f = beta * beta * std::sqrt(kE * kI_y / rho_a) / (2.0 * 3.14159265358979323846);
  EXPECT_NEAR(r.modes.at(0).frequency_hz / f, 1.0, 5e-3);
}

// ------------------------------------------------ transient steps of a deck (docs/theory/fem.md section 22)
// A tip mass of 100 kg on the cantilever, the beam 1000 times lighter than
// steel (0.0785 kg in all): a single-degree-of-freedom oscillator along z of
// stiffness k = 3 E I / L^3 and mass M + (33/140) m_beam (Rayleigh's
// quotient with the static shape), whose closed forms the transient steps
// are checked against.
constexpr double kTipMass = 100.0, kLightDensity = 7.85, kForce = 1000.0;
const double kBeamMass = kLightDensity * kA * kB * kL;
const double kOmega = std::sqrt(3.0 * kE * kI_z / (kL * kL * kL) / (kTipMass + 33.0 / 140.0 * kBeamMass));
const double kPeriod = 2.0 * M_PI / kOmega;
// The frame is the oscillator up to the beam's own mass beyond Rayleigh's
// quotient, second order in the mass ratio: (0.0785 / 100)^2 = 6e-7 (measured 3e-9 to 6e-9).
constexpr double kOscillatorTolerance = 1e-6;

std::string oscillator(const std::string& steps) {
  std::string s = cantilever("");
  const std::string steel = "*DENSITY\n7850";
  s.replace(s.find(steel), steel.size(), "*DENSITY\n7.85");
  return s + fmt::format("*ELEMENT, TYPE=MASS, ELSET=TIPMASS\n100, 5\n*MASS, ELSET=TIPMASS\n{}\n*BOUNDARY\n1, 1, 6\n", kTipMass) + steps;
}

// The tip's z history of step `step` (1-based) and its times.
std::pair<Eigen::VectorXd, Eigen::VectorXd> tip_history(const fem::FrameModel& m, int step) {
  const fem::TransientStepResult r = fem::run_transient_step(m, static_cast<std::size_t>(step - 1), "deck.inp");
  return {r.response.times, r.response.displacement.row(6 * m.node_index(5) + 2).transpose()};
}

std::string transient_deck(const std::string& procedure, const std::string& amplitude, double dt, double period) {
  return oscillator(fmt::format("*AMPLITUDE, NAME=LOAD\n{}\n*STEP\n*FREQUENCY\n2\n*END STEP\n*STEP\n{}\n{:.17g}, {:.17g}\n"
                                "*CLOAD, AMPLITUDE=LOAD\nTIP, 3, {}\n*END STEP\n",
                                amplitude, procedure, dt, period, kForce));
}

TEST(TransientSteps, ASuddenlyAppliedTipLoadPeaksAtTwiceTheStaticDeflection) {
  // u(t) = u_st (1 - cos omega t) for a load switched on at t = 0 and held
  // (Eq. 22.5): the modal step is exact at the output times for the one mode.
  const double ust = tip_deflection(kForce, kI_z);
  const fem::FrameModel m = fem::read_inp_text(transient_deck("*MODAL DYNAMIC", "0, 1, 1, 1", kPeriod / 200.0, kPeriod), "deck.inp", ".");
  const auto [t, u] = tip_history(m, 2);
  ASSERT_EQ(t.size(), 201);
  double worst = 0.0;
  for (Eigen::Index k = 0; k < t.size(); ++k) worst = std::max(worst, std::abs(u(k) - ust * (1.0 - std::cos(kOmega * t(k)))));
  EXPECT_LT(worst, kOscillatorTolerance * ust);
  EXPECT_NEAR(u.maxCoeff(), 2.0 * ust, kOscillatorTolerance * ust);
  EXPECT_NEAR(t(100), kPeriod / 2.0, 1e-12 * kPeriod);
}

TEST(TransientSteps, ARampedLoadFollowsTheClosedFormDuringAndAfterTheRamp) {
  // Ramp over t_r = 0.3 T, then held (the amplitude's last value holds after
  // its last point): u/u_st = t/t_r - sin(w t)/(w t_r) for t <= t_r, and
  // 1 - (sin(w t) - sin(w (t - t_r)))/(w t_r) after it (Eq. 22.6).
  const double ust = tip_deflection(kForce, kI_z), tr = 0.3 * kPeriod;
  const fem::FrameModel m =
      fem::read_inp_text(transient_deck("*MODAL DYNAMIC", fmt::format("0, 0, {:.17g}, 1", tr), kPeriod / 64.0, 2.0 * kPeriod), "deck.inp", ".");
  const auto [t, u] = tip_history(m, 2);
  EXPECT_EQ(t.size(), 129 + 1);  // the grid and the ramp's end, which is not on it
  double worst = 0.0;
  for (Eigen::Index k = 0; k < t.size(); ++k) {
    const double w = kOmega, x = t(k);
    const double exact = x <= tr ? x / tr - std::sin(w * x) / (w * tr) : 1.0 - (std::sin(w * x) - std::sin(w * (x - tr))) / (w * tr);
    worst = std::max(worst, std::abs(u(k) - ust * exact));
  }
  EXPECT_LT(worst, kOscillatorTolerance * ust);
}

TEST(TransientSteps, DirectIntegrationIsTheTrapezoidalRulesRotationAndConvergesToTheModalStep) {
  // Newmark's average acceleration on an undamped oscillator released from
  // u_st away from equilibrium rotates (u, v/omega) by Omega dt per step,
  // tan(Omega dt / 2) = omega dt / 2 (Eq. 22.4): u_n = u_st (1 - cos(n Omega dt)).
  const double ust = tip_deflection(kForce, kI_z);
  for (int per_period : {20, 80}) {
    const double dt = kPeriod / per_period;
    const fem::FrameModel m = fem::read_inp_text(transient_deck("*DYNAMIC", "0, 1, 1, 1", dt, kPeriod), "deck.inp", ".");
    EXPECT_EQ(m.steps[1].procedure, "DYNAMIC");
    const auto [t, u] = tip_history(m, 2);
    const double big_omega = 2.0 / dt * std::atan(kOmega * dt / 2.0);
    double worst = 0.0, from_exact = 0.0;
    for (Eigen::Index k = 0; k < t.size(); ++k) {
      worst = std::max(worst, std::abs(u(k) - ust * (1.0 - std::cos(big_omega * t(k)))));
      from_exact = std::max(from_exact, std::abs(u(k) - ust * (1.0 - std::cos(kOmega * t(k)))));
    }
    EXPECT_LT(worst, kOscillatorTolerance * ust) << per_period << " steps per period";
    // The phase error after one period, 2 pi (omega/Omega - 1) ~ (omega dt)^2 / 12 * 2 pi, bounds the distance to the exact history.
    const double phase = 2.0 * M_PI * (kOmega / big_omega - 1.0);
    EXPECT_LT(from_exact, (phase + kOscillatorTolerance) * ust) << per_period << " steps per period";
    EXPECT_GT(from_exact, 0.5 * phase * ust) << per_period << " steps per period";
  }
}

TEST(TransientSteps, ModalDampingRangesDampTheModesTheyName) {
  // *MODAL DAMPING 1, 2, 0.05: both modes (the tip mass along y and z) at
  // 5 % of critical; the step response along z is the damped oscillator's (Eq. 22.3).
  const fem::FrameModel m = fem::read_inp_text(
      oscillator("*AMPLITUDE, NAME=LOAD\n0, 1, 1, 1\n*STEP\n*FREQUENCY\n2\n*END STEP\n*STEP\n*MODAL DYNAMIC\n" +
                 fmt::format("{:.17g}, {:.17g}\n", kPeriod / 100.0, 3.0 * kPeriod) +
                 "*MODAL DAMPING\n1, 2, 0.05\n*CLOAD, AMPLITUDE=LOAD\nTIP, 3, 1000.\n*END STEP\n"),
      "deck.inp", ".");
  const fem::TransientStepResult r = fem::run_transient_step(m, 1, "deck.inp");
  ASSERT_EQ(r.response.damping_ratios.size(), 2);
  EXPECT_EQ(r.response.damping_ratios(0), 0.05);
  EXPECT_EQ(r.response.damping_ratios(1), 0.05);
  // Damped step response: u/u_st = 1 - exp(-z w t)(cos(wd t) + z/sqrt(1-z^2) sin(wd t)).
  const double z = 0.05, wd = kOmega * std::sqrt(1.0 - z * z), ust = tip_deflection(kForce, kI_z);
  double worst = 0.0;
  for (Eigen::Index k = 0; k < r.response.times.size(); ++k) {
    const double x = r.response.times(k);
    const double exact = 1.0 - std::exp(-z * kOmega * x) * (std::cos(wd * x) + z / std::sqrt(1.0 - z * z) * std::sin(wd * x));
    worst = std::max(worst, std::abs(r.response.displacement(6 * m.node_index(5) + 2, k) - ust * exact));
  }
  EXPECT_LT(worst, kOscillatorTolerance * ust);
}

TEST(TransientSteps, AnAmplitudeIsLinearBetweenItsPointsAndHeldOutsideThem) {
  const fem::FrameModel m = fem::read_inp_text(
      oscillator("*AMPLITUDE, NAME=A\n0.1, 2., 0.3, -1., 0.3, 4.\n*STEP\n*DYNAMIC\n0.1, 1.\n*CLOAD, AMPLITUDE=a\nTIP, 3, 1.\n*END STEP\n"), "deck.inp",
      ".");
  const fem::Amplitude& a = m.amplitudes.at("A");
  EXPECT_EQ(a.at(0.0), 2.0);
  EXPECT_NEAR(a.at(0.2), 0.5, 1e-15);  // (0.2 - 0.1) / (0.3 - 0.1) in binary: round-off
  EXPECT_EQ(a.at(0.3), 4.0);  // a repeated time is a jump: the later value from it on
  EXPECT_EQ(a.at(5.0), 4.0);
  EXPECT_EQ(m.steps[0].load_amplitudes, std::vector<std::string>{"A"});
}

}  // namespace
