// Shared inputs of the harmonic and random commands; see frequency_domain_input.h.
#include "apps/frequency_domain_input.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "apps/command_line.h"
#include "core/error.h"
#include "fem/static_analysis.h"

namespace framedyn::apps {

void FrequencyDomainOptions::add_to(CLI::App& cmd, const std::string& default_out_suffix) {
  suffix_ = default_out_suffix;
  mesh.add_options(cmd);
  cmd.add_option("--damping-ratio,-z", damping_ratio, "Modal damping ratio zeta of every elastic mode, 0 < zeta < 1 (e.g. 0.02)")
      ->required()
      ->check(number_check("a damping ratio between 0 and 1 (0 < zeta < 1)", [](double z) { return z > 0.0 && z < 1.0; }, false));
  cmd.add_option("--modes,-n", modes, "Number of modes in the superposition (default: the mesh's *FREQUENCY count, else 20)")
      ->check(number_check("a number of modes from 1 to 100000", [](double n) { return n >= 1 && n <= 100000; }, true));
  cmd.add_option("--output-set", output_set, "Node set (*NSET) whose nodes the tables list (default: all nodes)");
  cmd.add_option("--step", step, "Input step (*STEP, 1, 2, ...) whose loads and supports are used (default: the deck's only step with loads)")
      ->check(number_check("a step number from 1", [](double n) { return n >= 1 && n <= 1e6; }, true));
  cmd.add_flag("!--no-static-correction", static_correction, "Leave out the static correction for the modes not in the superposition");
  cmd.add_flag("!--no-figures", figures, "Write no PNG figures (gnuplot not needed)");
  cmd.add_option("--out,-o", out, "Results folder (default: <mesh name>_" + default_out_suffix + ")");
  progress.add_to(cmd);
}

std::string FrequencyDomainOptions::out_dir() const {
  return out.empty() ? std::filesystem::path(mesh.path).stem().string() + "_" + suffix_ : out;
}

namespace {

// The model as the chosen step has it: `step` (1, 2, ...) if given, else the
// one step whose loads are not empty; the deck itself if it has no *STEP.
// Several steps with loads and no --step: refused, the steps named, so that a
// multi-step deck never runs silently on one step's loads.
fem::FrameModel input_step(const fem::FrameModel& deck, const std::string& path, int step, int* used) {
  *used = 0;
  const int count = static_cast<int>(deck.steps.size());
  if (step > 0) {
    if (step > count)
      throw core::InputError(command_line("--step"),
                             count == 0 ? fmt::format("a step of {} (it has no *STEP: leave --step out)", path)
                                        : fmt::format("a step of {} (1 to {})", path, count),
                             std::to_string(step));
    *used = step;
    return fem::with_step(deck, static_cast<std::size_t>(step - 1));
  }
  std::vector<std::size_t> loaded;
  for (std::size_t i = 0; i < deck.steps.size(); ++i)
    if (!deck.steps[i].loads.empty() || !deck.steps[i].element_loads.empty()) loaded.push_back(i);
  if (loaded.size() > 1) {
    std::string names;
    for (std::size_t i : loaded) names += fmt::format("{}{} ({})", names.empty() ? "" : ", ", deck.steps[i].number, deck.steps[i].procedure);
    throw core::InputError(command_line("--step"), fmt::format("--step N naming the step whose loads are the amplitudes ({} has several steps with loads: {})", path, names),
                           "no --step");
  }
  if (loaded.empty()) return deck;
  *used = deck.steps[loaded.front()].number;
  return fem::with_step(deck, loaded.front());
}

}  // namespace

FrequencyDomainFrame prepare_frequency_domain(const FrequencyDomainOptions& opt, const std::string& analysis, Progress& progress) {
  FrequencyDomainFrame f;
  progress.stage("reading " + opt.mesh.path);
  f.model = std::make_unique<fem::FrameModel>(input_step(opt.mesh.load(), opt.mesh.path, opt.step, &f.step));
  const fem::FrameModel& model = *f.model;
  // The beams' line loads (*DLOAD) are load amplitudes like the nodal ones:
  // their consistent nodal loads are in applied_loads, their fixed-end terms
  // in the stress outputs' residual row (fem/modal_frequency_response.h).
  f.load = fem::applied_loads(model);
  if (f.load.cwiseAbs().maxCoeff() == 0.0)
    throw core::InputError({opt.mesh.path, 0, "*CLOAD"}, fmt::format("a nonzero nodal load (the load amplitudes of the {} analysis)", analysis),
                           f.step > 0 ? fmt::format("none in step {}", f.step) : std::string("none"));
  f.output_nodes = output_set_nodes(model, opt.mesh.path, opt.output_set);

  fem::ModalOptions mo;
  const int free = fem::make_dof_map(model).free_count();
  mo.mode_count = opt.modes > 0 ? opt.modes : std::min(model.requested_modes.value_or(20), free - 1);
  if (mo.mode_count >= free)
    throw core::InputError(command_line("--modes"), fmt::format("fewer modes than the {} free DOFs of {}", free, opt.mesh.path),
                           std::to_string(mo.mode_count));
  mo.progress = progress.callback();
  f.modes = fem::compute_modes(model, mo);
  progress.stage("modal superposition");
  f.frame = std::make_unique<fem::FrameDynamics>(model);
  f.basis = fem::modal_basis(f.frame->dofs(), f.modes);
  f.response.damping = fem::ModalDamping::ratio(opt.damping_ratio);
  f.response.static_correction = opt.static_correction;
  return f;
}

}  // namespace framedyn::apps
