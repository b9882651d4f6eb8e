// CVODE with event location and the fixed-step RK4 reference; see
// time_integration.h. SUNDIALS is used only in this file.
#include "rigid/time_integration.h"

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <stdexcept>
#include <utility>

#include "core/error.h"

namespace framedyn::rigid {
namespace internal {

// ---------------------------------------------------------------------------
// Shared by both integrators

void check_arguments(const SwitchedSystem& system, const Eigen::VectorXd& q0, const Eigen::VectorXd& v0,
                     const IntegrationOptions& o) {
  const int n = system.size();
  if (n < 1) throw std::invalid_argument(fmt::format("the system has {} coordinates; at least 1 is needed", n));
  if (q0.size() != n || v0.size() != n)
    throw std::invalid_argument(
        fmt::format("initial state: the system has {} coordinates but q0 has {} and v0 {} entries", n, q0.size(), v0.size()));
  if (!std::isfinite(o.start_time) || !std::isfinite(o.end_time) || !(o.end_time > o.start_time))
    throw std::invalid_argument(
        fmt::format("end_time must be finite and after start_time; found start {} s, end {} s", o.start_time, o.end_time));
  if (!(o.output_interval > 0.0) || !std::isfinite(o.output_interval))
    throw std::invalid_argument(fmt::format("output_interval must be positive; found {} s", o.output_interval));
  if ((o.end_time - o.start_time) / o.output_interval > 1e8)
    throw std::invalid_argument(fmt::format("output_interval {} s gives more than 1e8 samples over {} s", o.output_interval,
                                            o.end_time - o.start_time));
  if (o.max_steps < 1) throw std::invalid_argument(fmt::format("max_steps must be at least 1; found {}", o.max_steps));
}

// start + k * dt strictly before end (by more than 1e-9 dt, so round-off
// cannot put a sample a hair before the end), then end.
std::vector<double> output_times(const IntegrationOptions& o) {
  std::vector<double> times;
  for (long k = 0;; ++k) {
    const double t = o.start_time + static_cast<double>(k) * o.output_interval;
    if (!(t < o.end_time - 1e-9 * o.output_interval)) break;
    times.push_back(t);
  }
  times.push_back(o.end_time);
  return times;
}

// The first non-finite entry of x, or -1.
int first_non_finite(const double* x, int n) {
  for (int i = 0; i < n; ++i)
    if (!std::isfinite(x[i])) return i;
  return -1;
}

// "z_frame (coordinate 1)" with names, "coordinate 1" without.
std::string coordinate_label(const std::vector<std::string>& names, int i) {
  if (i >= 0 && static_cast<std::size_t>(i) < names.size()) return fmt::format("{} (coordinate {})", names[static_cast<std::size_t>(i)], i);
  return fmt::format("coordinate {}", i);
}

// The state coordinate by coordinate: "q: x 0.001, z -2e-05; v: x 0.1, z 0.3"
// (m or rad, m/s or rad/s), for the messages of failures.
std::string state_text(const Eigen::VectorXd& q, const Eigen::VectorXd& v, const std::vector<std::string>& names) {
  auto list = [&](const Eigen::VectorXd& x) {
    std::string out;
    for (Eigen::Index i = 0; i < x.size(); ++i) {
      const std::size_t k = static_cast<std::size_t>(i);
      out += fmt::format("{}{} {:.6g}", i ? ", " : "", k < names.size() ? names[k] : fmt::format("[{}]", i), x[i]);
    }
    return out;
  };
  return fmt::format("q: {}; v: {}", list(q), list(v));
}

void check_state(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v, const char* integrator,
                 const std::vector<std::string>& names) {
  const int n = static_cast<int>(q.size());
  const int iq = first_non_finite(q.data(), n);
  const int iv = first_non_finite(v.data(), n);
  if (iq < 0 && iv < 0) return;
  const bool in_q = iq >= 0;
  const int i = in_q ? iq : iv;
  throw core::NumericalError(fmt::format(
      "{}: the state became {} at t = {:.12g} s: {} of {} = {}. The motion is unbounded or the model "
      "produced a NaN: check its stiffness, damping and forces near this time{}. The state there: {}",
      integrator, std::isnan(in_q ? q[i] : v[i]) ? "NaN" : "infinite", t, in_q ? "q" : "v", coordinate_label(names, i),
      in_q ? q[i] : v[i], std::string(integrator) == "RK4" ? ", or reduce the step (RK4 is unstable for h omega_max > 2.8)" : "",
      state_text(q, v, names)));
}

core::NumericalError bad_acceleration(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v, const Eigen::VectorXd& a,
                                      int i, const char* integrator, const std::vector<std::string>& names) {
  // A state beyond sqrt(DBL_MAX) ~ 1.3e154 overflows in the products of the
  // model's forces (stiffness times displacement, Jacobians times forces):
  // the acceleration is then NaN or Inf because the motion is unbounded.
  Eigen::Index iq = 0, iv = 0;
  const double size_q = q.size() ? q.cwiseAbs().maxCoeff(&iq) : 0.0, size_v = v.size() ? v.cwiseAbs().maxCoeff(&iv) : 0.0;
  if (std::max(size_q, size_v) > 1e150) {
    const bool in_q = size_q >= size_v;
    return core::NumericalError(fmt::format(
        "{}: the motion is unbounded: by t = {:.12g} s the state has grown to {} of {} = {:.3g}, and the acceleration "
        "of {} overflowed to {}. Check the model's stability, stiffness and forces{}. The state there: {}",
        integrator, t, in_q ? "q" : "v", coordinate_label(names, static_cast<int>(in_q ? iq : iv)), in_q ? q[iq] : v[iv],
        coordinate_label(names, i), std::isnan(a[i]) ? "NaN" : "infinity",
        std::string(integrator) == "RK4" ? ", or reduce the step (RK4 is unstable for h omega_max > 2.8)" : "",
        state_text(q, v, names)));
  }
  return core::NumericalError(fmt::format(
      "{}: the system's acceleration of {} is {} at t = {:.12g} s with a finite state; the model produced "
      "a NaN or Inf (a zero mass, a division by zero, an input curve evaluated outside its range?). The state there: {}",
      integrator, coordinate_label(names, i), std::isnan(a[i]) ? "NaN" : "infinite", t, state_text(q, v, names)));
}

void evaluate_acceleration(const SwitchedSystem& system, double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                           Eigen::VectorXd& a, const char* integrator, const std::vector<std::string>& names) {
  system.acceleration(t, q, v, a);
  if (a.size() != q.size())
    throw std::logic_error(fmt::format("SwitchedSystem::acceleration returned {} entries for {} coordinates", a.size(), q.size()));
  const int i = first_non_finite(a.data(), static_cast<int>(a.size()));
  if (i >= 0) throw bad_acceleration(t, q, v, a, i, integrator, names);
}

double next_change_after(const SwitchedSystem& system, double t) {
  const double ts = system.next_scheduled_change(t);
  if (std::isnan(ts) || !(ts > t))
    throw std::logic_error(fmt::format("SwitchedSystem::next_scheduled_change({}) returned {}, not a later time", t, ts));
  return ts;
}

std::string event_description(std::string what, const std::vector<int>& fired, const std::vector<int>& directions) {
  if (!what.empty()) return what;
  std::string text = "event";
  for (std::size_t k = 0; k < fired.size(); ++k)
    text += fmt::format(" g[{}] {}", fired[k], directions[k] > 0 ? "rising" : "falling");
  return text;
}

void record_sample(const SwitchedSystem& system, Trajectory& out, double t, const Eigen::VectorXd& q,
                   const Eigen::VectorXd& v, const char* integrator, const std::vector<std::string>& names) {
  Eigen::VectorXd a = Eigen::VectorXd::Zero(q.size());
  evaluate_acceleration(system, t, q, v, a, integrator, names);
  out.time.push_back(t);
  out.q.push_back(q);
  out.v.push_back(v);
  out.a.push_back(std::move(a));
}

// ---------------------------------------------------------------------------
// CVODE

constexpr const char* kCvode = "CVODE";

// What the callbacks see. Exceptions never cross CVODE's C frames: a callback
// stores what it caught and returns a failure; the driver rethrows it.
struct CvodeCallbackData {
  SwitchedSystem* system = nullptr;
  const std::vector<std::string>* names = nullptr;  // the coordinates', for messages
  int n = 0;
  Eigen::VectorXd q, v, a;      // work space
  long rhs_calls = 0;
  std::exception_ptr pending;   // thrown by a callback
  std::string last_message;     // CVODE's last error message
};

int cvode_rhs(realtype t, N_Vector y, N_Vector ydot, void* user) {
  auto& d = *static_cast<CvodeCallbackData*>(user);
  try {
    const double* yd = N_VGetArrayPointer(y);
    double* fd = N_VGetArrayPointer(ydot);
    // A non-finite trial state comes from a diverging Newton iterate or an
    // oversized step: a recoverable failure, CVODE retries with a smaller step.
    if (first_non_finite(yd, 2 * d.n) >= 0) return 1;
    d.q = Eigen::Map<const Eigen::VectorXd>(yd, d.n);
    d.v = Eigen::Map<const Eigen::VectorXd>(yd + d.n, d.n);
    ++d.rhs_calls;
    evaluate_acceleration(*d.system, t, d.q, d.v, d.a, kCvode, *d.names);
    Eigen::Map<Eigen::VectorXd>(fd, d.n) = d.v;
    Eigen::Map<Eigen::VectorXd>(fd + d.n, d.n) = d.a;
    return 0;
  } catch (...) {
    d.pending = std::current_exception();
    return -1;
  }
}

int cvode_roots(realtype t, N_Vector y, realtype* g, void* user) {
  auto& d = *static_cast<CvodeCallbackData*>(user);
  try {
    const double* yd = N_VGetArrayPointer(y);
    d.q = Eigen::Map<const Eigen::VectorXd>(yd, d.n);
    d.v = Eigen::Map<const Eigen::VectorXd>(yd + d.n, d.n);
    const int m = d.system->event_count();
    d.system->events(t, d.q, d.v, g);
    const int i = first_non_finite(g, m);
    if (i >= 0)
      throw core::NumericalError(fmt::format("CVODE: event function g[{}] is {} at t = {:.12g} s", i, g[i], t));
    return 0;
  } catch (...) {
    d.pending = std::current_exception();
    return -1;
  }
}

void cvode_error_handler(int code, const char* /*module*/, const char* function, char* message, void* user) {
  if (code == CV_WARNING) return;  // warnings are not errors; library code prints nothing
  static_cast<CvodeCallbackData*>(user)->last_message = fmt::format("{}: {}", function ? function : "", message ? message : "");
}

// The SUNDIALS objects of one run, released in reverse order.
class CvodeSession {
 public:
  CvodeSession(int size, double* state, int lmm) {
    if (SUNContext_Create(nullptr, &context_) != 0) fail("SUNContext_Create");
    y_ = N_VMake_Serial(size, state, context_);
    tolerances_ = N_VNew_Serial(size, context_);
    matrix_ = SUNDenseMatrix(size, size, context_);
    if (!y_ || !tolerances_ || !matrix_) fail("N_Vector/SUNMatrix creation");
    solver_ = SUNLinSol_Dense(y_, matrix_, context_);
    memory_ = CVodeCreate(lmm, context_);
    if (!solver_ || !memory_) fail("CVodeCreate/SUNLinSol_Dense");
  }
  ~CvodeSession() {
    if (memory_) CVodeFree(&memory_);
    if (solver_) SUNLinSolFree(solver_);
    if (matrix_) SUNMatDestroy(matrix_);
    if (tolerances_) N_VDestroy(tolerances_);
    if (y_) N_VDestroy(y_);  // wraps the caller's memory: frees only the header
    if (context_) SUNContext_Free(&context_);
  }
  CvodeSession(const CvodeSession&) = delete;
  CvodeSession& operator=(const CvodeSession&) = delete;

