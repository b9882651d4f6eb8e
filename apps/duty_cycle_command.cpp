// The console of `framedyn run DUTY.yaml` for a duty cycle (model: duty_cycle;
// coupling/duty_cycle.h): each scenario's share at the shortest-life location, the
// shortest life. The run and its outputs are report::run_study_file's.
#include "apps/duty_cycle_command.h"

#include <fmt/format.h>

#include <cmath>

#include "report/duty_cycle_outputs.h"
#include "report/fatigue_outputs.h"
#include "report/study_run_details.h"

namespace framedyn::apps {

int print_duty_cycle_run(const std::string& file, const report::StudyRun& run, bool figures, const std::string& out_dir) {
  const coupling::DutyCycleRequest& q = *run.details->duty_cycle;
  const coupling::DutyCycleResults& r = *run.details->duty_cycle_results;
  const std::vector<std::string>& figure_files = run.figures;
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
  // At the shortest-life location: each stress's damage, the combination and the CV (theory/fatigue.md sections 10 and 12).
  const coupling::LifeMap& m = *first.frame.life;
  if (!life.normal_damage_per_cycle.at(ws).empty()) {
    const std::size_t p = static_cast<std::size_t>(wp);
    fmt::print("  there: normal stress alone {:.3g}, shear alone {:.3g}, combined {:.3g} per cycle of {:g} h ({})\n", life.normal_damage_per_cycle[ws][p],
               life.shear_damage_per_cycle[ws][p], d_cycle, life.cycle_hours, coupling::combination_rule(m.code_id));
    fmt::print("  proportionality there: {}; life under CV 1 {} h, under CV 0.5 {} h\n",
               report::comparison_value_reason(m.code_id, life.correlation[ws][p], life.comparison_value[ws][p]),
               report::life_text(life.cycle_hours, life.proportional_damage_per_cycle[ws][p]),
               report::life_text(life.cycle_hours, life.non_proportional_damage_per_cycle[ws][p]));
  }
  // Which detail categories were assumed where (the cycle's one fatigue block: the same in every scenario).
  for (std::size_t c = 0; c < m.curves.size(); ++c) {
    std::size_t n = 0;
    for (int k : m.curve_of_station) n += k == static_cast<int>(c);
    fmt::print("  detail assumed: {} / {} on {} ({} stations)\n", m.curves[c], m.shear_curves[c], m.assignment[c], n);
  }
  if (figures) fmt::print("figures: {}\n", figure_files.empty() ? std::string("none (no damage)") : figure_files.front());
  fmt::print("\nresults in {}/\n", out_dir);
  return 0;
}

}  // namespace framedyn::apps
