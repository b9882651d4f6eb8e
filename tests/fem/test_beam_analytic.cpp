// Straight beams against closed-form beam theory: Euler–Bernoulli bending
// frequencies (cantilever, simply supported, free-free) in both bending
// planes, torsional and axial frequencies of a clamped-free bar, static
// cantilever deflections, reactions and section forces, the Timoshenko
// frequency equation of a deep simply supported beam, and lumped mass.
//
// Every beam but the simply supported ones runs along an oblique direction
// with an oblique n1, so the element axes, the transformation T and the
// classification of the modes by plane are exercised in 3-D. A mode is
// assigned to the motion that holds nearly all of its kinetic energy:
// translation along t (axial), along n1, along n2, or twist about t; on a
// straight prismatic beam these four decouple exactly.
//
// Discretisation error estimates used for the tolerances (relative errors in
// frequency, h the element length, beta_n L or k_n the mode's wave number):
//   cubic Hermite bending, consistent mass:  +(beta_n h)^4 / 1440
//     (the (kh)^4/720 eigenvalue error of the Hermite element; measured
//     constant 0.00069 on all three support cases at 10..80 elements);
//   linear bar, consistent mass: the discrete modes of a uniform mesh are
//     sampled sinusoids, omega_h^2 = (6 c^2 / h^2)(1 - cos kh)/(2 + cos kh)
//     exactly, i.e. +(kh)^2/24 in frequency;
//   Timoshenko element (Przemieniecki, shear strain constant in each
//     element): O(h^2), checked by its observed order and by Richardson
//     extrapolation from two meshes.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <tuple>
#include <vector>

#include "fem/assembly.h"
#include "fem/beam_element.h"
#include "fem/beam_section.h"
#include "fem/modal_analysis.h"
#include "fem/section_forces.h"
#include "fem/static_analysis.h"
#include "tests/support/beam_meshes.h"

