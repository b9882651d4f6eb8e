// Harmonic response by mode superposition with static correction, against
// numbers nobody tuned: the single-degree-of-freedom oscillator's closed
// form (amplitude, phase and the resonance amplification 1/(2 zeta)), the
// direct frequency-domain solve (K - omega^2 M + i omega C) u = F of the
// same frame, and the steady state of a long transient at one frequency.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <iostream>

#include "fem/beam_section.h"
#include "fem/harmonic_response.h"
#include "fem/modal_frequency_response.h"
#include "fem/modal_transient.h"
#include "fem/section_forces.h"
#include "fem/static_analysis.h"
#include "tests/support/beam_meshes.h"
#include "tests/support/frequency_domain.h"

namespace {

using namespace framedyn::fem;
using cd = std::complex<double>;
constexpr double kPi = 3.14159265358979323846;

// A point mass m on two springs to ground, kx along X and ky along Y; every
// other DOF held. Two uncoupled oscillators: a load along X excites only the first.
FrameModel mass_on_springs(double m, double kx, double ky) {
  FrameModel model;
  model.nodes.push_back({1, Eigen::Vector3d::Zero()});
  model.point_masses.push_back({1, 0, m, Eigen::Matrix3d::Zero()});
  model.springs.push_back({2, 0, 0, -1, 0, kx});
  model.springs.push_back({3, 0, 1, -1, 0, ky});
  for (int d = 2; d < 6; ++d) model.constraints.push_back({0, d, 0.0});
  model.index();
  return model;
}

TEST(SingleDofOscillator, AmplitudeAndPhaseMatchClosedForm) {
  const double m = 3.0, k = 4.0e4, zeta = 0.03, F = 25.0;
  const FrameModel model = mass_on_springs(m, k, 9.0 * k);
  FrameDynamics frame(model);
  const ModalBasis basis = frame.all_modes();
  Eigen::VectorXd load = Eigen::VectorXd::Zero(model.dof_count());
  load(0) = F;
  FrequencyResponseOptions o;
  o.damping = ModalDamping::ratio(zeta);
  const ModalFrequencyResponse r = modal_frequency_response(frame, basis, load, o);
  const double wn = std::sqrt(k / m), c = 2 * zeta * std::sqrt(k * m);
  for (double ratio : {0.1, 0.5, 0.97, 1.0, 1.03, 2.0, 10.0}) {
    const double w = ratio * wn;
    const cd u = r.displacement(w)(0);
    // u = F / (k - m w^2 + i c w): |u| = F / sqrt((k - m w^2)^2 + (c w)^2), phase -atan2(c w, k - m w^2).
    const double amplitude = F / std::sqrt(std::pow(k - m * w * w, 2) + std::pow(c * w, 2));
    EXPECT_NEAR(std::abs(u), amplitude, 1e-12 * amplitude) << "omega/omega_n " << ratio;
    EXPECT_NEAR(std::arg(u), -std::atan2(c * w, k - m * w * w), 1e-12) << "omega/omega_n " << ratio;
    EXPECT_NEAR(std::abs(r.displacement(w)(1)), 0.0, 1e-14 * amplitude);  // the Y oscillator is not loaded
  }
  // At omega = omega_n the amplitude is the static deflection F/k amplified by 1/(2 zeta), 90 degrees behind the load.
  const cd at_resonance = r.displacement(wn)(0);
  EXPECT_NEAR(std::abs(at_resonance) / (F / k), 1.0 / (2 * zeta), 1e-10 / zeta);
  EXPECT_NEAR(std::arg(at_resonance), -kPi / 2, 1e-12);
}

TEST(SingleDofOscillator, SweepFindsTheResonancePeakAtTheDampedPeakFrequency) {
  // The peak of |H| lies at omega_n sqrt(1 - 2 zeta^2), where |u| = F / (k 2 zeta sqrt(1 - zeta^2)).
  const double m = 3.0, k = 4.0e4, zeta = 0.05, F = 25.0;
  const FrameModel model = mass_on_springs(m, k, 9.0 * k);
  FrameDynamics frame(model);
  HarmonicOptions o;
  o.response.damping = ModalDamping::ratio(zeta);
  const double fn = std::sqrt(k / m) / (2 * kPi), fpeak = fn * std::sqrt(1 - 2 * zeta * zeta);
  // A grid with the peak frequency on it.
  for (int i = -50; i <= 50; ++i) o.frequencies_hz.push_back(fpeak * (1 + 0.004 * i));
  o.output_dofs = {0};
  Eigen::VectorXd load = Eigen::VectorXd::Zero(model.dof_count());
  load(0) = F;
  const HarmonicResult h = harmonic_response(frame, frame.all_modes(), load, o);
  EXPECT_EQ(h.max_displacement_dof, 0);
  EXPECT_EQ(h.max_displacement_frequency, 50);
  const double peak = F / (k * 2 * zeta * std::sqrt(1 - zeta * zeta));
  EXPECT_NEAR(h.max_displacement, peak, 1e-12 * peak);
  EXPECT_NEAR(std::abs(h.output(0, 50)), peak, 1e-12 * peak);
}

// ---------------------------------------------------------------------------
// A small 3-D frame: an L of box tubes (a 1.2 m arm along X, a 0.6 m arm along
// Y), clamped at the origin, bending in both planes and twisting.

FrameModel l_frame() {
  FrameModel m;
  const int s = framedyn::testing::add_section(m, box_section(0.10, 0.06, 0.004, 0.004, 0.004, 0.004), framedyn::testing::steel(),
                                               Eigen::Vector3d(0, 0, 1));
  const int n0 = framedyn::testing::add_node(m, Eigen::Vector3d::Zero());
  const std::vector<int> a = framedyn::testing::add_beam_line(m, n0, Eigen::Vector3d(1.2, 0, 0), 6, s, BeamTheory::timoshenko);
  framedyn::testing::add_beam_line(m, a.back(), Eigen::Vector3d(1.2, 0.6, 0), 3, s, BeamTheory::timoshenko);
  framedyn::testing::clamp_node(m, n0);
  m.index();
  return m;
}

// A vertical force at the corner (node 6), a lateral force and a torque at the tip (node 9).
Eigen::VectorXd l_frame_load(const FrameModel& m) {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(m.dof_count());
  f(6 * 6 + 2) = 2000.0;
  f(6 * 9 + 0) = 800.0;
  f(6 * 9 + 3) = 150.0;
  return f;
}

// (K - omega^2 M + i omega (alpha M + beta K)) u = F on the free DOFs by sparse LU.
Eigen::VectorXcd direct_solve(const FrameDynamics& frame, const Eigen::VectorXd& load, double omega, double alpha, double beta) {
  return framedyn::testing::direct_frequency_solve(frame, load, omega, alpha, beta);
}

double relative_error(const Eigen::VectorXcd& a, const Eigen::VectorXcd& b) { return (a - b).cwiseAbs().maxCoeff() / b.cwiseAbs().maxCoeff(); }

constexpr double kAlpha = 4.0, kBeta = 2e-5;  // Rayleigh damping: diagonal in the modes, so both solves damp alike

TEST(ModalSeries, AllModesEqualTheDirectFrequencyDomainSolve) {
  const FrameModel model = l_frame();
  FrameDynamics frame(model);
  const ModalBasis basis = frame.all_modes();
  FrequencyResponseOptions o;
  o.damping = ModalDamping::rayleigh_damping(kAlpha, kBeta);
  o.static_correction = false;  // with every mode the series is complete: nothing is left to correct
  const ModalFrequencyResponse r = modal_frequency_response(frame, basis, l_frame_load(model), o);
  for (double f_hz : {3.0, 0.9 * std::sqrt(basis.eigenvalues(0)) / (2 * kPi), std::sqrt(basis.eigenvalues(1)) / (2 * kPi), 400.0, 2500.0}) {
    const double w = 2 * kPi * f_hz;
    const double err = relative_error(r.displacement(w), direct_solve(frame, l_frame_load(model), w, kAlpha, kBeta));
    // Both are exact solutions of the same equations; the difference is round-off amplified by the
    // condition of K - omega^2 M near a resonance (about 1e-8 of max|u| for 54 equations).
    EXPECT_LT(err, 1e-8) << f_hz << " Hz";
  }
}

TEST(ModalSeries, FiberStressAmplitudesEqualTheRecoveryOfTheDirectSolution) {
  // Stresses are linear in u: the modal stress outputs at omega must equal the stresses recovered
  // (fem/section_forces) from the real and the imaginary part of the direct solution, combined as |.|.
  const FrameModel model = l_frame();
  FrameDynamics frame(model);
  FrequencyResponseOptions o;
  o.damping = ModalDamping::rayleigh_damping(kAlpha, kBeta);
  const ModalFrequencyResponse r = modal_frequency_response(frame, frame.all_modes(), l_frame_load(model), o);
  std::vector<FiberPoint> points;
  const LinearOutputs stress = fiber_stress_outputs(model, r, points);
  ASSERT_EQ(static_cast<std::size_t>(stress.size()), points.size());
  const double w = 2 * kPi * 60.0;
  const Eigen::VectorXcd u = direct_solve(frame, l_frame_load(model), w, kAlpha, kBeta);
  Eigen::MatrixXcd q(r.mode_count(), 1);
  q.col(0) = r.modal_coordinates(w);
  const Eigen::VectorXcd modal = stress.evaluate(q).col(0);
  const std::vector<StationResult> re = recover_stations(model, u.real(), 2), im = recover_stations(model, u.imag(), 2);
  std::size_t row = 0;
  double scale = 0.0, worst = 0.0;
  for (std::size_t s = 0; s < re.size(); ++s)
    for (std::size_t p = 0; p < re[s].fiber_stress.size(); ++p, ++row) {
      EXPECT_EQ(points[row].element_id, re[s].element_id);
      const cd direct(re[s].fiber_stress[p], im[s].fiber_stress[p]);
      scale = std::max(scale, std::abs(direct));
      worst = std::max(worst, std::abs(direct - modal(static_cast<Eigen::Index>(row))));
    }
  EXPECT_EQ(row, points.size());
  EXPECT_LT(worst, 1e-8 * scale);  // round-off, as for the displacements
}

TEST(ModalSeries, StaticCorrectionMakesTheTruncatedSeriesConverge) {
  const FrameModel model = l_frame();
  FrameDynamics frame(model);
  const ModalBasis basis = frame.all_modes();
  const Eigen::VectorXd load = l_frame_load(model);
  const double f1 = std::sqrt(basis.eigenvalues(0)) / (2 * kPi);
  for (double f_hz : {0.3 * f1, 1.5 * f1}) {
    const double w = 2 * kPi * f_hz;
    const Eigen::VectorXcd exact = direct_solve(frame, load, w, kAlpha, kBeta);
    double previous = 1e300;
    for (int n : {2, 4, 8, 16}) {
      FrequencyResponseOptions o;
      o.damping = ModalDamping::rayleigh_damping(kAlpha, kBeta);
      o.mode_count = n;
      o.static_correction = false;
      const double plain = relative_error(modal_frequency_response(frame, basis, load, o).displacement(w), exact);
      o.static_correction = true;
      const double corrected = relative_error(modal_frequency_response(frame, basis, load, o).displacement(w), exact);
      const double wn1 = std::sqrt(basis.eigenvalues(n));  // first mode left out
      std::cout << "[ measured ] " << f_hz << " Hz, " << n << " modes: error " << plain << " without, " << corrected
                << " with the static correction; (omega/omega_" << n + 1 << ")^2 = " << std::pow(w / wn1, 2) << "\n";
      // The correction replaces each left-out mode's contribution p phi/(omega_j^2 - omega^2 + i c_j omega) by
      // p phi/omega_j^2: its error is that contribution times about (omega/omega_j)^2 + c_j omega/omega_j^2
      // (omega/omega_j <= omega/omega_{N+1}; c_j omega/omega_j^2 = (alpha + beta omega_j^2) omega/omega_j^2 <= the same
      // order for these alpha, beta). So the corrected error is below the plain one times 4 (omega/omega_{N+1})^2 + 2 beta omega.
      EXPECT_LT(corrected, plain * (4 * std::pow(w / wn1, 2) + 2 * kBeta * w)) << n << " modes";
      EXPECT_LT(corrected, previous) << "adding modes must reduce the corrected error";
      previous = corrected;
    }
  }
}

TEST(ModalSeries, StaticCorrectionIsExactAtZeroFrequencyWithOneMode) {
  // At omega -> 0 the corrected series is G F whatever the number of modes (Eq. H.4).
  const FrameModel model = l_frame();
  FrameDynamics frame(model);
  FrequencyResponseOptions o;
  o.mode_count = 1;
  const Eigen::VectorXcd u = modal_frequency_response(frame, frame.all_modes(), l_frame_load(model), o).displacement(1e-6);
  const Eigen::VectorXd u_static = solve_static([&] {
    FrameModel m = model;
    const Eigen::VectorXd f = l_frame_load(model);
    for (int g = 0; g < f.size(); ++g)
      if (f(g) != 0.0) m.loads.push_back({g / 6, g % 6, f(g)});
    return m;
  }()).displacement;
  EXPECT_LT((u.real() - u_static).cwiseAbs().maxCoeff(), 1e-9 * u_static.cwiseAbs().maxCoeff());
}

TEST(ModalSeries, SteadyStateOfALongTransientHasTheHarmonicAmplitudeAndPhase) {
  // The load F cos(Omega t) from rest, integrated in time by modal_transient (exact for a
  // piecewise-linear load) until the start-up transient has died out; the last periods are
  // fitted with a cos + b sin, and U = a - i b must be the harmonic amplitude.
  const FrameModel model = l_frame();
  FrameDynamics frame(model);
  const ModalBasis basis = frame.all_modes();
  const Eigen::VectorXd load = l_frame_load(model);
  const double zeta = 0.05, w1 = std::sqrt(basis.eigenvalues(0)), omega = 0.8 * w1, period = 2 * kPi / omega;
  // e^{-zeta omega_1 t} < 1e-6 at the end: every mode decays at least as fast as the first.
  const double duration = std::ceil(std::log(1e6) / (zeta * w1) / period + 3) * period;
  const int per_period = 400;
  const int n = static_cast<int>(std::lround(duration / period)) * per_period + 1;
  TransientInput in;
  in.times = Eigen::VectorXd::LinSpaced(n, 0.0, duration);
  std::vector<Eigen::Triplet<double>> t;
  for (int g = 0; g < load.size(); ++g)
    if (load(g) != 0.0) t.emplace_back(g, 0, load(g));
  in.distribution.resize(model.dof_count(), 1);
  in.distribution.setFromTriplets(t.begin(), t.end());
  in.components.resize(1, n);
  for (int k = 0; k < n; ++k) in.components(0, k) = std::cos(omega * in.times(k));
  ModalTransientOptions mo;
  mo.damping = ModalDamping::ratio(zeta);
  mo.initial = InitialState::rest;
  const TransientResult tr = modal_transient(frame, basis, in, mo);

  FrequencyResponseOptions o;
  o.damping = ModalDamping::ratio(zeta);
  const Eigen::VectorXcd u = modal_frequency_response(frame, basis, load, o).displacement(omega);
  // Least squares over the last two periods.
  const int last = 2 * per_period;
  Eigen::MatrixXd a(last, 2);
  for (int k = 0; k < last; ++k) {
    const double time = in.times(n - last + k);
    a(k, 0) = std::cos(omega * time);
    a(k, 1) = std::sin(omega * time);
  }
  for (int g : {6 * 6 + 2, 6 * 9 + 0, 6 * 9 + 1, 6 * 9 + 3}) {
    const Eigen::Vector2d ab = a.colPivHouseholderQr().solve(tr.displacement.row(g).tail(last).transpose());
    const cd fitted(ab(0), -ab(1));
    std::cout << "[ measured ] DOF " << g << ": |U_transient - U_harmonic| / |U| = " << std::abs(fitted - u(g)) / std::abs(u(g)) << "\n";
    // The piecewise-linear load differs from the cosine by O((Omega h)^2 / 12) = 2e-5 of its
    // amplitude (h = T/400); the remaining start-up transient is below 1e-6.
    EXPECT_LT(std::abs(fitted - u(g)), 2e-4 * std::abs(u(g))) << "DOF " << g << ": transient " << fitted << ", harmonic " << u(g);
  }
}

TEST(ModalSeries, FreeFreeFrameUnderAHarmonicForceFollowsNewtonsLawAtHighFrequency) {
  // Well above the elastic modes a free body responds as a rigid mass: the translation of the mass
  // centre is F / (-m omega^2). A free beam (no supports), an axial force: u_x of every node -> -F/(m omega^2) plus
  // the elastic part, tiny for a stiff bar below its first axial mode.
  framedyn::testing::StraightBeamSpec spec;
  spec.length = 2.0;
  spec.elements = 8;
  spec.section = rectangle_section(0.05, 0.05, 0.3);
  spec.material = framedyn::testing::steel();
  const FrameModel model = framedyn::testing::straight_beam(spec);
  FrameDynamics frame(model);
  ASSERT_TRUE(frame.free_free());
  const ModalBasis basis = frame.all_modes();
  Eigen::VectorXd load = Eigen::VectorXd::Zero(model.dof_count());
  load(0) = 100.0;
  const double mass = 7850.0 * 0.05 * 0.05 * 2.0, omega = 2 * kPi * 5.0;  // 5 Hz, far below the first elastic mode
  FrequencyResponseOptions o;
  o.damping = ModalDamping::ratio(0.02);
  const ModalFrequencyResponse r = modal_frequency_response(frame, basis, load, o);
  EXPECT_EQ(r.rigid_body_modes, 6);
  const Eigen::VectorXcd u = r.displacement(omega);
  const double rigid = 100.0 / (mass * omega * omega);
  // Axial stretch under the inertia load: of order F L / (E A) = 4e-7 m against the rigid 5e-3 m.
  for (int node = 0; node <= 8; ++node) EXPECT_NEAR(u(6 * node).real(), -rigid, 1e-4 * rigid) << "node " << node;
}

}  // namespace
