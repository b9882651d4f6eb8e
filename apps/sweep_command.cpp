// `framedyn sweep STUDY.yaml --parameter KEY --values v1,v2,...`: runs a study
// once per value of one of its numbers, named by key path (a one-parameter
// design study on the batch engine: batch/sweep_runs.h; 2-D and 3-D) and writes
// DIR/sweep.csv, DIR/summary.json and PNG figures: blade amplitude against the
// parameter (thesis Figure 9), peak cutting and backing force (Figure 10), the
// relative change of each against the run at the study file's value, and the
// natural frequencies. The outputs are assembled in report/sweep_outputs.h;
// here the options, the progress and the console.
#include <fmt/format.h>

#include <algorithm>
#include <filesystem>

#include "apps/command_line.h"
#include "apps/commands.h"
#include "apps/progress.h"
#include "batch/sweep_runs.h"
#include "core/error.h"
#include "core/results_folder.h"
#include "report/plot.h"
#include "report/sweep_outputs.h"

namespace framedyn::apps {

namespace {

struct SweepOptions {
  std::string study;
  std::string parameter;
  std::vector<double> values;
  std::string out;
  int jobs = 2;
  bool figures = true;
  ProgressFlags progress;
};

int run_sweep(const SweepOptions& opt) {
  Progress progress(opt.progress);
  if (opt.figures && !report::gnuplot_available())
    throw report::PlotError("framedyn sweep draws figures with gnuplot (Debian package gnuplot-nox, installed by ./install-deps.sh), and 'gnuplot' cannot be run; "
                          "install it or give --no-figures");
  if (opt.jobs < 1) throw core::InputError(command_line("--jobs"), "at least 1 run at a time", fmt::format("{}", opt.jobs));
  const std::string out_dir =
      opt.out.empty() ? std::filesystem::path(opt.study).stem().string() + "_sweep_" + opt.parameter : opt.out;
  core::check_results_target(out_dir, {opt.study});  // before the run: a refusal costs no time
  progress.stage("reading " + opt.study);  // then one line per run
  batch::OneParameterSweep request{opt.study, opt.parameter, opt.values, opt.jobs, progress.callback()};
  const batch::OneParameterSweepResult r = batch::run_one_parameter_sweep(request);

  progress.stage("writing results");
  core::ResultsFolder folder(out_dir, {opt.study});
  const report::SweepReport w{opt.study, r.study_name, r.units, &r.result, opt.values, r.parameter_unit, opt.jobs};
  folder.write_text("sweep.csv", report::sweep_csv(w));
  std::vector<std::string> pngs;
  if (opt.figures) {
    progress.stage("figures");
    pngs = report::write_sweep_figures(w, folder);
  }
  folder.write_text("summary.json", report::sweep_summary(w, pngs).dump(2) + "\n");
  folder.commit();
  progress.done();
  if (progress.quiet()) {  // -q: errors only, and the results folder on stdout
    fmt::print("results in {}/\n", out_dir);
    return 0;
  }
  fmt::print("{}", report::sweep_console_text(w, pngs));
  fmt::print("\nresults in {}/\n", out_dir);
  return 0;
}

}  // namespace

void add_sweep_command(CLI::App& app, std::function<int()>& run) {
  auto opt = std::make_shared<SweepOptions>();
  CLI::App* cmd = app.add_subcommand("sweep", "Run a study once per value of one of its numbers (thesis Figures 9 and 10)");
  cmd->add_option("study", opt->study, "Study file (.yaml)")->required();
  cmd->add_option("--parameter,-p", opt->parameter, "Key path of the number to vary, e.g. soil.damping, soil.stiffness, plow.shaker.frequency_hz")->required();
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
