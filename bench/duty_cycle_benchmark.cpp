// The life map of the shipped duty cycle (issue 18's target: four scenarios under 2 s on
// 2 cores). Times, in one run and on the same inputs (examples/duty_cycle.yaml):
//   cycle        run_duty_cycle: every scenario's pipeline (3-D machine, frame loads, frame
//                transient, stress histories) with its life map, and the Miner sum;
//   life maps    frame_life_map alone on each scenario's stored stress histories (rainflow
//                of every station and section point over the steady window, S-N, Miner);
//   baseline     the same four pipelines without a fatigue block.
// Printed as a markdown table (docs/benchmarks.md): medians of R repeats, and the ratios
// cycle / baseline and life maps / cycle, which say what the fatigue assessment adds to
// the simulations it needs anyway.
//
//   duty_cycle_benchmark [--repeats R]   (default 5)
#include <fmt/format.h>
#include <time.h>

#include <algorithm>
#include <cstdlib>
#include <string>
#include <vector>

#include "coupling/duty_cycle.h"
#include "coupling/frame_fatigue.h"
#include "coupling/frame_loads_3d.h"
#include "coupling/frame_study.h"
#include "coupling/load_history.h"
#include "coupling/rigid_study_3d.h"

namespace {

namespace c = framedyn::coupling;

double now() {
  timespec t{};
  clock_gettime(CLOCK_MONOTONIC, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// The scenarios' pipelines without fatigue: what the cycle must simulate anyway.
double baseline(const c::DutyCycleRequest& q) {
  const double t0 = now();
  for (const c::DutyCycleScenarioSpec& s : q.scenarios) {
    const c::RigidStudy3D study = c::read_rigid_study_3d(s.study.string());
    c::FrameStudyRequest request = *study.frame_response;
    request.fatigue.reset();
    request.paraview = c::ParaviewOutput::none;
    const c::RigidResults3D r = c::run_rigid_study_3d(study);
    const c::LoadHistory loads = c::all_frame_loads(*r.frame_loads), static_loads = c::all_frame_loads(*r.static_frame_loads);
    const c::FrameStudyResults f = c::run_frame_study(request, &loads, &static_loads, r.steady.operation.reached_at);
    if (f.response.times.size() == 0) std::abort();
  }
  return now() - t0;
}

}  // namespace

int main(int argc, char** argv) {
  int repeats = 5;
  for (int i = 1; i + 1 < argc; i += 2)
    if (std::string(argv[i]) == "--repeats") repeats = std::max(1, std::atoi(argv[i + 1]));
  const c::DutyCycleRequest q = c::read_duty_cycle(std::string(FRAMEDYN_SOURCE_DIR) + "/examples/duty_cycle.yaml");

  std::vector<double> cycle, maps, base;
  double life_h = 0.0;
  for (int k = 0; k < repeats; ++k) {
    double t0 = now();
    const c::DutyCycleResults r = c::run_duty_cycle(q);
    cycle.push_back(now() - t0);
    life_h = r.life.life_hours(r.life.worst_station, r.life.worst_point);
    t0 = now();
    for (const c::DutyCycleScenarioResult& s : r.scenarios) {
      const c::LifeMap m = c::frame_life_map(s.frame.model, s.frame.stress, s.frame.static_forces, s.frame.hot_spots.window, *s.request.fatigue);
      if (m.max_damage_per_hour() <= 0.0) std::abort();
    }
    maps.push_back(now() - t0);
    base.push_back(baseline(q));
  }
  const double tc = median(cycle), tm = median(maps), tb = median(base);
  fmt::print("duty cycle {} ({} scenarios), {} repeats, medians; shortest life {:.3f} h\n\n", q.name, q.scenarios.size(), repeats, life_h);
  fmt::print("| what | wall time | ratio |\n|---|---|---|\n");
  fmt::print("| baseline: the {} pipelines without fatigue | {:.3f} s | 1 |\n", q.scenarios.size(), tb);
  fmt::print("| the duty cycle (pipelines + life maps + Miner sum) | {:.3f} s | {:.2f} x baseline |\n", tc, tc / tb);
  fmt::print("| the {} life maps alone | {:.3f} s | {:.1f} % of the cycle |\n", q.scenarios.size(), tm, 100.0 * tm / tc);
  fmt::print("\ntarget: the cycle under 2 s on 2 cores: {}\n", tc < 2.0 ? "met" : "NOT met");
  return 0;
}
