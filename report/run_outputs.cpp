// rigid.contacts, rigid.steady and frame.steady of summary.json: see run_outputs.h.
#include "report/run_outputs.h"

#include "report/fatigue_outputs.h"
#include "report/json_quantity.h"

#include <fmt/format.h>

#include <cstdio>

namespace framedyn::report {

nlohmann::ordered_json contacts_json(const std::vector<coupling::ContactSummary>& contacts, const core::UnitSystem& units) {
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  const std::string f = units.label(core::Quantity::force);
  for (const coupling::ContactSummary& c : contacts)
    j[c.name] = {{"min_force", {{"value", units.from_si(c.min_force, core::Quantity::force)}, {"unit", f}}},
                 {"max_force", {{"value", units.from_si(c.max_force, core::Quantity::force)}, {"unit", f}}},
                 {"tension_fraction", c.tension_fraction},
                 {"lift_off_fraction", c.lift_off_fraction}};
  return j;
}

nlohmann::ordered_json static_json(const std::vector<coupling::StaticContact>& contacts, const core::UnitSystem& units) {
  nlohmann::ordered_json forces = nlohmann::ordered_json::object(), engaged = nlohmann::ordered_json::array(),
                         lifted = nlohmann::ordered_json::array();
  for (const coupling::StaticContact& c : contacts) {
    forces[c.name] = {{"value", units.from_si(c.force, core::Quantity::force)}, {"unit", units.label(core::Quantity::force)}};
    (c.engaged ? engaged : lifted).push_back(c.name);
  }
  return {{"contact_forces", forces}, {"engaged", engaged}, {"lifted", lifted}};
}

nlohmann::ordered_json modes_by_state_json(const std::vector<coupling::StateModes>& states) {
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  for (const coupling::StateModes& s : states) {
    std::vector<double> f;
    for (const rigid::RigidMode& m : s.modes) f.push_back(m.frequency_hz);
    j[s.state] = {{"label", s.label}, {"frequencies", report::quantity(f, core::UnitSystem::si().label(core::Quantity::frequency))}};
  }
  return j;
}

namespace {

// {start_up: {value, unit, time {value, unit}}, steady: {...}}, a part
// absent when it holds no sample (steady: not reached; start_up: steady from t = 0).
nlohmann::ordered_json split_json(const rigid::PeakSplit& s, double factor, const std::string& unit) {
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  if (s.start_up) j["start_up"] = {{"value", s.start_up->value * factor}, {"unit", unit}, {"time", report::quantity(s.start_up->time, "s")}};
  if (s.steady) j["steady"] = {{"value", s.steady->value * factor}, {"unit", unit}, {"time", report::quantity(s.steady->time, "s")}};
  return j;
}

}  // namespace

nlohmann::ordered_json steady_json(const coupling::SteadyReport& st, const core::UnitSystem& units) {
  nlohmann::ordered_json j;
  const rigid::SteadyOperation& op = st.operation;
  j["reached_at"] = op.reached_at ? nlohmann::ordered_json{{"value", *op.reached_at}, {"unit", "s"}} : nlohmann::ordered_json(nullptr);
  if (!st.assessed) {
    j["assessed"] = false;
    j["reason"] = st.not_assessed;
    return j;
  }
  j["period_multiple"] = op.reached_at ? nlohmann::ordered_json(op.period_multiple) : nlohmann::ordered_json(nullptr);
  j["shaker_period"] = {{"value", op.shaker_period}, {"unit", "s"}};
  j["tolerance"] = st.criterion.tolerance;
  j["window_periods"] = st.criterion.window_periods;
  j["max_period_multiple"] = st.criterion.max_period_multiple;
  j["remaining_change"] = {{"value", op.remaining_change}, {"unit", "1"}, {"period_multiple", op.remaining_period_multiple}, {"signal", op.leading_signal}};
  j["watched"] = st.watched;
  nlohmann::ordered_json peaks = nlohmann::ordered_json::object();
  for (const coupling::SteadyPeak& p : st.peaks) {
    peaks[p.name] = split_json(p.split, 1.0 / units.to_si_factor(p.quantity), units.label(p.quantity));
  }
  j["peaks"] = peaks;
  return j;
}

void print_hot_spot_line(const coupling::FrameStudyResults& f, const core::UnitSystem& u) {
  const coupling::HotSpotReport& h = f.hot_spots;
  if (h.peak.point_name.empty() || h.peak.station >= f.stress.stations.size()) return;
  using core::Quantity;
  const coupling::StressStation& st = f.stress.stations[h.peak.station];
  fmt::print("peak von Mises stress {:.5g} {} at {} element {} station {} ({}), X = {:.4g} {}, t = {:.4f} s; steady from {:.4g} s ({}): "
             "steady peak {:.5g} {}\n",
             u.from_si(h.peak.von_mises_total, Quantity::stress), u.label(Quantity::stress), st.set, st.element_id, st.station, h.peak.point_name,
             u.from_si(st.point.x(), Quantity::length), u.label(Quantity::length), h.peak.time, h.window.from, h.window.source,
             u.from_si(h.steady_peak.von_mises_total, Quantity::stress), u.label(Quantity::stress));
}

void print_fatigue_line(const coupling::FrameStudyResults& f, const coupling::FrameStudyRequest& q) {
  if (!f.life || !q.fatigue) return;
  const coupling::LifeMap& m = *f.life;
  const coupling::StressStation& st = f.stress.stations.at(m.worst_station);
  const double d = m.max_damage_per_hour();
  const std::string point = f.stress.points[static_cast<std::size_t>(st.section)][static_cast<std::size_t>(m.worst_point)].name;
  fmt::print("fatigue ({}): shortest life {} at {} element {} station {} ({}), X = {:.4g} {}; damage {:.3g} in {:g} h\n", m.code,
             d > 0.0 ? fmt::format("{:.4g} h", 1.0 / d) : std::string("unlimited (no damaging cycle)"), st.set, st.element_id, st.station, point,
             q.units.from_si(st.point.x(), core::Quantity::length), q.units.label(core::Quantity::length), d * q.fatigue->hours, q.fatigue->hours);
  const std::size_t wp = static_cast<std::size_t>(m.worst_point);
  fmt::print("  there: normal stress alone {:.3g}/h, shear alone {:.3g}/h, combined {:.3g}/h ({})\n", m.normal_damage_per_hour[m.worst_station][wp],
             m.shear_damage_per_hour[m.worst_station][wp], d, coupling::combination_rule(m.code_id));
  fmt::print("  proportionality there: {}; life under CV 1 {} h, under CV 0.5 {} h\n",
             comparison_value_reason(m.code_id, m.correlation[m.worst_station][wp], m.comparison_value[m.worst_station][wp]),
             life_text(1.0, m.proportional_damage_per_hour[m.worst_station][wp]), life_text(1.0, m.non_proportional_damage_per_hour[m.worst_station][wp]));
  // Which detail categories were assumed where (normal and shear curves).
  for (std::size_t c = 0; c < m.curves.size(); ++c) {
    std::size_t n = 0;
    for (int k : m.curve_of_station) n += k == static_cast<int>(c);
    fmt::print("  detail assumed: {} / {} on {} ({} stations)\n", m.curves[c], m.shear_curves[c], m.assignment[c], n);
  }
}

nlohmann::ordered_json frame_steady_json(const coupling::FrameStudyResults& frame, std::optional<double> reached_at, const core::UnitSystem& units) {
  nlohmann::ordered_json j;
  j["reached_at"] = reached_at ? nlohmann::ordered_json{{"value", *reached_at}, {"unit", "s"}} : nlohmann::ordered_json(nullptr);
  const std::vector<double> t(frame.response.times.data(), frame.response.times.data() + frame.response.times.size());
  nlohmann::ordered_json rails = nlohmann::ordered_json::object();
  for (const coupling::RailRecovery& r : frame.rails) {
    const std::vector<double> stress(r.series_normal_stress.data(), r.series_normal_stress.data() + r.series_normal_stress.size());
    const std::vector<double> moment(r.series_bending_moment.data(), r.series_bending_moment.data() + r.series_bending_moment.size());
    rails[r.spec.name] = {
        {"peak_abs_normal_stress", split_json(rigid::split_peaks(t, stress, reached_at), 1.0 / units.to_si_factor(core::Quantity::stress),
                                          units.label(core::Quantity::stress))},
        {"peak_bending_moment", split_json(rigid::split_peaks(t, moment, reached_at), 1.0 / units.to_si_factor(core::Quantity::moment),
                                           units.label(core::Quantity::moment))}};
  }
  j["rails"] = rails;
  return j;
}

}  // namespace framedyn::report
