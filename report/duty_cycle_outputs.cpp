// The outputs of a duty cycle; see duty_cycle_outputs.h.
#include "report/duty_cycle_outputs.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "report/csv_writer.h"
#include "report/fatigue_outputs.h"
#include "report/plot.h"
#include "report/response_figures.h"

namespace framedyn::report {

using core::Quantity;
using nlohmann::ordered_json;

namespace {

std::string point_name(const coupling::StressHistories& h, std::size_t station, int point) {
  return h.points[static_cast<std::size_t>(h.stations[station].section)][static_cast<std::size_t>(point)].name;
}

// The `count` stations of largest damage per cycle, each at its worst point (ties: lowest station, then point).
std::vector<std::pair<std::size_t, int>> worst_locations(const coupling::DutyLife& life, std::size_t count) {
  std::vector<std::pair<std::size_t, int>> at;
  std::vector<double> worst;
  for (std::size_t s = 0; s < life.damage_per_cycle.size(); ++s) {
    const auto [unused, p] = coupling::worst_location({life.damage_per_cycle[s]});
    at.emplace_back(s, p);
    worst.push_back(life.damage_per_cycle[s].empty() ? 0.0 : life.damage_per_cycle[s][static_cast<std::size_t>(p)]);
  }
  double top = 0.0;
  for (double w : worst) top = std::max(top, w);
  // Rank by value rounded to 1e-6 relative of the largest, then by station: the same order on every CPU.
  const double q = top > 0.0 ? 1e-6 * top : 1.0;
  std::vector<std::size_t> order(at.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return std::floor(worst[a] / q) > std::floor(worst[b] / q); });
  std::vector<std::pair<std::size_t, int>> out;
  for (std::size_t i = 0; i < order.size() && out.size() < count; ++i)
    if (worst[order[i]] > 0.0) out.push_back(at[order[i]]);
  return out;
}

}  // namespace

std::vector<std::size_t> locations_dominated(const coupling::DutyLife& life, std::size_t scenarios) {
  std::vector<std::size_t> dominated(scenarios, 0);
  for (std::size_t s = 0; s < life.dominant.size(); ++s)
    for (std::size_t p = 0; p < life.dominant[s].size(); ++p)
      if (life.damage_per_cycle[s][p] > 0.0) ++dominated[static_cast<std::size_t>(life.dominant[s][p])];
  return dominated;
}

double scenario_share(const coupling::DutyCycleResults& r, std::size_t scenario, std::size_t station, int point) {
  const auto part = [&](std::size_t i) { return r.scenarios[i].hours * r.scenarios[i].frame.life->damage_per_hour[station][static_cast<std::size_t>(point)]; };
  double sum = 0.0;
  for (std::size_t i = 0; i < r.scenarios.size(); ++i) sum += part(i);
  return sum > 0.0 ? part(scenario) / sum : 0.0;
}

