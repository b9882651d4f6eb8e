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
  cmd.add_flag("!--no-static-correction", static_correction, "Leave out the static correction for the modes not in the superposition");
  cmd.add_flag("!--no-figures", figures, "Write no PNG figures (gnuplot not needed)");
  cmd.add_option("--out,-o", out, "Results folder (default: <mesh name>_" + default_out_suffix + ")");
  progress.add_to(cmd);
}

std::string FrequencyDomainOptions::out_dir() const {
  return out.empty() ? std::filesystem::path(mesh.path).stem().string() + "_" + suffix_ : out;
}

FrequencyDomainFrame prepare_frequency_domain(const FrequencyDomainOptions& opt, const std::string& analysis, Progress& progress) {
  FrequencyDomainFrame f;
  progress.stage("reading " + opt.mesh.path);
  f.model = std::make_unique<fem::FrameModel>(opt.mesh.load());
  const fem::FrameModel& model = *f.model;
  // The beams' line loads (*DLOAD) are load amplitudes like the nodal ones:
  // their consistent nodal loads are in applied_loads, their fixed-end terms
  // in the stress outputs' residual row (fem/modal_frequency_response.h).
  f.load = fem::applied_loads(model);
  if (f.load.cwiseAbs().maxCoeff() == 0.0)
    throw core::InputError({opt.mesh.path, 0, "*CLOAD"}, fmt::format("a nonzero nodal load (the load amplitudes of the {} analysis)", analysis),
                           "none");
  if (!opt.output_set.empty()) {
    std::string name = opt.output_set;
    std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
    const auto it = model.node_sets.find(name);
    if (it == model.node_sets.end()) {
      std::string known;
      for (const auto& [set, nodes] : model.node_sets) known += (known.empty() ? "" : ", ") + set;
      throw core::InputError({opt.mesh.path, 0, "--output-set"},
                             fmt::format("a node set of the mesh ({})", known.empty() ? std::string("it defines none") : known), "'" + opt.output_set + "'");
    }
    f.output_nodes = it->second;
  } else {
    for (int n = 0; n < static_cast<int>(model.nodes.size()); ++n) f.output_nodes.push_back(n);
  }

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
