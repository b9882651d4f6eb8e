// `framedyn static MESH.inp`: linear static response to the mesh's *CLOAD
// and *DLOAD loads and *BOUNDARY supports. Parses the options, solves
// (fem/static_analysis, fem/section_forces), writes the results with
// report/static_outputs (summary.json, displacements.csv, reactions.csv,
// section_forces.csv with fiber stresses, static.vtu) and prints the peaks.
#include <fmt/format.h>

#include <filesystem>

#include "apps/command_line.h"
#include "apps/commands.h"
#include "apps/mesh_input.h"
#include "apps/progress.h"
#include "core/error.h"
#include "core/results_folder.h"
#include "fem/partial_supports.h"
#include "fem/section_forces.h"
#include "fem/static_analysis.h"
#include "report/static_outputs.h"

namespace framedyn::apps {

namespace {

using core::Quantity;

struct StaticOptions {
  MeshInput mesh;
  std::string out;
  int stations = 3;
  bool inertia_relief = false;
  ProgressFlags progress;
};

int run_static(const StaticOptions& opt) {
  Progress progress(opt.progress);
  const std::string out_dir = opt.out.empty() ? std::filesystem::path(opt.mesh.path).stem().string() + "_static" : opt.out;
  core::check_results_target(out_dir, {opt.mesh.path});  // before the run: a refusal costs no time
  progress.stage("reading " + opt.mesh.path);
  const fem::FrameModel model = opt.mesh.load();
  const core::UnitSystem& u = model.units;
  // A deck with several static steps: one load case per step (docs/theory/fem.md section 18).
  std::vector<fem::FrameModel> cases;
  std::vector<int> step_numbers;
  for (fem::StaticLoadCase& c : fem::static_load_cases(model, opt.mesh.path)) cases.push_back(std::move(c.model)), step_numbers.push_back(c.step);
  const bool several = cases.size() > 1;
  fem::StaticOptions so;
  so.inertia_relief = opt.inertia_relief;
  std::vector<fem::StaticResult> results;
  try {
    results = fem::solve_static_cases(cases, progress.callback(), so);
  } catch (const fem::UnbalancedLoadError& e) {
    // Loads that do work on a rigid motion the supports leave free (docs/theory/fem.md, Eq. 19.1): the input's fault, named as such.
    throw core::InputError({opt.mesh.path, 0, model.loads.empty() ? "*DLOAD" : "*CLOAD"},
                           "loads that do no work on the rigid motions the supports leave free (add supports, balance the loads, or ask for "
                           "--inertia-relief)",
                           e.what());
  }
  if (opt.inertia_relief && results.front().free_rigid_motions == 0)
    throw nothing_to_relieve(opt.mesh.path);
  progress.stage("recovering section forces");
  std::vector<std::vector<fem::StationResult>> stations;
  for (std::size_t c = 0; c < cases.size(); ++c) stations.push_back(fem::recover_stations(cases[c], results[c].displacement, opt.stations));

  progress.stage("writing results");
  core::ResultsFolder folder(out_dir, {opt.mesh.path});
  for (std::size_t c = 0; c < cases.size(); ++c) {
    report::StaticRun run{opt.mesh.path, opt.stations};
    if (several) run.file_suffix = fmt::format("_step{}", step_numbers[c]), run.step = step_numbers[c];
    report::write_static_results(cases[c], results[c], stations[c], run, folder);
  }
  folder.commit();
  progress.done();
  if (progress.quiet()) {  // -q: errors only, and the results folder on stdout
    fmt::print("results in {}/\n", out_dir);
    return 0;
  }

  fmt::print("framedyn static: {} ({} nodes, {} beam elements, units {})\n", opt.mesh.path, model.nodes.size(), model.beams.size(), u.name());
  const std::string L = u.label(Quantity::length), F = u.label(Quantity::force), S = u.label(Quantity::stress);
  for (std::size_t c = 0; c < cases.size(); ++c) {
    const fem::StaticResult& r = results[c];
    if (several) fmt::print("step {}:\n", step_numbers[c]);
    const report::StaticPeaks p = report::static_peaks(cases[c], r, stations[c]);
    fmt::print("max displacement {:.6g} {} at node {}\n", p.max_displacement, L, p.max_displacement_node);
    fmt::print("peak fiber stress {:.6g} {} in element {}\n", p.peak_fiber_stress, S, p.peak_fiber_stress_element);
    fmt::print("applied force sum ({:.6g}, {:.6g}, {:.6g}) {}; reactions ({:.6g}, {:.6g}, {:.6g}) {}\n", p.applied_force_sum.x(), p.applied_force_sum.y(),
               p.applied_force_sum.z(), F, p.reaction_force_sum.x(), p.reaction_force_sum.y(), p.reaction_force_sum.z(), F);
    if (r.free_rigid_motions > 0)
      fmt::print("{} free rigid motion(s) ({}): {}\n", r.free_rigid_motions, r.free_motions,
                 r.inertia_relief ? "loads relieved by their inertia, elastic part shown"
                                  : "loads balanced on them; the displacement is defined up to that rigid motion");
  }
  if (several)
    fmt::print("results in {}/ (per step N: summary_stepN.json, displacements_stepN.csv, reactions_stepN.csv, section_forces_stepN.csv, static_stepN.vtu)\n", out_dir);
  else
    fmt::print("results in {}/ (summary.json, displacements.csv, reactions.csv, section_forces.csv, static.vtu)\n", out_dir);
  return 0;
}

}  // namespace

void add_static_command(CLI::App& app, std::function<int()>& run) {
  auto opt = std::make_shared<StaticOptions>();
  CLI::App* cmd = app.add_subcommand("static", "Static displacements, reactions, section forces and fiber stresses under nodal loads");
  opt->mesh.add_options(*cmd);
  cmd->add_option("--out,-o", opt->out, "Results folder (default: <mesh name>_static)");
  cmd->add_option("--stations", opt->stations, "Section-force stations per element, ends included (default 3)")->check(number_check("2 to 101 stations (the element's ends and points between)", [](double n) { return n >= 2 && n <= 101; }, true));
  cmd->add_flag("--inertia-relief", opt->inertia_relief,
                "Take the loads' unbalanced part by the accelerations of the rigid motions the supports leave free (d'Alembert)");
  opt->progress.add_to(*cmd);
  cmd->callback([opt, &run]() { run = [opt]() { return run_static(*opt); }; });
}

}  // namespace framedyn::apps
