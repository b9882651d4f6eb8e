// The fatigue life map's outputs; see fatigue_outputs.h.
#include "report/fatigue_outputs.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "report/csv_writer.h"
#include "report/vtu_writer.h"

namespace framedyn::report {

using core::Quantity;
using nlohmann::ordered_json;

namespace {

double life_of(double damage_per_hour) { return damage_per_hour > 0.0 ? 1.0 / damage_per_hour : std::numeric_limits<double>::infinity(); }

// An empty cell for a point without damage (every cycle below the cut-off): framedyn writes no "inf".
std::string life_text(double life) { return std::isfinite(life) ? fmt::format("{:.6g}", life) : ""; }

}  // namespace

ordered_json life_json(double hours_per_damage, double damage) {
  if (damage > 0.0) return {{"value", hours_per_damage / damage}, {"unit", "h"}};
  return {{"unit", "h"}, {"none", kUnlimitedLifeReason}};
}

std::string life_text(double hours_per_damage, double damage) { return damage > 0.0 ? life_text(hours_per_damage / damage) : std::string(); }

std::string comparison_value_reason(coupling::FatigueCode code, double r, double cv) {
  if (code != coupling::FatigueCode::iiw) return fmt::format("no CV (EN 1993-1-9 adds the damage sums); |r| = {:.3f}", std::abs(r));
  return fmt::format("CV {:g} (|r| = {:.3f} {} {:g}: {})", cv, std::abs(r), cv == coupling::kIiwProportionalComparisonValue ? ">=" : "<",
                     coupling::kProportionalCorrelation, cv == coupling::kIiwProportionalComparisonValue ? "proportional" : "not proportional");
}

ordered_json proportionality_summary(coupling::FatigueCode code, double r, double cv, double d_prop, double d_non, double hours_per_damage) {
  ordered_json j;
  j["measure"] = coupling::proportionality_rule(code);
  j["correlation"] = r;
  // EN 1993-1-9 has no comparison value (it adds the damage sums, F.29): no comparison_value and
  // no lives under IIW's two CVs, only the correlation and why; a null would be refused as a broken-down number.
  if (code == coupling::FatigueCode::iiw) j["comparison_value"] = cv;
  j["why"] = comparison_value_reason(code, r, cv);
  if (code != coupling::FatigueCode::iiw) return j;
  j["life_proportional"] = life_json(hours_per_damage, d_prop);
  j["life_proportional"]["comparison_value"] = coupling::kIiwProportionalComparisonValue;
  j["life_non_proportional"] = life_json(hours_per_damage, d_non);
  j["life_non_proportional"]["comparison_value"] = coupling::kIiwNonProportionalComparisonValue;
  return j;
}

ordered_json damage_parts(double normal, double shear, double combined, const std::string& unit) {
  return {{"normal", normal}, {"shear", shear}, {"combined", combined}, {"unit", unit}};
}

void write_life_map(const coupling::FrameStudyResults& r, const coupling::FrameStudyRequest& q, const core::ResultsFolder& folder) {
  if (!r.life || !q.fatigue) return;
  const coupling::LifeMap& m = *r.life;
  const core::UnitSystem& u = q.units;
  CsvTable t({"output", "element", "station", column("X", u.label(Quantity::length)), column("Y", u.label(Quantity::length)),
              column("Z", u.label(Quantity::length)), "point", "sn_curve", "shear_sn_curve", column("damage_per_hour", "1/h"), column("life", "h"),
              fmt::format("damage in {:g} h", q.fatigue->hours), column("normal_damage_per_hour", "1/h"), column("shear_damage_per_hour", "1/h"),
              "sigma_tau_correlation", "comparison_value", column("life_cv_1", "h"), column("life_cv_0.5", "h")});
  for (std::size_t s = 0; s < r.stress.stations.size(); ++s) {
    const coupling::StressStation& st = r.stress.stations[s];
    const auto& points = r.stress.points[static_cast<std::size_t>(st.section)];
    for (std::size_t p = 0; p < points.size(); ++p) {
      const double d = m.damage_per_hour[s][p];
      t.row().add(st.set).add(st.element_id).add(st.station).add(u.from_si(st.point.x(), Quantity::length))
          .add(u.from_si(st.point.y(), Quantity::length)).add(u.from_si(st.point.z(), Quantity::length)).add(points[p].name)
          .add(m.curves[static_cast<std::size_t>(m.curve_of_station[s])]).add(m.shear_curves[static_cast<std::size_t>(m.curve_of_station[s])])
          .add(d).add(life_text(life_of(d))).add(d * q.fatigue->hours).add(m.normal_damage_per_hour[s][p]).add(m.shear_damage_per_hour[s][p])
          .add(m.correlation[s][p]).add(m.code_id == coupling::FatigueCode::iiw ? fmt::format("{:g}", m.comparison_value[s][p]) : std::string())
          .add(life_text(1.0, m.proportional_damage_per_hour[s][p])).add(life_text(1.0, m.non_proportional_damage_per_hour[s][p]));
    }
  }
  folder.write_text("life_map.csv", t.str());
  write_life_vtu(r.model, r.stress, m.damage_per_hour, u, folder);
}

std::vector<VtuField> life_cell_fields(const fem::FrameModel& model, const coupling::StressHistories& stress,
                                       const std::vector<std::vector<double>>& damage_per_hour) {
  // Per beam element the largest damage per hour over its stations and points (0 off the outputs),
  // and its life, capped at kUnlimitedLife where nothing (or next to nothing) is damaged: framedyn's
  // files hold no infinity or NaN (the XDMF writer refuses them).
  VtuField damage{"fatigue_damage_per_hour [1/h]", 1, std::vector<double>(model.beams.size(), 0.0)};
  for (std::size_t s = 0; s < stress.stations.size() && s < damage_per_hour.size(); ++s) {
    const int b = model.beam_index(stress.stations[s].element_id);
    if (b < 0) continue;
    for (double d : damage_per_hour[s]) damage.values[static_cast<std::size_t>(b)] = std::max(damage.values[static_cast<std::size_t>(b)], d);
  }
  VtuField life{"fatigue_life [h]", 1, {}};
  for (double d : damage.values) life.values.push_back(d > 1.0 / kUnlimitedLife ? 1.0 / d : kUnlimitedLife);
  return {damage, life};
}

void write_life_vtu(const fem::FrameModel& model, const coupling::StressHistories& stress, const std::vector<std::vector<double>>& damage_per_hour,
                    const core::UnitSystem& u, const core::ResultsFolder& folder) {
  folder.write_text("frame_life.vtu", vtu_document(model, 1.0 / u.to_si_factor(Quantity::length), {}, life_cell_fields(model, stress, damage_per_hour)));
}

ordered_json fatigue_summary(const coupling::FrameStudyResults& r, const coupling::FrameStudyRequest& q) {
  ordered_json j;
  if (!r.life || !q.fatigue) return j;
  const coupling::LifeMap& m = *r.life;
  const core::UnitSystem& u = q.units;
  const coupling::StressStation& st = r.stress.stations.at(m.worst_station);
  const double d = m.max_damage_per_hour();
  j["code"] = m.code;
  j["stress"] = kStressDescription;
  j["combination"] = coupling::combination_rule(m.code_id);
  j["hours"] = q.fatigue->hours;
  j["min_life"] = life_json(1.0, d);
  j["min_life"].update(ordered_json{{"element", st.element_id},
                   {"station", st.station},
                   {"point", r.stress.points[static_cast<std::size_t>(st.section)][static_cast<std::size_t>(m.worst_point)].name},
                   {"output", st.set},
                   {"X", {{"value", u.from_si(st.point.x(), Quantity::length)}, {"unit", u.label(Quantity::length)}}}});
  j["damage_per_hour"] = {{"value", d}, {"unit", "1/h"}};
  j["damage_per_hour_parts"] = damage_parts(m.normal_damage_per_hour[m.worst_station][static_cast<std::size_t>(m.worst_point)],
                                            m.shear_damage_per_hour[m.worst_station][static_cast<std::size_t>(m.worst_point)], d, "1/h");
  {
    const std::size_t ws = m.worst_station, wp = static_cast<std::size_t>(m.worst_point);
    j["proportionality"] = proportionality_summary(m.code_id, m.correlation[ws][wp], m.comparison_value[ws][wp], m.proportional_damage_per_hour[ws][wp],
                                                   m.non_proportional_damage_per_hour[ws][wp], 1.0);
  }
  j["damage"] = {{"value", d * q.fatigue->hours}, {"hours", q.fatigue->hours}};
  j["mean_stress"] = q.fatigue->mean_stress.describe();
  j["block"] = {{"seconds", m.block_seconds}, {"samples", m.block_samples}, {"residue", "repeated block (closed at the absolute maximum)"}};
  // Which detail categories were assumed where.
  ordered_json assumed = ordered_json::array();
  for (std::size_t c = 0; c < m.curves.size(); ++c) {
    std::size_t stations = 0;
    for (int k : m.curve_of_station) stations += k == static_cast<int>(c);
    assumed.push_back({{"where", m.assignment[c]}, {"sn_curve", m.curves[c]}, {"shear_sn_curve", m.shear_curves[c]}, {"stations", stations}});
  }
  j["details_assumed"] = assumed;
  return j;
}

LinePlot life_along_rails_figure(const coupling::FrameStudyResults& r, const core::UnitSystem& u) {
  if (!r.life) return life_along_rails_figure(r.stress, {}, "", u);
  return life_along_rails_figure(r.stress, r.life->damage_per_hour, r.life->code, u);
}

LinePlot life_along_rails_figure(const coupling::StressHistories& stress, const std::vector<std::vector<double>>& damage_per_hour, const std::string& code,
                                 const core::UnitSystem& u) {
  LinePlot plot;
  plot.title = fmt::format("Fatigue life along the outputs, shortest over the section points ({})", code);
  plot.x_label = "X along the frame";
  plot.x_unit = u.label(Quantity::length);
  plot.y_label = "life";
  plot.y_unit = "h";
  plot.log_y = true;
  plot.mark_points = true;
  std::map<std::string, std::size_t> series_of;
  for (std::size_t s = 0; s < damage_per_hour.size() && s < stress.stations.size(); ++s) {
    double worst = 0.0;
    for (double d : damage_per_hour[s]) worst = std::max(worst, d);
    if (!(worst > 0.0)) continue;
    const std::string& set = stress.stations[s].set;
    auto at = series_of.find(set);
    if (at == series_of.end()) {
      at = series_of.emplace(set, plot.series.size()).first;
      plot.series.push_back({set, {}, {}, false, ""});
    }
    plot.series[at->second].x.push_back(u.from_si(stress.stations[s].point.x(), Quantity::length));
    plot.series[at->second].y.push_back(1.0 / worst);
  }
  // Along X within each output (its elements need not be listed in X order); stable for equal X.
  for (PlotSeries& ps : plot.series) {
    std::vector<std::size_t> order(ps.x.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return ps.x[a] < ps.x[b]; });
    PlotSeries sorted{ps.name, {}, {}, false, ""};
    for (std::size_t i : order) sorted.x.push_back(ps.x[i]), sorted.y.push_back(ps.y[i]);
    ps = sorted;
  }
  return plot;
}

}  // namespace framedyn::report
