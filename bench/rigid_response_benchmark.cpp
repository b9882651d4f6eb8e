// Rigid-body forced response of the plowing machine: the event-located
// integrator (CVODE with root finding) against the thesis's fixed-step RK4.
// Two parts, both printed as markdown tables (docs/validation_integration.md):
//
//   convergence  RK4 at 0.005, 0.0005, 0.00025 and 0.0001 s and the
//                event-located integrator at rtol 1e-6, 1e-8, 1e-10, each
//                against an event-located reference at rtol 1e-11: blade
//                vertical motion, peak plow force, average peak-to-peak blade
//                motion, soil-law switches. On the shipped machine (no switch
//                in 0.5 s) and on two variants at lower forward speeds: one
//                with isolated switches, one with sliding regimes (the law
//                switching back and forth within microseconds). Also the RK4
//                stability limit from the system's eigenvalues.
//   benchmark    CPU time (CLOCK_PROCESS_CPUTIME_ID): simulated seconds per
//                CPU second, event-located against RK4 at the thesis's step,
//                and the CPU cost of 0.1 % accuracy in peak plow force with
//                each integrator; every figure a ratio measured in one run.
//
//   rigid_response_benchmark [--part convergence|benchmark|all]
//                            [--study FILE]          (default examples/r100_plow_2d_vertical_path.yaml)
//                            [--chain-study FILE]    (default examples/r100_chain_2d.yaml: timed only)
//                            [--switching-speed IN_S] [--sliding-speed IN_S]  (the variants' forward speeds; 1.5, 3)
//                            [--min-cpu SECONDS]     (each timing block at least this long; default 0.25)
//
// All runs: 0.5 s (the study's duration) from rest at the static equilibrium,
// outputs every 0.0005 s (the study's output_interval), CVODE with the
// study's absolute tolerances (1e-12 m, velocity_scale 100 1/s, as
// coupling::run_rigid_study uses). Quantities follow run_rigid_study's
// definitions and are evaluated on the output samples.
#include <fmt/format.h>
#include <time.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <complex>
#include <fstream>
#include <functional>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "coupling/rigid_study.h"
#include "rigid/machine_2d.h"
#include "rigid/time_integration.h"
#include "rigid/vehicle_model.h"
#include "rigid/vehicle_run.h"

using namespace framedyn;

