// `framedyn harmonic MESH.inp --frequencies F1:F2:N --damping-ratio Z`: the
// steady-state response to the mesh's loads as amplitudes of F cos(omega t),
// by mode superposition with a static correction (fem/harmonic_response.h).
// Parses the options, solves, writes the results with
// report/frequency_response_outputs (DIR/summary.json, DIR/frf.csv: amplitude
// and phase of every DOF of the output nodes at every frequency, DIR/frf.png,
// DIR/fiber_stress.png) and prints the peaks.
#include <fmt/format.h>

#include <cmath>

#include "apps/command_line.h"
#include "apps/commands.h"
#include "apps/frequency_domain_input.h"
#include "report/response_figures.h"
#include "core/error.h"
#include "core/results_folder.h"
#include "fem/harmonic_response.h"
#include "report/frequency_response_outputs.h"

namespace framedyn::apps {

namespace {

using core::Quantity;

struct HarmonicCommandOptions {
  FrequencyDomainOptions common;
  std::string frequencies;  // F1:F2:N
};

// F1:F2:N as N frequencies evenly spaced from F1 to F2; "" when `text` is
// well formed, else what was wrong (for the validator's message).
std::string parse_frequencies(const std::string& text, std::vector<double>* out) {
  const std::size_t a = text.find(':'), b = a == std::string::npos ? a : text.find(':', a + 1);
  double f1 = 0, f2 = 0, n = 0;
  auto number = [](const std::string& s, double& v) {
    char* end = nullptr;
    v = std::strtod(s.c_str(), &end);
    return !s.empty() && end == s.c_str() + s.size() && std::isfinite(v);
  };
  if (b == std::string::npos || text.find(':', b + 1) != std::string::npos || !number(text.substr(0, a), f1) ||
      !number(text.substr(a + 1, b - a - 1), f2) || !number(text.substr(b + 1), n))
    return fmt::format("expected F1:F2:N (first and last frequency in Hz, number of frequencies; e.g. 5:200:500), found '{}'", text);
  if (!(f1 > 0.0) || !(f2 > f1)) return fmt::format("expected frequencies 0 < F1 < F2 in F1:F2:N, found '{}'", text);
  if (n != std::floor(n) || n < 2 || n > 1e6) return fmt::format("expected N from 2 to 1000000 frequencies in F1:F2:N, found '{}'", text);
  if (out) {
    out->clear();
    const int count = static_cast<int>(n);
    for (int k = 0; k < count; ++k) out->push_back(k + 1 == count ? f2 : f1 + (f2 - f1) * k / (count - 1));
  }
  return "";
}

int run_harmonic(const HarmonicCommandOptions& opt) {
  if (opt.common.figures) report::require_gnuplot();
  Progress progress(opt.common.progress);
  const FrequencyDomainFrame f = prepare_frequency_domain(opt.common, "harmonic", progress);
  const fem::FrameModel& model = *f.model;
  const core::UnitSystem& u = model.units;

  fem::HarmonicOptions ho;
  ho.response = f.response;
  parse_frequencies(opt.frequencies, &ho.frequencies_hz);
  for (int n : f.output_nodes)
    for (int d = 0; d < fem::kDofsPerNode; ++d) ho.output_dofs.push_back(fem::kDofsPerNode * n + d);
  progress.stage(fmt::format("harmonic response at {} frequencies ({} modes)", ho.frequencies_hz.size(), f.basis.eigenvalues.size()));
  const fem::HarmonicResult r = fem::harmonic_response(*f.frame, f.basis, f.load, ho);

  progress.stage("writing results");
  const std::string out_dir = opt.common.out_dir();
  core::ResultsFolder folder(out_dir);
  report::FrequencyResponseRun run{opt.common.mesh.path, opt.common.damping_ratio, opt.common.output_set, "", opt.common.figures, f.output_nodes};
  run.step = f.step;
  const std::vector<std::string> figures = report::write_harmonic_results(model, r, f.modes, run, folder, progress.callback());
  folder.commit();
  progress.done();
  if (progress.quiet()) {  // -q: errors only, and the results folder on stdout
    fmt::print("results in {}/\n", out_dir);
    return 0;
  }

  const double lf = 1.0 / u.to_si_factor(Quantity::length), sf = 1.0 / u.to_si_factor(Quantity::stress);
  const std::string L = u.label(Quantity::length), S = u.label(Quantity::stress);
  const report::HarmonicPeaks p = report::harmonic_peaks(model, r);
  fmt::print("framedyn harmonic: {} ({} nodes, {} beam elements, {} free DOFs, units {})\n", opt.common.mesh.path, model.nodes.size(),
             model.beams.size(), f.modes.free_dofs, u.name());
  if (f.step > 0) fmt::print("loads and supports of step {} ({})\n", f.step, model.steps[static_cast<std::size_t>(f.step - 1)].procedure);
  fmt::print("{} frequencies from {:.6g} to {:.6g} Hz; {} modes up to {:.6g} Hz, zeta = {}, static correction {}\n", r.frequencies_hz.size(),
             r.frequencies_hz.front(), r.frequencies_hz.back(), r.modes_used, f.modes.modes.back().frequency_hz, opt.common.damping_ratio,
             r.static_correction ? "on" : "off");
  if (f.modes.modes.back().frequency_hz < r.frequencies_hz.back())
    fmt::print("note: the highest mode used ({:.6g} Hz) lies below the last frequency ({:.6g} Hz): modes above it respond only "
               "quasi-statically{}; ask for more with --modes\n",
               f.modes.modes.back().frequency_hz, r.frequencies_hz.back(), r.static_correction ? " (static correction)" : " and are left out");
  fmt::print("max displacement amplitude {:.6g} {} at node {} ({}) at {:.6g} Hz\n", r.max_displacement * lf, L, p.node, p.dof, p.frequency_hz);
  if (p.has_stress)
    fmt::print("max fiber stress amplitude {:.6g} {} in element {} at {:.6g} Hz\n", r.max_fiber_stress * sf, S, r.max_fiber_stress_point.element_id,
               p.stress_frequency_hz);
  fmt::print("results in {}/ (summary.json, frf.csv{})\n", out_dir, figures.empty() ? "" : ", " + fmt::format("{}", fmt::join(figures, ", ")));
  return 0;
}

}  // namespace

void add_harmonic_command(CLI::App& app, std::function<int()>& run) {
  auto opt = std::make_shared<HarmonicCommandOptions>();
  CLI::App* cmd = app.add_subcommand("harmonic", "Steady-state harmonic response (frequency response) to the mesh's loads as amplitudes");
  cmd->add_option("--frequencies,-f", opt->frequencies, "F1:F2:N: N frequencies evenly spaced from F1 to F2 Hz (0 < F1 < F2)")
      ->required()
      ->check(CLI::Validator([](std::string& s) { return parse_frequencies(s, nullptr); }, ""));
  opt->common.add_to(*cmd, "harmonic");
  cmd->callback([opt, &run]() { run = [opt]() { return run_harmonic(*opt); }; });
}

}  // namespace framedyn::apps
