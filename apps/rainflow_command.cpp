// `framedyn rainflow SERIES.csv [--column NAME] [--sn CURVE] [--repeat] --out DIR`: rainflow
// counting (ASTM E1049-85) of one stress history from a CSV file and, with an S-N curve, its
// Palmgren-Miner damage and equivalent range at 2e6 cycles (fatigue/, docs/theory/fatigue.md).
// Reads with fatigue::read_stress_series (the unit from the column's header), counts, writes
// DIR/cycles.csv and DIR/summary.json with report/rainflow_outputs, prints the totals.
#include <fmt/format.h>

#include <filesystem>
#include <stdexcept>

#include "apps/command_line.h"
#include "apps/commands.h"
#include "apps/progress.h"
#include "core/error.h"
#include "core/number_text.h"
#include "core/results_folder.h"
#include "fatigue/counted_history.h"
#include "fatigue/mean_stress.h"
#include "fatigue/sn_curve.h"
#include "fatigue/stress_series.h"
#include "report/rainflow_outputs.h"

namespace framedyn::apps {

namespace {

struct RainflowOptions {
  std::string series, column, sn, out;
  bool repeat = false;
  ProgressFlags progress;
};

int run_rainflow(const RainflowOptions& opt) {
  Progress progress(opt.progress);
  std::optional<fatigue::SnCurve> curve;
  if (!opt.sn.empty()) {
    try {
      curve = fatigue::sn_curve_from_name(opt.sn);
    } catch (const std::invalid_argument&) {
      throw core::InputError(command_line("--sn"), fatigue::sn_curve_names(), "'" + opt.sn + "'");
    }
  }
  const std::string out_dir = opt.out.empty() ? std::filesystem::path(opt.series).stem().string() + "_rainflow" : opt.out;
  core::check_results_target(out_dir, {opt.series});  // before the run: a refusal costs no time
  progress.stage("reading " + opt.series);
  const fatigue::StressSeries s = fatigue::read_stress_series(opt.series, opt.column);

  progress.stage("counting cycles");
  report::RainflowRun run;
  run.series_file = opt.series;
  run.column = s.header;
  run.unit = s.unit;
  fatigue::CountedHistory counted =
      fatigue::count_history(s.values, opt.repeat ? fatigue::Residue::repeated_block : fatigue::Residue::half_cycles, curve, s.pascals_per_unit);
  run.summary = counted.summary;
  run.cycles = std::move(counted.cycles);
  if (curve) {
    run.curve = curve;
    run.mean_stress = fatigue::MeanStressCorrection::none().describe();
    run.damage = *counted.damage;
    run.equivalent_range = counted.equivalent_range;
  }

  progress.stage("writing results");
  core::ResultsFolder folder(out_dir, {opt.series});
  report::write_rainflow_results(run, folder);
  folder.commit();
  progress.done();
  if (progress.quiet()) {  // -q: errors only, and the results folder on stdout
    fmt::print("results in {}/\n", out_dir);
    return 0;
  }
  fmt::print("framedyn rainflow: {} column '{}' ({} samples, {} turning points)\n", opt.series, s.header, run.summary.samples, run.summary.turning_points);
  fmt::print("{} cycles, max range {} {}; residue: {}\n", core::format_number(run.summary.cycles), core::format_number(run.summary.max_range), s.unit,
             fatigue::describe(run.summary.residue));
  if (curve) {
    fmt::print("S-N curve {} ({}); mean stress: {}\n", curve->name(), curve->code(), run.mean_stress);
    fmt::print("Miner damage {}; equivalent range at 2e6 cycles {}\n", core::format_number(run.damage),
               run.equivalent_range ? core::format_number(*run.equivalent_range) + " " + s.unit : std::string("none (damage below the cut-off's)"));
  }
  fmt::print("results in {}/ (summary.json, cycles.csv)\n", out_dir);
  return 0;
}

}  // namespace

void add_rainflow_command(CLI::App& app, std::function<int()>& run) {
  auto opt = std::make_shared<RainflowOptions>();
  CLI::App* cmd = app.add_subcommand("rainflow", "Rainflow cycle counting (ASTM E1049-85) and Miner damage of one stress history");
  cmd->add_option("series", opt->series, "Stress history, CSV with a header 'name [unit]' per column (unit: Pa, kPa, MPa, GPa, N/mm^2, psi, ksi; "
                                          "an optional 'time [s]' column must increase)")
      ->required();
  cmd->add_option("--column,-c", opt->column, "The stress column to count, by name or header (default: the only column that is not time)");
  cmd->add_option("--sn", opt->sn, "S-N curve for the damage: " + fatigue::sn_curve_names());
  cmd->add_flag("--repeat", opt->repeat, "Count the history as a block repeated for ever (closed at its absolute maximum; no half cycles)");
  cmd->add_option("--out,-o", opt->out, "Results folder (default: <series name>_rainflow)");
  opt->progress.add_to(*cmd);
  cmd->callback([opt, &run]() { run = [opt]() { return run_rainflow(*opt); }; });
}

}  // namespace framedyn::apps
