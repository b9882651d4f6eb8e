// The outputs of `framedyn sweep`; see sweep_outputs.h.
#include "report/sweep_outputs.h"

#include <fmt/format.h>

#include <algorithm>
#include <optional>

#include "report/csv_writer.h"
#include "report/json_quantity.h"
#include "report/plot.h"

namespace framedyn::report {

namespace {

using core::Quantity;

// One response figure of the sweep: how to get it from a run, its unit.
struct Figure {
  std::string key;    // in summary.json and the CSV
  std::string label;  // for the axis and the legend
  Quantity quantity;
  std::optional<double> coupling::SweepPoint::*member;
};

const std::vector<Figure>& figures() {
  static const std::vector<Figure> f = {
      {"plow_vertical_pp", "blade vertical motion, peak to peak", Quantity::length, &coupling::SweepPoint::plow_vertical_pp},
      {"peak_cutting_force", "peak cutting force", Quantity::force, &coupling::SweepPoint::peak_cutting_force},
      {"peak_backing_force", "peak backing force", Quantity::force, &coupling::SweepPoint::peak_backing_force},
      {"average_peak_cutting_force", "average of the cycles' peak cutting force", Quantity::force, &coupling::SweepPoint::average_peak_cutting_force},
      {"average_peak_backing_force", "average of the cycles' peak backing force", Quantity::force, &coupling::SweepPoint::average_peak_backing_force},
  };
  return f;
}

// Relative spread of a figure over the sweep, (max - min) / reference: the
// thesis's "changes 0.2 % around 0.466 in".
std::optional<double> spread(const coupling::SweepResult& s, const Figure& f) {
  const std::optional<double>& ref = s.reference.*f.member;
  if (!ref || *ref == 0.0) return std::nullopt;
  double lo = 1e300, hi = -1e300;
  for (const coupling::SweepPoint& p : s.points) {
    if (!(p.*f.member)) return std::nullopt;
    lo = std::min(lo, *(p.*f.member));
    hi = std::max(hi, *(p.*f.member));
  }
  return (hi - lo) / *ref;
}

// A figure a run does not give (no plow; no shaker cycle; a blade that never
// backs off) is left out of the summary, not written as null: a null in a
// results file means a NaN or an infinity (core/finite_output.h) and stops the run.
void set_if(nlohmann::ordered_json& j, const std::string& key, const std::optional<double>& v) {
  if (v) j[key] = *v;
}

}  // namespace

std::string sweep_csv(const SweepReport& w) {
  const coupling::SweepResult& s = *w.result;
  const core::UnitSystem& u = w.units;
  const std::vector<double>& x = w.values;
  std::vector<std::string> h = {column(s.parameter, w.parameter_unit)};
  for (const Figure& f : figures()) h.push_back(column(f.key, u.label(f.quantity)));
  for (const Figure& f : figures()) h.push_back(column(f.key + "_change", u.label(Quantity::percent)));
  const std::size_t modes = s.points.front().frequencies_hz.size();
  for (std::size_t m = 0; m < modes; ++m) {
    h.push_back(column(fmt::format("frequency_{}", m + 1), u.label(Quantity::frequency)));
    h.push_back(fmt::format("dominant_{}", m + 1));
  }
  CsvTable csv(h);
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    const coupling::SweepPoint& p = s.points[i];
    csv.row().add(x[i]);
    for (const Figure& f : figures()) {
      const std::optional<double>& v = p.*f.member;
      if (v) csv.add(u.from_si(*v, f.quantity));
      else csv.add(std::string());
    }
    for (const Figure& f : figures()) {
      const std::optional<double> c = coupling::relative_change(p.*f.member, s.reference.*f.member);
      if (c) csv.add(100.0 * *c);
      else csv.add(std::string());
    }
    for (std::size_t m = 0; m < modes; ++m) {
      if (m < p.frequencies_hz.size()) csv.add(p.frequencies_hz[m]).add(p.dominant[m]);
      else csv.add(std::string()).add(std::string());
    }
  }
  return csv.str();
}

