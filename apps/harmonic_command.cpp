// `framedyn harmonic MESH.inp --frequencies F1:F2:N --damping-ratio Z`: the
// steady-state response to the mesh's loads as amplitudes of F cos(omega t),
// by mode superposition with a static correction (fem/harmonic_response.h).
// Writes DIR/summary.json, DIR/frf.csv (amplitude and phase of every DOF of
// the output nodes at every frequency) and DIR/frf.png.
#include <fmt/format.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "apps/command_line.h"
#include "apps/commands.h"
#include "apps/frequency_domain_input.h"
#include "report/response_figures.h"
#include "report/csv_writer.h"
#include "core/error.h"
#include "report/plot.h"
#include "core/results_folder.h"
#include "fem/harmonic_response.h"

namespace framedyn::apps {

namespace {

using core::Quantity;
constexpr double kDegrees = 57.29577951308232;

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
  const double lf = 1.0 / u.to_si_factor(Quantity::length), sf = 1.0 / u.to_si_factor(Quantity::stress);
  const std::string L = u.label(Quantity::length), S = u.label(Quantity::stress);
  const std::string out_dir = opt.common.out_dir();
  core::ResultsFolder folder(out_dir);

  // frf.csv: per output node and frequency, amplitude and phase of each DOF; u_d(t) = |u_d| cos(omega t + phase_d).
  std::vector<std::string> headers = {"node", report::column("frequency", u.label(Quantity::frequency))};
  for (int d = 0; d < fem::kDofsPerNode; ++d) {
    headers.push_back(report::column(std::string(fem::dof_name(d)) + "_amplitude", d < 3 ? L : u.label(Quantity::angle)));
    headers.push_back(report::column(std::string(fem::dof_name(d)) + "_phase", u.label(Quantity::angle_degrees)));
  }
  report::CsvTable frf(headers);
  // The phase of an amplitude at round-off level (below 1e-12 of the largest of its kind, translations
  // or rotations: a DOF the load does not excite) is noise: written as 0.
  double largest[2] = {0.0, 0.0};
  for (Eigen::Index row = 0; row < r.output.rows(); ++row)
    largest[row % fem::kDofsPerNode < 3 ? 0 : 1] = std::max(largest[row % fem::kDofsPerNode < 3 ? 0 : 1], r.output.row(row).cwiseAbs().maxCoeff());
  for (std::size_t i = 0; i < f.output_nodes.size(); ++i)
    for (std::size_t k = 0; k < r.frequencies_hz.size(); ++k) {
      frf.row().add(model.nodes[static_cast<std::size_t>(f.output_nodes[i])].id).add(r.frequencies_hz[k]);
      for (int d = 0; d < fem::kDofsPerNode; ++d) {
        const std::complex<double> v = r.output(static_cast<Eigen::Index>(fem::kDofsPerNode * i + static_cast<std::size_t>(d)), static_cast<Eigen::Index>(k));
        frf.add(std::abs(v) * (d < 3 ? lf : 1.0)).add(std::abs(v) > 1e-12 * largest[d < 3 ? 0 : 1] ? std::arg(v) * kDegrees : 0.0);
      }
    }
  folder.write_text("frf.csv", frf.str());

  const int peak_node = node_id_of_dof(model, r.max_displacement_dof);
  const std::string peak_dof = fem::dof_name(r.max_displacement_dof % fem::kDofsPerNode);
  const double peak_f = r.frequencies_hz[static_cast<std::size_t>(r.max_displacement_frequency)];
  const bool has_stress = r.max_fiber_stress_frequency >= 0;
  const double stress_f = has_stress ? r.frequencies_hz[static_cast<std::size_t>(r.max_fiber_stress_frequency)] : 0.0;