namespace {

constexpr double kInch = 0.0254;             // m
constexpr double kPound = 4.4482216152605;   // N
constexpr double kDuration = 0.5;            // s, the study's
constexpr double kOutput = 5e-4;             // s, the study's output interval
constexpr double kFine = 5e-5;               // s, the reference's sampling (divides every grid used)
constexpr double kReferenceRtol = 1e-11;

double cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

struct Method {
  bool rk4 = false;
  double value = 0.0;  // RK4 step (s) or CVODE rtol
  std::string label() const { return rk4 ? fmt::format("RK4, h = {:g} s", value) : fmt::format("event-located, rtol = {:g}", value); }
};

struct Switch {
  double time;
  bool cutting;  // the state entered
};

// One response, sampled on its output grid.
struct Response {
  double interval = 0.0;  // s
  std::vector<double> time, blade_z, force;  // s, m, N (signed magnitude, positive for forward travel)
  std::vector<Switch> switches;
  long steps = 0, rhs = 0;
  double penetration = 0.0;  // m: the largest distance the blade stood ahead of the uncut soil line while "backing"
};

rigid::IntegrationOptions options(double interval, double rtol) {
  rigid::IntegrationOptions o;
  o.end_time = kDuration;
  o.output_interval = interval;
  o.relative_tolerance = rtol;
  o.absolute_tolerance = 1e-12;  // as coupling::run_rigid_study
  o.velocity_scale = 100.0;
  o.max_steps = 100000000;
  return o;
}

// Integrates only (what the benchmark times).
rigid::VehicleRun integrate(const rigid::VehicleModel& m, const Method& method, double interval) {
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(m.size());
  rigid::VehicleRun run{rigid::start_run(m, 0.0, zero), {}};
  rigid::VehicleDynamics dynamics(m, run.state);
  const rigid::IntegrationOptions o = options(interval, method.rk4 ? 1e-8 : method.value);
  run.trajectory = method.rk4 ? rigid::integrate_rk4(dynamics, zero, zero, method.value, o) : rigid::integrate_event_located(dynamics, zero, zero, o);
  return run;
}

Response respond(const rigid::VehicleModel& m, const rigid::Machine2DParameters& p, const Method& method, double interval) {
  const rigid::VehicleRun run = integrate(m, method, interval);
  const rigid::Trajectory& tr = run.trajectory;
  Response r;
  r.interval = interval;
  r.steps = tr.steps;
  r.rhs = tr.rhs_evaluations;
  const auto& history = run.state.soil.history();
  for (std::size_t i = 1; i < history.size(); ++i) r.switches.push_back({history[i].time, history[i].cutting});
  const rigid::Jacobian& j = m.multibody.points()[static_cast<std::size_t>(m.blade_point)].displacement;
  const double vs = p.forward_speed * std::cos(p.ground_slope);
  for (std::size_t i = 0; i < tr.time.size(); ++i) {
    const Eigen::Vector3d d = j * tr.q[i];
    r.time.push_back(tr.time[i]);
    r.blade_z.push_back(d(2));
    const Eigen::Vector3d f3 = rigid::plow_force(m, run.state, tr.time[i], tr.q[i], tr.v[i]);
    const Eigen::Vector2d f(f3.x(), f3.z());
    r.force.push_back(f.x() < 0 ? f.norm() : -f.norm());
    const rigid::SoilState s = rigid::soil_state_at(run.state, tr.time[i]);
    if (!s.cutting) r.penetration = std::max(r.penetration, s.line + vs * (tr.time[i] - s.time) - d(0));
  }
  return r;
}

// The samples of `r` every `interval` (a multiple of r.interval).
Response subsample(const Response& r, double interval) {
  const long stride = std::lround(interval / r.interval);
  Response s = r;
  s.interval = interval;
  s.time.clear();
  s.blade_z.clear();
  s.force.clear();
  for (std::size_t i = 0; i < r.time.size(); i += static_cast<std::size_t>(stride)) {
    s.time.push_back(r.time[i]);
    s.blade_z.push_back(r.blade_z[i]);
    s.force.push_back(r.force[i]);
  }
  return s;
}

// run_rigid_study's peak cutting force: the largest signed magnitude.
double peak_force(const Response& r) { return std::max(0.0, *std::max_element(r.force.begin(), r.force.end())); }

// run_rigid_study's average peak-to-peak vertical blade motion over whole shaker cycles.
double average_peak_to_peak(const Response& r, double shaker_hz) {
  const double period = 1.0 / shaker_hz;
  const int cycles = static_cast<int>(std::floor(kDuration / period + 1e-9));
  double sum = 0.0;
  int counted = 0;
  for (int c = 0; c < cycles; ++c) {
    double lo = 1e300, hi = -1e300;
    for (std::size_t i = 0; i < r.time.size(); ++i)
      if (r.time[i] >= c * period - 1e-12 && r.time[i] <= (c + 1) * period + 1e-12) {
        lo = std::min(lo, r.blade_z[i]);
        hi = std::max(hi, r.blade_z[i]);
      }
    if (hi >= lo) {
      sum += hi - lo;
      ++counted;
    }
  }
  return counted ? sum / counted : 0.0;
}

// Largest |blade z - reference| at r's sample times (the reference's grid is finer).
double max_blade_difference(const Response& r, const Response& ref) {
  double worst = 0.0;
  for (std::size_t i = 0; i < r.time.size(); ++i) {
    const std::size_t k = static_cast<std::size_t>(std::lround(r.time[i] / ref.interval));
    if (std::abs(ref.time[k] - r.time[i]) > 1e-9) throw std::logic_error("sample times do not match");
    worst = std::max(worst, std::abs(r.blade_z[i] - ref.blade_z[k]));
  }
  return worst;
}

struct SwitchComparison {
  std::size_t matched = 0;        // leading switches of the same kind in the same order
  double max_error = 0.0;         // s, over the matched ones
  double mean_error = 0.0;        // s, signed (late > 0)
};

SwitchComparison compare_switches(const std::vector<Switch>& s, const std::vector<Switch>& ref) {
  SwitchComparison c;
  double sum = 0.0;
  for (std::size_t i = 0; i < std::min(s.size(), ref.size()) && s[i].cutting == ref[i].cutting; ++i) {
    const double e = s[i].time - ref[i].time;
    c.max_error = std::max(c.max_error, std::abs(e));
    sum += e;
    ++c.matched;
  }
  if (c.matched) c.mean_error = sum / static_cast<double>(c.matched);
  return c;
}

std::string relative(double value, double reference) {
  const double e = (value - reference) / reference;
  return fmt::format("{:+.2e}", e);
}

// ---------------------------------------------------------------------------
// Stability of RK4 on the linear system of each soil state

// |R(z)| for classical RK4, R(z) = 1 + z + z^2/2 + z^3/6 + z^4/24.
double rk4_amplification(std::complex<double> z) { return std::abs(1.0 + z + z * z / 2.0 + z * z * z / 6.0 + z * z * z * z / 24.0); }

// The largest h with |R(h lambda)| <= 1 (scanning outward from 0).
double rk4_limit(std::complex<double> lambda) {
  double h = 0.0;
  const double dh = 1e-4 / std::abs(lambda);
  while (rk4_amplification(h * lambda) <= 1.0 + 1e-12 && h < 10.0 / std::abs(lambda)) h += dh;
  return h;
}

Eigen::VectorXcd first_order_eigenvalues(const rigid::VehicleModel& m) {
  const int n = m.size();
  const Eigen::MatrixXd mi = m.m.inverse();
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  a.topRightCorner(n, n).setIdentity();
  a.bottomLeftCorner(n, n) = -mi * m.k_full;
  a.bottomRightCorner(n, n) = -mi * m.c_full;
  return Eigen::EigenSolver<Eigen::MatrixXd>(a).eigenvalues();
}

void print_stability(const rigid::Machine2DParameters& p) {
  fmt::print("\n### RK4 stability (eigenvalues of the first-order system, each soil state)\n\n");
  fmt::print("| soil state | fastest eigenvalue (1/s) | abs (rad/s) | RK4 stable for h up to | h abs(lambda) at h = 0.005 s | abs(R) at 0.005 s, fastest / worst over all eigenvalues |\n|---|---|---:|---:|---:|---:|\n");
  for (int backing = 0; backing < 2; ++backing) {
    rigid::Machine2DParameters q = p;
    if (backing) {
      q.soil.stiffness *= p.soil.stiffness_reduction;
      q.soil.damping *= p.soil.damping_reduction;
    }
    const rigid::VehicleModel m = rigid::build_vehicle_model(q);
    const Eigen::VectorXcd ev = first_order_eigenvalues(m);
    std::complex<double> fastest = 0.0;
    double limit = 1e300, worst = 0.0;
    for (int i = 0; i < ev.size(); ++i) {
      if (std::abs(ev[i]) > std::abs(fastest)) fastest = ev[i];
      limit = std::min(limit, rk4_limit(ev[i]));
      worst = std::max(worst, rk4_amplification(0.005 * ev[i]));
    }
    fmt::print("| {} | {:.2f} {:+.2f}i | {:.1f} | {:.4f} s | {:.3f} | {:.4f} / {:.4f} |\n", backing ? "backing (REK K5, REC C5)" : "cutting (K5, C5)",
               fastest.real(), std::abs(fastest.imag()), std::abs(fastest), limit, 0.005 * std::abs(fastest),
               rk4_amplification(0.005 * fastest), worst);
  }
}

// ---------------------------------------------------------------------------
// Convergence study

void print_switch_list(const std::vector<Switch>& s) {
  std::string text;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s.size() > 12 && i == 6) {
      text += fmt::format(", ... ({} more) ...", s.size() - 10);
      i = s.size() - 4;
    }
    text += fmt::format("{}{:.5f} s ({})", text.empty() ? "" : ", ", s[i].time, s[i].cutting ? "cuts" : "backs off");
  }
  fmt::print("Reference switches: {}\n", text.empty() ? "none" : text);
}