namespace {

using framedyn::fem::BeamTheory;
using framedyn::fem::FrameModel;
using framedyn::fem::MassFormulation;
using framedyn::testing::StraightBeamSpec;
namespace fem = framedyn::fem;
namespace support = framedyn::testing;

constexpr double kPi = 3.14159265358979323846;

// Roots of the characteristic equations to 15 digits (the 7-digit values of
// the handbooks would limit the comparison to about 1e-7 in frequency).
constexpr std::array<double, 3> kCantileverBetaL = {1.87510406871196, 4.69409113297418, 7.85475743823761};
constexpr std::array<double, 3> kFreeFreeBetaL = {4.73004074486270, 7.85320462409584, 10.9956078380017};
constexpr std::array<double, 3> kSimplySupportedBetaL = {kPi, 2 * kPi, 3 * kPi};

// f = (beta^2 / (2 pi L^2)) sqrt(E I / (rho A)).
double euler_bernoulli_frequency(double beta_l, double length, double ei, double rho_a) {
  return beta_l * beta_l / (2.0 * kPi * length * length) * std::sqrt(ei / rho_a);
}

// Motion classes of a straight-beam mode.
enum MotionClass { kAxial = 0, kAlongN1 = 1, kAlongN2 = 2, kTwist = 3 };

// Elastic frequencies of `result` sorted by motion class, keeping the modes
// whose dominant class holds at least `min_purity` of the kinetic-energy
// proxy sum_nodes (t.u)^2, (n1.u)^2, (n2.u)^2, (Ip/A)(t.theta)^2. On a
// straight beam the classes decouple exactly; a pure mode's purity falls
// short of 1 only by the square of the eigenvector error (Lanczos
// tolerance 1e-10, so ~1e-20, plus round-off).
struct ClassifiedFrequencies {
  std::array<std::vector<double>, 4> hz;
  int impure = 0;  // elastic modes left out
};

ClassifiedFrequencies classify_modes(const FrameModel& model, const fem::ModalResult& result, const Eigen::Matrix3d& axes,
                                     double twist_weight, double min_purity = 1.0 - 1e-9) {
  ClassifiedFrequencies out;
  for (std::size_t i = 0; i < result.modes.size(); ++i) {
    if (result.modes[i].rigid_body) continue;
    const Eigen::VectorXd phi = result.shapes.col(static_cast<Eigen::Index>(i));
    std::array<double, 4> w{0.0, 0.0, 0.0, 0.0};
    for (std::size_t n = 0; n < model.nodes.size(); ++n) {
      const Eigen::Vector3d u = axes * phi.segment<3>(6 * static_cast<Eigen::Index>(n));
      const Eigen::Vector3d th = axes * phi.segment<3>(6 * static_cast<Eigen::Index>(n) + 3);
      w[0] += u(0) * u(0);
      w[1] += u(1) * u(1);
      w[2] += u(2) * u(2);
      w[3] += twist_weight * th(0) * th(0);
    }
    const double total = w[0] + w[1] + w[2] + w[3];
    int best = 0;
    for (int c = 1; c < 4; ++c)
      if (w[static_cast<std::size_t>(c)] > w[static_cast<std::size_t>(best)]) best = c;
    if (w[static_cast<std::size_t>(best)] >= min_purity * total)
      out.hz[static_cast<std::size_t>(best)].push_back(result.modes[i].frequency_hz);
    else
      ++out.impure;
  }
  return out;
}

// Slender steel beam with a 40 mm x 20 mm rectangle: a = 0.04 m along n1,
// b = 0.02 m along n2, so I22 = b a^3 / 12 = 4 I11 and the two bending planes
// have frequencies a factor 2 apart. Along an oblique direction with an
// oblique n1.
StraightBeamSpec slender_rect_beam(int elements, BeamTheory theory) {
  StraightBeamSpec s;
  s.start = Eigen::Vector3d(0.3, -0.2, 1.1);
  s.direction = Eigen::Vector3d(1.0, 2.0, -0.5);
  s.length = 2.0;
  s.elements = elements;
  s.section = fem::rectangle_section(0.04, 0.02, 0.3);
  s.material = support::steel();
  s.theory = theory;
  s.n1_direction = Eigen::Vector3d(0.2, -0.4, 1.0);
  return s;
}

double twist_weight(const fem::SectionProperties& s) { return s.polar_moment() / s.area; }

void print_errors(const char* what, const std::vector<double>& fe, const std::vector<double>& exact) {
  std::printf("%-48s", what);
  for (std::size_t i = 0; i < exact.size() && i < fe.size(); ++i) std::printf("  %+.3e", fe[i] / exact[i] - 1.0);
  std::printf("\n");
}

// First three frequencies of each bending plane against closed form, for a
// 40-element Euler–Bernoulli beam with the given supports.
void check_euler_bernoulli_planes(const char* name, const StraightBeamSpec& spec, const FrameModel& model,
                                  const std::array<double, 3>& beta_l, const Eigen::Matrix3d& axes, int mode_count) {
  fem::ModalOptions options;
  options.mode_count = mode_count;
  const fem::ModalResult result = fem::compute_modes(model, options);
  const ClassifiedFrequencies c = classify_modes(model, result, axes, twist_weight(spec.section));
  EXPECT_EQ(c.impure, 0) << "the bending planes, axial and torsional motion of a straight beam decouple";
  const double rho_a = spec.material.density * spec.section.area;
  const double h = spec.length / spec.elements;
  // Tolerance: twice the Hermite estimate (beta_3 h)^4 / 1440 of the third
  // (worst) mode; the next term is smaller by another (beta h)^2 < 0.08.
  // Lower bound: consistent mass gives upper bounds (Rayleigh–Ritz), less a
  // round-off allowance: eps max(K_ii/M_ii) / lambda_1 = 5e-8 in lambda for
  // the first cantilever mode (2.5e-8 in frequency); allow 5e-8.
  const double bh3 = beta_l[2] / spec.length * h;
  const double upper = 2.0 * std::pow(bh3, 4) / 1440.0;
  // Deflection along n1 bends about n2 (I22); along n2 about n1 (I11).
  const std::array<std::pair<int, double>, 2> planes = {{{kAlongN1, spec.section.i22}, {kAlongN2, spec.section.i11}}};
  for (const auto& [plane, inertia] : planes) {
    const std::vector<double>& fe = c.hz[static_cast<std::size_t>(plane)];
    ASSERT_GE(fe.size(), 3u) << name << ": fewer than three bending modes along n" << plane;
    std::vector<double> exact;
    for (int n = 0; n < 3; ++n) {
      exact.push_back(euler_bernoulli_frequency(beta_l[static_cast<std::size_t>(n)], spec.length,
                                                spec.material.youngs_modulus * inertia, rho_a));
      const double rel = fe[static_cast<std::size_t>(n)] / exact.back() - 1.0;
      EXPECT_LE(rel, upper) << name << " plane n" << plane << " mode " << n + 1;
      EXPECT_GE(rel, -5e-8) << name << " plane n" << plane << " mode " << n + 1;
    }
    char label[96];
    std::snprintf(label, sizeof label, "%s, deflection along n%d:", name, plane);
    print_errors(label, fe, exact);
  }
}

}  // namespace

// ---------------------------------------------------------------------------
// Euler–Bernoulli bending frequencies

TEST(CantileverEuler, FirstThreeFrequenciesMatchBetaLInBothPlanes) {
  const StraightBeamSpec spec = slender_rect_beam(40, BeamTheory::euler_bernoulli);
  FrameModel model = support::straight_beam(spec);
  support::clamp_node(model, 0);
  // Six bending modes lie below 150 Hz; torsion starts near 300 Hz, axial at 650 Hz.
  check_euler_bernoulli_planes("cantilever", spec, model, kCantileverBetaL, support::straight_beam_axes(spec), 10);
}

TEST(FreeFreeEuler, FirstThreeElasticFrequenciesMatchBetaLInBothPlanes) {
  const StraightBeamSpec spec = slender_rect_beam(40, BeamTheory::euler_bernoulli);
  const FrameModel model = support::straight_beam(spec);
  // Six rigid-body modes, then six bending modes below 290 Hz.
  check_euler_bernoulli_planes("free-free", spec, model, kFreeFreeBetaL, support::straight_beam_axes(spec), 16);
}

