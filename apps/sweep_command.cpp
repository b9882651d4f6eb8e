// `framedyn sweep STUDY.yaml --parameter NAME --values v1,v2,...`: runs a study
// once per value of a machine parameter (coupling/parameter_sweep.h) and writes
// DIR/sweep.csv, DIR/summary.json and PNG figures: blade amplitude against the
// parameter (thesis Figure 9), peak cutting and backing force (Figure 10), the
// relative change of each against the run at the study file's value, and the
// natural frequencies.
#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <thread>

#include "apps/command_line.h"
#include "apps/commands.h"
#include "apps/progress.h"
#include "report/csv_writer.h"
#include "report/json_quantity.h"
#include "core/error.h"
#include "report/plot.h"
#include "core/results_folder.h"
#include "coupling/parameter_sweep.h"
#include "coupling/rigid_study.h"

namespace framedyn::apps {

namespace {

using core::Quantity;

struct SweepOptions {
  std::string study;
  std::string parameter;
  std::vector<double> values;
  std::string out;
  int jobs = 2;
  bool figures = true;
  ProgressFlags progress;
};

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

std::vector<std::string> write_figures(const coupling::RigidStudy& study, const coupling::SweepResult& s, const std::vector<double>& x,
                                       const std::string& x_unit, const core::ResultsFolder& folder) {
  const core::UnitSystem& u = study.units;
  std::vector<std::string> written;
  const auto series_of = [&](const Figure& f, bool relative) {
    report::PlotSeries ps{f.label, {}, {}};
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
    report::LinePlot p;
    p.title = title + ": " + study.name;
    p.x_label = s.parameter;
    p.x_unit = x_unit;
    p.y_label = y_label;
    p.y_unit = y_unit;
    p.mark_points = true;
    return p;
  };
  const auto write = [&](report::LinePlot& p, const std::string& file) {
    p.series.erase(std::remove_if(p.series.begin(), p.series.end(), [](const report::PlotSeries& ps) { return ps.x.empty(); }), p.series.end());
    if (p.series.empty()) return;
    report::write_png(p, folder.path_of(file));
    written.push_back(file);
  };
  const std::vector<Figure>& f = figures();
  report::LinePlot amplitude = base("Plow blade amplitude vs " + s.parameter + " (thesis Figure 9)", "blade vertical motion, average peak to peak", u.label(Quantity::length));
  amplitude.series.push_back(series_of(f[0], false));
  write(amplitude, "amplitude.png");
  report::LinePlot forces = base("Peak plow forces vs " + s.parameter + " (thesis Figure 10)", "peak plow force", u.label(Quantity::force));
  forces.series.push_back(series_of(f[1], false));
  forces.series.push_back(series_of(f[2], false));
  forces.series.push_back(series_of(f[3], false));
  forces.series.push_back(series_of(f[4], false));
  write(forces, "peak_forces.png");
  const double ref = u.from_si(s.reference.value, s.quantity);
  report::LinePlot change = base(fmt::format("Change against the run at {} = {:g} {}", s.parameter, ref, x_unit), "relative change", u.label(Quantity::percent));
  for (const Figure& fig : f) change.series.push_back(series_of(fig, true));
  write(change, "relative_change.png");
  report::LinePlot freq = base("Natural frequencies vs " + s.parameter, "natural frequency", u.label(Quantity::frequency));
  const std::size_t modes = s.points.empty() ? 0 : s.points.front().frequencies_hz.size();
  for (std::size_t m = 0; m < modes; ++m) {
    report::PlotSeries ps{fmt::format("mode {} ({})", m + 1, s.points.front().dominant[m]), {}, {}};
    for (std::size_t i = 0; i < s.points.size(); ++i)
      if (m < s.points[i].frequencies_hz.size()) ps.x.push_back(x[i]), ps.y.push_back(s.points[i].frequencies_hz[m]);
    freq.series.push_back(std::move(ps));
  }
  write(freq, "frequencies.png");
  return written;
}

int run_sweep(const SweepOptions& opt) {
  Progress progress(opt.progress);
  if (opt.figures && !report::gnuplot_available())
    throw report::PlotError("framedyn sweep draws figures with gnuplot (Debian package gnuplot-nox, installed by ./install-deps.sh), and 'gnuplot' cannot be run; "
                          "install it or give --no-figures");
  if (opt.jobs < 1) throw core::InputError(command_line("--jobs"), "at least 1 run at a time", fmt::format("{}", opt.jobs));
  const std::string out_dir =
      opt.out.empty() ? std::filesystem::path(opt.study).stem().string() + "_sweep_" + opt.parameter : opt.out;
  core::check_results_target(out_dir, {opt.study});  // before the run: a refusal costs no time
  progress.stage("reading " + opt.study);
  const coupling::RigidStudy study = coupling::read_rigid_study(opt.study);
  const core::UnitSystem& u = study.units;
  Quantity q;
  try {
    q = coupling::parameter_quantity(study.machine, opt.parameter);
  } catch (const std::invalid_argument&) {
    std::string known;
    for (const std::string& k : coupling::sweepable_parameters()) known += (known.empty() ? "" : ", ") + k;
    throw core::InputError({opt.study, 0, "--parameter"}, "one of " + known, "'" + opt.parameter + "'");
  }
  std::vector<double> values_si;
  for (double v : opt.values) values_si.push_back(u.to_si(v, q));
  const coupling::SweepResult s = coupling::run_parameter_sweep(study, opt.parameter, values_si, opt.jobs, progress.callback());

  progress.stage("writing results");
  core::ResultsFolder folder(out_dir, {opt.study});
  const std::string unit = u.label(q), hz = u.label(Quantity::frequency);
  // The values as given on the command line (the study's units), for the CSV, JSON and figures.
  const std::vector<double>& x = opt.values;
  const double reference = u.from_si(s.reference.value, q);

  std::vector<std::string> h = {report::column(opt.parameter, unit)};
  for (const Figure& f : figures()) h.push_back(report::column(f.key, u.label(f.quantity)));
  for (const Figure& f : figures()) h.push_back(report::column(f.key + "_change", u.label(Quantity::percent)));
  const std::size_t modes = s.points.front().frequencies_hz.size();
  for (std::size_t m = 0; m < modes; ++m) {
    h.push_back(report::column(fmt::format("frequency_{}", m + 1), u.label(Quantity::frequency)));
    h.push_back(fmt::format("dominant_{}", m + 1));
  }
  report::CsvTable csv(h);
  nlohmann::ordered_json runs = nlohmann::ordered_json::array();
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    const coupling::SweepPoint& p = s.points[i];
    csv.row().add(x[i]);
    nlohmann::ordered_json jr;
    jr["parameter"] = report::quantity(x[i], unit);
    for (const Figure& f : figures()) {
      const std::optional<double>& v = p.*f.member;
      if (v) csv.add(u.from_si(*v, f.quantity));
      else csv.add(std::string());
      if (v) jr[f.key] = {{"value", u.from_si(*v, f.quantity)}, {"unit", u.label(f.quantity)}};
    }
    nlohmann::ordered_json change;
    for (const Figure& f : figures()) {
      const std::optional<double> c = coupling::relative_change(p.*f.member, s.reference.*f.member);
      if (c) csv.add(100.0 * *c);
      else csv.add(std::string());
      set_if(change, f.key, c);
    }
    jr["relative_change"] = change;
    for (std::size_t m = 0; m < modes; ++m) {
      if (m < p.frequencies_hz.size()) csv.add(p.frequencies_hz[m]).add(p.dominant[m]);
      else csv.add(std::string()).add(std::string());
    }
    jr["frequencies"] = report::quantity(p.frequencies_hz, hz);
    jr["dominant"] = p.dominant;
    runs.push_back(jr);
  }
  folder.write_text("sweep.csv", csv.str());

