// Random response to a load scaled by a PSD: the mean square of a single-DOF
// oscillator under white noise against its closed form, the response PSD
// against |H|^2 S with the closed-form H, the log-log interpolation of the
// load PSD (exact for a power law), the PSD file's errors, and the RMS of a
// cantilever's tip against a long direct (Newmark) transient of the same beam
// under a load whose PSD is the same flat band (two independent paths).
//
// Convention (docs/theory/fem.md, "Random response"): one-sided PSDs in Hz,
// mean square = integral over f >= 0 of S(f) df. For m x'' + c x' + k x = F(t)
// with a white one-sided force PSD G0 (N^2/Hz),
//   sigma^2 = G0 / (4 k c) = G0 / (8 zeta m^2 omega_n^3),
// which is pi S0 / (2 zeta m^2 omega_n^3) for the two-sided PSD S0 = G0 / (4 pi) per rad/s.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <iostream>
#include <random>

#include "core/error.h"
#include "fem/direct_integration.h"
#include "fem/load_psd.h"
#include "fem/random_response.h"
#include "tests/support/beam_meshes.h"
#include "tests/support/temp_dir.h"

namespace {

using namespace framedyn::fem;
constexpr double kPi = 3.14159265358979323846;

// A point mass m on two springs to ground, kx along X and ky along Y; every other DOF held.
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

LoadPsd table(std::vector<double> f, std::vector<double> s) { return LoadPsd{std::move(f), std::move(s)}; }

TEST(SingleDofOscillator, WhiteNoiseMeanSquareMatchesClosedForm) {
  const double m = 2.0, fn = 10.0, k = m * std::pow(2 * kPi * fn, 2), F = 3.0, s_a = 0.5;
  for (double zeta : {0.005, 0.02, 0.1}) {
    const FrameModel model = mass_on_springs(m, k, 7.0 * k);
    FrameDynamics frame(model);
    Eigen::VectorXd load = Eigen::VectorXd::Zero(model.dof_count());
    load(0) = F;
    RandomOptions o;
    o.response.damping = ModalDamping::ratio(zeta);
    // A flat PSD over six decades around f_n stands for white noise.
    const RandomResult r = random_response(frame, frame.all_modes(), load, table({1e-2, 1e4}, {s_a, s_a}), o);
    const double w = 2 * kPi * fn, g0 = s_a * F * F;
    const double exact = g0 / (8 * zeta * m * m * w * w * w);
    // What the band leaves out: below 0.01 Hz |H|^2 ~ 1/k^2, a fraction 8 zeta (0.01 Hz)/omega_n
    // of sigma^2 (2.5e-5 at zeta = 0.02); above 1e4 Hz a fraction 8 zeta (f_n/f)^3 / 3, negligible.
    const double tail = 8 * zeta * 0.01 / w;
    const double measured = r.rms(0) * r.rms(0);
    std::cout << "[ measured ] zeta " << zeta << ": sigma^2 / closed form - 1 = " << measured / exact - 1 << " (band tail " << -tail
              << "), " << r.frequencies_hz.size() << " grid points\n";
    // The quadrature on the refined grid adds at most 2e-4 (trapezoid rule on the peak's tan-spaced points and
    // on the 100-per-decade base grid).
    EXPECT_NEAR(measured / exact, 1.0 - tail, 2e-4) << "zeta " << zeta;
    EXPECT_EQ(r.max_displacement_rms_dof, 0);
    EXPECT_NEAR(r.rms(1), 0.0, 1e-12 * r.rms(0));  // the Y oscillator is not loaded
  }
}

TEST(SingleDofOscillator, ResponsePsdIsTransferFunctionSquaredTimesLoadPsd) {
  const double m = 2.0, k = 8.0e3, zeta = 0.04, F = 3.0;
  const FrameModel model = mass_on_springs(m, k, 7.0 * k);
  FrameDynamics frame(model);
  Eigen::VectorXd load = Eigen::VectorXd::Zero(model.dof_count());
  load(0) = F;
  RandomOptions o;
  o.response.damping = ModalDamping::ratio(zeta);
  o.output_dofs = {0};
  // S = 1e-3 (f / 1 Hz)^-1.5 from 1 to 100 Hz: log-log interpolation of two rows reproduces it.
  const LoadPsd psd = table({1.0, 100.0}, {1e-3, 1e-3 * std::pow(100.0, -1.5)});
  const RandomResult r = random_response(frame, frame.all_modes(), load, psd, o);
  const double c = 2 * zeta * std::sqrt(k * m);
  double peak = 0.0, peak_f = 0.0;
  for (std::size_t i = 0; i < r.frequencies_hz.size(); ++i) {
    const double f = r.frequencies_hz[i], w = 2 * kPi * f;
    const double h2 = F * F / (std::pow(k - m * w * w, 2) + std::pow(c * w, 2));
    const double expected = h2 * 1e-3 * std::pow(f, -1.5);
    EXPECT_NEAR(r.output_psd(0, static_cast<Eigen::Index>(i)), expected, 1e-11 * expected) << f << " Hz";
    if (expected > peak) peak = expected, peak_f = f;
  }
  EXPECT_NEAR(r.max_displacement_psd, peak, 1e-11 * peak);
  EXPECT_DOUBLE_EQ(r.frequencies_hz[static_cast<std::size_t>(r.max_displacement_psd_frequency)], peak_f);
}

// Two independent framedyn paths for one mean square. A steel cantilever (1 m, 10 B33
// elements, 0.05 m x 0.1 m, f1 = 41.8 Hz in the weak plane), Rayleigh damping
// C = alpha M with alpha = 2 zeta omega_1 (zeta_1 = 0.05), a tip load F a(t) along Z:
//  - frequency domain: random_response with a flat one-sided PSD S over 20..80 Hz
//    (modal |H|^2 S integrated on the refined grid, all modes of the basis);
//  - time domain: direct_transient (Newmark on the full sparse matrices, no modes) under
//    a(t) = sum_k A_k cos(2 pi f_k t + phi_k), f_k = 20, 20.1, ..., 80 Hz, A_k^2 / 2 = S df
//    (S df / 2 at the two ends: the trapezoid rule), phases random (fixed seed), from rest.
// After 3 s the start has died out (e^(-alpha t / 2) = e^-39), and a(t) is periodic with
// T = 1 / df = 10 s, so the mean square of the tip deflection over one period is the sum
// of |H(f_k)|^2 S df whatever the phases: no statistical scatter, only discretisation.
// Newmark (average acceleration = the trapezoidal rule) answers at f as the exact system
// at (2/h) tan(2 pi f h / 2) / (2 pi): a stretch of the frequency axis by 1 + (omega h)^2 / 4
// near omega_1, which shrinks the integral of the resonance peak by (omega_1 h)^2 / 4.
TEST(RandomResponse, CantileverTipRmsEqualsALongNewmarkTransientUnderTheSameBandOfLoadPower) {
  framedyn::testing::StraightBeamSpec spec;
  spec.elements = 10;
  spec.section = rectangle_section(0.05, 0.1, 0.3);
  spec.material = framedyn::testing::steel();
  FrameModel model = framedyn::testing::straight_beam(spec);
  framedyn::testing::clamp_node(model, 0);
  FrameDynamics frame(model);
  const ModalBasis basis = frame.all_modes();
  const double w1 = std::sqrt(basis.eigenvalues(0)), zeta = 0.05, alpha = 2 * zeta * w1;
  const int tip_z = 6 * spec.elements + 2;
  const double F = 1000.0, s_a = 2e-3, f_lo = 20.0, f_hi = 80.0, df = 0.1;
  Eigen::VectorXd load = Eigen::VectorXd::Zero(model.dof_count());
  load(tip_z) = F;

  RandomOptions o;
  o.response.damping = ModalDamping::rayleigh_damping(alpha, 0.0);
  const RandomResult r = random_response(frame, basis, load, table({f_lo, f_hi}, {s_a, s_a}), o);
  const double random_ms = r.rms(tip_z) * r.rms(tip_z);

  const double h = 2e-4, settle = 3.0, period = 1.0 / df;
  const int steps = static_cast<int>(std::lround((settle + period) / h)), settle_steps = static_cast<int>(std::lround(settle / h));
  const int components = static_cast<int>(std::lround((f_hi - f_lo) / df)) + 1;
  std::mt19937_64 rng(20261204);
  std::uniform_real_distribution<double> phase(0.0, 2 * kPi);
  TransientInput in;
  in.times = Eigen::VectorXd::LinSpaced(steps + 1, 0.0, steps * h);
  in.components = Eigen::MatrixXd::Zero(1, steps + 1);
  for (int k = 0; k < components; ++k) {
    const double weight = (k == 0 || k == components - 1) ? 0.5 : 1.0;
    const double amplitude = std::sqrt(2 * s_a * df * weight), f = f_lo + k * df, phi = phase(rng);
    for (int i = 0; i <= steps; ++i) in.components(0, i) += amplitude * std::cos(2 * kPi * f * in.times(i) + phi);
  }
  in.distribution = SparseMatrix(model.dof_count(), 1);
  in.distribution.insert(tip_z, 0) = F;
  NewmarkOptions no;
  no.rayleigh_alpha = alpha;
  no.initial = InitialState::rest;
  const TransientResult t = direct_transient(frame, in, no);
  ASSERT_EQ(t.displacement.cols(), steps + 1);
  double transient_ms = 0.0;
  for (int i = settle_steps; i < steps; ++i) transient_ms += t.displacement(tip_z, i) * t.displacement(tip_z, i);
  transient_ms /= (steps - settle_steps);

  const double warp = std::pow(w1 * h, 2) / 4;
  std::cout << "[ measured ] tip RMS: random " << std::sqrt(random_ms) << " m, Newmark transient " << std::sqrt(transient_ms)
            << " m; mean squares transient / random - 1 = " << transient_ms / random_ms - 1 << " (Newmark's frequency warp -"
            << warp << ")\n";
  // The random path's quadrature is within 2e-4 (SingleDofOscillator above); Newmark's warp is -(omega_1 h)^2 / 4.
  EXPECT_NEAR(transient_ms / random_ms, 1.0 - warp, 2e-4);
}

TEST(RandomResponse, FreeFreeFrameIsRefused) {
  framedyn::testing::StraightBeamSpec spec;
  spec.elements = 4;
  spec.section = rectangle_section(0.05, 0.05, 0.3);
  spec.material = framedyn::testing::steel();
  const FrameModel model = framedyn::testing::straight_beam(spec);
  FrameDynamics frame(model);
  Eigen::VectorXd load = Eigen::VectorXd::Zero(model.dof_count());
  load(2) = 1.0;
  EXPECT_THROW(random_response(frame, frame.all_modes(), load, table({1, 10}, {1, 1}), RandomOptions{}), std::invalid_argument);
}

TEST(LoadPsd, LogLogInterpolationReproducesPowerLaws) {
  // -3 dB/octave and +6 dB/octave segments: S ~ f^-1 then f^2.
  const LoadPsd p = table({2.0, 20.0, 40.0}, {0.1, 0.01, 0.04});
  for (double f : {2.0, 3.3, 7.1, 19.9}) EXPECT_NEAR(p.at(f), 0.2 / f, 1e-15);
  for (double f : {20.0, 27.0, 40.0}) EXPECT_NEAR(p.at(f), 0.01 * (f / 20) * (f / 20), 1e-15);
  EXPECT_THROW(p.at(1.0), std::invalid_argument);
  EXPECT_THROW(p.at(41.0), std::invalid_argument);
}

// The message of read_load_psd on a file with `text`.
std::string psd_error(const std::string& text) {
  framedyn::testing::TempDir dir;
  const std::string path = dir.write("psd.csv", text).string();
  try {
    read_load_psd(path);
  } catch (const framedyn::core::InputError& e) {
    const std::string m = e.what();
    return m.substr(m.find("psd.csv"));
  }
  return "no error";
}

TEST(LoadPsd, ReaderNamesFileLineExpectedAndFound) {
  const std::string header = "frequency [Hz],psd [1/Hz]\n";
  EXPECT_EQ(psd_error("# shaker table\n" + header + "5,0.001\n200,0.001\n"), "no error");
  EXPECT_EQ(psd_error("frequency,psd\n5,1\n"), "psd.csv:1: header: expected the columns 'frequency [Hz],psd [1/Hz]', found 'frequency,psd'");
  EXPECT_EQ(psd_error(header + "5,0.001\n10;0.002\n"), "psd.csv:3: expected two numbers 'frequency,psd' (Hz, 1/Hz), found '10;0.002'");
  EXPECT_EQ(psd_error(header + "5,0.001\n10,abc\n"), "psd.csv:3: expected two numbers 'frequency,psd' (Hz, 1/Hz), found '10,abc'");
  EXPECT_EQ(psd_error(header + "5,0.001\n10,0.1,3\n"), "psd.csv:3: expected two numbers 'frequency,psd' (Hz, 1/Hz), found '10,0.1,3'");
  EXPECT_EQ(psd_error(header + "0,0.001\n10,0.1\n"), "psd.csv:2: frequency [Hz]: expected a positive frequency, found 0");
  EXPECT_EQ(psd_error(header + "5,0\n10,0.1\n"), "psd.csv:2: psd [1/Hz]: expected a positive PSD (it is interpolated log-log), found 0");
  EXPECT_EQ(psd_error(header + "5,1\n10,0.1\n10,0.2\n"), "psd.csv:4: frequency [Hz]: expected frequencies increasing row by row, found 10 Hz after 10 Hz");
  EXPECT_EQ(psd_error(header + "5,1\n"),
            "psd.csv:1: expected at least two rows after the header (the band's lowest and highest frequency), found 1 row(s)");
  EXPECT_EQ(psd_error("# nothing\n"), "psd.csv: header: expected the columns 'frequency [Hz],psd [1/Hz]', found an empty file");
}

TEST(LoadPsd, MissingFileIsAnInputError) {
  try {
    read_load_psd("/nonexistent/psd.csv");
    FAIL() << "no error";
  } catch (const framedyn::core::InputError& e) {
    EXPECT_EQ(std::string(e.what()), "/nonexistent/psd.csv: cannot open /nonexistent/psd.csv (no such file)");
  }
}

}  // namespace