TEST(SimplySupportedEuler, FirstThreeFrequenciesAreNPiInBothPlanes) {
  // Simple supports need the twist about the axis held at one end, which is
  // one global DOF only for an axis-parallel beam: along global y, with the
  // section turned 30 degrees about the axis so that neither bending plane is
  // a global plane.
  StraightBeamSpec spec = slender_rect_beam(40, BeamTheory::euler_bernoulli);
  spec.start = Eigen::Vector3d(0.5, 1.0, -0.25);
  spec.direction = Eigen::Vector3d::UnitY();
  spec.n1_direction = Eigen::Vector3d(std::sin(kPi / 6), 0.0, std::cos(kPi / 6));
  FrameModel model = support::straight_beam(spec);
  support::pin_dofs(model, 0, {0, 1, 2, 4});  // translations and the twist ry
  support::pin_dofs(model, spec.elements, {0, 1, 2});
  check_euler_bernoulli_planes("simply supported", spec, model, kSimplySupportedBetaL, support::straight_beam_axes(spec), 10);
}

// ---------------------------------------------------------------------------
// Torsion and axial vibration of a clamped-free bar (linear elements)

namespace {

// Clamped-free steel shaft, solid circle r = 0.1 m, L = 2 m, 40 elements,
// oblique. Bending modes are degenerate pairs (I11 = I22) and are ignored.
struct ShaftModes {
  StraightBeamSpec spec;
  ClassifiedFrequencies c;
};

ShaftModes clamped_free_shaft_modes() {
  ShaftModes s;
  s.spec.start = Eigen::Vector3d(-1.0, 0.5, 0.2);
  s.spec.direction = Eigen::Vector3d(-0.3, 0.4, 1.2);
  s.spec.length = 2.0;
  s.spec.elements = 40;
  s.spec.section = fem::circle_section(0.1, 0.3);
  s.spec.material = support::steel();
  s.spec.theory = BeamTheory::euler_bernoulli;
  s.spec.n1_direction = Eigen::Vector3d(1.0, 0.0, 0.0);
  FrameModel model = support::straight_beam(s.spec);
  support::clamp_node(model, 0);
  fem::ModalOptions options;
  // Third axial mode at 3.2 kHz; about 12 bending modes lie below it.
  options.mode_count = 30;
  const fem::ModalResult r = fem::compute_modes(model, options);
  s.c = classify_modes(model, r, support::straight_beam_axes(s.spec), twist_weight(s.spec.section));
  return s;
}

// Checks a clamped-free bar with wave speed c: continuum f_n = (2n-1) c / (4L),
// the FE frequency exactly the discrete dispersion relation of linear
// elements with consistent mass (to the eigensolver's accuracy), and the
// error against the continuum the predicted +(kh)^2/24.
void check_clamped_free_bar(const char* name, const std::vector<double>& fe, double wave_speed, double length, int elements) {
  ASSERT_GE(fe.size(), 3u) << name;
  const double h = length / elements;
  std::vector<double> exact;
  for (int n = 1; n <= 3; ++n) {
    const double k = (2 * n - 1) * kPi / (2.0 * length);
    exact.push_back(k * wave_speed / (2.0 * kPi));
    const double discrete =
        std::sqrt(6.0 * wave_speed * wave_speed / (h * h) * (1.0 - std::cos(k * h)) / (2.0 + std::cos(k * h))) / (2.0 * kPi);
    const double fe_n = fe[static_cast<std::size_t>(n - 1)];
    // The discrete relation is exact for this mesh: only the eigensolver's
    // error remains (Lanczos tolerance 1e-10 on the shift-inverted values,
    // plus round-off eps lambda_max / lambda ~ 1e-11 here).
    EXPECT_NEAR(fe_n / discrete, 1.0, 1e-9) << name << " mode " << n << " against the discrete dispersion relation";
    // Against the continuum: +(kh)^2/24; the next term of the expansion of
    // the dispersion relation is 0.4 % of it at kh = 0.2; allow 5 %.
    const double predicted = (k * h) * (k * h) / 24.0;
    EXPECT_NEAR(fe_n / exact.back() - 1.0, predicted, 0.05 * predicted) << name << " mode " << n << " against the continuum";
  }
  print_errors(name, fe, exact);
}

}  // namespace

TEST(ClampedFreeShaft, TorsionalFrequenciesMatchOddQuarterWaves) {
  const ShaftModes s = clamped_free_shaft_modes();
  // sqrt(G J / (rho Ip)); J = Ip exactly for a solid circle.
  const double c = std::sqrt(s.spec.material.shear_modulus * s.spec.section.torsion_constant /
                             (s.spec.material.density * s.spec.section.polar_moment()));
  check_clamped_free_bar("clamped-free shaft, torsion:", s.c.hz[kTwist], c, s.spec.length, s.spec.elements);
}

