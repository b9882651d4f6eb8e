// Time integration of a SwitchedSystem (rigid/switched_system.h,
// docs/theory/rigid.md, section 8), M q'' + C_s q' + K_s q = f_s(t), written as
// the first-order system y = [q; v], y' = [v; a(t, q, v)] with a from
// SwitchedSystem::acceleration.
//
// Two integrators:
//   integrate_event_located  CVODE (variable-order, variable-step linear
//       multistep, Newton iteration with a dense direct linear solver) with
//       root finding on the system's event functions and stops at its
//       scheduled changes. After each event the discrete state is updated and
//       CVODE restarts (CVodeReInit), so no step ever straddles a switch.
//   integrate_rk4  the thesis's fixed-step classical fourth-order Runge-Kutta,
//       kept as a reference: event functions are only looked at step ends.
//
// Units: SI throughout; q and v are in the units of the model's generalised
// coordinates (m or rad, m/s or rad/s), times in s.
//
// Errors: invalid arguments throw std::invalid_argument; a run that cannot
// continue (CVODE cannot meet the tolerance, a NaN/Inf state or
// acceleration, too many steps) throws core::NumericalError saying when,
// why and what to try.
#pragma once

#include <Eigen/Dense>

#include <string>
#include <vector>

#include "rigid/switched_system.h"

namespace framedyn::rigid {

// CVODE's linear multistep family.
//   adams_moulton  orders 1..12. The default: the vehicle and frame models are
//       lightly damped oscillators whose eigenvalues lie near the imaginary
//       axis, where BDF of order 3..5 is not stable for large h*omega (its
//       A(alpha) sectors are 86, 73, 51 degrees) and low-order BDF damps the
//       motion numerically; Adams reaches a high order, takes fewer steps at
//       tight tolerances and locates events more accurately (measured in
//       tests/rigid/test_time_integration.cpp: 8138 against 14868 steps over
//       100 periods of an oscillator at rtol 1e-8; contact times within
//       4e-11 s against 9e-10 s at rtol 1e-10).
//   bdf            orders 1..5, for models made stiff by a heavily damped fast
//       component (a stiff, strongly damped soil or tyre contact), where Adams
//       is stable only at orders 1 and 2 (measured: 8 times fewer steps than
//       Adams on a wheel with a 1e7 N/m, 1e5 N s/m contact).
enum class MultistepMethod { adams_moulton, bdf };

struct IntegrationOptions {
  double start_time = 0.0;               // s
  double end_time = 1.0;                 // s, > start_time
  // Samples are written at start_time + k * output_interval (k = 0, 1, ...)
  // strictly before end_time, and at end_time. The outputs do not influence
  // the steps CVODE takes (they are interpolated from its dense output).
  double output_interval = 1e-3;         // s
  double relative_tolerance = 1e-8;      // CVODE's rtol (unused by integrate_rk4)
  // CVODE's absolute tolerance: absolute_tolerance for each q_i (m or rad),
  // absolute_tolerance * velocity_scale for each v_i (m/s or rad/s). With the
  // default velocity_scale = 1 1/s the same number is used in SI units; since
  // a mode at omega rad/s has velocities omega times its displacements, this
  // is the tighter side for every mode above 0.16 Hz. Set velocity_scale to a
  // typical omega of the model to weigh q and v errors equally.
  double absolute_tolerance = 1e-10;
  int max_steps = 1000000;               // internal steps over the whole run (both integrators)
  MultistepMethod method = MultistepMethod::adams_moulton;
  double velocity_scale = 1.0;           // 1/s, see absolute_tolerance
  // Names of the coordinates (size() of them, or none), for the messages of
  // numerical failures: the state at the failure is given coordinate by
  // coordinate. Without names the coordinates are called by their index.
  std::vector<std::string> coordinate_names;
};

struct Trajectory {
  std::vector<double> time;              // s, the output samples
  // At each sample: coordinates, velocities and the system's acceleration
  // evaluated there. A sample that falls exactly on a change of the discrete
  // state reports the state after the change (a is right-continuous).
  std::vector<Eigen::VectorXd> q, v, a;
  struct Event {
    double time;                         // s
    std::string what;                    // on_event / on_scheduled_change's description
    std::string length_name;             // a length that goes with it (SwitchedSystem::last_event_length), or empty
    double length = std::numeric_limits<double>::quiet_NaN();  // m
  };
  std::vector<Event> events;             // located switches and scheduled changes, in order
  long steps = 0;                        // internal steps taken (summed over restarts)
  long rhs_evaluations = 0;              // calls of SwitchedSystem::acceleration by the integrator
                                         // (CVODE: including its difference-quotient Jacobians;
                                         //  not counting the a written at the samples)
};

// CVODE with root finding on the system's event functions and stops at its
// scheduled changes. On a root, on_event receives the indices of the event
// functions that crossed and their directions (+1 rising, -1 falling); at a
// scheduled time on_scheduled_change is called; then CVODE is re-initialised
// at that time and state. Step sizes and orders are CVODE's own (the first
// step after each restart included). The Newton matrix is built by
// difference quotients (the interface has no Jacobian).
// Throws core::NumericalError if CVODE fails (at what time, which condition,
// what to try, and the state there), if max_steps is exceeded, or if a state
// or acceleration becomes NaN/Inf (time and coordinate).
Trajectory integrate_event_located(SwitchedSystem& system, const Eigen::VectorXd& q0, const Eigen::VectorXd& v0,
                                   const IntegrationOptions& options);

// The fixed-step classical Runge-Kutta method (RK4) with step `step` (s). The
// discrete state is frozen during a step. At each step end the event
// functions are evaluated; a sign change since the previous step end (from
// < 0 to >= 0 rising, from > 0 to <= 0 falling) calls on_event there, with no
// location inside the step. A scheduled change is applied at the first step
// end at or after its time (within 1e-9 step of round-off). `step` must divide
// options.output_interval (to 1e-9 relative); if the span is not a multiple of
// the step, the last step is shortened to end at end_time. Tolerances in
// `options` are not used. Throws core::NumericalError on a NaN/Inf state or
// acceleration (time and coordinate) and when more than max_steps are needed.
Trajectory integrate_rk4(SwitchedSystem& system, const Eigen::VectorXd& q0, const Eigen::VectorXd& v0, double step,
                         const IntegrationOptions& options);

}  // namespace framedyn::rigid