std::vector<std::string> write_duty_cycle_outputs(const std::string& file, const coupling::DutyCycleRequest& q, const coupling::DutyCycleResults& r,
                                                  bool figures, core::ResultsFolder& folder) {
  const coupling::DutyCycleScenarioResult& first = r.scenarios.front();
  const coupling::StressHistories& h = first.frame.stress;
  const core::UnitSystem& u = first.request.units;
  const coupling::DutyLife& life = r.life;
  const std::string L = u.label(Quantity::length);
  // life_map.csv
  std::vector<std::string> header = {"output", "element", "station", column("X", L), column("Y", L), column("Z", L), "point",
                                     "sn_curve", "shear_sn_curve", column("damage_per_cycle", "1"), column("life", "h"), "dominant",
                                     column("normal_damage_per_cycle", "1"), column("shear_damage_per_cycle", "1"),
                                     "sigma_tau_correlation", "comparison_value", column("life_cv_1", "h"), column("life_cv_0.5", "h")};
  for (const auto& s : r.scenarios) header.push_back(column("damage_per_hour " + s.name, "1/h"));
  CsvTable t(header);
  for (std::size_t s = 0; s < h.stations.size(); ++s) {
    const coupling::StressStation& st = h.stations[s];
    for (std::size_t p = 0; p < life.damage_per_cycle[s].size(); ++p) {
      const double l = life.life_hours(s, static_cast<int>(p));
      t.row().add(st.set).add(st.element_id).add(st.station).add(u.from_si(st.point.x(), Quantity::length)).add(u.from_si(st.point.y(), Quantity::length))
          .add(u.from_si(st.point.z(), Quantity::length)).add(point_name(h, s, static_cast<int>(p)))
          .add(first.frame.life->curves[static_cast<std::size_t>(first.frame.life->curve_of_station[s])])
          .add(first.frame.life->shear_curves[static_cast<std::size_t>(first.frame.life->curve_of_station[s])]).add(life.damage_per_cycle[s][p])
          .add(std::isfinite(l) ? fmt::format("{:.6g}", l) : std::string())
          .add(life.damage_per_cycle[s][p] > 0.0 ? r.scenarios[static_cast<std::size_t>(life.dominant[s][p])].name : std::string())
          .add(life.normal_damage_per_cycle[s][p]).add(life.shear_damage_per_cycle[s][p]).add(life.correlation[s][p])
          .add(first.frame.life->code_id == coupling::FatigueCode::iiw ? fmt::format("{:g}", life.comparison_value[s][p]) : std::string())
          .add(life_text(life.cycle_hours, life.proportional_damage_per_cycle[s][p]))
          .add(life_text(life.cycle_hours, life.non_proportional_damage_per_cycle[s][p]));
      for (const auto& sc : r.scenarios) t.add(sc.frame.life->damage_per_hour[s][p]);
    }
  }
  folder.write_text("life_map.csv", t.str());
  std::vector<std::vector<double>> per_hour = life.damage_per_cycle;  // per hour of the cycle
  for (auto& row : per_hour)
    for (double& d : row) d /= life.cycle_hours;
  write_life_vtu(first.frame.model, h, per_hour, u, folder);
  std::vector<std::string> figure_files;
  if (figures) {
    const LinePlot plot = life_along_rails_figure(h, per_hour, "duty cycle, " + first.frame.life->code.substr(0, first.frame.life->code.find(' ')), u);
    if (!plot.series.empty()) {
      write_png(plot, folder.path_of("frame_life.png"));
      figure_files.push_back("frame_life.png");
    }
  }
  folder.write_text("summary.json", duty_cycle_summary(file, q, r).dump(2) + "\n");
  return figure_files;
}

