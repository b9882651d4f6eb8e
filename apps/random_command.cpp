// `framedyn random MESH.inp --psd FILE.csv --damping-ratio Z`: the response
// to the mesh's loads scaled by one random factor with the given PSD (all
// loads fully correlated), by mode superposition with a static correction
// (fem/random_response.h). Writes DIR/summary.json, DIR/response_psd.csv
// (PSD of every DOF of the output nodes over the integration grid),
// DIR/rms.csv (RMS of every DOF of the output nodes), response_psd.png and
// stress_psd.png. `--inertia-relief`: a frame free to move rigidly, its
// elastic response relative to the rigid motion (fem::RandomOptions).
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
#include "fem/random_response.h"

namespace framedyn::apps {

namespace {

using core::Quantity;

struct RandomCommandOptions {
  FrequencyDomainOptions common;
  std::string psd;
  bool inertia_relief = false;
};

report::LinePlot spectrum_plot(const std::string& title, const std::string& y_label, const std::string& y_unit, const std::string& name,
                             const std::vector<double>& f, const Eigen::VectorXd& values, double factor) {
  report::LinePlot p;
  p.title = title;
  p.x_label = "frequency";
  p.x_unit = core::UnitSystem::si().label(core::Quantity::frequency);  // the same in every system
  p.y_label = y_label;
  p.y_unit = y_unit;
  report::PlotSeries s{name, f, {}};
  for (Eigen::Index k = 0; k < values.size(); ++k) s.y.push_back(values(k) * factor);
  p.log_x = true;
  p.log_y = *std::min_element(s.y.begin(), s.y.end()) > 0.0;
  p.series.push_back(std::move(s));
  return p;
}

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
  const double lf = 1.0 / u.to_si_factor(Quantity::length), sf = 1.0 / u.to_si_factor(Quantity::stress);
  const std::string L = u.label(Quantity::length), S = u.label(Quantity::stress);
  const std::string L2 = u.label(Quantity::translation_psd), S2 = u.label(Quantity::stress_psd);
  const std::string out_dir = opt.common.out_dir();
  core::ResultsFolder folder(out_dir);

  std::vector<std::string> headers = {"node", report::column("frequency", u.label(Quantity::frequency)), report::column("load_psd", u.label(Quantity::per_frequency))};
  for (int d = 0; d < fem::kDofsPerNode; ++d) headers.push_back(report::column(std::string(fem::dof_name(d)) + "_psd", d < 3 ? L2 : u.label(Quantity::rotation_psd)));
  report::CsvTable table(headers);
  for (std::size_t i = 0; i < f.output_nodes.size(); ++i)
    for (std::size_t k = 0; k < r.frequencies_hz.size(); ++k) {
      table.row().add(model.nodes[static_cast<std::size_t>(f.output_nodes[i])].id).add(r.frequencies_hz[k]).add(r.load_psd[k]);
      for (int d = 0; d < fem::kDofsPerNode; ++d)
        table.add(r.output_psd(static_cast<Eigen::Index>(fem::kDofsPerNode * i + static_cast<std::size_t>(d)), static_cast<Eigen::Index>(k)) *
                  (d < 3 ? lf * lf : 1.0));
    }
  folder.write_text("response_psd.csv", table.str());

  std::vector<std::string> rms_headers = {"node"};
  for (int d = 0; d < fem::kDofsPerNode; ++d) rms_headers.push_back(report::column(std::string(fem::dof_name(d)) + "_rms", d < 3 ? L : u.label(Quantity::angle)));
  report::CsvTable rms(rms_headers);
  for (int n : f.output_nodes) {
    rms.row().add(model.nodes[static_cast<std::size_t>(n)].id);
    for (int d = 0; d < fem::kDofsPerNode; ++d) rms.add(r.rms(fem::kDofsPerNode * n + d) * (d < 3 ? lf : 1.0));
  }
  folder.write_text("rms.csv", rms.str());

  const int psd_node = node_id_of_dof(model, r.max_displacement_psd_dof);
  const std::string psd_dof = fem::dof_name(r.max_displacement_psd_dof % fem::kDofsPerNode);
  const int rms_node = node_id_of_dof(model, r.max_displacement_rms_dof);
  const std::string rms_dof = fem::dof_name(r.max_displacement_rms_dof % fem::kDofsPerNode);
  const bool has_stress = r.max_stress_psd_frequency >= 0;
  const double psd_f = r.frequencies_hz[static_cast<std::size_t>(r.max_displacement_psd_frequency)];
  const double stress_f = has_stress ? r.frequencies_hz[static_cast<std::size_t>(r.max_stress_psd_frequency)] : 0.0;
  double load_ms = 0.0;  // the load factor's mean square over the band, for the summary
  for (std::size_t k = 0; k + 1 < r.frequencies_hz.size(); ++k)
    load_ms += 0.5 * (r.load_psd[k] + r.load_psd[k + 1]) * (r.frequencies_hz[k + 1] - r.frequencies_hz[k]);

