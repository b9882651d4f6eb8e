// The outputs of `framedyn harmonic` and `framedyn random`; see frequency_response_outputs.h.
#include "report/frequency_response_outputs.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <complex>

#include "report/json_quantity.h"
#include "report/csv_writer.h"
#include "report/plot.h"
#include "report/summary_warnings.h"

namespace framedyn::report {

namespace {

using core::Quantity;
constexpr double kDegrees = 57.29577951308232;

// The mesh's node number of a global DOF.
int node_id_of_dof(const fem::FrameModel& model, int global_dof) { return model.nodes[static_cast<std::size_t>(global_dof / fem::kDofsPerNode)].id; }

// summary.json's "input" entry: the mesh and its units, then `specific`, then the damping ratio and the output set.
nlohmann::ordered_json input_entry(const FrequencyResponseRun& run, const core::UnitSystem& u, const nlohmann::ordered_json& specific) {
  nlohmann::ordered_json in = {{"mesh", run.mesh_path}, {"units", u.name()}};
  for (const auto& [key, value] : specific.items()) in[key] = value;
  if (run.step > 0) in["step"] = run.step;
  in["damping_ratio"] = run.damping_ratio;
  in["output_set"] = run.output_set.empty() ? std::string("all nodes") : run.output_set;
  return in;
}

// summary.json: framedyn, input and frame {nodes, beam_elements, free_dofs, <analysis>: response}.
void write_summary(const fem::FrameModel& model, const fem::ModalResult& modes, const std::string& analysis, const nlohmann::ordered_json& input,
                   const nlohmann::ordered_json& response, const core::ResultsFolder& folder) {
  nlohmann::ordered_json j;
  j["framedyn"] = {{"version", FRAMEDYN_VERSION}, {"command", analysis}};
  j["input"] = input;
  j["frame"] = {{"nodes", model.nodes.size()}, {"beam_elements", model.beams.size()}, {"free_dofs", modes.free_dofs}, {analysis, response}};
  add_warnings(j, model.reader_warnings);
  folder.write_text("summary.json", j.dump(2) + "\n");
}

LinePlot spectrum_plot(const std::string& title, const std::string& y_label, const std::string& y_unit, const std::string& name,
                       const std::vector<double>& f, const Eigen::VectorXd& values, double factor) {
  LinePlot p;
  p.title = title;
  p.x_label = "frequency";
  p.x_unit = core::UnitSystem::si().label(core::Quantity::frequency);  // the same in every system
  p.y_label = y_label;
  p.y_unit = y_unit;
  PlotSeries s{name, f, {}};
  for (Eigen::Index k = 0; k < values.size(); ++k) s.y.push_back(values(k) * factor);
  p.log_x = true;
  p.log_y = *std::min_element(s.y.begin(), s.y.end()) > 0.0;
  p.series.push_back(std::move(s));
  return p;
}

}  // namespace

HarmonicPeaks harmonic_peaks(const fem::FrameModel& model, const fem::HarmonicResult& r) {
  HarmonicPeaks p;
  p.node = node_id_of_dof(model, r.max_displacement_dof);
  p.dof = fem::dof_name(r.max_displacement_dof % fem::kDofsPerNode);
  p.frequency_hz = r.frequencies_hz[static_cast<std::size_t>(r.max_displacement_frequency)];
  p.has_stress = r.max_fiber_stress_frequency >= 0;
  p.stress_frequency_hz = p.has_stress ? r.frequencies_hz[static_cast<std::size_t>(r.max_fiber_stress_frequency)] : 0.0;
  return p;
}

std::vector<std::string> write_harmonic_results(const fem::FrameModel& model, const fem::HarmonicResult& r, const fem::ModalResult& modes,
                                                const FrequencyResponseRun& run, const core::ResultsFolder& folder,
                                                const std::function<void(const std::string&)>& stage) {
  const core::UnitSystem& u = model.units;
  const double lf = 1.0 / u.to_si_factor(Quantity::length), sf = 1.0 / u.to_si_factor(Quantity::stress);
  const std::string L = u.label(Quantity::length), S = u.label(Quantity::stress), hz = u.label(Quantity::frequency);

  // frf.csv: per output node and frequency, amplitude and phase of each DOF; u_d(t) = |u_d| cos(omega t + phase_d).
  std::vector<std::string> headers = {"node", column("frequency", u.label(Quantity::frequency))};
  for (int d = 0; d < fem::kDofsPerNode; ++d) {
    headers.push_back(column(std::string(fem::dof_name(d)) + "_amplitude", d < 3 ? L : u.label(Quantity::angle)));
    headers.push_back(column(std::string(fem::dof_name(d)) + "_phase", u.label(Quantity::angle_degrees)));
  }
  CsvTable frf(headers);
  // The phase of an amplitude at round-off level (below 1e-12 of the largest of its kind, translations
  // or rotations: a DOF the load does not excite) is noise: written as 0.
  double largest[2] = {0.0, 0.0};
  for (Eigen::Index row = 0; row < r.output.rows(); ++row)
    largest[row % fem::kDofsPerNode < 3 ? 0 : 1] = std::max(largest[row % fem::kDofsPerNode < 3 ? 0 : 1], r.output.row(row).cwiseAbs().maxCoeff());
  for (std::size_t i = 0; i < run.output_nodes.size(); ++i)
    for (std::size_t k = 0; k < r.frequencies_hz.size(); ++k) {
      frf.row().add(model.nodes[static_cast<std::size_t>(run.output_nodes[i])].id).add(r.frequencies_hz[k]);
      for (int d = 0; d < fem::kDofsPerNode; ++d) {
        const std::complex<double> v = r.output(static_cast<Eigen::Index>(fem::kDofsPerNode * i + static_cast<std::size_t>(d)), static_cast<Eigen::Index>(k));
        frf.add(std::abs(v) * (d < 3 ? lf : 1.0)).add(std::abs(v) > 1e-12 * largest[d < 3 ? 0 : 1] ? std::arg(v) * kDegrees : 0.0);
      }
    }
  folder.write_text("frf.csv", frf.str());

  const HarmonicPeaks peaks = harmonic_peaks(model, r);
  std::vector<std::string> figures;
  if (run.figures) {
    if (stage) stage("figures");
    LinePlot plot;
    plot.title = fmt::format("Frequency response: largest amplitude at node {} ({}), {} modes, zeta = {}", peaks.node, peaks.dof, r.modes_used,
                             run.damping_ratio);
    plot.x_label = "frequency";
    plot.x_unit = u.label(Quantity::frequency);
    plot.y_label = "displacement amplitude";
    plot.y_unit = L;
    PlotSeries ps{fmt::format("node {} {}", peaks.node, peaks.dof), r.frequencies_hz, {}};
    for (Eigen::Index k = 0; k < r.max_displacement_frf.size(); ++k) ps.y.push_back(std::abs(r.max_displacement_frf(k)) * lf);
    plot.log_y = *std::min_element(ps.y.begin(), ps.y.end()) > 0.0;
    plot.series.push_back(std::move(ps));
    write_png(plot, folder.path_of("frf.png"));
    figures.push_back("frf.png");
    if (peaks.has_stress) {
      LinePlot sp;
      sp.title = fmt::format("Fiber stress amplitude at the peak point of element {}", r.max_fiber_stress_point.element_id);
      sp.x_label = "frequency";
      sp.x_unit = u.label(Quantity::frequency);
      sp.y_label = "fiber stress amplitude";
      sp.y_unit = S;
      PlotSeries ss{fmt::format("element {}, {}, stress point {}", r.max_fiber_stress_point.element_id, fem::describe_station(r.max_fiber_stress_point),
                                r.max_fiber_stress_point.stress_point + 1),
                    r.frequencies_hz, {}};
      for (Eigen::Index k = 0; k < r.max_fiber_stress_spectrum.size(); ++k) ss.y.push_back(r.max_fiber_stress_spectrum(k) * sf);
      sp.log_y = *std::min_element(ss.y.begin(), ss.y.end()) > 0.0;
      sp.series.push_back(std::move(ss));
      write_png(sp, folder.path_of("fiber_stress.png"));
      figures.push_back("fiber_stress.png");
    }
  }

  const nlohmann::ordered_json input = input_entry(
      run, u, {{"frequencies", {{"first", quantity(r.frequencies_hz.front(), hz)}, {"last", quantity(r.frequencies_hz.back(), hz)}, {"count", r.frequencies_hz.size()}}}});
  nlohmann::ordered_json h;
  h["mode_count"] = r.modes_used;
  h["rigid_body_modes"] = r.rigid_body_modes;
  h["highest_mode_frequency"] = quantity(modes.modes.back().frequency_hz, hz);
  h["static_correction"] = r.static_correction;
  h["max_displacement"] = {{"value", r.max_displacement * lf}, {"unit", L}, {"node", peaks.node}, {"dof", peaks.dof}, {"frequency", quantity(peaks.frequency_hz, hz)}};
  if (peaks.has_stress)
    h["max_fiber_stress"] = {{"value", r.max_fiber_stress * sf},
                             {"unit", S},
                             {"element", r.max_fiber_stress_point.element_id},
                             {"frequency", quantity(peaks.stress_frequency_hz, hz)}};
  h["figures"] = figures;
  write_summary(model, modes, "harmonic", input, h, folder);
  return figures;
}

RandomPeaks random_peaks(const fem::FrameModel& model, const fem::RandomResult& r) {
  RandomPeaks p;
  p.psd_node = node_id_of_dof(model, r.max_displacement_psd_dof);
  p.psd_dof = fem::dof_name(r.max_displacement_psd_dof % fem::kDofsPerNode);
  p.rms_node = node_id_of_dof(model, r.max_displacement_rms_dof);
  p.rms_dof = fem::dof_name(r.max_displacement_rms_dof % fem::kDofsPerNode);
  p.has_stress = r.max_stress_psd_frequency >= 0;
  p.psd_frequency_hz = r.frequencies_hz[static_cast<std::size_t>(r.max_displacement_psd_frequency)];
  p.stress_frequency_hz = p.has_stress ? r.frequencies_hz[static_cast<std::size_t>(r.max_stress_psd_frequency)] : 0.0;
  double load_ms = 0.0;  // the load factor's mean square over the band, for the summary
  for (std::size_t k = 0; k + 1 < r.frequencies_hz.size(); ++k)
    load_ms += 0.5 * (r.load_psd[k] + r.load_psd[k + 1]) * (r.frequencies_hz[k + 1] - r.frequencies_hz[k]);
  p.load_factor_rms = std::sqrt(load_ms);
  return p;
}

std::vector<std::string> write_random_results(const fem::FrameModel& model, const fem::RandomResult& r, const fem::LoadPsd& psd,
                                              const fem::ModalResult& modes, const FrequencyResponseRun& run, const core::ResultsFolder& folder,
                                              const std::function<void(const std::string&)>& stage) {
  const core::UnitSystem& u = model.units;
  const double lf = 1.0 / u.to_si_factor(Quantity::length), sf = 1.0 / u.to_si_factor(Quantity::stress);
  const std::string L = u.label(Quantity::length), S = u.label(Quantity::stress), hz = u.label(Quantity::frequency);
  const std::string L2 = u.label(Quantity::translation_psd), S2 = u.label(Quantity::stress_psd);

  std::vector<std::string> headers = {"node", column("frequency", u.label(Quantity::frequency)), column("load_psd", u.label(Quantity::per_frequency))};
  for (int d = 0; d < fem::kDofsPerNode; ++d) headers.push_back(column(std::string(fem::dof_name(d)) + "_psd", d < 3 ? L2 : u.label(Quantity::rotation_psd)));
  CsvTable table(headers);
  for (std::size_t i = 0; i < run.output_nodes.size(); ++i)
    for (std::size_t k = 0; k < r.frequencies_hz.size(); ++k) {
      table.row().add(model.nodes[static_cast<std::size_t>(run.output_nodes[i])].id).add(r.frequencies_hz[k]).add(r.load_psd[k]);
      for (int d = 0; d < fem::kDofsPerNode; ++d)
        table.add(r.output_psd(static_cast<Eigen::Index>(fem::kDofsPerNode * i + static_cast<std::size_t>(d)), static_cast<Eigen::Index>(k)) *
                  (d < 3 ? lf * lf : 1.0));
    }
  folder.write_text("response_psd.csv", table.str());

  std::vector<std::string> rms_headers = {"node"};
  for (int d = 0; d < fem::kDofsPerNode; ++d) rms_headers.push_back(column(std::string(fem::dof_name(d)) + "_rms", d < 3 ? L : u.label(Quantity::angle)));
  CsvTable rms(rms_headers);
  for (int n : run.output_nodes) {
    rms.row().add(model.nodes[static_cast<std::size_t>(n)].id);
    for (int d = 0; d < fem::kDofsPerNode; ++d) rms.add(r.rms(fem::kDofsPerNode * n + d) * (d < 3 ? lf : 1.0));
  }
  folder.write_text("rms.csv", rms.str());

  const RandomPeaks peaks = random_peaks(model, r);
  std::vector<std::string> figures;
  if (run.figures) {
    if (stage) stage("figures");
    write_png(spectrum_plot(fmt::format("Response PSD at node {} ({}), the largest; RMS {:.4g} {}", peaks.psd_node, peaks.psd_dof,
                                        r.rms(r.max_displacement_psd_dof) * lf, L),
                            "displacement PSD", L2, fmt::format("node {} {}", peaks.psd_node, peaks.psd_dof), r.frequencies_hz,
                            r.max_displacement_psd_spectrum, lf * lf),
              folder.path_of("response_psd.png"));
    figures.push_back("response_psd.png");
    if (peaks.has_stress) {
      write_png(spectrum_plot(fmt::format("Fiber stress PSD in element {}, the largest", r.max_stress_psd_point.element_id), "fiber stress PSD", S2,
                              fmt::format("element {}, {}, stress point {}", r.max_stress_psd_point.element_id, fem::describe_station(r.max_stress_psd_point),
                                          r.max_stress_psd_point.stress_point + 1),
                              r.frequencies_hz, r.max_stress_psd_spectrum, sf * sf),
                folder.path_of("stress_psd.png"));
      figures.push_back("stress_psd.png");
    }
  }

  const nlohmann::ordered_json input =
      input_entry(run, u,
                  {{"psd", run.psd_path}, {"band", {{"lowest", quantity(psd.lowest(), hz)}, {"highest", quantity(psd.highest(), hz)}}}, {"load_factor_rms", peaks.load_factor_rms}});
  nlohmann::ordered_json h;
  h["mode_count"] = r.modes_used;
  h["highest_mode_frequency"] = quantity(modes.modes.back().frequency_hz, hz);
  h["static_correction"] = r.static_correction;
  h["displacements"] = r.inertia_relief ? "elastic part (inertia relief: relative to the rigid motion that takes the loads' unbalanced part)"
                                        : "total";
  if (r.inertia_relief) h["free_rigid_motions"] = r.rigid_body_modes;
  h["grid_points"] = r.frequencies_hz.size();
  h["max_displacement_psd"] = {{"value", r.max_displacement_psd * lf * lf}, {"unit", L2}, {"node", peaks.psd_node}, {"dof", peaks.psd_dof},
                               {"frequency", quantity(peaks.psd_frequency_hz, hz)}};
  if (peaks.has_stress)
    h["max_stress_psd"] = {{"value", r.max_stress_psd * sf * sf}, {"unit", S2}, {"element", r.max_stress_psd_point.element_id},
                           {"frequency", quantity(peaks.stress_frequency_hz, hz)}};
  h["max_displacement_rms"] = {{"value", r.max_displacement_rms * lf}, {"unit", L}, {"node", peaks.rms_node}, {"dof", peaks.rms_dof}};
  if (peaks.has_stress) h["max_stress_rms"] = {{"value", r.max_stress_rms * sf}, {"unit", S}, {"element", r.max_stress_rms_point.element_id}};
  h["figures"] = figures;
  write_summary(model, modes, "random", input, h, folder);
  return figures;
}

}  // namespace framedyn::report