void convergence(const std::string& title, const rigid::Machine2DParameters& p) {
  const rigid::VehicleModel m = rigid::build_vehicle_model(p);
  const double shaker = p.plow.shaker_frequency;
  const Response ref = respond(m, p, {false, kReferenceRtol}, kFine);
  fmt::print("\n### {}\n\n", title);
  print_switch_list(ref.switches);
  // The reference's own error: against rtol 1e-12.
  const Response tighter = respond(m, p, {false, 1e-12}, kFine);
  const Response ref_out = subsample(ref, kOutput);
  const double ref_peak = peak_force(ref_out), ref_pp = average_peak_to_peak(ref_out, shaker);
  fmt::print(
      "\nReference (rtol {:g}, {} steps), on the 0.0005 s output grid: peak plow force {:.2f} lbf, average peak-to-peak blade motion "
      "{:.5f} in, {} switches. Its own error, against rtol 1e-12: blade z {:.1e} in, peak force {:.1e}, peak-to-peak {:.1e}, switch "
      "times {:.1e} s. Largest penetration of the blade ahead of the soil line while backing: {:.3g} in.\n",
      kReferenceRtol, ref.steps, ref_peak / kPound, ref_pp / kInch, ref.switches.size(), max_blade_difference(tighter, ref) / kInch,
      (peak_force(subsample(tighter, kOutput)) - ref_peak) / ref_peak,
      (average_peak_to_peak(subsample(tighter, kOutput), shaker) - ref_pp) / ref_pp,
      compare_switches(tighter.switches, ref.switches).max_error, ref.penetration / kInch);
  fmt::print("Sampling alone (the reference sampled every 0.005 s instead of 0.0005 s): peak force {}, peak-to-peak {}; "
             "(every 5e-5 s instead of 0.0005 s): peak force {}, peak-to-peak {}.\n\n",
             relative(peak_force(subsample(ref, 0.005)), ref_peak), relative(average_peak_to_peak(subsample(ref, 0.005), shaker), ref_pp),
             relative(peak_force(ref), ref_peak), relative(average_peak_to_peak(ref, shaker), ref_pp));

  fmt::print("| method | steps | RHS evals | max abs(blade z error) (in) | peak plow force (lbf) | rel. error | avg p-p blade z (in) | rel. error | switches (ref. {}) | matched in order | max abs(switch time error) | mean switch time error | last switch (ref. {}) | penetration (in) |\n",
             ref.switches.size(), ref.switches.empty() ? std::string("-") : fmt::format("{:.5f} s", ref.switches.back().time));
  fmt::print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  const std::vector<Method> methods = {{true, 0.005}, {true, 0.0005}, {true, 0.00025}, {true, 0.0001},
                                       {false, 1e-6}, {false, 1e-8}, {false, 1e-10}};
  for (const Method& method : methods) {
    // RK4 writes samples at its step ends: 0.005 s cannot give the 0.0005 s grid.
    const double interval = method.rk4 ? std::max(kOutput, method.value) : kOutput;
    std::string row = fmt::format("| {}{} ", method.label(), interval != kOutput ? " (samples every 0.005 s)" : "");
    try {
      const Response r = respond(m, p, method, interval);
      const Response ref_here = subsample(ref, interval);  // same sample times
      const double pk = peak_force(r), pp = average_peak_to_peak(r, shaker);
      const double ref_pk = peak_force(ref_here), ref_p = average_peak_to_peak(ref_here, shaker);
      const SwitchComparison sc = compare_switches(r.switches, ref.switches);
      row += fmt::format("| {} | {} | {:.2e} | {:.2f} | {} | {:.5f} | {} | {} | {} | {} | {} | {} | {:.3g} |", r.steps, r.rhs,
                         max_blade_difference(r, ref) / kInch, pk / kPound, relative(pk, ref_pk), pp / kInch, relative(pp, ref_p),
                         r.switches.size(), sc.matched, sc.matched ? fmt::format("{:.2e} s", sc.max_error) : "-",
                         sc.matched ? fmt::format("{:+.2e} s", sc.mean_error) : "-",
                         r.switches.empty() ? std::string("-") : fmt::format("{:.5f} s", r.switches.back().time), r.penetration / kInch);
    } catch (const std::exception& e) {
      row += fmt::format("| failed: {} ||||||||||||", std::string(e.what()).substr(0, 100));
    }
    fmt::print("{}\n", row);
  }
  fmt::print("\nErrors are against the reference sampled at the same times (for RK4 at 0.005 s: every 0.005 s; see 'Sampling alone' above "
             "for what that grid loses by itself).\n");
}