TEST(ClampedFreeRod, AxialFrequenciesMatchOddQuarterWaves) {
  const ShaftModes s = clamped_free_shaft_modes();
  const double c = std::sqrt(s.spec.material.youngs_modulus / s.spec.material.density);
  check_clamped_free_bar("clamped-free rod, axial:", s.c.hz[kAxial], c, s.spec.length, s.spec.elements);
}

// ---------------------------------------------------------------------------
// Static cantilever: end loads are reproduced exactly by both elements.

namespace {

// Scaled condition number of K_ff (Jacobi-scaled, the measure that governs
// the Cholesky solve's forward error, van der Sluis): the static checks
// allow 10 eps kappa, the worst-case forward error of a backward-stable solve.
double scaled_condition(const FrameModel& model) {
  const fem::DofMap dofs = fem::make_dof_map(model);
  const Eigen::MatrixXd k = Eigen::MatrixXd(fem::assemble(model, dofs, {MassFormulation::consistent, fem::Storage::full}).stiffness);
  const Eigen::VectorXd d = k.diagonal().cwiseSqrt().cwiseInverse();
  const Eigen::MatrixXd ks = d.asDiagonal() * k * d.asDiagonal();
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(ks, Eigen::EigenvaluesOnly);
  return es.eigenvalues().maxCoeff() / es.eigenvalues().minCoeff();
}

struct CantileverCase {
  StraightBeamSpec spec;
  FrameModel model;
  Eigen::Matrix3d axes;  // rows t, n1, n2
  int tip = 0;
  double tolerance = 0.0;  // relative
};

CantileverCase cantilever(BeamTheory theory) {
  CantileverCase c;
  c.spec = slender_rect_beam(8, theory);
  c.model = support::straight_beam(c.spec);
  support::clamp_node(c.model, 0);
  c.axes = support::straight_beam_axes(c.spec);
  c.tip = c.spec.elements;
  c.tolerance = 10.0 * std::numeric_limits<double>::epsilon() * scaled_condition(c.model);
  return c;
}

}  // namespace

TEST(CantileverStatic, EulerTipDeflectionAndRootMomentAreExactInBothPlanes) {
  const double p = 1234.5;  // N
  for (int plane : {kAlongN1, kAlongN2}) {
    CantileverCase c = cantilever(BeamTheory::euler_bernoulli);
    const Eigen::Vector3d dir = c.axes.row(plane).transpose();
    support::add_nodal_force(c.model, c.tip, p * dir);
    const fem::StaticResult r = fem::solve_static(c.model);
    const double L = c.spec.length, E = c.spec.material.youngs_modulus;
    const double inertia = plane == kAlongN1 ? c.spec.section.i22 : c.spec.section.i11;
    const double expected = p * L * L * L / (3.0 * E * inertia);
    const Eigen::Vector3d tip = r.displacement.segment<3>(6 * c.tip);
    EXPECT_NEAR(tip.dot(dir) / expected, 1.0, c.tolerance) << "plane n" << plane;
    // No motion out of the load's plane: the planes decouple.
    EXPECT_LE((tip - tip.dot(dir) * dir).norm(), c.tolerance * expected) << "plane n" << plane;
    // Root reactions: force -P dir, moment -(L t) x (P dir) = P L (n of the
    // other plane), of magnitude P L.
    const Eigen::Vector3d t = c.axes.row(0).transpose();
    const Eigen::Vector3d reaction_force = r.reaction.segment<3>(0);
    const Eigen::Vector3d reaction_moment = r.reaction.segment<3>(3);
    EXPECT_LE((reaction_force + p * dir).norm(), c.tolerance * p) << "plane n" << plane;
    EXPECT_LE((reaction_moment + (L * t).cross(p * dir)).norm(), c.tolerance * p * L) << "plane n" << plane;
    EXPECT_NEAR(reaction_moment.norm() / (p * L), 1.0, c.tolerance) << "plane n" << plane;
    std::printf("cantilever B33, load along n%d: tip deflection rel. error %+.2e (tolerance %.1e)\n", plane,
                tip.dot(dir) / expected - 1.0, c.tolerance);
  }
}

TEST(CantileverStatic, AxialLoadAndTorqueGivePLOverEAAndTLOverGJ) {
  CantileverCase c = cantilever(BeamTheory::euler_bernoulli);
  const Eigen::Vector3d t = c.axes.row(0).transpose();
  const double p = 5.0e4, torque = 321.0;
  support::add_nodal_force(c.model, c.tip, p * t);
  support::add_nodal_moment(c.model, c.tip, torque * t);
  const fem::StaticResult r = fem::solve_static(c.model);
  const double L = c.spec.length;
  const double stretch = p * L / (c.spec.material.youngs_modulus * c.spec.section.area);
  const double twist = torque * L / (c.spec.material.shear_modulus * c.spec.section.torsion_constant);
  EXPECT_NEAR(r.displacement.segment<3>(6 * c.tip).dot(t) / stretch, 1.0, c.tolerance);
  EXPECT_NEAR(r.displacement.segment<3>(6 * c.tip + 3).dot(t) / twist, 1.0, c.tolerance);
  EXPECT_LE((r.reaction.segment<3>(0) + p * t).norm(), c.tolerance * p);
  EXPECT_LE((r.reaction.segment<3>(3) + torque * t).norm(), c.tolerance * torque);
}