  std::vector<std::string> figures;
  if (opt.common.figures) {
    progress.stage("figures");
    report::write_png(spectrum_plot(fmt::format("Response PSD at node {} ({}), the largest; RMS {:.4g} {}", psd_node, psd_dof,
                                              r.rms(r.max_displacement_psd_dof) * lf, L),
                                  "displacement PSD", L2, fmt::format("node {} {}", psd_node, psd_dof), r.frequencies_hz,
                                  r.max_displacement_psd_spectrum, lf * lf),
                    folder.path_of("response_psd.png"));
    figures.push_back("response_psd.png");
    if (has_stress) {
      report::write_png(spectrum_plot(fmt::format("Fiber stress PSD in element {}, the largest", r.max_stress_psd_point.element_id), "fiber stress PSD", S2,
                                    fmt::format("element {}, {}, stress point {}", r.max_stress_psd_point.element_id, fem::describe_station(r.max_stress_psd_point),
                                                r.max_stress_psd_point.stress_point + 1),
                                    r.frequencies_hz, r.max_stress_psd_spectrum, sf * sf),
                      folder.path_of("stress_psd.png"));
      figures.push_back("stress_psd.png");
    }
  }

  nlohmann::ordered_json j;
  j["framedyn"] = {{"version", FRAMEDYN_VERSION}, {"command", "random"}};
  j["input"] = {{"mesh", opt.common.mesh.path},
                {"units", u.name()},
                {"psd", opt.psd},
                {"band", {{"lowest_hz", psd.lowest()}, {"highest_hz", psd.highest()}}},
                {"load_factor_rms", std::sqrt(load_ms)},
                {"damping_ratio", opt.common.damping_ratio},
                {"output_set", opt.common.output_set.empty() ? std::string("all nodes") : opt.common.output_set}};
  nlohmann::ordered_json h;
  h["mode_count"] = r.modes_used;
  h["highest_mode_frequency_hz"] = f.modes.modes.back().frequency_hz;
  h["static_correction"] = r.static_correction;
  h["displacements"] = r.inertia_relief ? "elastic part (inertia relief: relative to the rigid motion that takes the loads' unbalanced part)"
                                        : "total";
  if (r.inertia_relief) h["free_rigid_motions"] = r.rigid_body_modes;
  h["grid_points"] = r.frequencies_hz.size();
  h["max_displacement_psd"] = {{"value", r.max_displacement_psd * lf * lf}, {"unit", L2}, {"node", psd_node}, {"dof", psd_dof}, {"frequency_hz", psd_f}};
  if (has_stress)
    h["max_stress_psd"] = {{"value", r.max_stress_psd * sf * sf}, {"unit", S2}, {"element", r.max_stress_psd_point.element_id}, {"frequency_hz", stress_f}};
  h["max_displacement_rms"] = {{"value", r.max_displacement_rms * lf}, {"unit", L}, {"node", rms_node}, {"dof", rms_dof}};
  if (has_stress) h["max_stress_rms"] = {{"value", r.max_stress_rms * sf}, {"unit", S}, {"element", r.max_stress_rms_point.element_id}};
  h["figures"] = figures;
  j["frame"] = {{"nodes", model.nodes.size()}, {"beam_elements", model.beams.size()}, {"free_dofs", f.modes.free_dofs}, {"random", h}};
  folder.write_text("summary.json", j.dump(2) + "\n");
  folder.commit();
  progress.done();
  if (progress.quiet()) {  // -q: errors only, and the results folder on stdout
    fmt::print("results in {}/\n", out_dir);
    return 0;
  }

  fmt::print("framedyn random: {} ({} nodes, {} beam elements, {} free DOFs, units {})\n", opt.common.mesh.path, model.nodes.size(), model.beams.size(),
             f.modes.free_dofs, u.name());
  fmt::print("load PSD {} from {:.6g} to {:.6g} Hz (load factor RMS {:.6g}); {} modes up to {:.6g} Hz, zeta = {}, static correction {}; {} grid points\n",
             opt.psd, psd.lowest(), psd.highest(), std::sqrt(load_ms), r.modes_used, f.modes.modes.back().frequency_hz, opt.common.damping_ratio,
             r.static_correction ? "on" : "off", r.frequencies_hz.size());
  if (r.inertia_relief)
    fmt::print("inertia relief: {} free rigid motions take the loads' unbalanced part; displacements are the elastic part\n", r.rigid_body_modes);
  fmt::print("max displacement RMS {:.6g} {} at node {} ({})\n", r.max_displacement_rms * lf, L, rms_node, rms_dof);
  fmt::print("max displacement PSD {:.6g} {} at node {} ({}) at {:.6g} Hz\n", r.max_displacement_psd * lf * lf, L2, psd_node, psd_dof, psd_f);
  if (has_stress) {
    fmt::print("max fiber stress RMS {:.6g} {} in element {}\n", r.max_stress_rms * sf, S, r.max_stress_rms_point.element_id);
    fmt::print("max fiber stress PSD {:.6g} {} in element {} at {:.6g} Hz\n", r.max_stress_psd * sf * sf, S2, r.max_stress_psd_point.element_id, stress_f);
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
