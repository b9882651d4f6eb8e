// `framedyn random MESH.inp --psd FILE.csv --damping-ratio Z`: the response
// to the mesh's loads scaled by one random factor with the given PSD (all
// loads fully correlated), by mode superposition with a static correction
// (fem/random_response.h). Parses the options, solves, writes the results with
// report/frequency_response_outputs (DIR/summary.json, DIR/response_psd.csv:
// PSD of every DOF of the output nodes over the integration grid, DIR/rms.csv:
// RMS of every DOF of the output nodes, response_psd.png, stress_psd.png) and
// prints the peaks. `--inertia-relief`: a frame free to move rigidly, its
// elastic response relative to the rigid motion (fem::RandomOptions).
#include <fmt/format.h>


#include "apps/command_line.h"
#include "apps/commands.h"
#include "apps/frequency_domain_input.h"
#include "report/response_figures.h"
#include "core/error.h"
#include "core/results_folder.h"
#include "fem/random_response.h"
#include "report/frequency_response_outputs.h"

namespace framedyn::apps {

namespace {

using core::Quantity;

struct RandomCommandOptions {
  FrequencyDomainOptions common;
  std::string psd;
  bool inertia_relief = false;
};

int run_random(const RandomCommandOptions& opt) {
  if (opt.common.figures) report::require_gnuplot();
  Progress progress(opt.common.progress);
  const fem::LoadPsd psd = fem::read_load_psd(opt.psd);  // before the modes: a bad file fails at once
  const FrequencyDomainFrame f = prepare_frequency_domain(opt.common, "random", progress);
  const fem::FrameModel& model = *f.model;
  const core::UnitSystem& u = model.units;
  const int free_rigid = f.frame->rigid_count();
  if (free_rigid > 0 && !opt.inertia_relief)
    throw core::InputError({opt.common.mesh.path, 0, "*BOUNDARY"},
                           "supports that hold the frame against every rigid motion (a frame free to move as a rigid body has no "
                           "stationary random response; ask for --inertia-relief for the elastic response relative to its rigid motion)",
                           f.frame->free_free() ? std::string("none")
                                                : fmt::format("supports that leave {} rigid motion{} free", free_rigid, free_rigid == 1 ? "" : "s"));
  if (opt.inertia_relief && free_rigid == 0)
    throw nothing_to_relieve(opt.common.mesh.path);

  fem::RandomOptions ro;
  ro.response = f.response;
  ro.inertia_relief = opt.inertia_relief;
  for (int n : f.output_nodes)
    for (int d = 0; d < fem::kDofsPerNode; ++d) ro.output_dofs.push_back(fem::kDofsPerNode * n + d);
  progress.stage(fmt::format("random response over {} to {} Hz ({} modes)", psd.lowest(), psd.highest(), f.basis.eigenvalues.size()));
  const fem::RandomResult r = fem::random_response(*f.frame, f.basis, f.load, psd, ro);

  progress.stage("writing results");
  const std::string out_dir = opt.common.out_dir();
  core::ResultsFolder folder(out_dir);
  report::FrequencyResponseRun run{opt.common.mesh.path, opt.common.damping_ratio, opt.common.output_set, opt.psd, opt.common.figures, f.output_nodes};
  run.step = f.step;
  const std::vector<std::string> figures = report::write_random_results(model, r, psd, f.modes, run, folder, progress.callback());
  folder.commit();
  progress.done();
  if (progress.quiet()) {  // -q: errors only, and the results folder on stdout
    fmt::print("results in {}/\n", out_dir);
    return 0;
  }

  const double lf = 1.0 / u.to_si_factor(Quantity::length), sf = 1.0 / u.to_si_factor(Quantity::stress);
  const std::string L = u.label(Quantity::length), S = u.label(Quantity::stress);
  const std::string L2 = u.label(Quantity::translation_psd), S2 = u.label(Quantity::stress_psd);
  const report::RandomPeaks p = report::random_peaks(model, r);
  fmt::print("framedyn random: {} ({} nodes, {} beam elements, {} free DOFs, units {})\n", opt.common.mesh.path, model.nodes.size(), model.beams.size(),
             f.modes.free_dofs, u.name());
  if (f.step > 0) fmt::print("loads and supports of step {} ({})\n", f.step, model.steps[static_cast<std::size_t>(f.step - 1)].procedure);
  fmt::print("load PSD {} from {:.6g} to {:.6g} Hz (load factor RMS {:.6g}); {} modes up to {:.6g} Hz, zeta = {}, static correction {}; {} grid points\n",
             opt.psd, psd.lowest(), psd.highest(), p.load_factor_rms, r.modes_used, f.modes.modes.back().frequency_hz, opt.common.damping_ratio,
             r.static_correction ? "on" : "off", r.frequencies_hz.size());
  if (r.inertia_relief)
    fmt::print("inertia relief: {} free rigid motions take the loads' unbalanced part; displacements are the elastic part\n", r.rigid_body_modes);
  fmt::print("max displacement RMS {:.6g} {} at node {} ({})\n", r.max_displacement_rms * lf, L, p.rms_node, p.rms_dof);
  fmt::print("max displacement PSD {:.6g} {} at node {} ({}) at {:.6g} Hz\n", r.max_displacement_psd * lf * lf, L2, p.psd_node, p.psd_dof, p.psd_frequency_hz);
  if (p.has_stress) {
    fmt::print("max fiber stress RMS {:.6g} {} in element {}\n", r.max_stress_rms * sf, S, r.max_stress_rms_point.element_id);
    fmt::print("max fiber stress PSD {:.6g} {} in element {} at {:.6g} Hz\n", r.max_stress_psd * sf * sf, S2, r.max_stress_psd_point.element_id, p.stress_frequency_hz);
  }
  fmt::print("results in {}/ (summary.json, response_psd.csv, rms.csv{})\n", out_dir, figures.empty() ? "" : ", " + fmt::format("{}", fmt::join(figures, ", ")));
  return 0;
}

}  // namespace

void add_random_command(CLI::App& app, std::function<int()>& run) {
  auto opt = std::make_shared<RandomCommandOptions>();
  CLI::App* cmd = app.add_subcommand("random", "Random response (PSD and RMS) to the mesh's loads scaled by a load PSD");
  cmd->add_option("--psd", opt->psd, "Load PSD, CSV with columns 'frequency [Hz],psd [1/Hz]' (one-sided; interpolated log-log)")->required();
  cmd->add_flag("--inertia-relief", opt->inertia_relief,
                "A frame free to move rigidly: the elastic response relative to its rigid motion, the loads' unbalanced part taken by "
                "that motion's inertia");
  opt->common.add_to(*cmd, "random");
  cmd->callback([opt, &run]() { run = [opt]() { return run_random(*opt); }; });
}

}  // namespace framedyn::apps