TEST(CantileverStatic, TimoshenkoTipDeflectionAddsShearTermPLOverGAs) {
  const double p = 1234.5;
  for (int plane : {kAlongN1, kAlongN2}) {
    CantileverCase c = cantilever(BeamTheory::timoshenko);
    const Eigen::Vector3d dir = c.axes.row(plane).transpose();
    support::add_nodal_force(c.model, c.tip, p * dir);
    const fem::StaticResult r = fem::solve_static(c.model);
    const double L = c.spec.length, E = c.spec.material.youngs_modulus, G = c.spec.material.shear_modulus;
    // Deflection along n1: bending with I22, shear along 1 with A_s1.
    const double inertia = plane == kAlongN1 ? c.spec.section.i22 : c.spec.section.i11;
    const double shear_area = plane == kAlongN1 ? c.spec.section.shear_area_1 : c.spec.section.shear_area_2;
    const double bending = p * L * L * L / (3.0 * E * inertia), shear = p * L / (G * shear_area);
    const double tip = r.displacement.segment<3>(6 * c.tip).dot(dir);
    EXPECT_NEAR(tip / (bending + shear), 1.0, c.tolerance) << "plane n" << plane;
    // The shear term is resolved, not lost in the tolerance.
    ASSERT_GT(shear / bending, 1e3 * c.tolerance);
    std::printf("cantilever B31, load along n%d: tip deflection rel. error %+.2e (shear term %.2e of bending)\n", plane,
                tip / (bending + shear) - 1.0, shear / bending);
  }
}

TEST(CantileverStatic, MomentIsLinearPTimesLMinusXAndCornerStressesAreMcOverI) {
  const double p = 1234.5;
  for (int plane : {kAlongN1, kAlongN2}) {
    CantileverCase c = cantilever(BeamTheory::euler_bernoulli);
    const Eigen::Vector3d dir = c.axes.row(plane).transpose();
    support::add_nodal_force(c.model, c.tip, p * dir);
    const fem::StaticResult r = fem::solve_static(c.model);
    const std::vector<fem::StationResult> stations = fem::recover_stations(c.model, r.displacement, 5);
    ASSERT_EQ(stations.size(), static_cast<std::size_t>(5 * c.spec.elements));
    const double L = c.spec.length, a = c.spec.section.dimensions[0], b = c.spec.section.dimensions[1];
    const Eigen::Vector3d start = c.spec.start;
    double worst_moment = 0.0, worst_stress = 0.0;
    for (const fem::StationResult& s : stations) {
      const double x = (s.point - start).norm();  // distance from the root
      const double moment = p * (L - x);
      // The load beyond the cut, P dir at distance L - x along t, acts on the
      // cut's positive face with moment (L - x) t x P dir: +P (L - x) about
      // n2 for a load along n1 (Mz), -P (L - x) about n1 for a load along n2 (My).
      const double mz = plane == kAlongN1 ? moment : 0.0, my = plane == kAlongN2 ? -moment : 0.0;
      const double vy = plane == kAlongN1 ? p : 0.0, vz = plane == kAlongN2 ? p : 0.0;
      const double pl = p * L;
      EXPECT_NEAR(s.forces.mz, mz, c.tolerance * pl) << "x = " << x;
      EXPECT_NEAR(s.forces.my, my, c.tolerance * pl) << "x = " << x;
      EXPECT_NEAR(s.forces.vy, vy, c.tolerance * p) << "x = " << x;
      EXPECT_NEAR(s.forces.vz, vz, c.tolerance * p) << "x = " << x;
      EXPECT_NEAR(s.forces.n, 0.0, c.tolerance * p) << "x = " << x;
      EXPECT_NEAR(s.forces.t, 0.0, c.tolerance * pl) << "x = " << x;
      worst_moment = std::max(worst_moment, std::abs((plane == kAlongN1 ? s.forces.mz : -s.forces.my) - moment) / pl);
      // Corners (x1, x2) = (+-a/2, +-b/2): sigma = -+ M c / I, compression on
      // the side the load pushes towards (the concave side).
      const double inertia = plane == kAlongN1 ? c.spec.section.i22 : c.spec.section.i11;
      const double half = plane == kAlongN1 ? a / 2 : b / 2;
      const double sigma_max = moment * half / inertia, sigma_scale = pl * half / inertia;
      ASSERT_EQ(s.fiber_stress.size(), 4u);
      const auto& pts = c.spec.section.stress_points;
      for (std::size_t k = 0; k < 4; ++k) {
        const double coord = plane == kAlongN1 ? pts[k].x() : pts[k].y();
        const double expected = coord > 0 ? -sigma_max : sigma_max;
        EXPECT_NEAR(s.fiber_stress[k], expected, c.tolerance * sigma_scale) << "x = " << x << ", corner " << k;
        worst_stress = std::max(worst_stress, std::abs(s.fiber_stress[k] - expected) / sigma_scale);
      }
    }
    std::printf("cantilever section forces, load along n%d: max |M - P(L-x)|/(PL) %.1e, corner stress %.1e\n", plane,
                worst_moment, worst_stress);
  }
}