// ---------------------------------------------------------------------------
// Benchmark

double min_cpu = 0.25;  // s per timing block
constexpr int kBlocks = 5;

// CPU time of one run, from a block of repeated runs at least min_cpu long.
double block(const std::function<void()>& run, long& runs) {
  const double start = cpu_seconds();
  long k = 0;
  double elapsed = 0.0;
  do {
    run();
    ++k;
    elapsed = cpu_seconds() - start;
  } while (elapsed < min_cpu);
  runs += k;
  return elapsed / static_cast<double>(k);
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// Two integrations timed in alternating blocks (so that both see the same
// machine load): the median CPU per run of each and the median of the
// per-pair ratios b / a.
struct PairTiming {
  double a = 0.0, b = 0.0, ratio = 0.0;
  long runs_a = 0, runs_b = 0;
};

PairTiming time_pair(const std::function<void()>& a, const std::function<void()>& b) {
  PairTiming t;
  std::vector<double> ta, tb, ratio;
  for (int i = 0; i < kBlocks; ++i) {
    ta.push_back(block(a, t.runs_a));
    tb.push_back(block(b, t.runs_b));
    ratio.push_back(tb.back() / ta.back());
  }
  t.a = median(ta);
  t.b = median(tb);
  t.ratio = median(ratio);
  return t;
}

std::function<void()> runner(const rigid::VehicleModel& m, const Method& method, double interval = kOutput) {
  return [&m, method, interval] { (void)integrate(m, method, interval); };
}

// `interval`: the output interval (the study's, or kDuration for samples only at the ends).
void throughput(const std::string& what, const rigid::Machine2DParameters& p, const std::vector<double>& rk4_steps, double interval = kOutput) {
  const rigid::VehicleModel m = rigid::build_vehicle_model(p);
  const Method el{false, 1e-8};
  const rigid::Trajectory tr = integrate(m, el, interval).trajectory;
  const long el_steps = tr.steps;
  for (double h : rk4_steps) {
    const PairTiming t = time_pair(runner(m, el, interval), runner(m, {true, h}, interval));
    fmt::print("| {} | event-located, rtol 1e-8 (study default); {} events | {} | {:.3f} ms | {:.0f} | {} | |\n", what, tr.events.size(), el_steps, 1e3 * t.a,
               kDuration / t.a, t.runs_a);
    fmt::print("| {} | RK4, h = {:g} s | {} | {:.3f} ms | {:.0f} | {} | {:.2f} |\n", what, h, std::lround(kDuration / h), 1e3 * t.b, kDuration / t.b,
               t.runs_b, 1.0 / t.ratio);
  }
}

// The loosest rtol (largest h) such that it and every tighter one tried reach `target` in peak plow force.
void cost_of_accuracy(const std::string& what, const rigid::Machine2DParameters& p, double target) {
  const rigid::VehicleModel m = rigid::build_vehicle_model(p);
  const double ref_peak = peak_force(respond(m, p, {false, kReferenceRtol}, kOutput));
  auto error_of = [&](const Method& method) { return std::abs(peak_force(respond(m, p, method, kOutput)) - ref_peak) / ref_peak; };

  std::vector<double> rtols = {1e-3, 3e-4, 1e-4, 3e-5, 1e-5, 3e-6, 1e-6, 3e-7, 1e-7, 3e-8, 1e-8, 1e-9, 1e-10};
  std::vector<double> rtol_errors;
  std::vector<long> rtol_steps;
  for (double r : rtols) {
    rtol_errors.push_back(error_of({false, r}));
    rtol_steps.push_back(integrate(m, {false, r}, kOutput).trajectory.steps);
  }
  std::optional<std::size_t> el_pick;
  for (std::size_t i = rtols.size(); i-- > 0;) {
    if (rtol_errors[i] > target) break;
    el_pick = i;
  }
  std::vector<double> steps;
  for (double h = kOutput; h >= kOutput / 128 * 0.999; h /= 2) steps.push_back(h);
  std::vector<double> step_errors;
  for (double h : steps) step_errors.push_back(error_of({true, h}));
  std::optional<std::size_t> rk_pick;
  for (std::size_t i = steps.size(); i-- > 0;) {
    if (step_errors[i] > target) break;
    rk_pick = i;
  }
  std::string el_scan, rk_scan;
  for (std::size_t i = 0; i < rtols.size(); ++i) el_scan += fmt::format("{}{:g}: {:.1e} ({} steps)", i ? ", " : "", rtols[i], rtol_errors[i], rtol_steps[i]);
  for (std::size_t i = 0; i < steps.size(); ++i) rk_scan += fmt::format("{}{:g} s: {:.1e}", i ? ", " : "", steps[i], step_errors[i]);
  fmt::print("\n{}: reference peak plow force {:.2f} lbf (event-located, rtol 1e-11, 0.0005 s samples).\n", what, ref_peak / kPound);
  fmt::print("Peak-force error by rtol: {}.\nPeak-force error by RK4 step (halving from the thesis's 0.0005 s, the largest step that writes the 0.0005 s samples): {}.\n\n",
             el_scan, rk_scan);
  if (!el_pick || !rk_pick) {
    fmt::print("| {} | target {:g} not reached by {} |\n", what, target, !el_pick ? "the event-located integrator" : "RK4");
    return;
  }
  const Method el{false, rtols[*el_pick]}, rk{true, steps[*rk_pick]};
  const PairTiming t = time_pair(runner(m, el), runner(m, rk));
  const long el_steps = integrate(m, el, kOutput).trajectory.steps;
  fmt::print("| case | integrator reaching {:g} % | its error | steps | CPU per 0.5 s run | runs timed | CPU / event-located CPU |\n|---|---|---:|---:|---:|---:|---:|\n",
             100 * target);
  fmt::print("| {} | event-located, rtol {:g} | {:.1e} | {} | {:.3f} ms | {} | 1 |\n", what, el.value, rtol_errors[*el_pick], el_steps, 1e3 * t.a, t.runs_a);
  fmt::print("| {} | RK4, h = {:g} s | {:.1e} | {} | {:.3f} ms | {} | {:.2f} |\n", what, rk.value, step_errors[*rk_pick], std::lround(kDuration / rk.value),
             1e3 * t.b, t.runs_b, t.ratio);
  // Where a looser rtol costs more (the law switching back and forth in a
  // sliding regime: each switch restarts CVODE), the cheapest rtol that
  // reaches the target as well, chosen by a short timing of each.
  // Reported only if it is clearly (20 %) cheaper, not by timing noise.
  std::size_t cheapest = *el_pick;
  double cheapest_cpu = 1e300, loosest_cpu = 0.0;
  const double saved = min_cpu;
  min_cpu = saved / 5;
  for (std::size_t i = *el_pick; i < rtols.size(); ++i) {
    long runs = 0;
    const double cpu = block(runner(m, {false, rtols[i]}), runs);
    if (i == *el_pick) loosest_cpu = cpu;
    if (cpu < cheapest_cpu) cheapest_cpu = cpu, cheapest = i;
  }
  min_cpu = saved;
  if (cheapest != *el_pick && cheapest_cpu < 0.8 * loosest_cpu) {
    const Method ec{false, rtols[cheapest]};
    const PairTiming c = time_pair(runner(m, ec), runner(m, rk));
    fmt::print("| {} | event-located, rtol {:g} (the cheapest reaching it) | {:.1e} | {} | {:.3f} ms | {} | RK4 / this: {:.2f} |\n", what, ec.value,
               rtol_errors[cheapest], rtol_steps[cheapest], 1e3 * c.a, c.runs_a, c.ratio);
  }
}

}  // namespace