std::vector<std::string> write_sweep_figures(const SweepReport& w, const core::ResultsFolder& folder) {
  const coupling::SweepResult& s = *w.result;
  const core::UnitSystem& u = w.units;
  const std::vector<double>& x = w.values;
  const std::string x_unit = w.parameter_unit;
  std::vector<std::string> written;
  const auto series_of = [&](const Figure& f, bool relative) {
    PlotSeries ps{f.label, {}, {}};
    for (std::size_t i = 0; i < s.points.size(); ++i) {
      const std::optional<double>& v = s.points[i].*f.member;
      const std::optional<double> value = relative ? coupling::relative_change(v, s.reference.*f.member) : v;
      if (!value) continue;
      ps.x.push_back(x[i]);
      ps.y.push_back(relative ? 100.0 * *value : u.from_si(*value, f.quantity));
    }
    return ps;
  };
  const auto base = [&](const std::string& title, const std::string& y_label, const std::string& y_unit) {
    LinePlot p;
    p.title = title + ": " + w.study_name;
    p.x_label = s.parameter;
    p.x_unit = x_unit;
    p.y_label = y_label;
    p.y_unit = y_unit;
    p.mark_points = true;
    return p;
  };
  const auto write = [&](LinePlot& p, const std::string& file) {
    p.series.erase(std::remove_if(p.series.begin(), p.series.end(), [](const PlotSeries& ps) { return ps.x.empty(); }), p.series.end());
    if (p.series.empty()) return;
    write_png(p, folder.path_of(file));
    written.push_back(file);
  };
  const std::vector<Figure>& f = figures();
  LinePlot amplitude = base("Plow blade amplitude vs " + s.parameter + " (thesis Figure 9)", "blade vertical motion, average peak to peak", u.label(Quantity::length));
  amplitude.series.push_back(series_of(f[0], false));
  write(amplitude, "amplitude.png");
  LinePlot forces = base("Peak plow forces vs " + s.parameter + " (thesis Figure 10)", "peak plow force", u.label(Quantity::force));
  forces.series.push_back(series_of(f[1], false));
  forces.series.push_back(series_of(f[2], false));
  forces.series.push_back(series_of(f[3], false));
  forces.series.push_back(series_of(f[4], false));
  write(forces, "peak_forces.png");
  const double ref = u.from_si(s.reference.value, s.quantity);
  LinePlot change = base(fmt::format("Change against the run at {} = {:g} {}", s.parameter, ref, x_unit), "relative change", u.label(Quantity::percent));
  for (const Figure& fig : f) change.series.push_back(series_of(fig, true));
  write(change, "relative_change.png");
  LinePlot freq = base("Natural frequencies vs " + s.parameter, "natural frequency", u.label(Quantity::frequency));
  const std::size_t modes = s.points.empty() ? 0 : s.points.front().frequencies_hz.size();
  for (std::size_t m = 0; m < modes; ++m) {
    PlotSeries ps{fmt::format("mode {} ({})", m + 1, s.points.front().dominant[m]), {}, {}};
    for (std::size_t i = 0; i < s.points.size(); ++i)
      if (m < s.points[i].frequencies_hz.size()) ps.x.push_back(x[i]), ps.y.push_back(s.points[i].frequencies_hz[m]);
    freq.series.push_back(std::move(ps));
  }
  write(freq, "frequencies.png");
  return written;
}

