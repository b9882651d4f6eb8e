// `framedyn modes MESH.inp`: natural frequencies and mode shapes of a frame.
// Parses the options, computes the modes (fem/modal_analysis), writes them with
// report/modes_outputs (summary.json, modes.csv, modes.xdmf + modes.h5 or
// modes.vtu, on request mode_shapes.csv)
// and prints a table.
#include <fmt/format.h>

#include <cmath>
#include <filesystem>

#include "apps/command_line.h"
#include "apps/commands.h"
#include "apps/mesh_input.h"
#include "apps/progress.h"
#include "core/results_folder.h"
#include "fem/modal_analysis.h"
#include "report/mode_shape_figure.h"
#include "report/modes_outputs.h"
#include "report/response_figures.h"

namespace framedyn::apps {

namespace {

using core::Quantity;

struct ModesOptions {
  MeshInput mesh;
  int modes = 0;  // 0: the mesh's *FREQUENCY count, else 10
  std::string out;
  bool lumped = false;
  double shift_hz = 1.0;
  bool figures = false;
  std::string paraview = "xdmf";
  bool mode_shapes_csv = false;
  ProgressFlags progress;
};

int run_modes(const ModesOptions& opt) {
  Progress progress(opt.progress);
  const std::string out_dir = opt.out.empty() ? std::filesystem::path(opt.mesh.path).stem().string() + "_modes" : opt.out;
  core::check_results_target(out_dir, {opt.mesh.path});  // before the run: a refusal costs no time
  if (opt.figures) report::require_gnuplot();
  progress.stage("reading " + opt.mesh.path);
  const fem::FrameModel model = fem::with_frequency_step(opt.mesh.load());  // a multi-step deck: its *FREQUENCY step's supports
  const core::UnitSystem& u = model.units;

  fem::ModalOptions mo;
  mo.mode_count = opt.modes > 0 ? opt.modes : model.requested_modes.value_or(10);
  mo.mass = opt.lumped ? fem::MassFormulation::lumped : fem::MassFormulation::consistent;
  mo.shift_hz = opt.shift_hz;
  mo.progress = progress.callback();
  const fem::ModalResult r = fem::compute_modes(model, mo);

  progress.stage("writing results");
  core::ResultsFolder folder(out_dir, {opt.mesh.path});

  const report::ParaviewOutput paraview = opt.paraview == "vtu"    ? report::ParaviewOutput::vtu
                                         : opt.paraview == "none" ? report::ParaviewOutput::none
                                                                  : report::ParaviewOutput::xdmf;
  report::write_modes_results(model, r, {opt.mesh.path, opt.lumped, opt.shift_hz, paraview, opt.mode_shapes_csv}, folder);
  bool drew = false;
  if (opt.figures) {
    // The lowest elastic modes (a rigid-body mode has no shape worth a picture).
    std::vector<Eigen::Index> elastic;
    std::vector<double> hz;
    for (std::size_t i = 0; i < r.modes.size() && elastic.size() < 4; ++i)
      if (!r.modes[i].rigid_body) elastic.push_back(static_cast<Eigen::Index>(i)), hz.push_back(r.modes[i].frequency_hz);
    if (!elastic.empty()) {
      progress.stage("figures");
      Eigen::MatrixXd shapes(r.shapes.rows(), static_cast<Eigen::Index>(elastic.size()));
      for (std::size_t k = 0; k < elastic.size(); ++k) shapes.col(static_cast<Eigen::Index>(k)) = r.shapes.col(elastic[k]);
      report::write_png(report::mode_shape_figure(model, shapes, hz, "Mode shapes: " + std::filesystem::path(opt.mesh.path).filename().string()),
                        folder.path_of("mode_shapes.png"));
      drew = true;
    }
  }
  folder.commit();
  progress.done();
  if (progress.quiet()) {  // -q: errors only, and the results folder on stdout
    fmt::print("results in {}/\n", out_dir);
    return 0;
  }

  // The table.
  const double mass_f = 1.0 / u.to_si_factor(Quantity::mass), rot_f = 1.0 / u.to_si_factor(Quantity::rotary_inertia);
  auto fraction = [&](const fem::Vector6d& v, int d) { return r.total_mass(d) > 0 ? v(d) / r.total_mass(d) : 0.0; };
  fmt::print("framedyn modes: {} ({} nodes, {} beam elements, {} free DOFs, units {})\n", opt.mesh.path, model.nodes.size(),
             model.beams.size(), r.free_dofs, u.name());
  fmt::print("total mass {:.6g} {} (supported DOFs included); carried by the free DOFs: x {:.6g}, y {:.6g}, z {:.6g}\n",
             r.total_mass(0) * mass_f, u.label(Quantity::mass), r.free_mass(0) * mass_f, r.free_mass(1) * mass_f, r.free_mass(2) * mass_f);
  fmt::print("rotary inertia about the origin {:.6g}, {:.6g}, {:.6g} {}\n", r.total_mass(3) * rot_f, r.total_mass(4) * rot_f,
             r.total_mass(5) * rot_f, u.label(Quantity::rotary_inertia));
  fmt::print("rigid-body modes {} ({} part(s)); Sturm check: {} eigenvalue(s) below {:.6g} Hz, {}\n\n", r.rigid_body_modes_expected,
             r.parts, r.sturm_count, r.sturm_shift_hz, r.certified ? "the set is complete" : "not checked");
  fmt::print(" mode  frequency [Hz]   effective mass / total mass:  x      y      z      rx     ry     rz\n");
  fem::Vector6d sum_all = fem::Vector6d::Zero();
  for (std::size_t i = 0; i < r.modes.size(); ++i) {
    const fem::Mode& m = r.modes[i];
    std::string line = fmt::format("{:5d}  {:>14}", i + 1, m.rigid_body ? "0 (rigid body)" : fmt::format("{:.6g}", m.frequency_hz));
    line += "                            ";
    for (int d = 0; d < 6; ++d) line += fmt::format("{:7.3f}", fraction(m.effective_mass, d));
    sum_all += m.effective_mass;
    fmt::print("{}\n", line);
  }
  std::string line = fmt::format("{:>5}  {:>14}                            ", "sum", "");
  for (int d = 0; d < 6; ++d) line += fmt::format("{:7.3f}", fraction(sum_all, d));
  fmt::print("{}\n", line);
  std::string files = "summary.json, modes.csv";
  if (opt.mode_shapes_csv) files += ", mode_shapes.csv";
  if (paraview == report::ParaviewOutput::xdmf) files += ", modes.xdmf, modes.h5";
  if (paraview == report::ParaviewOutput::vtu) files += ", modes.vtu";
  if (drew) files += ", mode_shapes.png";
  fmt::print("\nresults in {}/ ({})\n", out_dir, files);
  return 0;
}

}  // namespace

void add_modes_command(CLI::App& app, std::function<int()>& run) {
  auto opt = std::make_shared<ModesOptions>();
  CLI::App* cmd = app.add_subcommand("modes", "Natural frequencies and mode shapes of a beam frame");
  opt->mesh.add_options(*cmd);
  cmd->add_option("--modes,-n", opt->modes, "Number of modes (default: the mesh's *FREQUENCY count, else 10)")->check(number_check("a number of modes from 1 to 100000", [](double n) { return n >= 1 && n <= 100000; }, true));
  cmd->add_option("--out,-o", opt->out, "Results folder (default: <mesh name>_modes)");
  cmd->add_flag("--lumped", opt->lumped, "Lumped mass instead of consistent mass");
  cmd->add_option("--shift", opt->shift_hz, "Shift of the shift-invert iteration, Hz below zero (default 1)")->check(number_check("a positive shift in Hz", [](double hz) { return hz > 0; }, false));
  cmd->add_flag("--figures", opt->figures, "Draw the lowest four elastic mode shapes, three views each, into mode_shapes.png (gnuplot)");
  cmd->add_option("--paraview", opt->paraview, "ParaView output: xdmf (modes.xdmf + modes.h5, each mode a time step; default), vtu (modes.vtu) or none")
      ->check(CLI::Validator(
          [](std::string& input) {
            return input == "xdmf" || input == "vtu" || input == "none" ? std::string()
                                                                        : fmt::format("expected xdmf, vtu or none, found '{}'", input);
          },
          ""));
  cmd->add_flag("--mode-shapes-csv", opt->mode_shapes_csv, "Also write mode_shapes.csv, the mass-normalised shapes as a text table (large)");
  opt->progress.add_to(*cmd);
  cmd->callback([opt, &run]() { run = [opt]() { return run_modes(*opt); }; });
}

}  // namespace framedyn::apps