// ---------------------------------------------------------------------------
// Timoshenko: a deep simply supported beam

namespace {

// Timoshenko (1921) for a simply supported beam, mode n, k = n pi / L:
// with w = W sin kx, psi = Psi cos kx in
//   kGA (w'' - psi') = rho A w_tt,   EI psi'' + kGA (w' - psi) = rho I psi_tt,
// the determinant gives
//   (rho^2 I / kG) w^4 - (rho A + rho I k^2 + E I rho k^2 / kG) w^2 + E I k^4 = 0,
// kG = G A_s / A. The lower root is the flexural mode.
double timoshenko_ss_frequency(int n, double length, double e, double g, double rho, double area, double inertia,
                               double shear_area) {
  const double k = n * kPi / length, kg = g * shear_area / area;
  const double qa = rho * rho * inertia / kg;
  const double qb = rho * area + rho * inertia * k * k + e * inertia * rho * k * k / kg;
  const double qc = e * inertia * k * k * k * k;
  const double omega2 = 2.0 * qc / (qb + std::sqrt(qb * qb - 4.0 * qa * qc));  // lower root, no cancellation
  return std::sqrt(omega2) / (2.0 * kPi);
}

// Steel, L = 1 m, a = 0.1 m along n1, b = 0.2 m along n2: L/b = 5 in the
// plane of deflection along n2, L/a = 10 along n1. Along global y, section
// turned 30 degrees about the axis; translations held at both ends, twist at one.
StraightBeamSpec deep_beam(int elements, BeamTheory theory) {
  StraightBeamSpec s;
  s.start = Eigen::Vector3d(0.2, -0.3, 0.4);
  s.direction = Eigen::Vector3d::UnitY();
  s.length = 1.0;
  s.elements = elements;
  s.section = fem::rectangle_section(0.1, 0.2, 0.3);
  s.material = support::steel();
  s.theory = theory;
  s.n1_direction = Eigen::Vector3d(std::sin(kPi / 6), 0.0, std::cos(kPi / 6));
  return s;
}

ClassifiedFrequencies deep_beam_modes(int elements, BeamTheory theory) {
  const StraightBeamSpec spec = deep_beam(elements, theory);
  FrameModel model = support::straight_beam(spec);
  support::pin_dofs(model, 0, {0, 1, 2, 4});
  support::pin_dofs(model, elements, {0, 1, 2});
  fem::ModalOptions options;
  // Three flexural modes per plane lie below 4.3 kHz (Euler–Bernoulli) with
  // about six axial and torsional modes, which are classified out.
  options.mode_count = 20;
  const fem::ModalResult r = fem::compute_modes(model, options);
  return classify_modes(model, r, support::straight_beam_axes(spec), twist_weight(spec.section));
}

}  // namespace

TEST(SimplySupportedTimoshenko, DeepBeamFrequenciesConvergeToTimoshenkoEquation) {
  const int coarse = 20, fine = 40;
  const ClassifiedFrequencies fc = deep_beam_modes(coarse, BeamTheory::timoshenko);
  const ClassifiedFrequencies ff = deep_beam_modes(fine, BeamTheory::timoshenko);
  EXPECT_EQ(fc.impure + ff.impure, 0);
  const StraightBeamSpec spec = deep_beam(fine, BeamTheory::timoshenko);
  const fem::Material& m = spec.material;
  const fem::SectionProperties& s = spec.section;
  const std::array<std::tuple<int, double, double>, 2> planes = {
      {{kAlongN1, s.i22, s.shear_area_1}, {kAlongN2, s.i11, s.shear_area_2}}};
  for (const auto& [plane, inertia, shear_area] : planes) {
    const auto& coarse_hz = fc.hz[static_cast<std::size_t>(plane)];
    const auto& fine_hz = ff.hz[static_cast<std::size_t>(plane)];
    ASSERT_GE(coarse_hz.size(), 3u);
    ASSERT_GE(fine_hz.size(), 3u);
    std::vector<double> exact;
    for (int n = 1; n <= 3; ++n) {
      exact.push_back(timoshenko_ss_frequency(n, spec.length, m.youngs_modulus, m.shear_modulus, m.density, s.area, inertia, shear_area));
      const double e_coarse = coarse_hz[static_cast<std::size_t>(n - 1)] / exact.back() - 1.0;
      const double e_fine = fine_hz[static_cast<std::size_t>(n - 1)] / exact.back() - 1.0;
      // Rayleigh–Ritz: the consistent-mass element approaches from above.
      EXPECT_GT(e_fine, 0.0) << "plane n" << plane << " mode " << n;
      EXPECT_GT(e_coarse, e_fine) << "plane n" << plane << " mode " << n;
      // The element's shear strain is constant in each element, so the error
      // is O(h^2): halving h divides it by 4 (observed order 2 +- 0.1; the
      // O(h^4) remainder changes the ratio by (kh)^2 ~ 5 % at most).
      const double order = std::log2(e_coarse / e_fine);
      EXPECT_NEAR(order, 2.0, 0.1) << "plane n" << plane << " mode " << n;
      // Richardson extrapolation (4 f_fine - f_coarse) / 3 removes the h^2
      // term and turns an h^4 term C h_fine^4 into -4 C h_fine^4. The h^4
      // term is the Hermite bending error the element shares with
      // Euler–Bernoulli, (kh)^4 / 1440, plus the next shear term, about
      // (kh)^2 times the h^2 term: the remainder is bounded by 4 times their sum.
      const double richardson = (4.0 * fine_hz[static_cast<std::size_t>(n - 1)] - coarse_hz[static_cast<std::size_t>(n - 1)]) / 3.0;
      const double kh = n * kPi / fine;
      const double h2_term = (e_coarse - e_fine) / 3.0;
      const double remainder = 4.0 * (std::pow(kh, 4) / 1440.0 + kh * kh * h2_term);
      EXPECT_NEAR(richardson / exact.back(), 1.0, remainder) << "plane n" << plane << " mode " << n;
      std::printf("Timoshenko SS plane n%d mode %d: error %+.3e (%d el), %+.3e (%d el), order %.3f, Richardson %+.2e (bound %.1e)\n",
                  plane, n, e_coarse, coarse, e_fine, fine, order, richardson / exact.back() - 1.0, remainder);
    }
  }
}

