// `framedyn transient DECK.inp [--step N] [--output-set NSET] [--element-set
// ELSET] [--paraview xdmf|none] --out DIR`: runs a *MODAL DYNAMIC or *DYNAMIC
// step of a deck as the deck defines it (fem/transient_step.h) and writes the
// displacement and section-force histories, the ParaView series and the
// summary with report/transient_step_outputs.
#include <fmt/format.h>

#include <cmath>
#include <filesystem>

#include "apps/command_line.h"
#include "apps/commands.h"
#include "apps/mesh_input.h"
#include "apps/progress.h"
#include "core/error.h"
#include "core/results_folder.h"
#include "fem/transient_step.h"
#include "report/transient_step_outputs.h"

namespace framedyn::apps {

namespace {

using core::Quantity;

struct TransientCommandOptions {
  MeshInput mesh;
  int step = 0;
  std::string output_set;
  std::string element_set;
  std::string paraview = "xdmf";
  std::string out;
  ProgressFlags progress;
};

// The step --step names, or the deck's only transient step.
std::size_t chosen_step(const fem::FrameModel& deck, const TransientCommandOptions& opt) {
  std::vector<std::size_t> transient;
  std::string names;
  for (std::size_t i = 0; i < deck.steps.size(); ++i)
    if (deck.steps[i].transient) {
      transient.push_back(i);
      names += fmt::format("{}{} (*{})", names.empty() ? "" : ", ", deck.steps[i].number, deck.steps[i].procedure);
    }
  if (opt.step > 0) {
    const std::size_t i = static_cast<std::size_t>(opt.step - 1);
    if (i >= deck.steps.size() || !deck.steps[i].transient)  // CLI-49
      throw core::InputError(command_line("--step"),
                             fmt::format("a *MODAL DYNAMIC or *DYNAMIC step of {} ({})", opt.mesh.path, names.empty() ? std::string("it has none") : names),
                             i < deck.steps.size() ? fmt::format("{} (*{})", opt.step, deck.steps[i].procedure) : std::to_string(opt.step));
    return i;
  }
  if (transient.size() != 1)  // CLI-50
    throw core::InputError(command_line("--step"),
                           transient.empty() ? fmt::format("a *MODAL DYNAMIC or *DYNAMIC step in {}", opt.mesh.path)
                                             : fmt::format("--step N naming the transient step to run ({} has several: {})", opt.mesh.path, names),
                           transient.empty() ? std::string("none") : std::string("no --step"));
  return transient.front();
}

int run_transient(const TransientCommandOptions& opt) {
  Progress progress(opt.progress);
  const std::string out_dir = opt.out.empty() ? std::filesystem::path(opt.mesh.path).stem().string() + "_transient" : opt.out;
  core::check_results_target(out_dir, {opt.mesh.path});
  progress.stage("reading " + opt.mesh.path);
  const fem::FrameModel deck = opt.mesh.load();
  const std::size_t index = chosen_step(deck, opt);
  const std::vector<int> output_nodes = output_set_nodes(deck, opt.mesh.path, opt.output_set);
  const std::vector<int> output_beams = output_set_beams(deck, opt.mesh.path, opt.element_set);
  progress.stage(fmt::format("step {} (*{})", deck.steps[index].number, deck.steps[index].procedure));
  const fem::TransientStepResult r = fem::run_transient_step(deck, index, opt.mesh.path);

  progress.stage("writing results");
  core::ResultsFolder folder(out_dir, {opt.mesh.path});
  const report::TransientStepRun run{opt.mesh.path, output_nodes, opt.element_set, output_beams, opt.paraview == "xdmf"};
  const nlohmann::ordered_json summary = report::write_transient_step_results(deck, r, run, folder);
  folder.write_text("summary.json", summary.dump(2) + "\n");
  folder.commit();
  progress.done();
  if (progress.quiet()) {
    fmt::print("results in {}/\n", out_dir);
    return 0;
  }
  const core::UnitSystem& u = deck.units;
  const report::TransientPeak p = report::transient_peak(deck, r.response, output_nodes);
  fmt::print("framedyn transient: {} step {} (*{}), units {}\n", opt.mesh.path, r.step, r.procedure, u.name());
  fmt::print("{}; {} output times\n", r.scheme, r.response.times.size());
  fmt::print("max displacement {:.6g} {} at node {} ({}) at t = {:.6g} s\n", p.value / u.to_si_factor(Quantity::length), u.label(Quantity::length),
             p.node, fem::dof_name(p.dof), p.time);
  const nlohmann::ordered_json& m = summary["frame"]["transient"]["max_bending_moment"];  // as summary.json has it
  fmt::print("max bending moment {:.6g} {} at element {} end {} at t = {:.6g} s\n", m["value"].get<double>(), m["unit"].get<std::string>(),
             m["element"].get<int>(), m["end"].get<int>(), m["time"].get<double>());
  fmt::print("results in {}/ (summary.json, displacement_history.csv, section_force_history.csv{})\n", out_dir,
             run.paraview ? ", transient.xdmf, transient.h5" : "");
  return 0;
}

}  // namespace

void add_transient_command(CLI::App& app, std::function<int()>& run) {
  auto opt = std::make_shared<TransientCommandOptions>();
  CLI::App* cmd = app.add_subcommand("transient", "Run a *MODAL DYNAMIC or *DYNAMIC step of a deck (loads scaled by their *AMPLITUDE)");
  opt->mesh.add_options(*cmd);
  cmd->add_option("--step", opt->step, "Input step (*STEP, 1, 2, ...) to run (default: the deck's only *MODAL DYNAMIC or *DYNAMIC step)")
      ->check(number_check("a step number from 1", [](double n) { return n >= 1 && n <= 1e6; }, true));
  cmd->add_option("--output-set", opt->output_set, "Node set (*NSET) whose nodes displacement_history.csv lists (default: all nodes)");
  cmd->add_option("--element-set", opt->element_set,
                  "Element set (*ELSET) whose beams section_force_history.csv lists, both ends (default: all beams)");
  cmd->add_option("--paraview", opt->paraview, "ParaView output: xdmf (transient.xdmf + transient.h5, every output time; default) or none")
      ->check(CLI::Validator(
          [](std::string& s) { return s == "xdmf" || s == "none" ? std::string() : fmt::format("expected xdmf or none, found '{}'", s); }, ""));
  cmd->add_option("--out,-o", opt->out, "Results folder (default: <mesh name>_transient)");
  opt->progress.add_to(*cmd);
  cmd->callback([opt, &run]() { run = [opt]() { return run_transient(*opt); }; });
}

}  // namespace framedyn::apps