int main(int argc, char** argv) {
  std::string part = "all";
  std::string study_file = std::string(FRAMEDYN_SOURCE_DIR) + "/examples/r100_plow_2d_vertical_path.yaml";
  std::string chain_file = std::string(FRAMEDYN_SOURCE_DIR) + "/examples/r100_chain_2d.yaml";
  double switching_speed = 1.5, sliding_speed = 3.0;  // in/s
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string k = argv[i], v = argv[i + 1];
    if (k == "--part") part = v;
    else if (k == "--study") study_file = v;
    else if (k == "--chain-study") chain_file = v;
    else if (k == "--switching-speed") switching_speed = std::stod(v);
    else if (k == "--sliding-speed") sliding_speed = std::stod(v);
    else if (k == "--min-cpu") min_cpu = std::stod(v);
    else {
      std::cerr << "unknown option " << k << "\n";
      return 1;
    }
  }
  try {
    const coupling::RigidStudy study = coupling::read_rigid_study(study_file);
    const rigid::Machine2DParameters shipped = study.machine_2d();
    if (shipped.attachment != rigid::Attachment::plow) throw std::invalid_argument(study_file + " is not a plowing study");
    struct Case {
      std::string name, title;
      rigid::Machine2DParameters p;
    };
    const double shipped_speed = shipped.forward_speed / kInch;
    std::vector<Case> cases = {{fmt::format("plowing, study file ({:g} in/s)", shipped_speed),
                                fmt::format("The study file's machine (forward speed {:g} in/s)", shipped_speed), shipped}};
    for (const auto& [speed, kind] : {std::pair<double, const char*>{switching_speed, "switching"}, {sliding_speed, "sliding"}}) {
      Case c{fmt::format("plowing, {:g} in/s", speed),
             fmt::format("{} variant: the shipped machine at a forward speed of {:g} in/s instead of {:g}", kind, speed, shipped.forward_speed / kInch),
             shipped};
      c.p.forward_speed = speed * kInch;
      cases.push_back(c);
    }

    if (part == "convergence" || part == "all") {
      fmt::print("## Convergence: {}, 0.5 s\n", study_file);
      print_stability(shipped);
      for (const Case& c : cases) convergence(c.title, c.p);
    }
    if (part == "benchmark" || part == "all") {
      fmt::print("\n## Benchmark: CPU time (CLOCK_PROCESS_CPUTIME_ID); each pair timed in {} alternating blocks of at least {:g} s, medians\n\n", kBlocks, min_cpu);
      fmt::print("| case | integrator | steps | CPU per 0.5 s run | simulated s per CPU s | runs timed | speed relative to event-located |\n");
      fmt::print("|---|---|---:|---:|---:|---:|---:|\n");
      for (const Case& c : cases) throughput(c.name, c.p, {0.0005});
      throughput(cases.front().name + ", samples only at 0 and 0.5 s", cases.front().p, {0.0005}, kDuration);
      if (!chain_file.empty() && std::ifstream(chain_file).good()) {
        const coupling::RigidStudy chain = coupling::read_rigid_study(chain_file);
        throughput("digging chain (" + chain_file.substr(chain_file.find_last_of('/') + 1) + ")", chain.machine_2d(), {0.00025, 0.0001});
      } else {
        fmt::print("\nDigging: no chain study at {}; pass --chain-study FILE to time one.\n", chain_file);
      }
      fmt::print("\n### CPU cost of 0.1 % accuracy in peak plow force\n");
      for (const Case& c : cases) cost_of_accuracy(c.name, c.p, 1e-3);
    }
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
