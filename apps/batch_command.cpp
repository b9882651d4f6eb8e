// `framedyn batch DESIGN.yaml --out DIR`: a design study (batch/): every sample
// of the design run in memory on threads (or MPI ranks: `mpirun -n N framedyn
// batch ...`, batch/mpi_engine.cpp), DIR/runs.csv and DIR/summary.json written
// through core/results_folder, checkpointed so that --resume continues a batch
// that was stopped; with --figures, scatter and main-effect figures
// (batch/batch_figures.h). Here the options, the progress and the console's lines.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <filesystem>
#include <thread>

#include "apps/command_line.h"
#include "apps/commands.h"
#include "apps/progress.h"
#include "batch/batch_figures.h"
#include "batch/design.h"
#include "batch/engine.h"
#include "batch/mpi_engine.h"
#include "core/error.h"
#include "report/plot.h"

namespace framedyn::apps {

namespace {

struct BatchCommandOptions {
  std::string design, out;
  int threads = 0;  // 0: one per core
  bool resume = false, keep_runs = false, rebuild_models = false, figures = false;
  int checkpoint = 0;
  ProgressFlags progress;
};

int run_batch_command(const BatchCommandOptions& opt) {
  if (opt.threads < 0) throw core::InputError(command_line("--threads"), "at least 1 thread (or 0: one per core)", fmt::format("{}", opt.threads));
  if (opt.checkpoint < 0) throw core::InputError(command_line("--checkpoint"), "a number of runs >= 1 (or 0: every 5 % of the runs)", fmt::format("{}", opt.checkpoint));
  if (opt.figures && !report::gnuplot_available())
    throw report::PlotError("framedyn batch --figures draws figures with gnuplot (Debian package gnuplot-nox, installed by ./install-deps.sh), and 'gnuplot' cannot be run; "
                            "install it or leave out --figures");
  Progress progress(opt.progress);
  batch::BatchOptions bo;
  bo.out = opt.out.empty() ? std::filesystem::path(opt.design).stem().string() + "_results" : opt.out;
  if (opt.resume && !std::filesystem::exists(bo.out / "runs.csv"))
    throw core::InputError(command_line("--resume"), "the results folder of an earlier run of this design (with runs.csv)",
                           fmt::format("'{}' without runs.csv", bo.out.string()));
  bo.threads = opt.threads > 0 ? opt.threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  bo.resume = opt.resume;
  bo.keep_runs = opt.keep_runs;
  bo.reuse_models = !opt.rebuild_models;
  bo.checkpoint_runs = static_cast<std::size_t>(opt.checkpoint);
  progress.stage("reading " + opt.design);
  const batch::BatchDesign design = batch::read_batch_design(opt.design);
  progress.stage("runs");
  bo.progress = [&](std::size_t done, std::size_t total) { progress.step(static_cast<long long>(done), static_cast<long long>(total)); };
  bo.stage = [&](const std::string& what) { progress.stage(what); };
  batch::BatchCounts c;
  if (batch::mpi_world_size() > 1) {
    c = batch::run_batch_mpi(design, bo);
    if (!batch::mpi_is_manager()) return 0;  // workers print nothing
  } else {
    c = batch::run_batch(design, bo);
  }
  std::vector<std::string> figures;
  if (opt.figures) {
    progress.stage("figures");
    figures = batch::write_batch_figures(design, bo);
  }
  progress.done();
  if (progress.quiet()) {
    fmt::print("results in {}/\n", bo.out.string());
    return 0;
  }
  fmt::print("framedyn batch: {} ({} runs of {}: {} done, {} failed{})\n", opt.design, c.total, design.study_file.string(), c.done, c.failed,
             c.skipped ? fmt::format(", {} read back by --resume", c.skipped) : std::string());
  if (!figures.empty()) fmt::print("figures: {}\n", fmt::join(figures, ", "));
  fmt::print("\nresults in {}/\n", bo.out.string());
  return c.failed == c.total && c.total > 0 ? 3 : 0;
}

}  // namespace

void add_batch_command(CLI::App& app, std::function<int()>& run) {
  auto opt = std::make_shared<BatchCommandOptions>();
  CLI::App* cmd = app.add_subcommand("batch", "Run a design study: a study's parameters sampled, outputs collected (threads or MPI)");
  cmd->add_option("design", opt->design, "Design file (.yaml, framedyn_batch: 1)")->required();
  cmd->add_option("--out,-o", opt->out, "Results folder (default: <design name>_results)");
  cmd->add_option("--threads,-j", opt->threads, "Runs at the same time on this machine (0: one per core); results do not depend on it")->capture_default_str();
  cmd->add_flag("--resume", opt->resume, "Continue the batch in --out: skip the runs its runs.csv holds");
  cmd->add_flag("--keep-runs", opt->keep_runs, "Also write each run's own results folder (<out>_runs/run_NNNNNN)");
  cmd->add_flag("--rebuild-models", opt->rebuild_models,
                "Build every run's frame model anew instead of once per worker (the same results; for timing the reuse)");
  cmd->add_flag("--figures", opt->figures, "Also draw scatter plots of each output against each parameter and, for a grid, main-effect plots (PNG, gnuplot)");
  cmd->add_option("--checkpoint", opt->checkpoint, "Write the results folder every N runs (0: every 5 % of the runs)")->capture_default_str();
  opt->progress.add_to(*cmd);
  cmd->callback([opt, &run]() { run = [opt]() { return run_batch_command(*opt); }; });
}

}  // namespace framedyn::apps
