// `framedyn run DUTY.yaml` for a duty cycle (model: duty_cycle; coupling/duty_cycle.h):
// every scenario's pipeline (coupling/), the outputs (report/duty_cycle_outputs.h), and the
// console's lines: each scenario's share at the shortest-life location, the shortest life.
#include "apps/duty_cycle_command.h"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>

#include "core/results_folder.h"
#include "coupling/duty_cycle.h"
#include "report/duty_cycle_outputs.h"
#include "report/response_figures.h"

namespace framedyn::apps {

int run_duty_cycle_study(const std::string& file, const std::string& out, bool figures, const ProgressFlags& flags) {
  Progress progress(flags);
  if (figures) report::require_gnuplot();
  const std::string out_dir = out.empty() ? std::filesystem::path(file).stem().string() + "_results" : out;
  core::check_results_target(out_dir, {file});
  progress.stage("reading " + file);
  const coupling::DutyCycleRequest q = coupling::read_duty_cycle(file);
  std::vector<std::filesystem::path> inputs = {file};
  for (const coupling::DutyCycleScenarioSpec& s : q.scenarios) inputs.push_back(s.study);
  core::check_results_target(out_dir, inputs);
  const coupling::DutyCycleResults r = coupling::run_duty_cycle(q, [&](const std::string& what) { progress.stage(what); });
  progress.stage("writing results");
  core::ResultsFolder folder(out_dir, inputs);
  const std::vector<std::string> figure_files = report::write_duty_cycle_outputs(file, q, r, figures, folder);
  folder.commit();
  progress.done();
  if (progress.quiet()) {
    fmt::print("results in {}/\n", out_dir);
    return 0;
  }
  const coupling::DutyCycleScenarioResult& first = r.scenarios.front();
  const coupling::StressHistories& h = first.frame.stress;
  const core::UnitSystem& u = first.request.units;
  const coupling::DutyLife& life = r.life;
  const std::size_t ws = life.worst_station;
  const int wp = life.worst_point;
  const double d_cycle = life.damage_per_cycle.at(ws).empty() ? 0.0 : life.damage_per_cycle[ws][static_cast<std::size_t>(wp)];
  const double min_life = life.life_hours(ws, wp);
  const std::vector<std::size_t> dominated = report::locations_dominated(life, r.scenarios.size());
  const std::string point = h.points[static_cast<std::size_t>(h.stations[ws].section)][static_cast<std::size_t>(wp)].name;
  fmt::print("framedyn run: {} (duty cycle {}, {} scenarios, {:g} h per cycle; {})\n", file, q.name, r.scenarios.size(), life.cycle_hours, first.frame.life->code);
  for (std::size_t i = 0; i < r.scenarios.size(); ++i) {
    const auto& sc = r.scenarios[i];
    fmt::print("  {:<16} {:8g} h  share of the damage at the shortest-life location {:5.1f} %, dominates {} locations  ({:.2f} s)\n", sc.name, sc.hours,
               100.0 * report::scenario_share(r, i, ws, wp), dominated[i],
               sc.wall_seconds);
  }
  const coupling::StressStation& st = h.stations[ws];
  fmt::print("shortest life {} at {} element {} station {} ({}), X = {:.4g} {}; damage per cycle {:.3g}\n",
             std::isfinite(min_life) ? fmt::format("{:.4g} h", min_life) : std::string("unlimited"), st.set, st.element_id, st.station,
             point, u.from_si(st.point.x(), core::Quantity::length), u.label(core::Quantity::length), d_cycle);
  if (figures) fmt::print("figures: {}\n", figure_files.empty() ? std::string("none (no damage)") : figure_files.front());
  fmt::print("\nresults in {}/\n", out_dir);
  return 0;
}

}  // namespace framedyn::apps