ordered_json duty_cycle_summary(const std::string& file, const coupling::DutyCycleRequest& q, const coupling::DutyCycleResults& r) {
  const coupling::DutyCycleScenarioResult& first = r.scenarios.front();
  const coupling::StressHistories& h = first.frame.stress;
  const core::UnitSystem& u = first.request.units;
  const coupling::DutyLife& life = r.life;
  const std::string L = u.label(Quantity::length);
  ordered_json j;
  j["framedyn"] = {{"version", FRAMEDYN_VERSION}, {"command", "run"}};
  j["input"] = {{"study", file}, {"name", q.name}, {"model", "duty_cycle"}};
  ordered_json fat;
  const std::size_t ws = life.worst_station;
  const int wp = life.worst_point;
  const double d_cycle = life.damage_per_cycle.at(ws).empty() ? 0.0 : life.damage_per_cycle[ws][static_cast<std::size_t>(wp)];
  const auto where = [&](std::size_t s, int p) {
    const coupling::StressStation& st = h.stations[s];
    return ordered_json{{"output", st.set}, {"element", st.element_id}, {"station", st.station}, {"point", point_name(h, s, p)},
                        {"X", {{"value", u.from_si(st.point.x(), Quantity::length)}, {"unit", L}}}};
  };
  fat["code"] = first.frame.life->code;
  fat["stress"] = kStressDescription;
  fat["combination"] = coupling::combination_rule(first.frame.life->code_id);
  fat["cycle_hours"] = life.cycle_hours;
  ordered_json ml = life_json(life.cycle_hours, d_cycle);
  ml.update(where(ws, wp));
  ml["dominant"] = r.scenarios[static_cast<std::size_t>(life.dominant[ws][static_cast<std::size_t>(wp)])].name;
  fat["min_life"] = ml;
  fat["damage_per_hour"] = {{"value", d_cycle / life.cycle_hours}, {"unit", "1/h"}};
  fat["damage_per_cycle"] = d_cycle;
  fat["damage_per_cycle_parts"] = damage_parts(life.normal_damage_per_cycle.at(ws).empty() ? 0.0 : life.normal_damage_per_cycle[ws][static_cast<std::size_t>(wp)],
                                               life.shear_damage_per_cycle.at(ws).empty() ? 0.0 : life.shear_damage_per_cycle[ws][static_cast<std::size_t>(wp)], d_cycle, "1");
  if (!life.correlation.at(ws).empty()) {
    const std::size_t p = static_cast<std::size_t>(wp);
    fat["proportionality"] = proportionality_summary(first.frame.life->code_id, life.correlation[ws][p], life.comparison_value[ws][p],
                                                     life.proportional_damage_per_cycle[ws][p], life.non_proportional_damage_per_cycle[ws][p], life.cycle_hours);
  }
  fat["mean_stress"] = q.fatigue.mean_stress.describe();
  ordered_json assumed = ordered_json::array();
  const coupling::LifeMap& m = *first.frame.life;
  for (std::size_t c = 0; c < m.curves.size(); ++c) {
    std::size_t n = 0;
    for (int k : m.curve_of_station) n += k == static_cast<int>(c);
    assumed.push_back({{"where", m.assignment[c]}, {"sn_curve", m.curves[c]}, {"shear_sn_curve", m.shear_curves[c]}, {"stations", n}});
  }
  fat["details_assumed"] = assumed;
  ordered_json scen = ordered_json::array();
  const std::vector<std::size_t> dominated = locations_dominated(life, r.scenarios.size());
  for (std::size_t i = 0; i < r.scenarios.size(); ++i) {
    const auto& sc = r.scenarios[i];
    const coupling::LifeMap& lm = *sc.frame.life;
    const double own = lm.max_damage_per_hour();
    ordered_json o = {{"name", sc.name},
                      {"study", q.scenarios[i].study.string()},
                      {"hours", sc.hours},
                      {"steady_window", {{"from", sc.frame.hot_spots.window.from}, {"source", sc.frame.hot_spots.window.source}, {"block_seconds", lm.block_seconds}}},
                      {"damage_at_min_life_location", sc.hours * lm.damage_per_hour[ws][static_cast<std::size_t>(wp)]},
                      {"share_at_min_life_location", scenario_share(r, i, ws, wp)},
                      {"locations_dominated", dominated[i]},
                      {"min_life_alone", life_json(1.0, own)}};
    o["min_life_alone"].update(where(lm.worst_station, lm.worst_point));
    scen.push_back(o);
  }
  fat["scenarios"] = scen;
  ordered_json worst = ordered_json::array();
  for (const auto& [s, p] : worst_locations(life, 10)) {
    ordered_json w = where(s, p);
    w["damage_per_cycle"] = life.damage_per_cycle[s][static_cast<std::size_t>(p)];
    w["life"] = {{"value", life.life_hours(s, p)}, {"unit", "h"}};
    w["dominant"] = r.scenarios[static_cast<std::size_t>(life.dominant[s][static_cast<std::size_t>(p)])].name;
    ordered_json by = ordered_json::object();
    for (const auto& sc : r.scenarios) by[sc.name] = sc.hours * sc.frame.life->damage_per_hour[s][static_cast<std::size_t>(p)];
    w["damage_by_scenario"] = by;
    worst.push_back(w);
  }
  fat["worst_locations"] = worst;
  j["fatigue"] = fat;
  return j;
}

}  // namespace framedyn::report
