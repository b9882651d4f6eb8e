// The outputs of `framedyn static`; see static_outputs.h.
#include "report/static_outputs.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <map>

#include "fem/section_stress.h"
#include "report/csv_writer.h"
#include "report/summary_warnings.h"
#include "report/vtu_writer.h"

namespace framedyn::report {

namespace {

using core::Quantity;

// A station's largest and smallest fiber stress (SI), 0 and 0 without stress points.
std::pair<double, double> fiber_extremes(const fem::StationResult& s) {
  if (s.fiber_stress.empty()) return {0.0, 0.0};
  return {*std::max_element(s.fiber_stress.begin(), s.fiber_stress.end()), *std::min_element(s.fiber_stress.begin(), s.fiber_stress.end())};
}

// Whether the mesh supports node index n (a *BOUNDARY on any of its DOFs): reactions.csv's rows.
bool supported(const fem::FrameModel& model, std::size_t n) {
  bool constrained = false;
  for (const fem::Constraint& c : model.constraints) constrained = constrained || c.node == static_cast<int>(n);
  return constrained;
}

}  // namespace

StaticPeaks static_peaks(const fem::FrameModel& model, const fem::StaticResult& r, const std::vector<fem::StationResult>& stations) {
  const core::UnitSystem& u = model.units;
  const double lf = 1.0 / u.to_si_factor(Quantity::length), ff = 1.0 / u.to_si_factor(Quantity::force), sf = 1.0 / u.to_si_factor(Quantity::stress);
  StaticPeaks p;
  double max_disp = 0.0;
  for (std::size_t n = 0; n < model.nodes.size(); ++n) {
    const auto d = r.displacement.segment<6>(static_cast<Eigen::Index>(6 * n));
    if (d.head<3>().norm() > max_disp) {
      max_disp = d.head<3>().norm();
      p.max_displacement_node = model.nodes[n].id;
    }
  }
  p.max_displacement = max_disp * lf;
  Eigen::Vector3d total = Eigen::Vector3d::Zero();
  for (std::size_t n = 0; n < model.nodes.size(); ++n) {
    if (supported(model, n)) total += r.reaction.segment<3>(static_cast<Eigen::Index>(6 * n));
  }
  p.reaction_force_sum = total * ff;
  double peak_stress = 0.0;
  for (const fem::StationResult& s : stations) {
    const auto [smax, smin] = fiber_extremes(s);
    const double peak = std::max(std::abs(smax), std::abs(smin));
    if (peak > peak_stress) {
      peak_stress = peak;
      p.peak_fiber_stress_element = s.element_id;
    }
  }
  p.peak_fiber_stress = peak_stress * sf;
  Eigen::Vector3d applied = Eigen::Vector3d::Zero();
  for (std::size_t n = 0; n < model.nodes.size(); ++n) applied += r.applied.segment<3>(static_cast<Eigen::Index>(6 * n));
  p.applied_force_sum = applied * ff;
  return p;
}

void write_static_results(const fem::FrameModel& model, const fem::StaticResult& r, const std::vector<fem::StationResult>& stations,
                          const StaticRun& run, const core::ResultsFolder& folder) {
  const core::UnitSystem& u = model.units;
  const double lf = 1.0 / u.to_si_factor(Quantity::length), ff = 1.0 / u.to_si_factor(Quantity::force);
  const double mf = 1.0 / u.to_si_factor(Quantity::moment), sf = 1.0 / u.to_si_factor(Quantity::stress);
  const std::string L = u.label(Quantity::length), F = u.label(Quantity::force), M = u.label(Quantity::moment), S = u.label(Quantity::stress);
  const StaticPeaks peaks = static_peaks(model, r, stations);

  CsvTable disp({"node", column("ux", L), column("uy", L), column("uz", L), "rx [rad]", "ry [rad]", "rz [rad]"});
  for (std::size_t n = 0; n < model.nodes.size(); ++n) {
    const auto d = r.displacement.segment<6>(static_cast<Eigen::Index>(6 * n));
    disp.row().add(model.nodes[n].id);
    for (int k = 0; k < 6; ++k) disp.add(d(k) * (k < 3 ? lf : 1.0));
  }
  folder.write_text("displacements" + run.file_suffix + ".csv", disp.str());

  CsvTable reac({"node", column("fx", F), column("fy", F), column("fz", F), column("mx", M), column("my", M), column("mz", M)});
  for (std::size_t n = 0; n < model.nodes.size(); ++n) {
    const auto rn = r.reaction.segment<6>(static_cast<Eigen::Index>(6 * n));
    if (!supported(model, n)) continue;
    reac.row().add(model.nodes[n].id);
    for (int k = 0; k < 6; ++k) reac.add(rn(k) * (k < 3 ? ff : mf));
  }
  folder.write_text("reactions" + run.file_suffix + ".csv", reac.str());

  CsvTable sec({"element", "station", column("x", L), column("X", L), column("Y", L), column("Z", L), column("N", F), column("Vy", F),
                column("Vz", F), column("T", M), column("My", M), column("Mz", M), column("fiber_stress_max", S), column("fiber_stress_min", S),
                column("von_mises_max", S), column("shear_max", S)});
  std::vector<double> cell_max(model.beams.size(), 0.0);
  std::map<int, std::size_t> beam_pos;
  for (std::size_t i = 0; i < model.beams.size(); ++i) beam_pos[model.beams[i].id] = i;
  // The section points of every section (fem/section_stress.h): von Mises and |tau| over them, per station.
  std::vector<std::vector<fem::SectionPoint>> points;
  for (const fem::SectionAssignment& a : model.sections) points.push_back(fem::section_points(a.properties));
  for (const fem::StationResult& s : stations) {
    const auto [smax, smin] = fiber_extremes(s);
    const double peak = std::max(std::abs(smax), std::abs(smin));
    double& cm = cell_max[beam_pos[s.element_id]];
    cm = std::max(cm, peak * sf);
    sec.row().add(s.element_id).add(s.station).add(s.x * lf).add(s.point.x() * lf).add(s.point.y() * lf).add(s.point.z() * lf);
    sec.add(s.forces.n * ff).add(s.forces.vy * ff).add(s.forces.vz * ff).add(s.forces.t * mf).add(s.forces.my * mf).add(s.forces.mz * mf);
    sec.add(s.fiber_stress.empty() ? 0.0 : smax * sf).add(s.fiber_stress.empty() ? 0.0 : smin * sf);
    const std::size_t section = static_cast<std::size_t>(model.beams[beam_pos[s.element_id]].section);
    double von_mises = 0.0, shear = 0.0;  // 0 for a GENERAL section (no points)
    for (const fem::PointStress& p : fem::point_stresses(model.sections[section].properties, points[section], s.forces)) {
      von_mises = std::max(von_mises, p.von_mises);
      shear = std::max(shear, p.shear);
    }
    sec.add(von_mises * sf).add(shear * sf);
  }
  folder.write_text("section_forces" + run.file_suffix + ".csv", sec.str());

  VtuField dfield{"displacement [" + L + "]", 3, {}}, rfield{"rotation [rad]", 3, {}};
  for (std::size_t n = 0; n < model.nodes.size(); ++n)
    for (int k = 0; k < 3; ++k) {
      dfield.values.push_back(r.displacement(static_cast<Eigen::Index>(6 * n + static_cast<std::size_t>(k))) * lf);
      rfield.values.push_back(r.displacement(static_cast<Eigen::Index>(6 * n + 3 + static_cast<std::size_t>(k))));
    }
  // Section forces at both ends of every element, as cell data.
  std::vector<VtuField> cells{{"max_abs_fiber_stress [" + S + "]", 1, cell_max}};
  const char* names[6] = {"N", "Vy", "Vz", "T", "My", "Mz"};
  const std::size_t per_element = static_cast<std::size_t>(run.stations);
  for (int end = 0; end < 2; ++end)
    for (int k = 0; k < 6; ++k) {
      VtuField f{fmt::format("{}_end{} [{}]", names[k], end + 1, k < 3 ? F : M), 1, {}};
      for (std::size_t i = 0; i < model.beams.size(); ++i) {
        const fem::SectionForces& s = stations[i * per_element + (end == 0 ? 0 : per_element - 1)].forces;
        const double v[6] = {s.n, s.vy, s.vz, s.t, s.my, s.mz};
        f.values.push_back(v[k] * (k < 3 ? ff : mf));
      }
      cells.push_back(std::move(f));
    }
  folder.write_text("static" + run.file_suffix + ".vtu", vtu_document(model, lf, {dfield, rfield}, cells));

  nlohmann::ordered_json j;
  j["framedyn"] = {{"version", FRAMEDYN_VERSION}, {"command", "static"}};
  j["input"] = {{"mesh", run.mesh_path}, {"units", u.name()}};
  if (run.step > 0) j["input"]["step"] = run.step;
  const Eigen::Vector3d& applied = peaks.applied_force_sum;
  const Eigen::Vector3d& total = peaks.reaction_force_sum;
  j["frame"] = {
      {"nodes", model.nodes.size()},
      {"beam_elements", model.beams.size()},
      {"max_displacement", {{"value", peaks.max_displacement}, {"unit", L}, {"node", peaks.max_displacement_node}}},
      {"peak_fiber_stress", {{"value", peaks.peak_fiber_stress}, {"unit", S}, {"element", peaks.peak_fiber_stress_element}}},
      {"applied_force_sum", {{"value", {applied.x(), applied.y(), applied.z()}}, {"unit", F}}},
      {"reaction_force_sum", {{"value", {total.x(), total.y(), total.z()}}, {"unit", F}}},
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
  add_warnings(j, model.reader_warnings);
  folder.write_text("summary" + run.file_suffix + ".json", j.dump(2) + "\n");
}

}  // namespace framedyn::report
