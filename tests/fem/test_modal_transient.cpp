// Transient response by mode superposition and by direct integration: the
// exact piecewise-linear modal update against closed-form SDOF solutions,
// mode superposition against Newmark, mode acceleration against mode
// displacement, inertia relief, and the quasi-static limit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <vector>

#include "fem/beam_section.h"
#include "fem/direct_integration.h"
#include "fem/inp_reader.h"
#include "fem/modal_transient.h"
#include "fem/static_analysis.h"
#include "tests/support/beam_meshes.h"

namespace {

using namespace framedyn::fem;
constexpr double kPi = 3.14159265358979323846;

// Steps q'' + c q' + k q = p from (q0, v0) over n steps of h with p(t) sampled at the step ends.
template <class Load>
Eigen::Vector2d integrate(double k, double c, double h, int n, Load p, Eigen::Vector2d z = Eigen::Vector2d::Zero()) {
  const PiecewiseLinearStep s = piecewise_linear_step(k, c, h);
  for (int i = 0; i < n; ++i) z = s.a * z + s.b0 * p(i * h) + s.b1 * p((i + 1) * h);
  return z;
}

TEST(PiecewiseLinearStep, StepLoadMatchesDampedClosedForm) {
  const double w = 10.0, z = 0.05, k = w * w, c = 2 * z * w, h = 0.01, t = 2.0;
  const double wd = w * std::sqrt(1 - z * z);
  const double exact = (1 - std::exp(-z * w * t) * (std::cos(wd * t) + z / std::sqrt(1 - z * z) * std::sin(wd * t))) / k;
  const Eigen::Vector2d q = integrate(k, c, h, 200, [](double) { return 1.0; });
  // Exact update: only round-off (200 steps of ~1e-16) remains.
  EXPECT_NEAR(q(0), exact, 1e-14 / k * 200);
}

// A long record's grid of rounded times t_k = k dt (the pipeline's: dt = 0.5 ms, 10 s) has steps
// t_k - t_{k-1} that differ by an ulp or two of t, more than 1e-12 h past t = 4 s, yet only a few
// distinct ones: the memo holds them all, gives each the exact step's own numbers, and the
// response over the whole record still matches the closed form of a unit step load.
TEST(PiecewiseLinearStep, RoundedTimeGridHasFewDistinctStepsAndTheMemoGivesTheExactStepOfEach) {
  const double dt = 0.0005, w = 2 * 3.14159265358979323846 * 32.49, z = 0.02, k = w * w, c = 2 * z * w;
  const int n = 20000;
  std::vector<double> times(n + 1);  // as rigid/time_integration.cpp makes its output times
  for (int i = 0; i <= n; ++i) times[static_cast<std::size_t>(i)] = 0.0 + static_cast<double>(i) * dt;
  framedyn::fem::StepMemo memo;
  std::vector<double> distinct;
  std::size_t asks = 0;  // how often the integrators' test |h - h_prev| > 1e-12 h asks for a new step
  double h_prev = -1.0;
  Eigen::Vector2d y(0.0, 0.0);
  for (int i = 1; i <= n; ++i) {
    const double h = times[static_cast<std::size_t>(i)] - times[static_cast<std::size_t>(i - 1)];
    if (std::find(distinct.begin(), distinct.end(), h) == distinct.end()) distinct.push_back(h);
    if (std::abs(h - h_prev) > 1e-12 * h) ++asks, h_prev = h;
    const framedyn::fem::PiecewiseLinearStep& s = memo.step(k, c, h);
    const framedyn::fem::PiecewiseLinearStep e = framedyn::fem::piecewise_linear_step(k, c, h);
    ASSERT_TRUE(s.a == e.a && s.b0 == e.b0 && s.b1 == e.b1) << "step " << i;
    y = s.a * y + s.b0 * 1.0 + s.b1 * 1.0;
  }
  EXPECT_LE(distinct.size(), framedyn::fem::kRememberedSteps);
  EXPECT_GT(asks, 10 * distinct.size());  // many more new steps asked than there are distinct ones: the memo's reason
  const double t = n * dt, wd = w * std::sqrt(1 - z * z);
  const double exact = (1 - std::exp(-z * w * t) * (std::cos(wd * t) + z / std::sqrt(1 - z * z) * std::sin(wd * t))) / k;
  EXPECT_NEAR(y(0), exact, 1e-14 / k * n);
  std::cout << "[ measured ] " << distinct.size() << " distinct steps in " << n << " of a " << dt << " s grid; " << asks
            << " asked for by the 1e-12 h test\n";
}

TEST(PiecewiseLinearStep, RampLoadMatchesDampedClosedForm) {
  for (const double z : {0.0, 0.02, 0.3}) {
    const double w = 25.0, k = w * w, c = 2 * z * w, h = 0.003, t = 1.5;
    const double wd = w * std::sqrt(1 - z * z);
    // q = (t - 2 zeta/w + e^{-zeta w t} (2 zeta/w cos wd t - (1 - 2 zeta^2)/wd sin wd t)) / k
    const double exact = (t - 2 * z / w + std::exp(-z * w * t) * (2 * z / w * std::cos(wd * t) - (1 - 2 * z * z) / wd * std::sin(wd * t))) / k;
    const Eigen::Vector2d q = integrate(k, c, h, 500, [](double s) { return s; });
    EXPECT_NEAR(q(0), exact, 1e-13 * t / k) << "zeta " << z;
  }
}

TEST(PiecewiseLinearStep, RigidBodyAndOverdampedModesAreExact) {
  // k = 0, c = 0: q'' = t gives q = t^3 / 6 (a PL load reproduces it exactly).
  EXPECT_NEAR(integrate(0.0, 0.0, 0.01, 100, [](double s) { return s; })(0), 1.0 / 6.0, 1e-14);
  // k = 0, c > 0, unit step: q = t/c - (1 - e^{-ct}) / c^2.
  const double c = 3.0, t = 1.0;
  EXPECT_NEAR(integrate(0.0, c, 0.01, 100, [](double) { return 1.0; })(0), t / c - (1 - std::exp(-c * t)) / (c * c), 1e-14);
  // zeta = 2 (overdamped), unit step: q = (1 - (l2 e^{l1 t} - l1 e^{l2 t}) / (l2 - l1)) / k.
  const double w = 5.0, z = 2.0, k = w * w;
  const double l1 = -z * w + w * std::sqrt(z * z - 1), l2 = -z * w - w * std::sqrt(z * z - 1);
  const double exact = (1 - (l2 * std::exp(l1 * t) - l1 * std::exp(l2 * t)) / (l2 - l1)) / k;
  EXPECT_NEAR(integrate(k, 2 * z * w, 0.01, 100, [](double) { return 1.0; })(0), exact, 1e-14);
  // zeta = 1 (critical): q = (1 - e^{-wt} (1 + w t)) / k.
  EXPECT_NEAR(integrate(k, 2 * w, 0.01, 100, [](double) { return 1.0; })(0), (1 - std::exp(-w * t) * (1 + w * t)) / k, 1e-14);
}

TEST(PiecewiseLinearStep, SampledSineConvergesAtSecondOrderToHarmonicSolution) {
  // Undamped, from rest: q = (sin W t - r sin w t) / (k (1 - r^2)), r = W / w.
  const double w = 20.0, k = w * w, W = 7.0, r = W / w, t = 3.0;
  const double exact = (std::sin(W * t) - r * std::sin(w * t)) / (k * (1 - r * r));
  double previous = 0.0;
  for (int n : {300, 600, 1200, 2400}) {
    const double err = std::abs(integrate(k, 0.0, t / n, n, [&](double s) { return std::sin(W * s); })(0) - exact);
    std::cout << "[ measured ] sampled sine, " << n << " steps: error " << err * k << " (relative to 1/k)\n";
    // The only error is the PL interpolation of the sine, O(h^2): halving h quarters it (ratio 4 +- 10 %).
    if (previous > 0.0) {
      EXPECT_NEAR(previous / err, 4.0, 0.4);
    }
    previous = err;
  }
}

TEST(PiecewiseLinearStep, NigamJenningsRecurrenceAgreesWithMatrixExponential) {
  for (const double z : {0.0, 0.05, 0.7})
    for (const double wh : {0.05, 0.5, 3.0, 40.0}) {
      const double w = 30.0, h = wh / w;
      const PiecewiseLinearStep a = piecewise_linear_step(w * w, 2 * z * w, h);
      const PiecewiseLinearStep b = internal::nigam_jennings_step(w, z, h);
      // Scale of each coefficient: a ~ 1 (q), w (v); b ~ h^2 or 1/k for q.
      EXPECT_NEAR(a.a(0, 0), b.a(0, 0), 1e-12);
      EXPECT_NEAR(a.a(1, 1), b.a(1, 1), 1e-12);
      EXPECT_NEAR(a.a(0, 1) * w, b.a(0, 1) * w, 1e-12);
      EXPECT_NEAR(a.a(1, 0) / w, b.a(1, 0) / w, 1e-12);
      // NJ loses digits as 1/(w h)^2 (cancellation); 1e-12 relative at w h = 0.05 allows 2.5e-14 / (wh)^2.
      const double tol = 1e-12 * std::max(1.0, 0.01 / (wh * wh));
      EXPECT_NEAR(a.b0(0) * w * w, b.b0(0) * w * w, tol) << z << " " << wh;
      EXPECT_NEAR(a.b1(0) * w * w, b.b1(0) * w * w, tol) << z << " " << wh;
      EXPECT_NEAR(a.b0(1) * w * h, b.b0(1) * w * h, tol) << z << " " << wh;
      EXPECT_NEAR(a.b1(1) * w * h, b.b1(1) * w * h, tol) << z << " " << wh;
    }
}

TEST(ModalDamping, RayleighRatioIsAlphaOverTwoOmegaPlusBetaOmegaOverTwo) {
  const ModalDamping d = ModalDamping::rayleigh_damping(2.0, 1e-4);
  EXPECT_DOUBLE_EQ(d.ratio_of(0, 100.0), 2.0 / 200.0 + 1e-4 * 50.0);
  const ModalDamping p{{0.01, 0.03}, false, 0, 0};
  EXPECT_DOUBLE_EQ(p.ratio_of(0, 10.0), 0.01);
  EXPECT_DOUBLE_EQ(p.ratio_of(5, 10.0), 0.03);  // the last value repeats
}

// ---------------------------------------------------------------------------
// A small 3-D frame: an L of box tubes (a 1.2 m arm along X, a 0.6 m arm along Y),
// bending in both planes and twisting.

FrameModel l_frame(bool clamped) {
  FrameModel m;
  const int s = framedyn::testing::add_section(m, box_section(0.10, 0.06, 0.004, 0.004, 0.004, 0.004), framedyn::testing::steel(),
                                               Eigen::Vector3d(0, 0, 1));
  const int n0 = framedyn::testing::add_node(m, Eigen::Vector3d::Zero());
  const std::vector<int> a = framedyn::testing::add_beam_line(m, n0, Eigen::Vector3d(1.2, 0, 0), 6, s, BeamTheory::timoshenko);
  framedyn::testing::add_beam_line(m, a.back(), Eigen::Vector3d(1.2, 0.6, 0), 3, s, BeamTheory::timoshenko);
  if (clamped) framedyn::testing::clamp_node(m, n0);
  m.index();
  return m;
}

// Load components: a vertical force at the corner, a lateral force at the tip, a torque at mid-arm.
SparseMatrix l_frame_loads(const FrameModel& m) {
  SparseMatrix b(m.dof_count(), 3);
  const int corner = 6, tip = 9, mid = 3;
  std::vector<Eigen::Triplet<double>> t = {{6 * corner + 2, 0, 1.0}, {6 * tip + 0, 1, 1.0}, {6 * mid + 3, 2, 1.0}};
  b.setFromTriplets(t.begin(), t.end());
  return b;
}

// A load history sampled every `dt` on [0, duration]: smooth pulses of a few times the first periods.
TransientInput pulse_history(const FrameModel& m, double dt, double duration, double scale_frequency) {
  TransientInput in;
  const int n = static_cast<int>(std::lround(duration / dt)) + 1;
  in.times = Eigen::VectorXd::LinSpaced(n, 0.0, duration);
  in.distribution = l_frame_loads(m);
  in.components.resize(3, n);
  for (int k = 0; k < n; ++k) {
    const double t = in.times(k), f = scale_frequency;
    in.components(0, k) = 2000.0 * std::sin(2 * kPi * f * t) * std::exp(-3 * t / duration);
    in.components(1, k) = 800.0 * (1 - std::cos(2 * kPi * 0.7 * f * t));
    in.components(2, k) = 150.0 * std::sin(2 * kPi * 1.9 * f * t + 0.3);
  }
  return in;
}

double max_abs_diff(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) { return (a - b).cwiseAbs().maxCoeff(); }

TEST(ModeSuperposition, AllModesEqualsNewmarkToSecondOrderInTheStep) {
  const FrameModel model = l_frame(true);
  FrameDynamics frame(model);
  const ModalBasis basis = frame.all_modes();
  const double f1 = std::sqrt(basis.eigenvalues(0)) / (2 * kPi);
  // 40 samples per period of the load; 0.1 s covers several periods of the lowest modes.
  const TransientInput in = pulse_history(model, 1.0 / (40 * 1.5 * f1), 0.1, 1.5 * f1);
  const double alpha = 4.0, beta = 2e-5;  // Rayleigh: comparable damping for both methods
  ModalTransientOptions mo;
  mo.damping = ModalDamping::rayleigh_damping(alpha, beta);
  const TransientResult modal = modal_transient(frame, basis, in, mo);
  const double scale = modal.displacement.cwiseAbs().maxCoeff();
  double previous = 0.0;
  for (int sub : {2, 4, 8, 16}) {
    NewmarkOptions no;
    no.rayleigh_alpha = alpha;
    no.rayleigh_beta = beta;
    no.substeps = sub;
    const double err = max_abs_diff(direct_transient(frame, in, no).displacement, modal.displacement) / scale;
    std::cout << "[ measured ] Newmark " << sub << " substeps: max |u_newmark - u_modal| / max|u| = " << err;
    if (previous > 0.0) std::cout << ", ratio " << previous / err;
    std::cout << "\n";
    // Average acceleration is second order: halving the step divides the difference by 4 (+-15 %),
    // so the modal solution with all modes is the limit Newmark converges to.
    if (previous > 0.0) {
      EXPECT_NEAR(previous / err, 4.0, 0.6);
    }
    previous = err;
  }
  EXPECT_LT(previous, 1e-3);
}

TEST(ModeSuperposition, ModeAccelerationConvergesFasterInModeCountWhenStaticPartDominates) {
  const FrameModel model = l_frame(true);
  FrameDynamics frame(model);
  const ModalBasis basis = frame.all_modes();
  const double f1 = std::sqrt(basis.eigenvalues(0)) / (2 * kPi);
  // Loads at a tenth of the fundamental: the response is mostly static.
  const TransientInput in = pulse_history(model, 1.0 / (200 * f1), 0.5, 0.1 * f1);
  ModalTransientOptions o;
  o.damping = ModalDamping::ratio(0.02);
  const TransientResult reference = modal_transient(frame, basis, in, o);  // all modes
  const double scale = reference.displacement.cwiseAbs().maxCoeff();
  double previous_ma = 1e300;
  for (int m : {1, 2, 4, 8, 16}) {
    o.mode_count = m;
    o.method = ResponseMethod::mode_displacement;
    const double e_md = max_abs_diff(modal_transient(frame, basis, in, o).displacement, reference.displacement) / scale;
    o.method = ResponseMethod::mode_acceleration;
    const double e_ma = max_abs_diff(modal_transient(frame, basis, in, o).displacement, reference.displacement) / scale;
    std::cout << "[ measured ] " << m << " modes: mode displacement error " << e_md << ", mode acceleration error " << e_ma << "\n";
    EXPECT_LT(e_ma, e_md) << m << " modes";
    EXPECT_LE(e_ma, previous_ma) << m << " modes";
    previous_ma = e_ma;
  }
  // With the full basis the static correction vanishes identically: both methods agree to round-off.
  o.mode_count = -1;
  o.method = ResponseMethod::mode_acceleration;
  EXPECT_LT(max_abs_diff(modal_transient(frame, basis, in, o).displacement, reference.displacement) / scale, 1e-9);
}

TEST(ModeSuperposition, SlowRampGivesTheStaticSolution) {
  FrameModel model = l_frame(true);
  FrameDynamics frame(model);
  const ModalBasis basis = frame.all_modes();
  const double f1 = std::sqrt(basis.eigenvalues(0)) / (2 * kPi);
  // Ramp over 20 periods of the fundamental, then hold 60 periods. The ramp leaves a free
  // vibration of at most 1/(omega T) = 8e-3 of the static value, damped by exp(-2 pi zeta 60) = 6e-9.
  const double period = 1.0 / f1;
  TransientInput in;
  in.times.resize(3);
  in.times << 0.0, 20 * period, 80 * period;
  in.distribution = l_frame_loads(model);
  in.components.resize(3, 3);
  in.components.col(0).setZero();
  in.components.col(1) << 1500.0, -700.0, 90.0;
  in.components.col(2) = in.components.col(1);
  // The same loads as a static load case.
  model.loads.push_back({6, 2, 1500.0});
  model.loads.push_back({9, 0, -700.0});
  model.loads.push_back({3, 3, 90.0});
  const StaticResult st = solve_static(model);
  const double scale = st.displacement.cwiseAbs().maxCoeff();
  for (ResponseMethod method : {ResponseMethod::mode_displacement, ResponseMethod::mode_acceleration}) {
    ModalTransientOptions o;
    o.method = method;
    o.damping = ModalDamping::ratio(0.05);
    o.initial = InitialState::rest;
    const TransientResult r = modal_transient(frame, basis, in, o);
    const double err = (r.displacement.col(2) - st.displacement).cwiseAbs().maxCoeff() / scale;
    std::cout << "[ measured ] slow ramp, method " << static_cast<int>(method) << ": |u - u_static| / max|u_static| = " << err << "\n";
    EXPECT_LT(err, 1e-7);
  }
}

TEST(InertiaRelief, RelievedLoadIsSelfEquilibratedAndAuxiliarySupportsCarryNothing) {
  const FrameModel model = l_frame(false);
  FrameDynamics frame(model);
  ASSERT_TRUE(frame.free_free());
  ASSERT_EQ(frame.auxiliary_supports().size(), 6u);
  TransientInput in = pulse_history(model, 1e-3, 0.01, 10.0);
  const Eigen::MatrixXd b = frame.free_loads(in.distribution);
  const Eigen::MatrixXd r_all = rigid_body_vectors(model, Eigen::Vector3d(0.3, -0.2, 0.1));
  for (int c = 0; c < 3; ++c) {
    // Resultant force and moment (about an arbitrary point) of F_rel = F - M a_rigid: zero,
    // i.e. the applied loads plus the inertia of the rigid-body acceleration are in equilibrium.
    const Eigen::VectorXd f = in.distribution.col(c);
    const double scale = f.cwiseAbs().maxCoeff() * 1.2;  // N and N m over a 1.2 m frame
    const Eigen::VectorXd resultant_applied = r_all.transpose() * f;
    const Eigen::VectorXd resultant = r_all.transpose() * b.col(c);
    EXPECT_GT(resultant_applied.cwiseAbs().maxCoeff(), 0.5);
    EXPECT_LT(resultant.cwiseAbs().maxCoeff(), 1e-12 * scale) << "component " << c;
    // The auxiliary supports carry no reaction under the relieved load.
    const Eigen::VectorXd reactions = frame.auxiliary_reactions(b.col(c));
    std::cout << "[ measured ] component " << c << ": |resultant of F_rel| = " << resultant.cwiseAbs().maxCoeff()
              << ", max auxiliary reaction = " << reactions.cwiseAbs().maxCoeff() << " (load 1)\n";
    EXPECT_LT(reactions.cwiseAbs().maxCoeff(), 1e-9 * scale);
    // ... but would under the unrelieved load (the supports are really there).
    Eigen::VectorXd f_free(frame.dofs().free_count());
    for (int e = 0; e < f_free.size(); ++e) f_free(e) = f(frame.dofs().free_dofs[static_cast<std::size_t>(e)]);
    EXPECT_GT(frame.auxiliary_reactions(f_free).cwiseAbs().maxCoeff(), 0.1);
  }
}

TEST(InertiaRelief, FreeFreeModalAndNewmarkResponsesAgree) {
  const FrameModel model = l_frame(false);
  FrameDynamics frame(model);
  const ModalBasis basis = frame.all_modes();
  ASSERT_EQ(basis.elastic_count(), frame.dofs().free_count() - 6);
  const double f1 = std::sqrt(basis.eigenvalues(6)) / (2 * kPi);
  const TransientInput in = pulse_history(model, 1.0 / (40 * f1), 0.05, f1);
  ModalTransientOptions mo;
  mo.damping = ModalDamping::rayleigh_damping(0.0, 2e-5);
  const TransientResult modal = modal_transient(frame, basis, in, mo);
  NewmarkOptions no;
  no.rayleigh_beta = 2e-5;
  no.substeps = 16;
  const double err = max_abs_diff(direct_transient(frame, in, no).displacement, modal.displacement) / modal.displacement.cwiseAbs().maxCoeff();
  std::cout << "[ measured ] free-free, Newmark 16 substeps vs all modes: " << err << "\n";
  // Newmark's O(h^2) error at 16 substeps of 1/40 of the first elastic period: (2 pi / 640)^2 / 12 ~ 1e-5 per period.
  EXPECT_LT(err, 1e-3);
  // The elastic displacement has no rigid-body part: R^T M u = 0.
  const Eigen::VectorXd u0 = modal.displacement.col(modal.displacement.cols() - 1);
  Eigen::VectorXd uf(frame.dofs().free_count());
  for (int e = 0; e < uf.size(); ++e) uf(e) = u0(frame.dofs().free_dofs[static_cast<std::size_t>(e)]);
  EXPECT_LT((frame.rigid_vectors().transpose() * frame.mass_times(uf)).cwiseAbs().maxCoeff(), 1e-10 * uf.norm());
}

TEST(FrameDynamics, DenseAllModesAgreeWithLanczosOnR100Frame) {
  for (const bool clamped : {true, false}) {
    FrameModel model = read_inp(std::string(FRAMEDYN_SOURCE_DIR) + "/meshes/r100_frame.inp");
    if (clamped)
      for (int node : model.node_sets.at("REAR_END"))
        for (int d = 0; d < 6; ++d) model.constraints.push_back({node, d, 0.0});
    FrameDynamics frame(model);
    const ModalBasis dense = frame.all_modes();
    ModalOptions mo;
    mo.mode_count = 16;
    const ModalBasis lanczos = modal_basis(frame.dofs(), compute_modes(model, mo));
    ASSERT_EQ(lanczos.elastic_count(), clamped ? 16 : 10);
    double worst = 0.0;
    for (int i = clamped ? 0 : 6; i < 16; ++i) worst = std::max(worst, std::abs(dense.eigenvalues(i) / lanczos.eigenvalues(i) - 1.0));
    std::cout << "[ measured ] " << (clamped ? "clamped" : "free-free") << ": largest relative eigenvalue difference dense/Lanczos " << worst << "\n";
    // Both are converged to round-off (Lanczos tolerance 1e-10 on 1/(lambda - sigma)).
    EXPECT_LT(worst, 1e-8);
  }
}

}  // namespace