TEST(SimplySupportedTimoshenko, EulerBernoulliOverestimatesDeepBeamFrequencies) {
  const int elements = 80;
  const ClassifiedFrequencies t = deep_beam_modes(elements, BeamTheory::timoshenko);
  const ClassifiedFrequencies eb = deep_beam_modes(elements, BeamTheory::euler_bernoulli);
  const StraightBeamSpec spec = deep_beam(elements, BeamTheory::euler_bernoulli);
  const fem::Material& m = spec.material;
  const fem::SectionProperties& s = spec.section;
  for (const auto& [plane, inertia, shear_area] :
       std::array<std::tuple<int, double, double>, 2>{{{kAlongN1, s.i22, s.shear_area_1}, {kAlongN2, s.i11, s.shear_area_2}}}) {
    const auto& f_t = t.hz[static_cast<std::size_t>(plane)];
    const auto& f_eb = eb.hz[static_cast<std::size_t>(plane)];
    ASSERT_GE(f_t.size(), 3u);
    ASSERT_GE(f_eb.size(), 3u);
    for (int n = 1; n <= 3; ++n) {
      const double exact_t = timoshenko_ss_frequency(n, spec.length, m.youngs_modulus, m.shear_modulus, m.density, s.area, inertia, shear_area);
      const double exact_eb = euler_bernoulli_frequency(n * kPi, spec.length, m.youngs_modulus * inertia, m.density * s.area);
      // Shear flexibility and rotary inertia both lower the frequencies, by
      // up to 44 % at L/h = 5..10 (exact ratio 1.02 .. 1.44 here):
      // the element's ratio must be the closed-form one, within the
      // Timoshenko element's error (the convergence test bounds it by 1e-3
      // at 40 elements, O(h^2): 2.5e-4 at 80; we allow twice that) and the
      // Hermite element's ((3 pi / 80)^4 / 1440 = 1.4e-9).
      const double ratio = f_eb[static_cast<std::size_t>(n - 1)] / f_t[static_cast<std::size_t>(n - 1)];
      EXPECT_GT(ratio, 1.0) << "plane n" << plane << " mode " << n;
      EXPECT_NEAR(ratio / (exact_eb / exact_t), 1.0, 5e-4) << "plane n" << plane << " mode " << n;
      std::printf("deep SS beam plane n%d mode %d: f_EB / f_T = %.4f (closed form %.4f)\n", plane, n, ratio, exact_eb / exact_t);
    }
  }
}

// ---------------------------------------------------------------------------
// Lumped mass

namespace {

// Relative frequency change the lumped mass makes to a cantilever mode, to
// leading order: the Rayleigh quotient's kinetic energy sum_i m_i w_i^2 is
// the trapezoidal rule for integral(w^2), whose error is
// (h^2 / 12)[(w^2)']_0^L = (h^2 / 6) w(L) w'(L) (clamped root: w(0) = 0);
// and the lumped matrix carries rotary inertia rho I h / 2 per node that
// Euler–Bernoulli theory has not, adding r^2 integral(w'^2) with r^2 = I/A.
// Then f_lumped / f = (1 + delta)^(-1/2), delta the sum of the two over
// integral(w^2). The mode shape is the closed-form one.
double lumped_cantilever_shift(double beta_l, double length, double h, double radius_of_gyration_sq) {
  const double k = beta_l / length;
  const double s = (std::cosh(beta_l) + std::cos(beta_l)) / (std::sinh(beta_l) + std::sin(beta_l));
  auto w = [&](double x) { return std::cosh(k * x) - std::cos(k * x) - s * (std::sinh(k * x) - std::sin(k * x)); };
  auto dw = [&](double x) { return k * (std::sinh(k * x) + std::sin(k * x) - s * (std::cosh(k * x) - std::cos(k * x))); };
  // Gauss–Legendre, 5 points on each of 200 panels: exact to round-off for these smooth shapes.
  const double gx[5] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831, 0.9061798459386640};
  const double gw[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665, 0.2369268850561891};
  const int panels = 200;
  double w2 = 0.0, dw2 = 0.0;
  for (int p = 0; p < panels; ++p) {
    const double a = length * p / panels, half = 0.5 * length / panels;
    for (int q = 0; q < 5; ++q) {
      const double x = a + half * (1.0 + gx[q]);
      w2 += half * gw[q] * w(x) * w(x);
      dw2 += half * gw[q] * dw(x) * dw(x);
    }
  }
  const double delta = (h * h / 6.0 * w(length) * dw(length) + radius_of_gyration_sq * dw2) / w2;
  return 1.0 / std::sqrt(1.0 + delta) - 1.0;
}

}  // namespace

