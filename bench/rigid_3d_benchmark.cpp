// The 3-D rigid-body model (issue 4, thesis program CMW3D): simulated seconds
// per CPU second of the forced response, the event-located integrator (CVODE
// with root finding) against the thesis's fixed-step RK4 at its steps —
// offset plowing (15 DOF, h = 0.0005 s) and the offset digging chain (13 DOF,
// h = 0.0001 s) — each pair timed in one run so that the ratios are
// comparable. Also how far each lies from a tight event-located reference
// (rtol 1e-11) in the frame loads at points 24-31 (coupling/frame_loads_3d.h),
// the quantity the pipeline hands on to the beam frame: at every output
// time, from 0.1 s on (after the chain's start), and in the peaks.
//
//   rigid_3d_benchmark [--plow FILE]   (default examples/r100_plow_offset.yaml)
//                      [--chain FILE]  (default examples/r100_chain_offset.yaml)
//                      [--min-cpu SECONDS]  (each timing block at least this long; default 0.25)
//
// Every run: the study's duration and output interval, from rest at the
// static equilibrium, CVODE with the tolerances coupling::run_rigid_study
// uses (rtol 1e-8, atol 1e-12 m, velocity_scale 100 1/s). CPU time is
// CLOCK_PROCESS_CPUTIME_ID, as bench/rigid_response_benchmark.cpp measures it.
// Results: docs/benchmarks.md, "3-D rigid-body response".
#include <fmt/format.h>
#include <time.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "coupling/frame_loads_3d.h"
#include "coupling/rigid_study.h"
#include "rigid/machine_3d.h"
#include "rigid/vehicle_model.h"
#include "rigid/vehicle_run.h"
#include "rigid/time_integration.h"

using namespace framedyn;

