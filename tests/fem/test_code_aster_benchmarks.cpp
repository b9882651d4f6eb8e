// code_aster's published beam benchmarks SDLL01 and SDLL15 (issue 13, public
// benchmark decks; docs/validation.md V33). Decks written for framedyn from
// the published statements (tests/data/benchmarks/code_aster_sdll01_*.inp,
// code_aster_sdll15_*.inp; each cites its source: code_aster's Validation
// Manual V2.02.001 / V2.02.015, after the VPCS guide of the French Society
// of Mechanics, and the statement and reference values of code_aster's test
// files astest/sdll01a.comm and sdll15a.comm), run as a user would
// (read_inp, compute_modes) on a coarse and a 4 times finer mesh.
//
// Two references per mode: the closed form of the stated problem (nobody's
// numbers: exact, so the tolerance is the discretisation error left after
// Richardson extrapolation, bounded by the correction) and the published
// value (to the acceptance code_aster's own test applies to it: 0.2 % for
// SDLL01, 0.5 % and 0.05 % for SDLL15's two cases). Where a published value
// is not the closed form of its own statement, the test says by how much.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <unsupported/Eigen/MatrixFunctions>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "fem/inp_reader.h"
#include "fem/modal_analysis.h"

namespace {

namespace fem = framedyn::fem;

constexpr double kPi = 3.14159265358979323846;

const std::string kBenchmarks = std::string(FRAMEDYN_SOURCE_DIR) + "/tests/data/benchmarks/";

struct ModeRun {
  std::vector<double> hz;
  fem::ModalResult result;
};

ModeRun modes_of(const std::string& deck, int n) {
  const fem::FrameModel model = fem::read_inp(kBenchmarks + deck);
  EXPECT_EQ(model.requested_modes, n) << deck;  // the deck's *FREQUENCY step: the published mode count
  fem::ModalOptions options;
  options.mode_count = n;
  ModeRun run{{}, fem::compute_modes(model, options)};
  EXPECT_TRUE(run.result.certified) << deck;
  EXPECT_EQ(run.result.rigid_body_modes_expected, 0) << deck;
  for (const fem::Mode& m : run.result.modes) run.hz.push_back(m.frequency_hz);
  EXPECT_EQ(run.hz.size(), static_cast<size_t>(n)) << deck;
  return run;
}

// A root of f in [lo, hi] by bisection (f changes sign there).
double bisect(const std::function<double(double)>& f, double lo, double hi) {
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (f(lo) * f(mid) <= 0.0 ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

// SDLL01's statement (both cases): the beam, SI units.
constexpr double kSdll01E = 2.0e11, kSdll01Nu = 0.3, kSdll01Rho = 7800.0, kSdll01Length = 1.0, kSdll01Area = 0.02,
                 kSdll01Inertia = 0.1 * 0.2 * 0.2 * 0.2 / 12.0;
constexpr double kSdll01G = kSdll01E / (2.0 * (1.0 + kSdll01Nu)), kSdll01K = 10.0 * (1.0 + kSdll01Nu) / (12.0 + 11.0 * kSdll01Nu);

// SDLL01 case 1's closed form: the simply supported Timoshenko beam's bending
// roots (the lower root of its quadratic in ω², α = nπ/L) and the fixed-free
// bar's axial roots, in ascending order (bending 1, axial 1, bending 2, 3,
// axial 2, bending 4).
std::array<double, 6> sdll01_case1_closed_form() {
  const double e = kSdll01E, rho = kSdll01Rho, length = kSdll01Length, area = kSdll01Area, inertia = kSdll01Inertia, g = kSdll01G, k = kSdll01K;
  auto bending = [&](int n) {
    const double a = n * kPi / length;
    const double c4 = rho * rho * inertia / (k * g), c2 = -(rho * area + rho * inertia * a * a + rho * e * inertia * a * a / (k * g)),
                 c0 = e * inertia * std::pow(a, 4);
    return std::sqrt((-c2 - std::sqrt(c2 * c2 - 4.0 * c4 * c0)) / (2.0 * c4)) / (2.0 * kPi);
  };
  auto axial = [&](int i) { return (2.0 * i - 1.0) / (4.0 * length) * std::sqrt(e / rho); };
  return {bending(1), axial(1), bending(2), bending(3), axial(2), bending(4)};
}

// SDLL01 case 1: a 1 m steel beam, RECT 0.1 × 0.2 (0.2 in the plane), on
// simple supports at its neutral fibre, A pinned, B on a roller, in-plane.
// Its in-plane roots are the simply supported Timoshenko beam's bending
// roots (shear coefficient k = 10(1 + ν)/(12 + 11ν) = 1/1.17692, the value
// the statement gives; rotary inertia ρI) and the fixed-free bar's axial
// roots (2i − 1)/(4L) √(E/ρ). Published (ANALYTIQUE): 431.555, 1265.924,
// 1498.295, 2870.661, 3797.773, 4377.837 Hz. The bending closed form gives
// 431.882, 1500.367, 2870.796, 4361.249: the published bending values are
// 0.08 %, 0.14 %, 0.005 % from it (inside code_aster's 0.2 %) and 0.38 %
// for the fourth, which the test states rather than hides. 10 and 40 B32,
// h^4 (quadratic elements): correction (fine − coarse)/255.
TEST(CodeAsterSdll01ShortBeam, InPlaneRootsEqualTheSimplySupportedTimoshenkoBeamAndTheBar) {
  const ModeRun coarse = modes_of("code_aster_sdll01_short_beam.inp", 6);
  const ModeRun fine = modes_of("code_aster_sdll01_short_beam_fine.inp", 6);
  ASSERT_EQ(fine.hz.size(), 6u);
  ASSERT_EQ(coarse.hz.size(), 6u);
  EXPECT_NEAR(1.0 / kSdll01K, 1.17692, 5e-6);  // the statement's shear coefficient
  const std::array<double, 6> closed = sdll01_case1_closed_form();
  const std::array<double, 6> published = {431.555, 1265.924, 1498.295, 2870.661, 3797.773, 4377.837};
  std::printf("mode  closed form  10 B32     40 B32     extrapolated  published\n");
  for (int m = 0; m < 6; ++m) {
    const double correction = (fine.hz[m] - coarse.hz[m]) / 255.0;
    const double extrapolated = fine.hz[m] + correction;
    std::printf("%4d  %10.4f  %10.4f %10.4f %10.4f  %10.3f\n", m + 1, closed[m], coarse.hz[m], fine.hz[m], extrapolated, published[m]);
    // + 1e-9: ten times the eigensolver's convergence tolerance.
    EXPECT_NEAR(extrapolated, closed[m], std::abs(correction) + 1e-9 * closed[m]) << "mode " << m + 1;
    if (m < 5) {
      EXPECT_LT(std::abs(fine.hz[m] / published[m] - 1.0), 2e-3) << "mode " << m + 1 << " against the published value (code_aster's 0.2 %)";
    }
  }
  // The published fourth bending root lies 0.38 % above the closed form of
  // its statement (and above code_aster's own 40-element 4370.82 Hz, an upper
  // bound): outside code_aster's 0.2 %, by the reference, not the model.
  EXPECT_GT(published[5] / closed[5] - 1.0, 3.5e-3);
  EXPECT_LT(published[5] / closed[5] - 1.0, 4.0e-3);
}

// SDLL01 case 2: the beam of case 1 supported at the base of its section,
// 0.1 m below the neutral fibre, through massless rigid arms (code_aster: two
// stiff elements, E = 2e16, RHO = 0; here *RIGID BODY ties): C under A
// pinned, D under B on a roller. The offset couples bending and extension
// (at A: v = 0, u + e ψ = 0, M − e N = 0; at B: v = 0, N = 0, M = 0: the
// roller leaves B's arm free to turn and slide). Closed form of that statement:
// the exact solution of the in-plane Timoshenko beam and bar, the state
// (u, N/EA, v, V/kGA, ψ, M/EI) carried over the span by the matrix
// exponential of the field equations (N' = −ρAω²u, V' = −ρAω²v,
// M' = −V − ρIω²ψ), the roots of the 3 × 3 determinant of the conditions at B
// by bisection. It reproduces case 1's closed form (e = 0) to 1e-8, checked
// below. Published (ANALYTIQUE, from the VPCS guide): 392.8, —, 1592.0, 2629.2,
// 3126.2 Hz with code_aster's acceptance 0.5 %, 3 %, 5.8 %, 4.5 %: an
// approximate reference, 0.4 % to 5.3 % below the exact roots (394.471,
// 922.559, 1637.753, 2776.872, 3259.083). code_aster's own 40 POU_D_T values
// (VALE_CALC: 394.477, 922.607, 1638.231, 2778.700, 3261.670) lie above the
// exact roots by its element's discretisation error, which its case-1 values
// show against case 1's closed form: at most 0.095 % below 4000 Hz.
TEST(CodeAsterSdll01BaseSupports, OffsetSupportRootsEqualTheExactTimoshenkoBeamAndBarSolution) {
  const ModeRun coarse = modes_of("code_aster_sdll01_base_supports.inp", 5);
  const ModeRun fine = modes_of("code_aster_sdll01_base_supports_fine.inp", 5);
  ASSERT_EQ(fine.hz.size(), 5u);
  ASSERT_EQ(coarse.hz.size(), 5u);
  const double e = kSdll01E, rho = kSdll01Rho, length = kSdll01Length, area = kSdll01Area, inertia = kSdll01Inertia, g = kSdll01G, k = kSdll01K;
  const double offset = 0.1;
  auto determinant = [&](double hz, double arm) {
    const double w2 = std::pow(2.0 * kPi * hz, 2);
    Eigen::Matrix<double, 6, 6> a = Eigen::Matrix<double, 6, 6>::Zero();  // y' = a y, y = (u, N/EA, v, V/kGA, ψ, M/EI)
    a(0, 1) = 1.0;
    a(1, 0) = -rho * w2 / e;
    a(2, 3) = 1.0;
    a(2, 4) = 1.0;
    a(3, 2) = -rho * w2 / (k * g);
    a(4, 5) = 1.0;
    a(5, 3) = -k * g * area / (e * inertia);
    a(5, 4) = -rho * w2 / e;
    const Eigen::Matrix<double, 6, 6> transfer = (a * length).exp();
    Eigen::Matrix<double, 6, 3> start = Eigen::Matrix<double, 6, 3>::Zero();  // at A: v = 0, u = −e ψ, M = e N; free ψ, N, V
    start(4, 0) = 1.0;
    start(0, 0) = -arm;
    start(1, 1) = 1.0;
    start(5, 1) = arm * area / inertia;
    start(3, 2) = 1.0;
    const Eigen::Matrix<double, 6, 3> end = transfer * start;
    Eigen::Matrix3d at_b;  // at B: v = 0, N = 0, M = 0
    at_b << end.row(2), end.row(1), end.row(5);
    return at_b.determinant();
  };
  auto roots = [&](double arm, double top_hz) {
    std::vector<double> found;
    for (double lo = 10.0; lo < top_hz; lo += 10.0) {
      if (determinant(lo, arm) * determinant(lo + 10.0, arm) <= 0.0) found.push_back(bisect([&](double f) { return determinant(f, arm); }, lo, lo + 10.0));
    }
    return found;
  };
  // The transfer matrix with no arm is case 1's problem: its closed form to 1e-9.
  const std::vector<double> case1 = roots(0.0, 4500.0);
  const std::array<double, 6> case1_closed = sdll01_case1_closed_form();
  ASSERT_EQ(case1.size(), 6u);
  for (int m = 0; m < 6; ++m) EXPECT_NEAR(case1[m], case1_closed[m], 1e-8 * case1_closed[m]) << "case 1, mode " << m + 1;

  const std::vector<double> closed = roots(offset, 3400.0);
  ASSERT_EQ(closed.size(), 5u);
  const std::array<double, 5> published = {392.8, 0.0, 1592.0, 2629.2, 3126.2};
  const std::array<double, 5> acceptance = {5e-3, 0.0, 0.03, 0.058, 0.045};
  const std::array<double, 5> code_aster = {394.477395644, 922.60726346859, 1638.23105, 2778.69999, 3261.66994};
  std::printf("mode  closed form  10 B32     40 B32     extrapolated  code_aster 40 POU_D_T  published\n");
  for (int m = 0; m < 5; ++m) {
    const double correction = (fine.hz[m] - coarse.hz[m]) / 255.0;
    const double extrapolated = fine.hz[m] + correction;
    std::printf("%4d  %10.4f  %10.4f %10.4f %10.4f  %10.3f  %10.1f\n", m + 1, closed[m], coarse.hz[m], fine.hz[m], extrapolated, code_aster[m], published[m]);
    // + 1e-9: ten times the eigensolver's convergence tolerance.
    EXPECT_NEAR(extrapolated, closed[m], std::abs(correction) + 1e-9 * closed[m]) << "mode " << m + 1;
    // code_aster's own model of the same statement: above the exact root by
    // at most its case-1 discretisation error (0.095 %).
    EXPECT_GT(code_aster[m], fine.hz[m] * (1.0 - 1e-6)) << "mode " << m + 1;
    EXPECT_LT(code_aster[m] / fine.hz[m] - 1.0, 9.5e-4) << "mode " << m + 1;
    if (published[m] > 0.0) {
      EXPECT_LT(std::abs(fine.hz[m] / published[m] - 1.0), acceptance[m]) << "mode " << m + 1 << " against the published value (code_aster's acceptance)";
    }
  }
}

// SDLL15 case 1: a 10 m steel tube cantilever (De 0.35, Di 0.32), Euler–
// Bernoulli, with 1000 kg at its tip (no rotary inertia). Closed forms: the
// bending roots of 1 + cos βL cosh βL + (M/m)βL(cos βL sinh βL − sin βL
// cosh βL) = 0 (m = ρAL, the beam's mass), twice each; the axial root of
// βL tan βL = m/M; the torsion root √(G/ρ)/(4L) (the tip mass has no rotary
// inertia). They give 1.65543, 16.07114, 50.02345, 76.47055, 80.44808,
// 103.19954 Hz against the published 1.65, 16.07, 50.02, 76.47, 80.47,
// 103.2: the first pair is published truncated (0.33 % below), the torsion
// root 0.027 % above; code_aster accepts 0.5 %. 10 and 40 B33: bending h^4
// (correction /255), axial and torsion h^2 (linear interpolation, /15).
TEST(CodeAsterSdll15TipMass, BendingPairsAxialAndTorsionRootsEqualTheirClosedFormsAndThePublishedValues) {
  const ModeRun coarse = modes_of("code_aster_sdll15_tip_mass.inp", 10);
  const ModeRun fine = modes_of("code_aster_sdll15_tip_mass_fine.inp", 10);
  ASSERT_EQ(fine.hz.size(), 10u);
  ASSERT_EQ(coarse.hz.size(), 10u);
  const double e = 2.1e11, nu = 0.3, rho = 7800.0, length = 10.0, tip = 1000.0;
  const double area = kPi / 4.0 * (0.35 * 0.35 - 0.32 * 0.32), inertia = kPi / 64.0 * (std::pow(0.35, 4) - std::pow(0.32, 4));
  const double beam = rho * area * length;
  // The model's mass: the tube and the tip mass (the supported DOFs included).
  EXPECT_NEAR(fine.result.total_mass[0], beam + tip, 1e-9 * (beam + tip));
  auto frequency_equation = [&](double b) {
    return 1.0 + std::cos(b) * std::cosh(b) + tip / beam * b * (std::cos(b) * std::sinh(b) - std::sin(b) * std::cosh(b));
  };
  auto bending = [&](double lo, double hi) {
    const double b = bisect(frequency_equation, lo, hi);
    return b * b / (2.0 * kPi * length * length) * std::sqrt(e * inertia / (rho * area));
  };
  const double f1 = bending(1.0, 1.6), f2 = bending(3.5, 4.5), f3 = bending(6.5, 7.5), f4 = bending(10.0, 10.6);
  const double axial = bisect([&](double b) { return b * std::tan(b) - beam / tip; }, 0.01, 1.5) / (2.0 * kPi * length) * std::sqrt(e / rho);
  const double torsion = std::sqrt(e / (2.0 * (1.0 + nu)) / rho) / (4.0 * length);
  const std::array<double, 10> closed = {f1, f1, f2, f2, f3, f3, axial, torsion, f4, f4};
  const std::array<double, 10> published = {1.65, 1.65, 16.07, 16.07, 50.02, 50.02, 76.47, 80.47, 103.2, 103.2};
  std::printf("mode  closed form  10 B33     40 B33     extrapolated  published\n");
  for (int m = 0; m < 10; ++m) {
    const double order = (m == 6 || m == 7) ? 15.0 : 255.0;  // h^2 for the axial and torsion roots, h^4 for bending
    const double correction = (fine.hz[m] - coarse.hz[m]) / order;
    const double extrapolated = fine.hz[m] + correction;
    std::printf("%4d  %10.5f  %10.5f %10.5f %10.5f  %10.3f\n", m + 1, closed[m], coarse.hz[m], fine.hz[m], extrapolated, published[m]);
    EXPECT_NEAR(extrapolated, closed[m], std::abs(correction) + 1e-8 * closed[m]) << "mode " << m + 1;
    EXPECT_LT(std::abs(fine.hz[m] / published[m] - 1.0), 5e-3) << "mode " << m + 1 << " against the published value (code_aster's 0.5 %)";
  }
  EXPECT_GT(closed[0] / published[0] - 1.0, 3e-3);  // the published 1.65 Hz is truncated: 0.33 % below the root
}

// SDLL15 case 2: the same tube with the 1000 kg mass 1 m off the axis (along
// y), tied to the tip by *RIGID BODY: bending in x-z couples with torsion,
// bending in x-y with extension. Published (VPCS, computed with an Euler
// beam): 1.636, 1.642, 13.46, 13.59, 28.90, 31.96, 61.62, 63.93 Hz;
// code_aster accepts 0.05 %. No closed form: the 40-element deck must lie
// within 0.05 % of each and be converged (10 → 40 elements moves no root by
// more than 0.05 %, the largest move 0.03 % on the torsion-dominated 61.6 Hz).
TEST(CodeAsterSdll15EccentricTipMass, CoupledRootsEqualThePublishedValues) {
  const ModeRun coarse = modes_of("code_aster_sdll15_tip_mass_eccentric.inp", 8);
  const ModeRun fine = modes_of("code_aster_sdll15_tip_mass_eccentric_fine.inp", 8);
  ASSERT_EQ(fine.hz.size(), 8u);
  ASSERT_EQ(coarse.hz.size(), 8u);
  const std::array<double, 8> published = {1.636, 1.642, 13.46, 13.59, 28.90, 31.96, 61.62, 63.93};
  std::printf("mode  10 B33     40 B33     published\n");
  for (int m = 0; m < 8; ++m) {
    std::printf("%4d  %10.5f %10.5f %10.3f\n", m + 1, coarse.hz[m], fine.hz[m], published[m]);
    EXPECT_LT(std::abs(fine.hz[m] / published[m] - 1.0), 5e-4) << "mode " << m + 1 << " against the published value (code_aster's 0.05 %)";
    EXPECT_LT(std::abs(coarse.hz[m] / fine.hz[m] - 1.0), 5e-4) << "mode " << m + 1 << ": the mesh is converged";
  }
}

}  // namespace
