// `framedyn run STUDY.yaml`: runs a study file through report::run_study_file
// (report/study_run.h: rigid_2d, rigid_3d and the pipeline, duty_cycle), which
// writes the results folder; here the options, the progress and the console's
// lines. 2-D (model: rigid_2d): natural frequencies with their dominant
// coordinates and a forced response with recovered forces; 3-D: run_3d.cpp;
// duty cycles: duty_cycle_command.cpp.
#include <fmt/format.h>

#include <filesystem>

#include "apps/command_line.h"
#include "apps/commands.h"
#include "core/error.h"
#include "apps/progress.h"
#include "report/calibration_output.h"
#include "report/study_run.h"
#include "report/study_run_details.h"
#include "apps/duty_cycle_command.h"
#include "apps/run_3d.h"

namespace framedyn::apps {

namespace {

using core::Quantity;

struct RunOptions {
  std::string study;
  std::string out;
  bool figures = false;  // --figures: PNG figures (report/response_figures.cpp)
  int threads = 0;       // --threads: a duty cycle's scenarios at the same time (0: one per core)
  ProgressFlags progress;
};


int run_study(const RunOptions& opt) {
  Progress progress(opt.progress);
  const std::string out_dir = opt.out.empty() ? std::filesystem::path(opt.study).stem().string() + "_results" : opt.out;
  report::StudyRunOptions ro;
  ro.out = out_dir;
  ro.figures = opt.figures;
  if (opt.threads < 0) throw core::InputError(command_line("--threads"), "at least 1 thread (or 0: one per core)", fmt::format("{}", opt.threads));
  ro.threads = opt.threads;
  ro.stage = progress.callback();
  ro.step = progress.step_callback();
  ro.warning = print_warning;
  const report::StudyRun run = report::run_study_file(opt.study, ro);
  progress.done();
  if (progress.quiet()) {  // -q: errors only, and the results folder on stdout
    fmt::print("results in {}/\n", out_dir);
    return 0;
  }
  if (run.model == "rigid_3d") return print_run_3d(opt.study, run, opt.figures, out_dir);  // issue 4
  if (run.model == "duty_cycle") return print_duty_cycle_run(opt.study, run, opt.figures, out_dir);  // issue 18
  const coupling::RigidStudy& study = *run.details->study_2d;
  const coupling::RigidResults& r = *run.details->results_2d;
  const core::UnitSystem& u = study.units;
  const std::vector<std::string>& figures = run.figures;

  fmt::print("framedyn run: {} ({}, {} coordinates, units {})\n", opt.study, study.name, r.coordinates.size(), u.name());
  if (!r.modes.empty()) {
    fmt::print("\n mode  frequency [Hz]  dominant\n");
    for (std::size_t i = 0; i < r.modes.size(); ++i) fmt::print("{:5d}  {:14.4f}  {}\n", i + 1, r.modes[i].frequency_hz, r.modes[i].dominant);
  }
  if (r.calibration && study.calibration) report::print_calibration(*study.calibration, *r.calibration);
  if (r.plow_vertical_peak_to_peak) {
    const double lf = 1.0 / u.to_si_factor(Quantity::length), ff = 1.0 / u.to_si_factor(Quantity::force);
    fmt::print("\nblade vertical motion, average peak to peak: {:.4g} {}\n", *r.plow_vertical_peak_to_peak * lf, u.label(Quantity::length));
    fmt::print("peak cutting force {:.5g} {}, peak backing force {:.5g} {}\n", r.peak_cutting_force.value_or(0) * ff, u.label(Quantity::force),
               r.peak_backing_force.value_or(0) * ff, u.label(Quantity::force));
    fmt::print("average of the shaker cycles' peaks: cutting {:.5g} {}, backing {:.5g} {}\n", r.average_peak_cutting_force.value_or(0) * ff,
               u.label(Quantity::force), r.average_peak_backing_force.value_or(0) * ff, u.label(Quantity::force));
  }
  if (opt.figures) fmt::print("\nfigures: {}\n", figures.empty() ? std::string("none (the study has no response)") : fmt::format("{}", fmt::join(figures, ", ")));
  fmt::print("\nresults in {}/\n", out_dir);
  return 0;
}

}  // namespace

void add_run_command(CLI::App& app, std::function<int()>& run) {
  auto opt = std::make_shared<RunOptions>();
  CLI::App* cmd = app.add_subcommand("run", "Run a study file (rigid-body vehicle modes and forced response)");
  cmd->add_option("study", opt->study, "Study file (.yaml)")->required();
  cmd->add_option("--out,-o", opt->out, "Results folder (default: <study name>_results)");
  cmd->add_flag("--figures", opt->figures, "Also write PNG figures of the response (needs gnuplot)");
  cmd->add_option("--threads,-j", opt->threads, "Duty cycles: scenarios run at the same time (0: one per core); results do not depend on it")
      ->capture_default_str();
  opt->progress.add_to(*cmd);
  cmd->callback([opt, &run]() { run = [opt]() { return run_study(*opt); }; });
}

}  // namespace framedyn::apps