  void* memory() const { return memory_; }
  N_Vector y() const { return y_; }
  N_Vector tolerances() const { return tolerances_; }
  SUNMatrix matrix() const { return matrix_; }
  SUNLinearSolver solver() const { return solver_; }
  SUNContext context() const { return context_; }

  static void check(int flag, const char* call) {
    if (flag < 0) throw std::runtime_error(fmt::format("CVODE set-up: {} returned {}", call, CVodeGetReturnFlagName(flag)));
  }

 private:
  [[noreturn]] static void fail(const char* what) {
    throw std::runtime_error(fmt::format("CVODE set-up: {} failed (out of memory?)", what));
  }
  SUNContext context_ = nullptr;
  N_Vector y_ = nullptr;
  N_Vector tolerances_ = nullptr;
  SUNMatrix matrix_ = nullptr;
  SUNLinearSolver solver_ = nullptr;
  void* memory_ = nullptr;
};

// A CVODE failure in human words: when, which condition, what to try.
core::NumericalError cvode_failure(int flag, double t, const Eigen::VectorXd& y, const CvodeCallbackData& d,
                                   const IntegrationOptions& o) {
  std::string condition, advice;
  switch (flag) {
    case CV_TOO_MUCH_WORK:
      condition = "too much work (CVODE's step limit per call)";
      advice = "raise max_steps, or look for a very fast or stiff component (method = bdf if it is strongly damped)";
      break;
    case CV_TOO_MUCH_ACC:
      condition = "too much accuracy requested (the tolerances are below what double precision can resolve here)";
      advice = fmt::format("loosen relative_tolerance ({:g}) or absolute_tolerance ({:g})", o.relative_tolerance,
                           o.absolute_tolerance);
      break;
    case CV_ERR_FAILURE:
      condition = "error test failed repeatedly (or with the smallest step)";
      advice =
          "this is nearly always a discontinuity CVODE was not told about: a force law or coefficient that switches "
          "without one of the model's event functions crossing zero, or a jump in an input; check the model near this "
          "time, or loosen the tolerances";
      break;
    case CV_CONV_FAILURE:
    case CV_NLS_FAIL:
      condition = "convergence failure of the Newton iteration (repeatedly or with the smallest step)";
      advice =
          "the solution may be growing without bound (check the model's stability and forces near this time), the "
          "acceleration may not be smooth in q and v between events (a switch missing from the event functions), or "
          "the model is stiff (method = bdf); check also for a nearly singular mass matrix";
      break;
    case CV_LINIT_FAIL:
    case CV_LSETUP_FAIL:
    case CV_LSOLVE_FAIL:
      condition = "the dense linear solver failed (the Newton matrix I - gamma J is singular)";
      advice = "check the model for a singular mass matrix or NaN coefficients";
      break;
    case CV_FIRST_RHSFUNC_ERR:
    case CV_REPTD_RHSFUNC_ERR:
    case CV_RHSFUNC_FAIL:
    case CV_UNREC_RHSFUNC_ERR:
      condition = "the acceleration could not be evaluated (repeatedly non-finite trial states)";
      advice = "the solution is probably blowing up: check the model's stability near this time, or loosen the tolerances";
      break;
    default:
      condition = fmt::format("CVODE returned {}", CVodeGetReturnFlagName(flag));
      advice = "check the model and the integration options";
  }
  return core::NumericalError(fmt::format("CVODE could not continue at t = {:.12g} s: {}. Try: {}.{} The state there: {}", t,
                                          condition, advice,
                                          d.last_message.empty() ? "" : " (CVODE says: " + d.last_message + ")",
                                          state_text(y.head(d.n), y.tail(d.n), o.coordinate_names)));
}

core::NumericalError too_much_work(double t, const Eigen::VectorXd& y, long steps, const IntegrationOptions& o) {
  const Eigen::Index n = y.size() / 2;
  return core::NumericalError(fmt::format(
      "CVODE: too much work: {} steps taken by t = {:.12g} s, more than max_steps = {} allowed for the run to {} s. "
      "Try: raise max_steps, or look for a very fast or stiff component (method = bdf if it is strongly damped), a "
      "singularity, or events firing repeatedly (chattering between two discrete states). The state there: {}",
      steps, t, o.max_steps, o.end_time, state_text(y.head(n), y.tail(n), o.coordinate_names)));
}

}  // namespace internal

Trajectory integrate_event_located(SwitchedSystem& system, const Eigen::VectorXd& q0, const Eigen::VectorXd& v0,
                                   const IntegrationOptions& options) {
  using namespace internal;
  check_arguments(system, q0, v0, options);
  if (!(options.relative_tolerance > 0.0) || !(options.absolute_tolerance > 0.0) || !(options.velocity_scale > 0.0))
    throw std::invalid_argument(fmt::format("tolerances must be positive; found relative {}, absolute {}, velocity_scale {}",
                                            options.relative_tolerance, options.absolute_tolerance, options.velocity_scale));
  const int n = system.size();
  const int m = system.event_count();
  const double t0 = options.start_time, t_end = options.end_time;

  Trajectory out;
  if (!options.coordinate_names.empty() && static_cast<int>(options.coordinate_names.size()) != n)
    throw std::invalid_argument(fmt::format("{} coordinate names for {} coordinates", options.coordinate_names.size(), n));
  const std::vector<std::string>& names = options.coordinate_names;
  check_state(t0, q0, v0, kCvode, names);
  const std::vector<double> times = output_times(options);
  out.time.reserve(times.size());
  out.q.reserve(times.size());
  out.v.reserve(times.size());
  out.a.reserve(times.size());

  // y = [q; v] lives in Eigen memory that CVODE's N_Vector wraps (never resized).
  Eigen::VectorXd y(2 * n), dense(2 * n);
  y << q0, v0;
  Eigen::VectorXd q = q0, v = v0;

  CvodeCallbackData data;
  data.system = &system;
  data.names = &names;
  data.n = n;
  data.q.resize(n);
  data.v.resize(n);
  data.a = Eigen::VectorXd::Zero(n);

  CvodeSession s(2 * n, y.data(), options.method == MultistepMethod::bdf ? CV_BDF : CV_ADAMS);
  N_Vector dense_vector = N_VMake_Serial(2 * n, dense.data(), s.context());
  if (!dense_vector) throw std::runtime_error("CVODE set-up: N_VMake_Serial failed");
  struct VectorGuard {
    N_Vector v;
    ~VectorGuard() { N_VDestroy(v); }
  } dense_guard{dense_vector};

  void* mem = s.memory();
  CvodeSession::check(CVodeSetErrHandlerFn(mem, cvode_error_handler, &data), "CVodeSetErrHandlerFn");
  CvodeSession::check(CVodeInit(mem, cvode_rhs, t0, s.y()), "CVodeInit");
  Eigen::Map<Eigen::VectorXd> atol(N_VGetArrayPointer(s.tolerances()), 2 * n);
  atol.head(n).setConstant(options.absolute_tolerance);
  atol.tail(n).setConstant(options.absolute_tolerance * options.velocity_scale);
  CvodeSession::check(CVodeSVtolerances(mem, options.relative_tolerance, s.tolerances()), "CVodeSVtolerances");
  CvodeSession::check(CVodeSetLinearSolver(mem, s.solver(), s.matrix()), "CVodeSetLinearSolver");
  CvodeSession::check(CVodeSetUserData(mem, &data), "CVodeSetUserData");
  // One-step mode: max_steps is enforced over the whole run below.
  CvodeSession::check(CVodeSetMaxNumSteps(mem, options.max_steps), "CVodeSetMaxNumSteps");
  if (m > 0) {
    CvodeSession::check(CVodeRootInit(mem, m, cvode_roots), "CVodeRootInit");
    CvodeSession::check(CVodeSetNoInactiveRootWarn(mem), "CVodeSetNoInactiveRootWarn");
  }
  std::vector<int> roots_found(static_cast<std::size_t>(std::max(m, 1)));

  std::size_t next = 0;  // the next output sample
  record_sample(system, out, times[next++], q, v, kCvode, names);

  auto rethrow_pending = [&] {
    if (data.pending) std::rethrow_exception(std::exchange(data.pending, nullptr));
  };
  auto unpack = [&](const Eigen::VectorXd& state) {
    q = state.head(n);
    v = state.tail(n);
  };

  double t = t0;
  long steps_before_restart = 0;  // CVodeReInit resets CVODE's counters
  long steps_now = 0;
  while (true) {
    const double scheduled = next_change_after(system, t);
    const double stop = std::min(scheduled, t_end);
    double t_reached = stop;
    int flag = CV_TSTOP_RETURN;
    // A stop closer than CVODE can resolve (an event a few ulp before it) is
    // taken as reached: the state moves by |v| * 1e-15 s at most.
    const bool stop_is_here = stop - t <= 8.0 * std::numeric_limits<double>::epsilon() * std::max(std::abs(t), std::abs(stop));
    if (!stop_is_here) {
      CvodeSession::check(CVodeSetStopTime(mem, stop), "CVodeSetStopTime");
      // One internal step at a time, so that the outputs never influence the
      // steps (they are interpolated below) and the first step after a
      // restart is sized by CVODE against the distance to the next stop.
      flag = CVode(mem, stop, s.y(), &t_reached, CV_ONE_STEP);
      rethrow_pending();
      if (flag < 0) throw cvode_failure(flag, t_reached, y, data, options);
      CVodeGetNumSteps(mem, &steps_now);
      if (steps_before_restart + steps_now > options.max_steps)
        throw too_much_work(t_reached, y, steps_before_restart + steps_now, options);
      unpack(y);
      check_state(t_reached, q, v, kCvode, names);
      // Samples strictly before t_reached from CVODE's dense output (the
      // interpolating polynomial of the current order, accurate to the
      // tolerance like the steps themselves).
      while (next < times.size() && times[next] < t_reached) {
        const int ok = CVodeGetDky(mem, times[next], 0, dense_vector);
        if (ok < 0) throw cvode_failure(ok, times[next], y, data, options);
        record_sample(system, out, times[next], dense.head(n), dense.tail(n), kCvode, names);
        ++next;
      }
    } else {
      while (next < times.size() && times[next] < t_reached) record_sample(system, out, times[next++], q, v, kCvode, names);
    }
    t = t_reached;

    bool restart = false;
    if (flag == CV_ROOT_RETURN) {
      CvodeSession::check(CVodeGetRootInfo(mem, roots_found.data()), "CVodeGetRootInfo");
      std::vector<int> fired, directions;
      for (int i = 0; i < m; ++i)
        if (roots_found[static_cast<std::size_t>(i)] != 0) {
          fired.push_back(i);
          directions.push_back(roots_found[static_cast<std::size_t>(i)] > 0 ? 1 : -1);
        }
      std::string what = system.on_event(t, q, v, fired, directions);
      const SwitchedSystem::EventLength at = system.last_event_length();
      out.events.push_back({t, event_description(std::move(what), fired, directions), at.name, at.metres});
      restart = true;
    }
    if (t == stop && scheduled <= t_end) {
      std::string what = system.on_scheduled_change(t, q, v);
      out.events.push_back({t, what.empty() ? std::string("scheduled change") : std::move(what), "", std::numeric_limits<double>::quiet_NaN()});
      restart = true;
    }
    // Samples exactly at t report the state after any change made there.
    while (next < times.size() && times[next] <= t) record_sample(system, out, times[next++], q, v, kCvode, names);
    if (t >= t_end) break;
    if (restart) {
      steps_before_restart += steps_now;
      steps_now = 0;
      CvodeSession::check(CVodeReInit(mem, t, s.y()), "CVodeReInit");
    }
  }
  out.steps = steps_before_restart + steps_now;
  out.rhs_evaluations = data.rhs_calls;
  return out;
}

Trajectory integrate_rk4(SwitchedSystem& system, const Eigen::VectorXd& q0, const Eigen::VectorXd& v0, double step,
                         const IntegrationOptions& options) {
  using namespace internal;
  constexpr const char* kRk4 = "RK4";
  check_arguments(system, q0, v0, options);
  if (!(step > 0.0) || !std::isfinite(step)) throw std::invalid_argument(fmt::format("the RK4 step must be positive; found {} s", step));
  const double ratio = options.output_interval / step;
  const long per_output = std::lround(ratio);
  if (per_output < 1 || std::abs(ratio - static_cast<double>(per_output)) > 1e-9 * ratio)
    throw std::invalid_argument(fmt::format(
        "the RK4 step must divide the output interval: {} s / {} s = {:.12g} is not a whole number", options.output_interval, step, ratio));

  const int n = system.size();
  const int m = system.event_count();
  const double t0 = options.start_time, t_end = options.end_time;
  const double span = t_end - t0;
  // Whole steps, then one shortened step if the span is not a multiple of h.
  long full_steps = static_cast<long>(std::floor(span / step + 1e-9));
  const bool short_last = t0 + static_cast<double>(full_steps) * step < t_end - 1e-9 * step;
  const long total_steps = full_steps + (short_last ? 1 : 0);
  if (total_steps > options.max_steps)
    throw core::NumericalError(fmt::format(
        "RK4: too much work: the run from {} s to {} s needs {} steps of {} s, more than max_steps = {}; the limit is "
        "reached at t = {:.12g} s. Try: raise max_steps or use a longer step (RK4 is stable for h omega_max < 2.8)",
        t0, t_end, total_steps, step, options.max_steps, t0 + static_cast<double>(options.max_steps) * step));

  Trajectory out;
  if (!options.coordinate_names.empty() && static_cast<int>(options.coordinate_names.size()) != n)
    throw std::invalid_argument(fmt::format("{} coordinate names for {} coordinates", options.coordinate_names.size(), n));
  const std::vector<std::string>& names = options.coordinate_names;
  check_state(t0, q0, v0, kRk4, names);
  const std::vector<double> times = output_times(options);
  std::size_t next = 0;
  Eigen::VectorXd q = q0, v = v0;
  record_sample(system, out, times[next++], q, v, kRk4, names);

  Eigen::VectorXd g_before(m), g_after(m);
  if (m > 0) system.events(t0, q, v, g_before.data());
  double scheduled = next_change_after(system, t0);

  Eigen::VectorXd a1(n), a2(n), a3(n), a4(n), q_stage(n), v_stage(n), v2(n), v3(n), v4(n);
  a1.setZero();
  a2.setZero();
  a3.setZero();
  a4.setZero();
  for (long i = 1; i <= total_steps; ++i) {
    const double ta = t0 + static_cast<double>(i - 1) * step;
    const double tb = (short_last && i == total_steps) ? t_end : t0 + static_cast<double>(i) * step;
    const double h = tb - ta;
    // Classical RK4 on y = [q; v], y' = [v; a]: the q-stages are the v-stages.
    evaluate_acceleration(system, ta, q, v, a1, kRk4, names);
    q_stage = q + 0.5 * h * v;
    v2 = v + 0.5 * h * a1;
    evaluate_acceleration(system, ta + 0.5 * h, q_stage, v2, a2, kRk4, names);
    q_stage = q + 0.5 * h * v2;
    v3 = v + 0.5 * h * a2;
    evaluate_acceleration(system, ta + 0.5 * h, q_stage, v3, a3, kRk4, names);
    q_stage = q + h * v3;
    v4 = v + h * a3;
    evaluate_acceleration(system, tb, q_stage, v4, a4, kRk4, names);
    q += (h / 6.0) * (v + 2.0 * v2 + 2.0 * v3 + v4);
    v += (h / 6.0) * (a1 + 2.0 * a2 + 2.0 * a3 + a4);
    ++out.steps;
    out.rhs_evaluations += 4;
    check_state(tb, q, v, kRk4, names);

    // Events at the step end only (no location inside the step).
    if (m > 0) {
      system.events(tb, q, v, g_after.data());
      std::vector<int> fired, directions;
      for (int k = 0; k < m; ++k) {
        if (!std::isfinite(g_after[k]))
          throw core::NumericalError(fmt::format("RK4: event function g[{}] is {} at t = {:.12g} s", k, g_after[k], tb));
        if (g_before[k] < 0.0 && g_after[k] >= 0.0) {
          fired.push_back(k);
          directions.push_back(1);
        } else if (g_before[k] > 0.0 && g_after[k] <= 0.0) {
          fired.push_back(k);
          directions.push_back(-1);
        }
      }
      if (!fired.empty()) {
        std::string what = system.on_event(tb, q, v, fired, directions);
        const SwitchedSystem::EventLength at = system.last_event_length();
        out.events.push_back({tb, event_description(std::move(what), fired, directions), at.name, at.metres});
        system.events(tb, q, v, g_after.data());  // the event functions may depend on the discrete state
      }
      g_before = g_after;
    }
    // Scheduled changes at the first step end at or after their time.
    bool changed = false;
    while (scheduled <= tb + 1e-9 * step) {
      std::string what = system.on_scheduled_change(tb, q, v);
      out.events.push_back({tb, what.empty() ? std::string("scheduled change") : std::move(what), "", std::numeric_limits<double>::quiet_NaN()});
      scheduled = next_change_after(system, scheduled);
      changed = true;
    }
    if (changed && m > 0) system.events(tb, q, v, g_before.data());

    if (i % per_output == 0 || i == total_steps) {
      while (next < times.size() && times[next] <= tb + 1e-9 * step) record_sample(system, out, times[next++], q, v, kRk4, names);
    }
  }
  return out;
}

}  // namespace framedyn::rigid
