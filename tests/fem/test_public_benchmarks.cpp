// Public benchmark decks (issue 13, last verification line): meshes written
// for framedyn from published problem statements, run as a user would run
// them (read_inp, compute_modes) and compared with the published reference
// values. Each deck's comment lines and docs/validation.md ("Public benchmark
// decks") cite the source.
//
// NAFEMS FV2, pin-ended double cross (tests/data/benchmarks/nafems_fv2_*.inp):
// eight 5 m arms of 0.125 m square steel section, pinned at their ends,
// in-plane vibration. Published closed-form frequencies (NAFEMS R0015 / TNSB,
// as restated in Altair's OS-V 0400 and SS-V 2060): 11.336 Hz (mode 1),
// 17.709 Hz (modes 2-8, grouped 2-3 and 4-8), 45.345 Hz (mode 9), 57.390 Hz
// (modes 10-16, grouped 10-11 and 12-16). The seven-fold roots are the case
// the certified mode sets fix: every request N = 1..16 must return the N
// lowest roots with their multiplicity.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "fem/assembly.h"
#include "fem/inp_reader.h"
#include "fem/modal_analysis.h"
#include "tests/support/run_framedyn.h"
#include "tests/support/temp_dir.h"

namespace {

namespace fem = framedyn::fem;

constexpr double kPi = 3.14159265358979323846;

const std::string kBenchmarks = std::string(FRAMEDYN_SOURCE_DIR) + "/tests/data/benchmarks/";

// The published FV2 frequencies (Hz), modes 1..16, and the published grouping
// of equal roots: {1}, {2,3}, {4..8}, {9}, {10,11}, {12..16} (first, last;
// 1-based).
constexpr std::array<double, 16> kFv2PublishedHz = {11.336, 17.709, 17.709, 17.709, 17.709, 17.709, 17.709, 17.709,
                                                    45.345, 57.390, 57.390, 57.390, 57.390, 57.390, 57.390, 57.390};
constexpr std::array<std::array<int, 2>, 6> kFv2Groups = {{{1, 1}, {2, 3}, {4, 8}, {9, 9}, {10, 11}, {12, 16}}};
// The published values are given to 5 significant figures: half a unit in
// the last digit.
constexpr double kFv2Rounding = 0.0005;  // Hz

// All eigenvalues of (K_ff, M_ff) by a dense solver, ascending: an
// independent reference for the sparse, certified solver.
Eigen::VectorXd dense_eigenvalues(const fem::FrameModel &model) {
  const fem::DofMap dofs = fem::make_dof_map(model);
  const fem::FreeSystem s = fem::assemble(model, dofs, {fem::MassFormulation::consistent, fem::Storage::full});
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> dense(Eigen::MatrixXd(s.stiffness), Eigen::MatrixXd(s.mass),
                                                                        Eigen::EigenvaluesOnly);
  EXPECT_EQ(dense.info(), Eigen::Success);
  return dense.eigenvalues();
}

std::vector<double> frequencies(const fem::FrameModel &model, int n) {
  fem::ModalOptions options;
  options.mode_count = n;
  const fem::ModalResult r = fem::compute_modes(model, options);
  EXPECT_TRUE(r.certified);
  EXPECT_EQ(r.rigid_body_modes_expected,
            0);  // the pinned ends hold the plane cross
  std::vector<double> f;
  for (const fem::Mode &m : r.modes) f.push_back(m.frequency_hz);
  return f;
}

TEST(NafemsFv2DoubleCross, EveryRequestFrom1To16ReturnsTheLowestRootsWithThePublishedMultiplicities) {
  const fem::FrameModel model = fem::read_inp(kBenchmarks + "nafems_fv2_double_cross.inp");
  const Eigen::VectorXd reference = dense_eigenvalues(model);
  ASSERT_GE(reference.size(), 17);
  // The dense roots fall into the published groups: equal within a group
  // (1e-8 relative: round-off of the dense solver is ~1e-12), separated
  // between groups (the 4-element mesh splits 2-3 from 4-8 and 10-11 from
  // 12-16 by 0.1-0.5 %, as in the published FE results).
  for (const auto &g : kFv2Groups) {
    for (int i = g[0]; i < g[1]; ++i)
      EXPECT_NEAR(reference(i) / reference(g[0] - 1), 1.0, 1e-8) << "mode " << i + 1 << " should equal mode " << g[0];
    EXPECT_GT(reference(g[1]) / reference(g[1] - 1) - 1.0, 1e-4) << "group ending at mode " << g[1];
  }
  // For every N, the certified solver returns exactly the N lowest: a
  // dropped copy of a repeated root (the next group in its place) differs
  // by > 1e-4 and cannot pass.
  for (int n = 1; n <= 16; ++n) {
    fem::ModalOptions options;
    options.mode_count = n;
    const fem::ModalResult r = fem::compute_modes(model, options);
    ASSERT_EQ(static_cast<int>(r.modes.size()), n) << "N = " << n;
    EXPECT_TRUE(r.certified) << "N = " << n;
    for (int i = 0; i < n; ++i)
      EXPECT_NEAR(r.modes[static_cast<std::size_t>(i)].eigenvalue, reference(i), 1e-8 * reference(i))
          << "N = " << n << ", mode " << i + 1;
  }
}

// Frequencies against the published closed form. The deck's mesh (4 B33 per
// arm, as the benchmark prescribes) and a 16-element refinement: cubic
// Hermite elements converge as h^4, so the Richardson estimate
// f_16 + (f_16 - f_4)/255 removes the discretisation error of the fine mesh.
// The extrapolated values must equal the published ones to their rounding
// (0.0005 Hz) plus what may be left of the discretisation error (bounded by
// the whole correction).
//
// The published closed form treats the arms as inextensible: the centre
// cannot translate, and every root is that of a pinned-pinned or a
// clamped-pinned arm. That holds for modes 1, 4-9 and 12-16 (the centre does
// not translate). Modes 2-3 and 10-11 move the centre, which the axial
// flexibility of real arms allows: they come out lower (measured 0.16 % and
// 0.55 %; the published 4-element CBAR ratios 0.9958 and 0.9944 show the
// same). So those four are checked on the same decks with the arms made
// axially rigid (A x 1e4, density / 1e4: rho A, E I and hence the in-plane
// bending are unchanged; torsion, whose inertia changes, is held by the
// in-plane boundary conditions), the model the closed form describes.
std::vector<double> fv2_frequencies(const std::string &deck, double axial_stiffening) {
  fem::FrameModel model = fem::read_inp(kBenchmarks + deck);
  for (fem::SectionAssignment &s : model.sections) {
    s.properties.area *= axial_stiffening;
    s.material.density /= axial_stiffening;
  }
  return frequencies(model, 16);
}

void expect_published_after_refinement(double axial_stiffening, const std::vector<int> &modes) {
  const std::vector<double> f4 = fv2_frequencies("nafems_fv2_double_cross.inp", axial_stiffening);
  const std::vector<double> f16 = fv2_frequencies("nafems_fv2_double_cross_fine.inp", axial_stiffening);
  ASSERT_EQ(f4.size(), 16u);
  ASSERT_EQ(f16.size(), 16u);
  std::printf(
      "axial stiffness x %g\nmode  published  4/arm (ratio)      "
      "16/arm (ratio)      extrapolated\n",
      axial_stiffening);
  for (std::size_t i = 0; i < 16; ++i) {
    const double correction = (f16[i] - f4[i]) / 255.0;
    const double extrapolated = f16[i] + correction;
    const double published = kFv2PublishedHz[i];
    std::printf("%4zu  %9.3f  %9.4f (%.4f)  %9.4f (%.5f)  %9.4f\n", i + 1, published, f4[i], f4[i] / published, f16[i],
                f16[i] / published, extrapolated);
    if (std::find(modes.begin(), modes.end(), static_cast<int>(i) + 1) != modes.end()) {
      EXPECT_NEAR(extrapolated, published, kFv2Rounding + std::abs(correction)) << "mode " << i + 1;
    }
  }
}

TEST(NafemsFv2DoubleCross, ModesThatKeepTheCentreStillEqualThePublishedClosedFormAfterRefinement) {
  expect_published_after_refinement(1.0, {1, 4, 5, 6, 7, 8, 9, 12, 13, 14, 15, 16});
}

TEST(NafemsFv2DoubleCross, CentreTranslationPairsEqualTheClosedFormOnceTheArmsAreAxiallyRigid) {
  expect_published_after_refinement(1e4, {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16});
}

// The deck as a user runs it: `framedyn modes DECK --modes 16`. The summary
// reports the library's frequencies (same solver, written to 10 digits), a
// certified set, no rigid-body modes (the pinned ends hold the cross in its
// plane) and the hand-computed mass: 8 arms x 5 m x 0.125^2 m^2 x 8000 kg/m^3
// = 5000 kg.
TEST(NafemsFv2DoubleCross, ModesCommandOnTheDeckReportsTheSameCertifiedSetAndTheHandMass) {
  const std::string deck = kBenchmarks + "nafems_fv2_double_cross.inp";
  const std::vector<double> library = frequencies(fem::read_inp(deck), 16);
  const framedyn::testing::TempDir dir("framedyn_fv2");
  const framedyn::testing::RunResult run =
      framedyn::testing::framedyn(dir, "modes " + framedyn::testing::quote(deck) + " --modes 16 --out out");
  ASSERT_EQ(run.status, 0) << run.err;
  const nlohmann::json summary = nlohmann::json::parse(framedyn::testing::read_file(dir / "out" / "summary.json"));
  const nlohmann::json &frame = summary.at("frame");
  EXPECT_NEAR(frame.at("total_mass").at("value").get<double>(), 8 * 5.0 * 0.125 * 0.125 * 8000.0, 1e-9 * 5000.0);
  EXPECT_TRUE(frame.at("sturm_check").at("certified").get<bool>());
  EXPECT_EQ(frame.at("rigid_body_modes_expected").get<int>(), 0);
  ASSERT_EQ(frame.at("modes").size(), 16u);
  for (std::size_t i = 0; i < 16; ++i)
    EXPECT_NEAR(frame.at("modes")[i].at("frequency").at("value").get<double>(), library[i], 1e-8 * library[i]) << "mode " << i + 1;
}

// NAFEMS FV5, deep simply supported beam
// (tests/data/benchmarks/nafems_fv5_*.inp): 10 m, 2 m x 2 m square, Timoshenko.
// Published closed-form frequencies (the NAFEMS sheet): 42.650 (modes
// 1-2), 71.20 (3, torsion), 125.00 (4, extension), 148.15 (5-6), 213.61 (7,
// torsion), 283.47 (8-9) Hz.
constexpr std::array<double, 9> kFv5PublishedHz = {42.650, 42.650, 71.20, 125.00, 148.15, 148.15, 213.61, 283.47, 283.47};
constexpr std::array<std::array<int, 2>, 6> kFv5Groups = {{{1, 2}, {3, 3}, {4, 4}, {5, 6}, {7, 7}, {8, 9}}};

TEST(NafemsFv5DeepBeam, EveryRequestFrom1To9ReturnsTheLowestRootsWithTheBendingPairs) {
  for (const char *deck : {"nafems_fv5_deep_beam.inp", "nafems_fv5_deep_beam_fine.inp"}) {
    const fem::FrameModel model = fem::read_inp(kBenchmarks + deck);
    const Eigen::VectorXd reference = dense_eigenvalues(model);
    for (const auto &g : kFv5Groups) {
      for (int i = g[0]; i < g[1]; ++i)
        EXPECT_NEAR(reference(i) / reference(g[0] - 1), 1.0, 1e-8) << deck << ": mode " << i + 1 << " should equal mode " << g[0];
      EXPECT_GT(reference(g[1]) / reference(g[1] - 1) - 1.0, 1e-4) << deck << ": group ending at mode " << g[1];
    }
    for (int n = 1; n <= 9; ++n) {
      fem::ModalOptions options;
      options.mode_count = n;
      const fem::ModalResult r = fem::compute_modes(model, options);
      ASSERT_EQ(static_cast<int>(r.modes.size()), n) << deck << ", N = " << n;
      EXPECT_TRUE(r.certified) << deck << ", N = " << n;
      for (int i = 0; i < n; ++i)
        EXPECT_NEAR(r.modes[static_cast<std::size_t>(i)].eigenvalue, reference(i), 1e-8 * reference(i))
            << deck << ", N = " << n << ", mode " << i + 1;
    }
  }
}

// Closed forms for the FV5 beam (10 m, 2 m square, E = 200 GPa, nu = 0.3,
// rho = 8000), from the section framedyn reads (area, I, J, shear area):
//  - bending, simply supported Timoshenko beam, mode n: the lower root of
//    det[kGA a^2 - rhoA w^2, kGA a; kGA a, EI a^2 + kGA - rhoI w^2] = 0,
//    a = n pi / L;
//  - torsion and extension, fixed-free bars (end A held, end B free in
//    u1 and ur1): f = (2m - 1) c / (4 L), c = sqrt(GJ / (rho Ip)), sqrt(E /
//    rho).
std::array<double, 9> fv5_closed_form(const fem::FrameModel &model) {
  const fem::SectionAssignment &s = model.sections.at(0);
  const double E = s.material.youngs_modulus, G = s.material.shear_modulus, rho = s.material.density;
  const double A = s.properties.area, I = s.properties.i11, kGA = G * s.properties.shear_area_1, L = 10.0;
  auto bending = [&](int n) {
    const double a = n * kPi / L;
    const double c2 = rho * A * rho * I;
    const double c1 = -(rho * A * (E * I * a * a + kGA) + rho * I * kGA * a * a);
    const double c0 = kGA * a * a * (E * I * a * a + kGA) - kGA * a * kGA * a;
    return std::sqrt((-c1 - std::sqrt(c1 * c1 - 4.0 * c2 * c0)) / (2.0 * c2)) / (2.0 * kPi);
  };
  const double torsion = std::sqrt(G * s.properties.torsion_constant / (rho * s.properties.polar_moment())) / (4.0 * L);
  const double extension = std::sqrt(E / rho) / (4.0 * L);
  return {bending(1), bending(1), torsion, extension, bending(2), bending(2), 3.0 * torsion, bending(3), bending(3)};
}

// The 5-element B32 deck (the benchmark's 3-noded model) and a 20-element
// refinement, Richardson-extrapolated as h^4 (quadratic elements):
//  - framedyn against the closed forms above (an independent check of the
//    elements): to the remaining discretisation error (the whole correction)
//    plus 1e-6 relative;
//  - against the published values: to their rounding (half a unit in the
//    last published digit) plus the correction, for the modes the published
//    closed form and the one above agree on (3-6, 8-9). Modes 1-2 (42.650)
//    and 7 (213.61) are not the closed forms that reproduce the other
//    published roots (42.645 and 3 x 71.196 = 213.588 Hz): those two are
//    checked against the closed form and their published difference is
//    reported (docs/validation.md, finding).
TEST(NafemsFv5DeepBeam, FrequenciesEqualTheClosedFormAndThePublishedValuesItReproduces) {
  const fem::FrameModel coarse_model = fem::read_inp(kBenchmarks + "nafems_fv5_deep_beam.inp");
  const std::vector<double> coarse = frequencies(coarse_model, 9);
  const std::vector<double> fine = frequencies(fem::read_inp(kBenchmarks + "nafems_fv5_deep_beam_fine.inp"), 9);
  ASSERT_EQ(coarse.size(), 9u);
  ASSERT_EQ(fine.size(), 9u);
  const std::array<double, 9> closed = fv5_closed_form(coarse_model);
  constexpr std::array<double, 9> rounding = {0.0005, 0.0005, 0.005, 0.005, 0.005, 0.005, 0.005, 0.005, 0.005};
  constexpr std::array<bool, 9> published_consistent = {false, false, true, true, true, true, false, true, true};
  std::printf(
      "mode  published  closed form  5 B32 (ratio to published)  20 "
      "B32 (ratio)  extrapolated\n");
  for (std::size_t i = 0; i < 9; ++i) {
    const double correction = (fine[i] - coarse[i]) / 255.0;
    const double extrapolated = fine[i] + correction;
    std::printf("%4zu  %9.3f  %11.4f  %9.4f (%.5f)  %9.4f (%.5f)  %9.4f\n", i + 1, kFv5PublishedHz[i], closed[i], coarse[i],
                coarse[i] / kFv5PublishedHz[i], fine[i], fine[i] / kFv5PublishedHz[i], extrapolated);
    EXPECT_NEAR(extrapolated, closed[i], std::abs(correction) + 1e-6 * closed[i])
        << "mode " << i + 1 << " against the closed form";
    if (published_consistent[i]) {
      EXPECT_NEAR(extrapolated, kFv5PublishedHz[i], rounding[i] + std::abs(correction)) << "mode " << i + 1 << " against NAFEMS";
    } else {
      // The finding, kept visible: the published value lies outside the
      // closed form's rounding interval.
      EXPECT_GT(std::abs(closed[i] - kFv5PublishedHz[i]), rounding[i]) << "mode " << i + 1;
    }
  }
}

// code_aster Validation Manual V2.05.400, case 1
// (tests/data/benchmarks/code_aster_v2_05_400_*.inp): a 0.783 m beam of
// 0.014 m square section (E = 6.07e10 Pa, nu = 0, rho = 2400 kg/m^3) pinned at
// A, free at B, bending in its plane. Published roots of
// sin(kL) cosh(kL) = cos(kL) sinh(kL): kL = 0, 3.9266, 7.06858, 10.2102,
// 13.3518, 16.4934, with omega = sqrt(EI / (rho S)) k^2. The first is the
// rotation about the pin: a partially supported beam, whose rigid-body mode
// must be counted from the support (one) and returned at zero frequency.
// Tolerance: the published roots' rounding (half a unit in their last
// digit, doubled since f ~ (kL)^2) plus the discretisation error left after
// Richardson extrapolation (10 and 40 B33, h^4), bounded by the correction.
TEST(CodeAsterV205400PinnedFreeBeam, RigidRotationAboutThePinAndFiveBendingRootsEqualThePublishedOnes) {
  constexpr std::array<double, 6> kL = {0.0, 3.9266, 7.06858, 10.2102, 13.3518, 16.4934};
  constexpr std::array<double, 6> half_unit = {0.0, 5e-5, 5e-6, 5e-5, 5e-5, 5e-5};
  const double c = 0.014, length = 0.783, E = 6.07e10, rho = 2400.0;
  const double bending = std::sqrt(E * c * c * c * c / 12.0 / (rho * c * c));  // sqrt(EI / (rho S)), m^2/s
  std::array<std::vector<fem::Mode>, 2> modes;
  const std::array<const char *, 2> decks = {"code_aster_v2_05_400_pinned_free_beam.inp",
                                             "code_aster_v2_05_400_pinned_free_beam_fine.inp"};
  for (std::size_t d = 0; d < 2; ++d) {
    fem::ModalOptions options;
    options.mode_count = 6;
    const fem::ModalResult r = fem::compute_modes(fem::read_inp(kBenchmarks + decks[d]), options);
    EXPECT_TRUE(r.certified) << decks[d];
    EXPECT_EQ(r.rigid_body_modes_expected, 1) << decks[d];  // the rotation about the pin
    modes[d] = r.modes;
    ASSERT_EQ(modes[d].size(), 6u) << decks[d];
    EXPECT_TRUE(modes[d][0].rigid_body) << decks[d];
    EXPECT_EQ(modes[d][0].frequency_hz, 0.0) << decks[d];
    for (std::size_t i = 1; i < 6; ++i) EXPECT_FALSE(modes[d][i].rigid_body) << decks[d] << ", mode " << i + 1;
  }
  std::printf("mode  kL        reference [Hz]  10 B33 (ratio)        40 B33 (ratio)         extrapolated\n");
  for (std::size_t i = 1; i < 6; ++i) {
    const double reference = bending * std::pow(kL[i] / length, 2) / (2.0 * kPi);
    const double coarse = modes[0][i].frequency_hz, fine = modes[1][i].frequency_hz;
    const double correction = (fine - coarse) / 255.0;
    const double extrapolated = fine + correction;
    std::printf("%4zu  %-8g  %14.4f  %9.4f (%.6f)  %9.4f (%.7f)  %9.4f\n", i + 1, kL[i], reference, coarse, coarse / reference,
                fine, fine / reference, extrapolated);
    EXPECT_NEAR(extrapolated, reference, 2.0 * half_unit[i] / kL[i] * reference + std::abs(correction)) << "mode " << i + 1;
  }
}

// code_aster SDLL02 (Validation Manual V2.02.002, after VPCS SDLL02/89;
// tests/data/benchmarks/code_aster_sdll02_folded_beam*.inp): a slender steel
// cantilever of two 0.5 m legs folded back on each other at B, in-plane
// bending. Published reference (analytic, Euler-Bernoulli, dynamic stiffness):
// double frequencies with cos(lambda) = 0, lambda_i = (2i - 1) pi / 2,
// f_i = lambda_i^2 / (2 pi L^2) sqrt(E Iz / (rho A)); the eight lowest are the
// reference results: 11.7642, 105.878, 294.104, 576.445 Hz, each twice. The
// pairs are the case certified mode sets exist for: a request for 8 must
// return both copies of every root. The formula is exact (no rounding to
// allow for); the tolerance is the discretisation error left after Richardson
// extrapolation (20 and 40 B33 per leg, h^4), bounded by the correction.
TEST(CodeAsterSdll02FoldedBeam, EightLowestAreTheFourPublishedDoubleRoots) {
  const double length = 0.5, h = 0.005, E = 2.1e11, rho = 7800.0;
  const double bending = std::sqrt(E * h * h / 12.0 / rho);  // sqrt(E Iz / (rho A)) for a rectangle, m^2/s
  std::array<std::vector<fem::Mode>, 2> modes;
  const std::array<const char *, 2> decks = {"code_aster_sdll02_folded_beam.inp", "code_aster_sdll02_folded_beam_fine.inp"};
  for (std::size_t d = 0; d < 2; ++d) {
    const fem::FrameModel model = fem::read_inp(kBenchmarks + decks[d]);
    ASSERT_EQ(model.requested_modes, 8) << decks[d];  // the deck's *FREQUENCY step, as code_aster's 8 reference values
    fem::ModalOptions options;
    options.mode_count = 8;
    const fem::ModalResult r = fem::compute_modes(model, options);
    EXPECT_TRUE(r.certified) << decks[d];
    EXPECT_EQ(r.rigid_body_modes_expected, 0) << decks[d];
    modes[d] = r.modes;
    ASSERT_EQ(modes[d].size(), 8u) << decks[d];
  }
  std::printf("mode  lambda     reference [Hz]  20 B33/leg (ratio)      40 B33/leg (ratio)      extrapolated\n");
  for (std::size_t m = 0; m < 8; ++m) {
    const double lambda = (2.0 * static_cast<double>(m / 2) + 1.0) * kPi / 2.0;
    const double reference = bending * std::pow(lambda / length, 2) / (2.0 * kPi);
    const double coarse = modes[0][m].frequency_hz, fine = modes[1][m].frequency_hz;
    const double correction = (fine - coarse) / 15.0;  // h^4: (2^4 - 1)
    const double extrapolated = fine + correction;
    std::printf("%4zu  %-9.6f  %14.6f  %10.6f (%.8f)  %10.6f (%.9f)  %10.6f\n", m + 1, lambda, reference, coarse, coarse / reference, fine,
                fine / reference, extrapolated);
    // + 1e-9: ten times the eigensolver's convergence tolerance (EigenOptions::tolerance, 1e-10).
    EXPECT_NEAR(extrapolated, reference, std::abs(correction) + 1e-9 * reference) << "mode " << m + 1;
    // The fine deck alone, as a user would run it: within twice the correction (fine - reference = -correction where the error goes as h^4).
    EXPECT_NEAR(fine, reference, 2.0 * std::abs(correction) + 1e-9 * reference) << "mode " << m + 1;
  }
}

}  // namespace