  std::vector<std::string> pngs;
  if (opt.figures) {
    progress.stage("figures");
    pngs = write_figures(study, s, x, unit, folder);
  }

  nlohmann::ordered_json j;
  j["framedyn"] = {{"version", FRAMEDYN_VERSION}, {"command", "sweep"}};
  j["input"] = {{"study", opt.study}, {"name", study.name}, {"units", u.name()}};
  nlohmann::ordered_json sw;
  sw["parameter"] = opt.parameter;
  sw["values"] = report::quantity(x, unit);
  sw["jobs"] = opt.jobs;
  nlohmann::ordered_json ref;
  ref["parameter"] = report::quantity(reference, unit);
  ref["in_values"] = s.reference_index >= 0;
  for (const Figure& f : figures()) {
    const std::optional<double>& v = s.reference.*f.member;
    if (v) ref[f.key] = {{"value", u.from_si(*v, f.quantity)}, {"unit", u.label(f.quantity)}};
  }
  ref["frequencies"] = report::quantity(s.reference.frequencies_hz, hz);
  sw["reference"] = ref;
  sw["runs"] = runs;
  nlohmann::ordered_json sp;
  for (const Figure& f : figures()) set_if(sp, f.key, spread(s, f));
  sw["relative_spread"] = sp;
  sw["figures"] = pngs;
  j["sweep"] = sw;
  folder.write_text("summary.json", j.dump(2) + "\n");
  folder.commit();
  progress.done();
  if (progress.quiet()) {  // -q: errors only, and the results folder on stdout
    fmt::print("results in {}/\n", out_dir);
    return 0;
  }

