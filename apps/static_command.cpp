// `framedyn static MESH.inp`: linear static response to the mesh's *CLOAD
// and *DLOAD loads and *BOUNDARY supports. Writes DIR/summary.json, displacements.csv,
// reactions.csv, section_forces.csv (with fiber stresses) and static.vtu.
#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "apps/command_line.h"
#include "apps/commands.h"
#include "apps/mesh_input.h"
#include "apps/progress.h"
#include "report/csv_writer.h"
#include "core/error.h"
#include "core/results_folder.h"
#include "fem/partial_supports.h"
#include "fem/section_forces.h"
#include "fem/static_analysis.h"
#include "report/vtu_writer.h"

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
  if (model.loads.empty() && model.element_loads.empty())
    throw core::InputError({opt.mesh.path, 0, "*CLOAD"}, "at least one nodal load (*CLOAD) or distributed load (*DLOAD) for a static analysis", "none");
  fem::StaticOptions so;
  so.inertia_relief = opt.inertia_relief;
  fem::StaticResult r;
  try {
    r = fem::solve_static(model, progress.callback(), so);
  } catch (const fem::UnbalancedLoadError& e) {
    // Loads that do work on a rigid motion the supports leave free (docs/theory/fem.md, Eq. 19.1): the input's fault, named as such.
    throw core::InputError({opt.mesh.path, 0, model.loads.empty() ? "*DLOAD" : "*CLOAD"},
                           "loads that do no work on the rigid motions the supports leave free (add supports, balance the loads, or ask for "
                           "--inertia-relief)",
                           e.what());
  }
  if (opt.inertia_relief && r.free_rigid_motions == 0)
    throw nothing_to_relieve(opt.mesh.path);
  progress.stage("recovering section forces");
  const std::vector<fem::StationResult> stations = fem::recover_stations(model, r.displacement, opt.stations);

  const double lf = 1.0 / u.to_si_factor(Quantity::length), ff = 1.0 / u.to_si_factor(Quantity::force);
  const double mf = 1.0 / u.to_si_factor(Quantity::moment), sf = 1.0 / u.to_si_factor(Quantity::stress);
  const std::string L = u.label(Quantity::length), F = u.label(Quantity::force), M = u.label(Quantity::moment), S = u.label(Quantity::stress);

  progress.stage("writing results");
  core::ResultsFolder folder(out_dir, {opt.mesh.path});

  report::CsvTable disp({"node", report::column("ux", L), report::column("uy", L), report::column("uz", L), "rx [rad]", "ry [rad]", "rz [rad]"});
  double max_disp = 0.0;
  int max_disp_node = 0;
  for (std::size_t n = 0; n < model.nodes.size(); ++n) {
    const auto d = r.displacement.segment<6>(static_cast<Eigen::Index>(6 * n));
    disp.row().add(model.nodes[n].id);
    for (int k = 0; k < 6; ++k) disp.add(d(k) * (k < 3 ? lf : 1.0));
    if (d.head<3>().norm() > max_disp) {
      max_disp = d.head<3>().norm();
      max_disp_node = model.nodes[n].id;
    }
  }
  folder.write_text("displacements.csv", disp.str());

  report::CsvTable reac({"node", report::column("fx", F), report::column("fy", F), report::column("fz", F), report::column("mx", M),
                       report::column("my", M), report::column("mz", M)});
  Eigen::Matrix<double, 6, 1> total = Eigen::Matrix<double, 6, 1>::Zero();
  for (std::size_t n = 0; n < model.nodes.size(); ++n) {
    const auto rn = r.reaction.segment<6>(static_cast<Eigen::Index>(6 * n));
    bool constrained = false;
    for (const fem::Constraint& c : model.constraints) constrained = constrained || c.node == static_cast<int>(n);
    if (!constrained) continue;
    reac.row().add(model.nodes[n].id);
    for (int k = 0; k < 6; ++k) reac.add(rn(k) * (k < 3 ? ff : mf));
    total.head<3>() += rn.head<3>();
  }
  folder.write_text("reactions.csv", reac.str());

  report::CsvTable sec({"element", "station", report::column("x", L), report::column("X", L), report::column("Y", L), report::column("Z", L),
                      report::column("N", F), report::column("Vy", F), report::column("Vz", F), report::column("T", M), report::column("My", M),
                      report::column("Mz", M), report::column("fiber_stress_max", S), report::column("fiber_stress_min", S)});
  double peak_stress = 0.0;
  int peak_element = 0;
  std::vector<double> cell_max(model.beams.size(), 0.0);
  std::map<int, std::size_t> beam_pos;
  for (std::size_t i = 0; i < model.beams.size(); ++i) beam_pos[model.beams[i].id] = i;
  for (const fem::StationResult& s : stations) {
    double smax = 0.0, smin = 0.0;
    if (!s.fiber_stress.empty()) {
      smax = *std::max_element(s.fiber_stress.begin(), s.fiber_stress.end());
      smin = *std::min_element(s.fiber_stress.begin(), s.fiber_stress.end());
    }
    const double peak = std::max(std::abs(smax), std::abs(smin));
    if (peak > peak_stress) {
      peak_stress = peak;
      peak_element = s.element_id;
    }
    double& cm = cell_max[beam_pos[s.element_id]];
    cm = std::max(cm, peak * sf);
    sec.row().add(s.element_id).add(s.station).add(s.x * lf).add(s.point.x() * lf).add(s.point.y() * lf).add(s.point.z() * lf);
    sec.add(s.forces.n * ff).add(s.forces.vy * ff).add(s.forces.vz * ff).add(s.forces.t * mf).add(s.forces.my * mf).add(s.forces.mz * mf);
    sec.add(s.fiber_stress.empty() ? 0.0 : smax * sf).add(s.fiber_stress.empty() ? 0.0 : smin * sf);
  }
  folder.write_text("section_forces.csv", sec.str());

  report::VtuField dfield{"displacement [" + L + "]", 3, {}}, rfield{"rotation [rad]", 3, {}};
  for (std::size_t n = 0; n < model.nodes.size(); ++n)
    for (int k = 0; k < 3; ++k) {
      dfield.values.push_back(r.displacement(static_cast<Eigen::Index>(6 * n + static_cast<std::size_t>(k))) * lf);
      rfield.values.push_back(r.displacement(static_cast<Eigen::Index>(6 * n + 3 + static_cast<std::size_t>(k))));
    }
  // Section forces at both ends of every element, as cell data.
  std::vector<report::VtuField> cells{{"max_abs_fiber_stress [" + S + "]", 1, cell_max}};
  const char* names[6] = {"N", "Vy", "Vz", "T", "My", "Mz"};
  for (int end = 0; end < 2; ++end)
    for (int k = 0; k < 6; ++k) {
      report::VtuField f{fmt::format("{}_end{} [{}]", names[k], end + 1, k < 3 ? F : M), 1, {}};
      for (std::size_t i = 0; i < model.beams.size(); ++i) {
        const fem::SectionForces& sf = stations[i * static_cast<std::size_t>(opt.stations) + (end == 0 ? 0 : static_cast<std::size_t>(opt.stations) - 1)].forces;
        const double v[6] = {sf.n, sf.vy, sf.vz, sf.t, sf.my, sf.mz};
        f.values.push_back(v[k] * (k < 3 ? ff : mf));
      }
      cells.push_back(std::move(f));
    }
  folder.write_text("static.vtu", report::vtu_document(model, lf, {dfield, rfield}, cells));

  nlohmann::ordered_json j;
  j["framedyn"] = {{"version", FRAMEDYN_VERSION}, {"command", "static"}};
  j["input"] = {{"mesh", opt.mesh.path}, {"units", u.name()}};
  Eigen::Vector3d applied = Eigen::Vector3d::Zero();
  for (std::size_t n = 0; n < model.nodes.size(); ++n) applied += r.applied.segment<3>(static_cast<Eigen::Index>(6 * n));
  j["frame"] = {
      {"nodes", model.nodes.size()},
      {"beam_elements", model.beams.size()},
      {"max_displacement", {{"value", max_disp * lf}, {"unit", L}, {"node", max_disp_node}}},
      {"peak_fiber_stress", {{"value", peak_stress * sf}, {"unit", S}, {"element", peak_element}}},
      {"applied_force_sum", {{"value", {applied.x() * ff, applied.y() * ff, applied.z() * ff}}, {"unit", F}}},
      {"reaction_force_sum", {{"value", {total.x() * ff, total.y() * ff, total.z() * ff}}, {"unit", F}}},
      {"relative_residual", r.relative_residual}};
  // A partially supported or free frame (docs/theory/fem.md, section 19): the
  // displacement is one solution; any free rigid motion may be added to it.
  nlohmann::ordered_json rigid = {{"count", r.free_rigid_motions}, {"parts", r.free_motions}};
  if (r.free_rigid_motions > 0) {
    nlohmann::ordered_json held = nlohmann::ordered_json::array();
    for (int g : r.auxiliary_dofs) held.push_back(model.describe_dof(g));
    rigid["auxiliary_supports"] = held;
    if (r.inertia_relief) {
      rigid["solution"] = "inertia relief: the elastic part (no rigid motion in the mean, R^T M u = 0)";
      double amax = 0.0;
      int anode = 0;
      for (std::size_t n = 0; n < model.nodes.size(); ++n)
        if (const double a = r.rigid_acceleration.segment<3>(static_cast<Eigen::Index>(6 * n)).norm(); a > amax * (1.0 + 1e-9)) amax = a, anode = model.nodes[n].id;
      rigid["max_rigid_acceleration"] = {{"value", amax * lf}, {"unit", L + "/s^2"}, {"node", anode}};
    } else {
      rigid["solution"] = "balanced loads: the displacement with the auxiliary supports held, defined up to a free rigid motion";
    }
  }
  j["frame"]["free_rigid_motions"] = rigid;
  folder.write_text("summary.json", j.dump(2) + "\n");
  folder.commit();
  progress.done();
  if (progress.quiet()) {  // -q: errors only, and the results folder on stdout
    fmt::print("results in {}/\n", out_dir);
    return 0;
  }

  fmt::print("framedyn static: {} ({} nodes, {} beam elements, units {})\n", opt.mesh.path, model.nodes.size(), model.beams.size(), u.name());
  fmt::print("max displacement {:.6g} {} at node {}\n", max_disp * lf, L, max_disp_node);
  fmt::print("peak fiber stress {:.6g} {} in element {}\n", peak_stress * sf, S, peak_element);
  fmt::print("applied force sum ({:.6g}, {:.6g}, {:.6g}) {}; reactions ({:.6g}, {:.6g}, {:.6g}) {}\n", applied.x() * ff, applied.y() * ff,
             applied.z() * ff, F, total.x() * ff, total.y() * ff, total.z() * ff, F);
  if (r.free_rigid_motions > 0)
    fmt::print("{} free rigid motion(s) ({}): {}\n", r.free_rigid_motions, r.free_motions,
               r.inertia_relief ? "loads relieved by their inertia, elastic part shown"
                                : "loads balanced on them; the displacement is defined up to that rigid motion");
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
