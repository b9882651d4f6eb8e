// `framedyn run STUDY.yaml`: runs a study file through report::run_study_file
// (report/study_run.h: rigid_2d, rigid_3d and the pipeline, duty_cycle), which
// writes the results folder; here the options, the progress and the console's
// lines. Vehicle studies, 2-D and 3-D (one console): natural frequencies with
// their dominant coordinates, the calibration, the blade's motion and force
// (2-D), the frame's peaks, static state, hot spot and fatigue lines (the
// pipeline, 3-D); duty cycles: duty_cycle_command.cpp.
#include <fmt/format.h>

#include <filesystem>

#include "apps/command_line.h"
#include "apps/commands.h"
#include "core/error.h"
#include "apps/progress.h"
#include "report/calibration_output.h"
#include "report/run_outputs.h"
#include "report/study_run.h"
#include "report/study_run_details.h"
#include "apps/duty_cycle_command.h"

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


// The console of a vehicle study's run (rigid_2d, rigid_3d and the pipeline): the modes with their
// dominant coordinates, the calibration, the blade's motion and forces (the same lines in 2-D and 3-D),
// the frame's lines (the pipeline), the figures.
void print_vehicle_run(const std::string& study_file, const report::StudyRun& run, bool figures) {
  const coupling::RigidStudy& study = *run.details->study;
  const coupling::RigidResults& r = *run.details->results;
  const core::UnitSystem& u = study.units;
  const double lf = 1.0 / u.to_si_factor(Quantity::length), ff = 1.0 / u.to_si_factor(Quantity::force);
  fmt::print("framedyn run: {} ({}, {}{} coordinates, units {})\n", study_file, study.name, study.dimensions() == 3 ? "3-D, " : "",
             r.coordinates.size(), u.name());
  if (!r.modes.empty()) {
    fmt::print("\n mode  frequency [Hz]  dominant\n");
    for (std::size_t i = 0; i < r.modes.size(); ++i) fmt::print("{:5d}  {:14.4f}  {}\n", i + 1, r.modes[i].frequency_hz, r.modes[i].dominant);
  }
  if (r.calibration && study.calibration) report::print_calibration(*study.calibration, *r.calibration);
  if (r.plow_vertical_peak_to_peak) {
    fmt::print("\nblade vertical motion, average peak to peak: {:.4g} {}\n", *r.plow_vertical_peak_to_peak * lf, u.label(Quantity::length));
    fmt::print("peak cutting force {:.5g} {}, peak backing force {:.5g} {}\n", r.peak_cutting_force.value_or(0) * ff, u.label(Quantity::force),
               r.peak_backing_force.value_or(0) * ff, u.label(Quantity::force));
    fmt::print("average of the shaker cycles' peaks: cutting {:.5g} {}, backing {:.5g} {}\n", r.average_peak_cutting_force.value_or(0) * ff,
               u.label(Quantity::force), r.average_peak_backing_force.value_or(0) * ff, u.label(Quantity::force));
  }
  if (run.details->frame) {
    const coupling::FrameStudyResults& f = *run.details->frame;
    fmt::print("\nframe ({}): {} nodes, {} beam elements, {} elastic modes used, lowest {:.2f} Hz; {} output times in {:.3f} s\n",
               study.frame_response->mesh.filename().string(), f.model.nodes.size(), f.model.beams.size(), f.frequencies_hz.size(),
               f.frequencies_hz.size() > 0 ? f.frequencies_hz(0) : 0.0, f.response.times.size(), f.wall_seconds);
    for (const coupling::RailRecovery& rail : f.rails)
      fmt::print("{}: peak bending moment {:.5g} {} at X = {:.4g} {}, t = {:.4f} s; peak normal stress {:.5g} {} ({:.0f} % from bending)\n",
                 rail.spec.name, u.from_si(rail.peak_bending_moment.value, Quantity::moment), u.label(Quantity::moment),
                 rail.peak_bending_moment.point.x() * lf, u.label(Quantity::length), rail.peak_bending_moment.time,
                 u.from_si(rail.peak_normal_stress.value, Quantity::stress), u.label(Quantity::stress), 100.0 * rail.bending_share);
    if (f.static_state) {
      const coupling::FrameStaticState& st = *f.static_state;
      fmt::print("static state (gravity and the static loads): peak normal stress {:.5g} {} on {} at X = {:.4g} {}; balance residual {:.1e} (force), "
                 "{:.1e} (moment)\n",
                 u.from_si(st.peak_normal_stress.value, Quantity::stress), u.label(Quantity::stress), st.peak_output,
                 st.peak_normal_stress.point.x() * lf, u.label(Quantity::length), st.force_residual, st.moment_residual);
      for (const coupling::RailRecovery& rail : f.rails)
        fmt::print("{}: peak total (static + dynamic) normal stress {:.5g} {} at X = {:.4g} {}, t = {:.4f} s\n", rail.spec.name,
                   u.from_si(rail.peak_total_normal_stress.value, Quantity::stress), u.label(Quantity::stress),
                   rail.peak_total_normal_stress.point.x() * lf, u.label(Quantity::length), rail.peak_total_normal_stress.time);
    }
    report::print_hot_spot_line(f, u);
    report::print_fatigue_line(f, *study.frame_response);
  }
  if (figures) fmt::print("\nfigures: {}\n", run.figures.empty() ? std::string("none (the study has no response)") : fmt::format("{}", fmt::join(run.figures, ", ")));
}

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
  if (run.model == "duty_cycle") return print_duty_cycle_run(opt.study, run, opt.figures, out_dir);  // issue 18
  print_vehicle_run(opt.study, run, opt.figures);
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