TEST(CantileverLumpedMass, FrequenciesConvergeAtSecondOrderToBetaL) {
  // Deflection along n2 (I11, r^2 = b^2 / 12). Lumped-mass frequencies lie
  // below the closed form, by an O(h^2) trapezoidal-rule error plus the
  // mesh-independent rotary-inertia term; the Hermite stiffness error,
  // (beta h)^4 / 1440, and the next terms of both expansions are
  // O((beta h)^4): we allow (beta_n h)^4 / 100 around the prediction, or
  // the round-off of the computed frequency where that is larger: a
  // backward-stable solve perturbs lambda by about eps times the largest
  // eigenvalue, here that of the lumped rotary DOFs, K_ii / M_ii =
  // (8 E I / h) / (rho I h) = 8 E / (rho h^2) at an interior node, so f_n by
  // eps (8 E / (rho h^2)) / (2 lambda_n) relative. At 80 elements mode 1
  // that is 5.5e-8 against a truncation allowance of 3.0e-9: the computed
  // frequency there differs by 4e-9 between -march=native builds on
  // different processors (found on an AMD EPYC), so the finer mesh checks
  // the prediction only to round-off.
  const fem::SectionProperties sec = fem::rectangle_section(0.04, 0.02, 0.3);
  const double r2 = sec.i11 / sec.area;
  std::array<std::vector<double>, 2> errors;  // [mesh][mode], discretisation part only
  const std::array<int, 2> meshes = {40, 80};
  for (std::size_t mesh = 0; mesh < 2; ++mesh) {
    const StraightBeamSpec spec = slender_rect_beam(meshes[mesh], BeamTheory::euler_bernoulli);
    FrameModel model = support::straight_beam(spec);
    support::clamp_node(model, 0);
    fem::ModalOptions options;
    options.mode_count = 10;
    options.mass = MassFormulation::lumped;
    const fem::ModalResult r = fem::compute_modes(model, options);
    const ClassifiedFrequencies c = classify_modes(model, r, support::straight_beam_axes(spec), twist_weight(spec.section));
    EXPECT_EQ(c.impure, 0);
    const std::vector<double>& fe = c.hz[kAlongN2];
    ASSERT_GE(fe.size(), 3u);
    const double h = spec.length / spec.elements;
    std::vector<double> exact;
    for (int n = 0; n < 3; ++n) {
      const double beta_l = kCantileverBetaL[static_cast<std::size_t>(n)];
      exact.push_back(euler_bernoulli_frequency(beta_l, spec.length, spec.material.youngs_modulus * sec.i11,
                                                spec.material.density * sec.area));
      const double rel = fe[static_cast<std::size_t>(n)] / exact.back() - 1.0;
      const double predicted = lumped_cantilever_shift(beta_l, spec.length, h, r2);
      const double bh = beta_l / spec.length * h;
      EXPECT_LT(rel, 0.0) << "lumped mass lowers the frequencies, mode " << n + 1;
      const double omega = 2.0 * M_PI * exact.back();
      const double round_off = std::numeric_limits<double>::epsilon() * 8.0 * spec.material.youngs_modulus /
                               (spec.material.density * h * h) / (2.0 * omega * omega);
      EXPECT_NEAR(rel, predicted, std::max(std::pow(bh, 4) / 100.0, round_off)) << meshes[mesh] << " elements, mode " << n + 1;
      errors[mesh].push_back(rel - lumped_cantilever_shift(beta_l, spec.length, 0.0, r2));
    }
    char label[96];
    std::snprintf(label, sizeof label, "lumped cantilever, %d elements:", meshes[mesh]);
    print_errors(label, fe, exact);
  }
  // The mesh-dependent part of the error falls as h^2 (observed order
  // 2 +- 0.1; the O(h^4) terms shift it by (beta h)^2 / 12 at most).
  for (std::size_t n = 0; n < 3; ++n) {
    const double order = std::log2(errors[0][n] / errors[1][n]);
    EXPECT_NEAR(order, 2.0, 0.1) << "mode " << n + 1;
    std::printf("lumped cantilever mode %zu: observed order of the mesh-dependent error %.3f\n", n + 1, order);
  }
}