namespace {

constexpr double kPound = 4.4482216152605;  // N
constexpr int kBlocks = 5;
constexpr double kSettled = 0.1;  // s: "from 0.1 s on" in the accuracy columns
double min_cpu = 0.25;  // s per timing block

double cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

struct Method {
  bool rk4 = false;
  double value = 0.0;  // RK4 step (s) or CVODE rtol
  std::string label() const { return rk4 ? fmt::format("RK4, h = {:g} s", value) : fmt::format("event-located, rtol {:g}", value); }
};

rigid::VehicleRun integrate(const rigid::VehicleModel& m, const Method& method, const coupling::ResponseRequest& req) {
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(m.size());
  rigid::VehicleRun run{rigid::start_run(m, 0.0, zero), {}};
  rigid::VehicleDynamics dynamics(m, run.state);
  rigid::IntegrationOptions o;
  o.end_time = req.duration;
  o.output_interval = req.output_interval;
  o.relative_tolerance = method.rk4 ? req.relative_tolerance : method.value;
  o.absolute_tolerance = 1e-12;  // as coupling::run_rigid_study
  o.velocity_scale = 100.0;
  o.max_steps = 100000000;
  run.trajectory = method.rk4 ? rigid::integrate_rk4(dynamics, zero, zero, method.value, o) : rigid::integrate_event_located(dynamics, zero, zero, o);
  return run;
}

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

// Alternating blocks (both see the same machine load): median CPU per run of
// each, and the median of the per-pair ratios b / a.
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

// Largest difference of any frame-load component at any output time from the
// reference, relative to that component's peak in the reference; and the
// component where it is largest.
// Three measures, each the largest over the components: (1) at every output
// time; (2) from `settled` on, after the start (the chain engages, ramps and
// first switches in its first 0.06 s: a load that jumps at an event differs by
// much of the jump at a sample one run takes just before the jump and the
// other just after, and RK4 restarts on the step grid); (3) the difference of
// the peaks (largest magnitude) relative to the reference's peak.
struct LoadDifference {
  double everywhere = 0.0, settled = 0.0, peaks = 0.0;
  std::string where, where_settled, where_peak;
  double when = 0.0;  // s, the output time of (1)
};

LoadDifference compare_loads(const coupling::FrameLoads3D& a, const coupling::FrameLoads3D& ref, double settled) {
  LoadDifference d;
  if (a.points.times.size() != ref.points.times.size()) throw std::logic_error("the runs have different output times");
  const Eigen::VectorXd& t = ref.points.times;
  for (std::size_t p = 0; p < ref.points.points.size(); ++p)
    for (int c = 0; c < 6; ++c) {
      const Eigen::VectorXd r = ref.points.points[p].values.col(c), x = a.points.points[p].values.col(c);
      const double peak = r.cwiseAbs().maxCoeff();
      if (peak < 1e-6) continue;  // a component that stays zero (TX at the pins, the cylinder's FX, ...)
      const std::string name = ref.points.points[p].name + "." + coupling::kLoadComponents[c];
      for (Eigen::Index i = 0; i < t.size(); ++i) {
        const double e = std::abs(x(i) - r(i)) / peak;
        if (e > d.everywhere) d.everywhere = e, d.where = name, d.when = t(i);
        if (t(i) >= settled - 1e-12 && e > d.settled) d.settled = e, d.where_settled = name;
      }
      const double e = std::abs(x.cwiseAbs().maxCoeff() - peak) / peak;
      if (e > d.peaks) d.peaks = e, d.where_peak = name;
    }
  return d;
}

std::string describe(const LoadDifference& d) {
  return fmt::format("{:.1e} ({}, t = {:.4f} s) | {:.1e} ({}) | {:.1e} ({})", d.everywhere, d.where, d.when, d.settled,
                     d.where_settled.empty() ? "-" : d.where_settled, d.peaks, d.where_peak);
}

void benchmark(const std::string& what, const std::string& file, double thesis_step) {
  const coupling::RigidStudy study = coupling::read_rigid_study(file);
  if (!study.response) throw std::invalid_argument(file + " has no analysis.response");
  const coupling::ResponseRequest& req = *study.response;
  const rigid::VehicleModel m = rigid::build_vehicle_model(study.machine_3d());
  const Method el{false, req.relative_tolerance}, rk{true, thesis_step}, reference{false, 1e-11};
  const rigid::VehicleRun run_ref = integrate(m, reference, req), run_el = integrate(m, el, req), run_rk = integrate(m, rk, req);
  const rigid::Trajectory &tr_ref = run_ref.trajectory, &tr_el = run_el.trajectory, &tr_rk = run_rk.trajectory;
  const coupling::FrameLoads3D loads_ref = coupling::frame_loads_3d(m, study.machine_3d(), run_ref.state, tr_ref);
  const coupling::FrameLoads3D loads_el = coupling::frame_loads_3d(m, study.machine_3d(), run_el.state, tr_el);
  const coupling::FrameLoads3D loads_rk = coupling::frame_loads_3d(m, study.machine_3d(), run_rk.state, tr_rk);
  const LoadDifference d_el = compare_loads(loads_el, loads_ref, kSettled), d_rk = compare_loads(loads_rk, loads_ref, kSettled);
  const PairTiming t = time_pair([&] { (void)integrate(m, el, req); }, [&] { (void)integrate(m, rk, req); });
  const std::string dofs = fmt::format("{} DOF", m.size());
  fmt::print("| {} ({}, {:g} s) | {}; {} events | {} | {:.3f} ms | {:.1f} | {} | 1 | {} |\n", what, dofs, req.duration, el.label(), tr_el.events.size(),
             tr_el.steps, 1e3 * t.a, req.duration / t.a, t.runs_a, describe(d_el));
  fmt::print("| {} ({}, {:g} s) | {} (the thesis's); {} events | {} | {:.3f} ms | {:.1f} | {} | {:.2f} | {} |\n", what, dofs, req.duration, rk.label(),
             tr_rk.events.size(), tr_rk.steps, 1e3 * t.b, req.duration / t.b, t.runs_b, 1.0 / t.ratio, describe(d_rk));
  double peak26 = 0.0;
  for (Eigen::Index i = 0; i < loads_ref.points.points[2].values.rows(); ++i) peak26 = std::max(peak26, std::abs(loads_ref.points.points[2].values(i, 2)));
  std::string events;
  for (const auto& e : tr_ref.events) events += fmt::format("{}{:.4f}", events.empty() ? "" : " ", e.time);
  fmt::print("<!-- {}: reference (rtol 1e-11) {} steps, peak rear-pin FZ {:.2f} lbf; events at {} s -->\n", what, tr_ref.steps, peak26 / kPound,
             events.empty() ? std::string("none") : events);
}

}  // namespace

int main(int argc, char** argv) {
  std::string plow = std::string(FRAMEDYN_SOURCE_DIR) + "/examples/r100_plow_offset.yaml";
  std::string chain = std::string(FRAMEDYN_SOURCE_DIR) + "/examples/r100_chain_offset.yaml";
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string k = argv[i], v = argv[i + 1];
    if (k == "--plow") plow = v;
    else if (k == "--chain") chain = v;
    else if (k == "--min-cpu") min_cpu = std::stod(v);
    else {
      std::cerr << "unknown option " << k << "\n";
      return 1;
    }
  }
  try {
    fmt::print("## 3-D rigid-body response: CPU time (CLOCK_PROCESS_CPUTIME_ID); each pair timed in {} alternating blocks of at least {:g} s, medians\n\n",
               kBlocks, min_cpu);
    fmt::print("| case | integrator | steps | CPU per run | simulated s per CPU s | runs timed | speed relative to event-located | "
               "frame loads against rtol 1e-11, largest difference / that component's peak: at any output time | from 0.1 s on | "
               "difference of the peaks |\n");
    fmt::print("|---|---|---:|---:|---:|---:|---:|---|---|---|\n");
    benchmark("offset plowing", plow, 0.0005);
    benchmark("offset digging chain", chain, 0.0001);
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