nlohmann::ordered_json sweep_summary(const SweepReport& w, const std::vector<std::string>& pngs) {
  const coupling::SweepResult& s = *w.result;
  const core::UnitSystem& u = w.units;
  const std::vector<double>& x = w.values;
  const std::string unit = w.parameter_unit, hz = u.label(Quantity::frequency);
  const double reference = u.from_si(s.reference.value, s.quantity);
  nlohmann::ordered_json runs = nlohmann::ordered_json::array();
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    const coupling::SweepPoint& p = s.points[i];
    nlohmann::ordered_json jr;
    jr["parameter"] = quantity(x[i], unit);
    for (const Figure& f : figures()) {
      const std::optional<double>& v = p.*f.member;
      if (v) jr[f.key] = {{"value", u.from_si(*v, f.quantity)}, {"unit", u.label(f.quantity)}};
    }
    nlohmann::ordered_json change;
    for (const Figure& f : figures()) set_if(change, f.key, coupling::relative_change(p.*f.member, s.reference.*f.member));
    jr["relative_change"] = change;
    jr["frequencies"] = quantity(p.frequencies_hz, hz);
    jr["dominant"] = p.dominant;
    runs.push_back(jr);
  }
  nlohmann::ordered_json j;
  j["framedyn"] = {{"version", FRAMEDYN_VERSION}, {"command", "sweep"}};
  j["input"] = {{"study", w.study_file}, {"name", w.study_name}, {"units", u.name()}};
  nlohmann::ordered_json sw;
  sw["parameter"] = s.parameter;
  sw["values"] = quantity(x, unit);
  sw["jobs"] = w.jobs;
  nlohmann::ordered_json ref;
  ref["parameter"] = quantity(reference, unit);
  ref["in_values"] = s.reference_index >= 0;
  for (const Figure& f : figures()) {
    const std::optional<double>& v = s.reference.*f.member;
    if (v) ref[f.key] = {{"value", u.from_si(*v, f.quantity)}, {"unit", u.label(f.quantity)}};
  }
  ref["frequencies"] = quantity(s.reference.frequencies_hz, hz);
  sw["reference"] = ref;
  sw["runs"] = runs;
  nlohmann::ordered_json sp;
  for (const Figure& f : figures()) set_if(sp, f.key, spread(s, f));
  sw["relative_spread"] = sp;
  sw["figures"] = pngs;
  j["sweep"] = sw;
  return j;
}

std::string sweep_console_text(const SweepReport& w, const std::vector<std::string>& pngs) {
  const coupling::SweepResult& s = *w.result;
  const core::UnitSystem& u = w.units;
  const std::vector<double>& x = w.values;
  const std::string unit = w.parameter_unit;
  const double reference = u.from_si(s.reference.value, s.quantity);
  std::string out = fmt::format("framedyn sweep: {} ({}), {} over {} values, units {}\n", w.study_file, w.study_name, s.parameter, x.size(), u.name());
  out += fmt::format("reference: {} = {:g} {} (the study file's value{})\n\n", s.parameter, reference, unit,
                     s.reference_index >= 0 ? "" : ", run on its own");
  const std::string lu = u.label(Quantity::length), fu = u.label(Quantity::force);
  // Peaks over the whole run, then the averages of the shaker cycles' peaks (the thesis's Figure 10).
  out += fmt::format("{:>14s}  {:>12s} {:>8s}  {:>12s} {:>8s}  {:>12s} {:>8s}  {:>12s} {:>8s}  {:>12s} {:>8s}\n", s.parameter, "pp [" + lu + "]", "change",
                     "cutting [" + fu + "]", "change", "backing [" + fu + "]", "change", "avg cut [" + fu + "]", "change", "avg back [" + fu + "]", "change");
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    std::string line = fmt::format("{:14.6g}", x[i]);
    for (const Figure& f : figures()) {
      const std::optional<double>& v = s.points[i].*f.member;
      const std::optional<double> c = coupling::relative_change(v, s.reference.*f.member);
      line += v ? fmt::format("  {:12.5g}", u.from_si(*v, f.quantity)) : fmt::format("  {:>12s}", "-");
      line += c ? fmt::format(" {:7.2f}%", 100.0 * *c) : fmt::format(" {:>8s}", "-");
    }
    out += line + "\n";
  }
  out += "\nspread (max - min) / reference:";
  for (const Figure& f : figures()) {
    const std::optional<double> v = spread(s, f);
    out += fmt::format(" {} {}", f.key, v ? fmt::format("{:.3g} %", 100.0 * *v) : std::string("-"));
  }
  out += "\n";
  if (!pngs.empty()) {
    std::string list;
    for (const std::string& p : pngs) list += (list.empty() ? "" : ", ") + p;
    out += fmt::format("figures: {}\n", list);
  }
  return out;
}

}  // namespace framedyn::report
