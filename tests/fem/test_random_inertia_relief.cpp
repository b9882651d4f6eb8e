// Random and harmonic response of frames free to move rigidly, against
// computations that share nothing with the modal superposition but the
// matrices:
//   - inertia relief in the random response (docs/theory/fem.md, Eq. S.6):
//     the elastic displacement and fiber-stress RMS of a free-free beam under
//     a white-noise end force equal those integrated from the direct solve
//     (K - omega^2 M + i omega C) u = F, its rigid part u_r = R R^T M u
//     removed, over the same grid;
//   - with only the rigid-body modes kept, the response is the relieved
//     static correction alone: the static inertia-relief solution
//     (`framedyn static --inertia-relief`, solved without modes);
//   - the harmonic response of a beam on one pin (three rotations free)
//     equals the direct solve, rigid rotations included;
//   - the refusals: a frame free to move rigidly without inertia relief,
//     inertia relief on a frame held against every rigid motion.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <iostream>

#include "fem/beam_section.h"
#include "fem/harmonic_response.h"
#include "fem/modal_frequency_response.h"
#include "fem/random_response.h"
#include "fem/section_forces.h"
#include "fem/static_analysis.h"
#include "tests/support/beam_meshes.h"
#include "tests/support/frequency_domain.h"

namespace {

using namespace framedyn::fem;
using cd = std::complex<double>;
constexpr double kPi = 3.14159265358979323846;
constexpr double kAlpha = 2.0, kBeta = 1e-5;  // Rayleigh damping: a matrix for the direct solve, diagonal in the modes

// A uniform steel beam 1 m long, 50 mm square, along X; `elements` Euler-Bernoulli (B33) elements, no supports.
FrameModel free_beam(int elements) {
  framedyn::testing::StraightBeamSpec spec;
  spec.length = 1.0;
  spec.elements = elements;
  spec.section = rectangle_section(0.05, 0.05, 0.3);
  spec.material = framedyn::testing::steel();
  return framedyn::testing::straight_beam(spec);
}

// The direct solve with the tests' Rayleigh damping, on all DOFs.
Eigen::VectorXcd direct_solve(const FrameDynamics& frame, const Eigen::VectorXd& load, double omega) {
  return framedyn::testing::direct_frequency_solve(frame, load, omega, kAlpha, kBeta);
}

LoadPsd white(double lo, double hi, double s) { return LoadPsd{{lo, hi}, {s, s}}; }

TEST(InertiaRelief, FreeFreeBeamElasticRmsUnderWhiteNoiseEqualsTheRelievedDirectSolve) {
  const FrameModel model = free_beam(20);
  FrameDynamics frame(model);
  ASSERT_TRUE(frame.free_free());
  ASSERT_EQ(frame.rigid_count(), 6);
  Eigen::VectorXd load = Eigen::VectorXd::Zero(model.dof_count());
  const int tip = 20;
  load(6 * tip + 2) = 100.0;  // a transverse force at one end: it drives the rigid translation and rotation, and bends the beam
  const double s_a = 0.3;     // 1/Hz, white from 1 Hz to 2 kHz (four bending modes, the first torsion mode)
  RandomOptions o;
  o.response.damping = ModalDamping::rayleigh_damping(kAlpha, kBeta);
  o.inertia_relief = true;
  const RandomResult r = random_response(frame, frame.all_modes(), load, white(1.0, 2000.0, s_a), o);
  EXPECT_TRUE(r.inertia_relief);
  EXPECT_EQ(r.rigid_body_modes, 6);
  EXPECT_EQ(r.modes_used, frame.dofs().free_count() - 6);

  // The direct computation on the same grid, by the trapezoidal rule: u_e = u - R R^T M u (R from the frame's geometry).
  const std::vector<double>& f = r.frequencies_hz;
  Eigen::VectorXd ms = Eigen::VectorXd::Zero(model.dof_count());
  std::vector<double> stress_ms;
  Eigen::VectorXd prev_u2;
  std::vector<double> prev_s2;
  for (std::size_t k = 0; k < f.size(); ++k) {
    const Eigen::VectorXcd u = direct_solve(frame, load, 2 * kPi * f[k]);
    Eigen::VectorXcd all = Eigen::VectorXcd::Zero(u.size());
    const std::vector<int>& free = frame.dofs().free_dofs;
    Eigen::VectorXd re_free(free.size()), im_free(free.size());
    for (std::size_t e = 0; e < free.size(); ++e) re_free(static_cast<Eigen::Index>(e)) = u(free[e]).real(), im_free(static_cast<Eigen::Index>(e)) = u(free[e]).imag();
    re_free = frame.elastic_part(re_free);
    im_free = frame.elastic_part(im_free);
    for (std::size_t e = 0; e < free.size(); ++e) all(free[e]) = cd(re_free(static_cast<Eigen::Index>(e)), im_free(static_cast<Eigen::Index>(e)));
    const Eigen::VectorXd u2 = all.cwiseAbs2() * s_a;
    const std::vector<StationResult> re = recover_stations(model, all.real(), 2), im = recover_stations(model, all.imag(), 2);
    std::vector<double> s2;
    for (std::size_t st = 0; st < re.size(); ++st)
      for (std::size_t p = 0; p < re[st].fiber_stress.size(); ++p) s2.push_back(std::norm(cd(re[st].fiber_stress[p], im[st].fiber_stress[p])) * s_a);
    if (k > 0) {
      const double h = 0.5 * (f[k] - f[k - 1]);
      ms += h * (u2 + prev_u2);
      stress_ms.resize(s2.size(), 0.0);
      for (std::size_t i = 0; i < s2.size(); ++i) stress_ms[i] += h * (s2[i] + prev_s2[i]);
    }
    prev_u2 = u2;
    prev_s2 = s2;
  }
  const Eigen::VectorXd rms = ms.cwiseSqrt();
  double worst = 0.0;
  for (int n = 0; n <= 20; ++n)
    for (int d = 0; d < 6; ++d) {
      const int g = 6 * n + d;
      // Each DOF against the largest RMS of its kind (translations, rotations): some are zero by symmetry.
      double kind = 0.0;
      for (int m = 0; m <= 20; ++m)
        for (int e = (d < 3 ? 0 : 3); e < (d < 3 ? 3 : 6); ++e) kind = std::max(kind, rms(6 * m + e));
      worst = std::max(worst, std::abs(r.rms(g) - rms(g)) / kind);
    }
  double stress_max = 0.0;
  for (double v : stress_ms) stress_max = std::max(stress_max, v);
  const double stress_error = std::abs(r.max_stress_rms - std::sqrt(stress_max)) / std::sqrt(stress_max);
  std::cout << "[ measured ] free-free beam, white noise 1-2000 Hz, " << f.size() << " grid points: elastic displacement RMS, "
            << "largest |modal - direct| / largest of its kind " << worst << "; tip w RMS " << r.rms(6 * tip + 2) << " m (direct "
            << rms(6 * tip + 2) << "); largest fiber-stress RMS " << r.max_stress_rms << " Pa (direct " << std::sqrt(stress_max)
            << "), relative difference " << stress_error << "\n";
  // All modes and the same grid on both sides: the two differ by the round-off of the eigensolution and of the
  // direct solves only (measured 8e-11; 1e-9 leaves a factor of ten for another machine's round-off).
  EXPECT_LT(worst, 1e-9);
  EXPECT_LT(stress_error, 1e-9);
  // The elastic part has no mean rigid motion: R^T M u_e = 0 for the RMS-carrying shapes is what elastic_part ensures;
  // here, the ends of a free beam bent by an end force both move (no support holds either).
  EXPECT_GT(r.rms(6 * 0 + 2), 0.1 * r.rms(6 * tip + 2));
}

TEST(InertiaRelief, FarBelowTheFirstElasticModeTheElasticRmsIsTheStaticInertiaReliefSolution) {
  // With the rigid-body modes only, the elastic part is the static correction alone, r = G F_rel (Eq. H.4), which must
  // be the relieved static solution of `framedyn static --inertia-relief` (Eq. 19.5), computed there without modes:
  // sigma_u = |u_static| sqrt(S_a (f_b - f_a)) to round-off. (The true elastic response differs from it by
  // O((f / f_1)^2), 3e-5 here: far below the first elastic mode f_1 the static correction is all of it.)
  FrameModel model = free_beam(20);
  framedyn::testing::add_nodal_force(model, 20, Eigen::Vector3d(0, 0, 100.0));
  model.index();
  FrameDynamics frame(model);
  StaticOptions so;
  so.inertia_relief = true;
  const StaticResult st = solve_static(model, {}, so);
  ASSERT_TRUE(st.inertia_relief);
  const ModalBasis basis = frame.all_modes();
  const double f1 = std::sqrt(basis.eigenvalues(6)) / (2 * kPi);
  const double fa = 0.5, fb = 1.0, s_a = 2.0;
  RandomOptions o;
  o.response.damping = ModalDamping::ratio(0.02);
  o.response.mode_count = 6;  // the rigid-body modes: no elastic mode left, the static correction carries it all
  o.inertia_relief = true;
  const RandomResult r = random_response(frame, basis, applied_loads(model), white(fa, fb, s_a), o);
  EXPECT_EQ(r.modes_used, 0);
  const double bound = 2.0 * (fb / f1) * (fb / f1);
  double worst = 0.0;
  for (int g = 0; g < model.dof_count(); ++g) {
    const double expected = std::abs(st.displacement(g)) * std::sqrt(s_a * (fb - fa));
    worst = std::max(worst, std::abs(r.rms(g) - expected) / (st.displacement.cwiseAbs().maxCoeff() * std::sqrt(s_a * (fb - fa))));
  }
  std::cout << "[ measured ] elastic RMS of the relieved static correction vs static --inertia-relief: largest difference "
            << worst << " of the largest (the dynamics left out: 2 (f_b/f_1)^2 = " << bound << ", f_1 = " << f1 << " Hz)\n";
  EXPECT_LT(worst, 1e-9);  // round-off: two solves of one linear system
}

TEST(PartialSupports, HarmonicResponseOfABeamOnOnePinEqualsTheDirectSolveRigidRotationsIncluded) {
  // A beam on a pin at one end (translations held, three rotations free): the modal series with all modes, rigid ones
  // included, is the direct frequency-domain solution at every frequency, below, between and above the elastic modes.
  FrameModel model = free_beam(12);
  framedyn::testing::pin_dofs(model, 0, {0, 1, 2});
  model.index();
  FrameDynamics frame(model);
  ASSERT_FALSE(frame.free_free());
  ASSERT_EQ(frame.rigid_count(), 3);
  Eigen::VectorXd load = Eigen::VectorXd::Zero(model.dof_count());
  load(6 * 12 + 2) = 100.0;  // turns the beam about the pin and bends it
  load(6 * 6 + 1) = 40.0;
  FrequencyResponseOptions o;
  o.damping = ModalDamping::rayleigh_damping(kAlpha, kBeta);
  const ModalBasis basis = frame.all_modes();
  const ModalFrequencyResponse r = modal_frequency_response(frame, basis, load, o);
  EXPECT_EQ(r.rigid_body_modes, 3);
  std::cout << "[ measured ] beam on one pin: first elastic mode " << std::sqrt(basis.eigenvalues(3)) / (2 * kPi) << " Hz\n";
  double worst = 0.0;
  const double f1 = std::sqrt(basis.eigenvalues(3)) / (2 * kPi);  // the first elastic mode
  for (double hz : {0.5, 5.0, 100.0, 300.0, 1000.0, 3000.0}) {
    const Eigen::VectorXcd exact = direct_solve(frame, load, 2 * kPi * hz);
    const double err = (r.displacement(2 * kPi * hz) - exact).cwiseAbs().maxCoeff() / exact.cwiseAbs().maxCoeff();
    worst = std::max(worst, err);
    std::cout << "[ measured ] beam on one pin at " << hz << " Hz: |modal - direct| / max|direct| = " << err << "\n";
    // Round-off of the dense eigensolution (about 1e-12 relative in its vectors), which the 1/omega^2 of the
    // rigid-body terms magnifies against the elastic ones by (f_1/f)^2 below the first elastic mode: the bound
    // 1e-9 + 1e-12 (f_1/f)^2 (measured 2e-8 at 0.5 Hz, where the bound is 1.3e-7; 1e-11 above f_1).
    EXPECT_LT(err, 1e-9 + 1e-12 * (f1 / hz) * (f1 / hz)) << hz << " Hz";
  }
  // Far below the elastic modes the beam turns about the pin as a rigid body: J theta'' + alpha J theta' = F L, so the
  // tip's w = L theta = (F L^2 / J) / (-omega^2 + i alpha omega), J = m L^2 / 3 the beam's moment of inertia about the
  // pin (the 40 N along Y turns it about Z), alpha J theta' the Rayleigh mass-proportional damping of the rotation.
  // The elastic part adds the pinned beam's relieved deflection, below F L^3 / (3 EI) = 3e-4 m against 1.3 m:
  // the bound is 1e-3 of the rigid motion.
  const double mass = 7850.0 * 0.05 * 0.05 * 1.0, omega = 2 * kPi * 0.5;
  const cd rigid_tip = 100.0 * 1.0 * 1.0 / (mass / 3.0) / cd(-omega * omega, kAlpha * omega);
  const cd tip = r.displacement(omega)(6 * 12 + 2);
  std::cout << "[ measured ] beam on one pin: harmonic modal series vs direct solve, largest relative difference " << worst
            << "; tip w at 0.5 Hz " << tip << " m, rigid rotation about the pin " << rigid_tip << " m, relative difference "
            << std::abs(tip - rigid_tip) / std::abs(rigid_tip) << "\n";
  EXPECT_LT(std::abs(tip - rigid_tip), 1e-3 * std::abs(rigid_tip));
}

TEST(InertiaRelief, FrameFreeToMoveRigidlyIsRefusedWithoutIt) {
  FrameModel model = free_beam(4);
  framedyn::testing::pin_dofs(model, 0, {0, 1, 2});
  model.index();
  FrameDynamics frame(model);
  Eigen::VectorXd load = Eigen::VectorXd::Zero(model.dof_count());
  load(6 * 4 + 2) = 1.0;
  try {
    random_response(frame, frame.all_modes(), load, white(1, 10, 1), RandomOptions{});
    FAIL() << "a beam on one pin was not refused";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("inertia relief"), std::string::npos) << e.what();
  }
}

TEST(InertiaRelief, IsRefusedForAFrameHeldAgainstEveryRigidMotion) {
  FrameModel model = free_beam(4);
  framedyn::testing::clamp_node(model, 0);
  model.index();
  FrameDynamics frame(model);
  Eigen::VectorXd load = Eigen::VectorXd::Zero(model.dof_count());
  load(6 * 4 + 2) = 1.0;
  RandomOptions o;
  o.inertia_relief = true;
  EXPECT_THROW(random_response(frame, frame.all_modes(), load, white(1, 10, 1), o), std::invalid_argument);
}

}  // namespace