  std::vector<std::string> figures;
  if (opt.common.figures) {
    progress.stage("figures");
    report::LinePlot plot;
    plot.title = fmt::format("Frequency response: largest amplitude at node {} ({}), {} modes, zeta = {}", peak_node, peak_dof, r.modes_used,
                             opt.common.damping_ratio);
    plot.x_label = "frequency";
    plot.x_unit = u.label(Quantity::frequency);
    plot.y_label = "displacement amplitude";
    plot.y_unit = L;
    report::PlotSeries ps{fmt::format("node {} {}", peak_node, peak_dof), r.frequencies_hz, {}};
    for (Eigen::Index k = 0; k < r.max_displacement_frf.size(); ++k) ps.y.push_back(std::abs(r.max_displacement_frf(k)) * lf);
    plot.log_y = *std::min_element(ps.y.begin(), ps.y.end()) > 0.0;
    plot.series.push_back(std::move(ps));
    report::write_png(plot, folder.path_of("frf.png"));
    figures.push_back("frf.png");
    if (has_stress) {
      report::LinePlot sp;
      sp.title = fmt::format("Fiber stress amplitude at the peak point of element {}", r.max_fiber_stress_point.element_id);
      sp.x_label = "frequency";
      sp.x_unit = u.label(Quantity::frequency);
      sp.y_label = "fiber stress amplitude";
      sp.y_unit = S;
      report::PlotSeries ss{fmt::format("element {}, {}, stress point {}", r.max_fiber_stress_point.element_id, fem::describe_station(r.max_fiber_stress_point),
                                      r.max_fiber_stress_point.stress_point + 1),
                          r.frequencies_hz, {}};
      for (Eigen::Index k = 0; k < r.max_fiber_stress_spectrum.size(); ++k) ss.y.push_back(r.max_fiber_stress_spectrum(k) * sf);
      sp.log_y = *std::min_element(ss.y.begin(), ss.y.end()) > 0.0;
      sp.series.push_back(std::move(ss));
      report::write_png(sp, folder.path_of("fiber_stress.png"));
      figures.push_back("fiber_stress.png");
    }
  }

  nlohmann::ordered_json j;
  j["framedyn"] = {{"version", FRAMEDYN_VERSION}, {"command", "harmonic"}};
  j["input"] = {{"mesh", opt.common.mesh.path},
                {"units", u.name()},
                {"frequencies", {{"first_hz", r.frequencies_hz.front()}, {"last_hz", r.frequencies_hz.back()}, {"count", r.frequencies_hz.size()}}},
                {"damping_ratio", opt.common.damping_ratio},
                {"output_set", opt.common.output_set.empty() ? std::string("all nodes") : opt.common.output_set}};
  nlohmann::ordered_json h;
  h["mode_count"] = r.modes_used;
  h["rigid_body_modes"] = r.rigid_body_modes;
  h["highest_mode_frequency_hz"] = f.modes.modes.back().frequency_hz;
  h["static_correction"] = r.static_correction;
  h["max_displacement"] = {{"value", r.max_displacement * lf}, {"unit", L}, {"node", peak_node}, {"dof", peak_dof}, {"frequency_hz", peak_f}};
  if (has_stress)
    h["max_fiber_stress"] = {{"value", r.max_fiber_stress * sf},
                             {"unit", S},
                             {"element", r.max_fiber_stress_point.element_id},
                             {"frequency_hz", stress_f}};
  h["figures"] = figures;
  j["frame"] = {{"nodes", model.nodes.size()}, {"beam_elements", model.beams.size()}, {"free_dofs", f.modes.free_dofs}, {"harmonic", h}};
  folder.write_text("summary.json", j.dump(2) + "\n");
  folder.commit();
  progress.done();
  if (progress.quiet()) {  // -q: errors only, and the results folder on stdout
    fmt::print("results in {}/\n", out_dir);
    return 0;
  }

  fmt::print("framedyn harmonic: {} ({} nodes, {} beam elements, {} free DOFs, units {})\n", opt.common.mesh.path, model.nodes.size(),
             model.beams.size(), f.modes.free_dofs, u.name());
  fmt::print("{} frequencies from {:.6g} to {:.6g} Hz; {} modes up to {:.6g} Hz, zeta = {}, static correction {}\n", r.frequencies_hz.size(),
             r.frequencies_hz.front(), r.frequencies_hz.back(), r.modes_used, f.modes.modes.back().frequency_hz, opt.common.damping_ratio,
             r.static_correction ? "on" : "off");
  if (f.modes.modes.back().frequency_hz < r.frequencies_hz.back())
    fmt::print("note: the highest mode used ({:.6g} Hz) lies below the last frequency ({:.6g} Hz): modes above it respond only "
               "quasi-statically{}; ask for more with --modes\n",
               f.modes.modes.back().frequency_hz, r.frequencies_hz.back(), r.static_correction ? " (static correction)" : " and are left out");
  fmt::print("max displacement amplitude {:.6g} {} at node {} ({}) at {:.6g} Hz\n", r.max_displacement * lf, L, peak_node, peak_dof, peak_f);
  if (has_stress)
    fmt::print("max fiber stress amplitude {:.6g} {} in element {} at {:.6g} Hz\n", r.max_fiber_stress * sf, S, r.max_fiber_stress_point.element_id,
               stress_f);
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
