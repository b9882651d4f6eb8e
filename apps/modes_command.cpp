// `framedyn modes MESH.inp`: natural frequencies and mode shapes of a frame.
// Writes DIR/summary.json, DIR/modes.csv (one row per mode), DIR/mode_shapes.csv
// (mass-normalised shapes per node) and DIR/modes.vtu (ParaView), and prints a table.
#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "apps/command_line.h"
#include "apps/commands.h"
#include "apps/mesh_input.h"
#include "apps/progress.h"
#include "report/csv_writer.h"
#include "core/results_folder.h"
#include "fem/modal_analysis.h"
#include "report/vtu_writer.h"

namespace framedyn::apps {

namespace {

using core::Quantity;
const char* kDirections[6] = {"x", "y", "z", "rx", "ry", "rz"};

struct ModesOptions {
  MeshInput mesh;
  int modes = 0;  // 0: the mesh's *FREQUENCY count, else 10
  std::string out;
  bool lumped = false;
  double shift_hz = 1.0;
  ProgressFlags progress;
};

int run_modes(const ModesOptions& opt) {
  Progress progress(opt.progress);
  const std::string out_dir = opt.out.empty() ? std::filesystem::path(opt.mesh.path).stem().string() + "_modes" : opt.out;
  core::check_results_target(out_dir, {opt.mesh.path});  // before the run: a refusal costs no time
  progress.stage("reading " + opt.mesh.path);
  const fem::FrameModel model = opt.mesh.load();
  const core::UnitSystem& u = model.units;

  fem::ModalOptions mo;
  mo.mode_count = opt.modes > 0 ? opt.modes : model.requested_modes.value_or(10);
  mo.mass = opt.lumped ? fem::MassFormulation::lumped : fem::MassFormulation::consistent;
  mo.shift_hz = opt.shift_hz;
  mo.progress = progress.callback();
  const fem::ModalResult r = fem::compute_modes(model, mo);

  progress.stage("writing results");
  core::ResultsFolder folder(out_dir, {opt.mesh.path});

  const double mass_f = 1.0 / u.to_si_factor(Quantity::mass);
  const double rot_f = 1.0 / u.to_si_factor(Quantity::rotary_inertia);
  auto eff_in_units = [&](const fem::Vector6d& v, int d) { return v(d) * (d < 3 ? mass_f : rot_f); };
  // Effective masses as fractions of the model's total mass (Eq. 7.5).
  auto fraction = [&](const fem::Vector6d& v, int d) { return r.total_mass(d) > 0 ? v(d) / r.total_mass(d) : 0.0; };

  // summary.json
  nlohmann::ordered_json j;
  j["framedyn"] = {{"version", FRAMEDYN_VERSION}, {"command", "modes"}};
  j["input"] = {{"mesh", opt.mesh.path}, {"units", u.name()}};
  nlohmann::ordered_json frame;
  frame["nodes"] = model.nodes.size();
  frame["beam_elements"] = model.beams.size();
  frame["dofs"] = model.dof_count();
  frame["free_dofs"] = r.free_dofs;
  frame["mass_formulation"] = opt.lumped ? "lumped" : "consistent";
  // Masses (docs/theory/fem.md Eqs. 7.4, 7.5): the whole model's, supported
  // DOFs included; the part the free DOFs carry, per direction.
  frame["total_mass"] = {{"value", r.total_mass(0) * mass_f}, {"unit", u.label(Quantity::mass)}};
  frame["total_rotary_inertia"] = {{"x", r.total_mass(3) * rot_f}, {"y", r.total_mass(4) * rot_f}, {"z", r.total_mass(5) * rot_f},
                                   {"unit", u.label(Quantity::rotary_inertia)}, {"about", "reference_point"}};
  nlohmann::ordered_json free_mass;
  for (int d = 0; d < 6; ++d) free_mass[kDirections[d]] = eff_in_units(r.free_mass, d);
  frame["free_dof_mass"] = free_mass;
  frame["reference_point"] = {{"value", {0.0, 0.0, 0.0}}, {"unit", u.label(Quantity::length)}};
  frame["effective_mass_unit"] = {{"translation", u.label(Quantity::mass)}, {"rotation", u.label(Quantity::rotary_inertia)}};
  frame["participation_factor_unit"] = {{"translation", "sqrt(" + u.label(Quantity::mass) + ")"},
                                        {"rotation", "sqrt(" + u.label(Quantity::rotary_inertia) + ")"}};
  frame["rigid_body_modes_expected"] = r.rigid_body_modes_expected;
  frame["parts"] = r.parts;
  frame["sturm_check"] = {{"certified", r.certified}, {"eigenvalues_below", r.sturm_count}, {"below_hz", r.sturm_shift_hz},
                          {"lanczos_runs", r.lanczos_runs}};
  nlohmann::ordered_json modes = nlohmann::ordered_json::array();
  fem::Vector6d sum = fem::Vector6d::Zero();
  for (std::size_t i = 0; i < r.modes.size(); ++i) {
    const fem::Mode& m = r.modes[i];
    nlohmann::ordered_json jm;
    jm["mode"] = i + 1;
    jm["frequency_hz"] = m.frequency_hz;
    jm["rigid_body"] = m.rigid_body;
    nlohmann::ordered_json eff, frac;
    for (int d = 0; d < 6; ++d) {
      eff[kDirections[d]] = eff_in_units(m.effective_mass, d);
      frac[kDirections[d]] = fraction(m.effective_mass, d);
    }
    sum += m.effective_mass;
    nlohmann::ordered_json gamma;
    for (int d = 0; d < 6; ++d) gamma[kDirections[d]] = m.participation(d) * std::sqrt(d < 3 ? mass_f : rot_f);
    jm["participation_factor"] = gamma;
    jm["effective_mass"] = eff;
    jm["effective_mass_fraction"] = frac;
    modes.push_back(jm);
  }
  frame["modes"] = modes;
  nlohmann::ordered_json cumulative;
  for (int d = 0; d < 6; ++d) cumulative[kDirections[d]] = fraction(sum, d);
  frame["effective_mass_fraction_sum"] = cumulative;
  frame["solver"] = {{"method", "shift-invert Lanczos (Spectra) on CHOLMOD, Sturm-count certified"}, {"shift_hz", -opt.shift_hz},
                     {"restarts", r.iterations}, {"operator_solves", r.operator_solves}};
  j["frame"] = frame;
  folder.write_text("summary.json", j.dump(2) + "\n");

  // modes.csv
  std::vector<std::string> headers = {"mode", report::column("frequency", "Hz"), "rigid_body"};
  for (int d = 0; d < 6; ++d)
    headers.push_back(report::column(std::string("effective_mass_") + kDirections[d], d < 3 ? u.label(Quantity::mass) : u.label(Quantity::rotary_inertia)));
  for (int d = 0; d < 6; ++d) headers.push_back(std::string("effective_mass_fraction_") + kDirections[d]);
  report::CsvTable table(headers);
  for (std::size_t i = 0; i < r.modes.size(); ++i) {
    const fem::Mode& m = r.modes[i];
    table.row().add(static_cast<int>(i + 1)).add(m.frequency_hz).add(std::string(m.rigid_body ? "yes" : "no"));
    for (int d = 0; d < 6; ++d) table.add(eff_in_units(m.effective_mass, d));
    for (int d = 0; d < 6; ++d) table.add(fraction(m.effective_mass, d));
  }
  folder.write_text("modes.csv", table.str());

  // mode_shapes.csv: mass-normalised, in the input's units.
  const double sqrt_m = std::sqrt(u.to_si_factor(Quantity::mass));
  const double tr_f = sqrt_m / u.to_si_factor(Quantity::length);
  const std::string tr_unit = u.label(Quantity::length) + "/sqrt(" + u.label(Quantity::mass) + ")";
  const std::string rot_unit = "rad/sqrt(" + u.label(Quantity::mass) + ")";
  report::CsvTable shapes({"mode", "node", report::column("ux", tr_unit), report::column("uy", tr_unit), report::column("uz", tr_unit),
                         report::column("rx", rot_unit), report::column("ry", rot_unit), report::column("rz", rot_unit)});
  std::vector<report::VtuField> fields;
  for (Eigen::Index i = 0; i < r.shapes.cols(); ++i) {
    double max_translation = 0.0;
    for (std::size_t n = 0; n < model.nodes.size(); ++n)
      max_translation = std::max(max_translation, r.shapes.col(i).segment<3>(static_cast<Eigen::Index>(6 * n)).norm());
    report::VtuField f{fmt::format("mode_{:02d}_{:.4g}Hz", i + 1, r.modes[static_cast<std::size_t>(i)].frequency_hz), 3, {}};
    for (std::size_t n = 0; n < model.nodes.size(); ++n) {
      const auto s = r.shapes.col(i).segment<6>(static_cast<Eigen::Index>(6 * n));
      shapes.row().add(static_cast<int>(i + 1)).add(model.nodes[n].id);
      for (int d = 0; d < 6; ++d) shapes.add(s(d) * (d < 3 ? tr_f : sqrt_m));
      for (int d = 0; d < 3; ++d) f.values.push_back(max_translation > 0 ? s(d) / max_translation : 0.0);
    }
    fields.push_back(std::move(f));
  }
  folder.write_text("mode_shapes.csv", shapes.str());
  folder.write_text("modes.vtu", report::vtu_document(model, 1.0 / u.to_si_factor(Quantity::length), fields, {}));
  folder.commit();
  progress.done();

  // The table.
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
  fmt::print("\nresults in {}/ (summary.json, modes.csv, mode_shapes.csv, modes.vtu)\n", out_dir);
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
  opt->progress.add_to(*cmd);
  cmd->callback([opt, &run]() { run = [opt]() { return run_modes(*opt); }; });
}

}  // namespace framedyn::apps
