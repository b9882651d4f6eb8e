// The thesis's fixed-step RK4 against the event-located integrator on the
// earlier shipped plowing machine (examples/r100_plow_2d_vertical_path.yaml), through the study
// runner, so that the compared numbers are the ones `framedyn run` reports.
// The convergence study behind the tolerances: docs/validation_integration.md
// (bench/rigid_response_benchmark --part convergence).
//
// With that plow the blade never backs off in the 0.5 s run (its
// rearward velocity stays below the forward speed), so the system integrated
// is linear with harmonic forcing: RK4 converges at fourth order and its
// error at 0.0001 s is at the reference's round-off level (1.4e-9 in peak
// plow force against an rtol 1e-11 reference). The two tests below assert
// that premise first; with switches the comparison is a different one (the
// study's switching variant: RK4 at 0.0001 s is 2 % off in peak plow force,
// because it applies each switch at the end of the step in which it happens).
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <cmath>
#include <cstdio>
#include <string>

#include "coupling/rigid_study.h"
#include "rigid/machine_2d.h"
#include "rigid/time_integration.h"
#include "rigid/vehicle_model.h"
#include "rigid/vehicle_run.h"

namespace {

using namespace framedyn;

std::string shipped_plow() { return std::string(FRAMEDYN_SOURCE_DIR) + "/examples/r100_plow_2d_vertical_path.yaml"; }

coupling::RigidResults respond(coupling::ResponseRequest::Method method, double rk4_step, double rtol) {
  coupling::RigidStudy study = coupling::read_rigid_study(shipped_plow());
  // The premise is a linear system: the thesis's bilateral tires (with one-sided
  // ones the bounce tire lifts off, an event, and RK4 drops to first order).
  study.machine_2d().contacts = rigid::ContactLaw::linear;
  study.modes = false;
  study.calibration.reset();
  coupling::ResponseRequest r;  // the shipped study's: 0.5 s, samples every 0.0005 s
  r.duration = 0.5;
  r.output_interval = 5e-4;
  r.method = method;
  r.rk4_step = rk4_step;
  r.relative_tolerance = rtol;
  study.response = r;
  return coupling::run_rigid_study(study);
}

// RK4 at 0.0001 s (the thesis's finest step, used for the offset chain)
// against CVODE at the study default rtol 1e-8, on the peak plow force and the
// average peak-to-peak blade motion that run_rigid_study reports.
//
// Tolerance 2e-5 (relative). The difference is bounded by the two errors.
// CVODE keeps each step's local error below rtol in the weighted RMS norm, so
// one component's global error after N steps is at most about
// N sqrt(2n) (rtol |y| + atol) (the policy of test_time_integration.cpp):
// N = 454 steps, n = 6 give 454 * 3.46 * 1e-8 = 1.6e-5. RK4's error at
// 0.0001 s is far below: 1.2e-8 at 0.0005 s, falling as h^4 (checked below).
// Measured: 2.0e-8 (peak force), 7.3e-9 (peak-to-peak).
TEST(IntegratorConvergence, Rk4AtTenthMillisecondAgreesWithEventLocatedOnPeakPlowForce) {
  using Method = coupling::ResponseRequest::Method;
  const coupling::RigidResults el = respond(Method::event_located, 5e-4, 1e-8);
  const coupling::RigidResults rk = respond(Method::rk4, 1e-4, 1e-8);
  ASSERT_TRUE(el.trajectory.events.empty() && rk.trajectory.events.empty())
      << "the shipped plow now switches its soil law within 0.5 s (" << el.trajectory.events.size()
      << " events): the smooth-problem tolerance below no longer applies; see docs/validation_integration.md";
  ASSERT_TRUE(el.peak_cutting_force && rk.peak_cutting_force && el.plow_vertical_peak_to_peak && rk.plow_vertical_peak_to_peak);
  const double df = std::abs(*rk.peak_cutting_force - *el.peak_cutting_force) / *el.peak_cutting_force;
  const double dp = std::abs(*rk.plow_vertical_peak_to_peak - *el.plow_vertical_peak_to_peak) / *el.plow_vertical_peak_to_peak;
  std::printf("peak plow force %.3f N (event-located) vs %.3f N (RK4 0.0001 s): %.2e; peak-to-peak %.3e m: %.2e\n", *el.peak_cutting_force,
              *rk.peak_cutting_force, df, *el.plow_vertical_peak_to_peak, dp);
  EXPECT_LE(df, 2e-5);
  EXPECT_LE(dp, 2e-5);
  // And a physical check that it is the plowing force being compared: the
  // cutting peak is tens of kN (24,553 lbf = 109 kN with the shipped data).
  EXPECT_GT(*el.peak_cutting_force, 1e4);
}

// Without switches RK4 is a fourth-order method on this machine: the largest
// blade-motion error against an rtol 1e-11 reference falls by 2^4 = 16 when
// the step is halved from 0.0005 s. Asserted: at least 2^3 = 8 (order 3, a
// margin for the higher-order terms at h omega = 0.04 for the fastest mode;
// measured 14.4). A step that applied the forcing or the state at the wrong
// stage time would show order 1 or 2.
TEST(IntegratorConvergence, Rk4IsFourthOrderOnTheShippedPlowWithoutSwitches) {
  coupling::RigidStudy study = coupling::read_rigid_study(shipped_plow());
  study.machine_2d().contacts = rigid::ContactLaw::linear;  // a linear system, as above
  const rigid::VehicleModel m = rigid::build_vehicle_model(study.machine_2d());
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(m.size());
  rigid::IntegrationOptions o;
  o.end_time = 0.5;
  o.output_interval = 5e-4;
  o.absolute_tolerance = 1e-12;
  o.velocity_scale = 100.0;
  const rigid::Jacobian& blade = m.multibody.points()[static_cast<std::size_t>(m.blade_point)].displacement;
  auto blade_z = [&](const rigid::Trajectory& t, std::size_t i) { return blade.row(2).dot(t.q[i]); };

  rigid::VehicleRunState m_run = rigid::start_run(m, 0.0, zero);
  rigid::VehicleDynamics m_dyn(m, m_run);
  o.relative_tolerance = 1e-11;
  const rigid::Trajectory ref = rigid::integrate_event_located(m_dyn, zero, zero, o);
  ASSERT_TRUE(ref.events.empty()) << "the shipped plow now switches: RK4 is then first order (docs/validation_integration.md)";
  m_run = rigid::start_run(m, 0.0, zero);
  o.relative_tolerance = 1e-12;
  const rigid::Trajectory tighter = rigid::integrate_event_located(m_dyn, zero, zero, o);
  double reference_error = 0.0;  // the reference's own, estimated against rtol 1e-12
  for (std::size_t i = 0; i < ref.time.size(); ++i) reference_error = std::max(reference_error, std::abs(blade_z(tighter, i) - blade_z(ref, i)));
  double error[2] = {0.0, 0.0};
  const double steps[2] = {5e-4, 2.5e-4};
  for (int k = 0; k < 2; ++k) {
    m_run = rigid::start_run(m, 0.0, zero);
    const rigid::Trajectory t = rigid::integrate_rk4(m_dyn, zero, zero, steps[k], o);
    ASSERT_EQ(t.time.size(), ref.time.size());
    for (std::size_t i = 0; i < t.time.size(); ++i) error[k] = std::max(error[k], std::abs(blade_z(t, i) - blade_z(ref, i)));
  }
  std::printf("max blade z error: %.3e m (h = 0.0005 s), %.3e m (0.00025 s), ratio %.1f; reference's own %.1e m\n", error[0], error[1],
              error[0] / error[1], reference_error);
  // The ratio measures RK4 only if the finer error stands well above the
  // reference's own (measured 7.2e-11 against 7.6e-12 m).
  ASSERT_GT(error[1], 5.0 * reference_error);
  EXPECT_GE(error[0] / error[1], 8.0);
}

}  // namespace