  fmt::print("framedyn sweep: {} ({}), {} over {} values, units {}\n", opt.study, study.name, opt.parameter, x.size(), u.name());
  fmt::print("reference: {} = {:g} {} (the study file's value{})\n\n", opt.parameter, reference, unit,
             s.reference_index >= 0 ? "" : ", run on its own");
  const std::string lu = u.label(Quantity::length), fu = u.label(Quantity::force);
  // Peaks over the whole run, then the averages of the shaker cycles' peaks (the thesis's Figure 10).
  fmt::print("{:>14s}  {:>12s} {:>8s}  {:>12s} {:>8s}  {:>12s} {:>8s}  {:>12s} {:>8s}  {:>12s} {:>8s}\n", opt.parameter, "pp [" + lu + "]", "change",
             "cutting [" + fu + "]", "change", "backing [" + fu + "]", "change", "avg cut [" + fu + "]", "change", "avg back [" + fu + "]", "change");
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    std::string line = fmt::format("{:14.6g}", x[i]);
    for (const Figure& f : figures()) {
      const std::optional<double>& v = s.points[i].*f.member;
      const std::optional<double> c = coupling::relative_change(v, s.reference.*f.member);
      line += v ? fmt::format("  {:12.5g}", u.from_si(*v, f.quantity)) : fmt::format("  {:>12s}", "-");
      line += c ? fmt::format(" {:7.2f}%", 100.0 * *c) : fmt::format(" {:>8s}", "-");
    }
    fmt::print("{}\n", line);
  }
  fmt::print("\nspread (max - min) / reference:");
  for (const Figure& f : figures()) {
    const std::optional<double> v = spread(s, f);
    fmt::print(" {} {}", f.key, v ? fmt::format("{:.3g} %", 100.0 * *v) : std::string("-"));
  }
  fmt::print("\n");
  if (!pngs.empty()) {
    std::string list;
    for (const std::string& p : pngs) list += (list.empty() ? "" : ", ") + p;
    fmt::print("figures: {}\n", list);
  }
  fmt::print("\nresults in {}/\n", out_dir);
  return 0;
}

}  // namespace

void add_sweep_command(CLI::App& app, std::function<int()>& run) {
  auto opt = std::make_shared<SweepOptions>();
  CLI::App* cmd = app.add_subcommand("sweep", "Run a study once per value of a machine parameter (thesis Figures 9 and 10)");
  cmd->add_option("study", opt->study, "Study file (.yaml)")->required();
  cmd->add_option("--parameter,-p", opt->parameter, "Machine parameter to vary, e.g. soil.damping or soil.stiffness")->required();
  cmd->add_option("--values", opt->values, "Values in the study's units, comma-separated: 100,200,300")
      ->required()
      ->delimiter(',')
      ->check(number_check("numbers in the study's units", [](double) { return true; }, false));
  cmd->add_option("--out,-o", opt->out, "Results folder (default: <study name>_sweep_<parameter>)");
  cmd->add_option("--jobs,-j", opt->jobs, "Runs at the same time (threads); results do not depend on it")->capture_default_str();
  cmd->add_flag("!--no-figures", opt->figures, "Write no PNG figures (gnuplot not needed)");
  opt->progress.add_to(*cmd);
  cmd->callback([opt, &run]() { run = [opt]() { return run_sweep(*opt); }; });
}

}  // namespace framedyn::apps
