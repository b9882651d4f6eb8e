// Outputs of a transient step run; see transient_step_outputs.h.
#include "report/transient_step_outputs.h"

#include <fmt/format.h>

#include <cmath>

#include "core/units.h"
#include "fem/distributed_loads.h"
#include "fem/section_forces.h"
#include "report/csv_writer.h"
#include "report/summary_warnings.h"
#include "report/xdmf_writer.h"

namespace framedyn::report {

using core::Quantity;

namespace {

// The six section forces in the order the outputs list them: N, Vy, Vz, T, My, Mz.
constexpr const char* kForceNames[6] = {"N", "Vy", "Vz", "T", "My", "Mz"};
double component(const fem::SectionForces& s, int k) {
  const double v[6] = {s.n, s.vy, s.vz, s.t, s.my, s.mz};
  return v[k];
}

}  // namespace

TransientPeak transient_peak(const fem::FrameModel& model, const fem::TransientResult& r, const std::vector<int>& output_nodes) {
  double largest = 0.0;
  for (Eigen::Index k = 0; k < r.times.size(); ++k)
    for (int n : output_nodes)
      for (int d = 0; d < 3; ++d) largest = std::max(largest, std::abs(r.displacement(fem::kDofsPerNode * n + d, k)));
  TransientPeak p;
  for (Eigen::Index k = 0; k < r.times.size(); ++k)
    for (int n : output_nodes)
      for (int d = 0; d < 3; ++d) {
        const double v = r.displacement(fem::kDofsPerNode * n + d, k);
        if (largest > 0.0 && std::abs(v) >= largest * (1.0 - 1e-6)) {
          p = {v, model.nodes[static_cast<std::size_t>(n)].id, d, r.times(k)};
          return p;
        }
      }
  return p;
}

EndForceHistory transient_end_forces(const fem::FrameModel& model, const fem::TransientStepResult& result) {
  // The step's own line loads (constant through the step: their fixed-end terms at every time).
  const fem::FrameModel step = fem::with_step(model, static_cast<std::size_t>(result.step - 1));
  const std::vector<fem::BeamLineLoad> line_loads = fem::beam_line_loads(step);
  const fem::TransientResult& r = result.response;
  EndForceHistory out(static_cast<std::size_t>(r.times.size()));
  Eigen::VectorXd u;
  for (Eigen::Index k = 0; k < r.times.size(); ++k) {
    u = r.displacement.col(k);
    std::vector<fem::SectionForces>& row = out[static_cast<std::size_t>(k)];
    row.reserve(2 * step.beams.size());
    for (std::size_t i = 0; i < step.beams.size(); ++i) {
      const std::vector<fem::StationResult> ends = fem::beam_stations(step, static_cast<int>(i), u, 2, line_loads[i]);
      row.push_back(ends.front().forces);
      row.push_back(ends.back().forces);
    }
  }
  return out;
}

TransientMomentPeak transient_moment_peak(const fem::FrameModel& model, const fem::TransientResult& r, const EndForceHistory& forces,
                                          const std::vector<int>& output_beams) {
  const auto moment = [&](std::size_t k, int beam, int end) {
    const fem::SectionForces& s = forces[k][2 * static_cast<std::size_t>(beam) + static_cast<std::size_t>(end)];
    return std::hypot(s.my, s.mz);
  };
  double largest = 0.0;
  for (std::size_t k = 0; k < forces.size(); ++k)
    for (int b : output_beams)
      for (int end = 0; end < 2; ++end) largest = std::max(largest, moment(k, b, end));
  for (std::size_t k = 0; k < forces.size(); ++k)
    for (int b : output_beams)
      for (int end = 0; end < 2; ++end)
        if (largest > 0.0 && moment(k, b, end) >= largest * (1.0 - 1e-6))
          return {moment(k, b, end), model.beams[static_cast<std::size_t>(b)].id, end + 1, r.times(static_cast<Eigen::Index>(k))};
  return {};
}

nlohmann::ordered_json write_transient_step_results(const fem::FrameModel& model, const fem::TransientStepResult& result,
                                                    const TransientStepRun& run, const core::ResultsFolder& folder) {
  const core::UnitSystem& u = model.units;
  const double lf = 1.0 / u.to_si_factor(Quantity::length), ff = 1.0 / u.to_si_factor(Quantity::force), mf = 1.0 / u.to_si_factor(Quantity::moment);
  const std::string L = u.label(Quantity::length), F = u.label(Quantity::force), M = u.label(Quantity::moment);
  const fem::TransientResult& r = result.response;

  CsvTable h({"time [s]", "node", column("ux", L), column("uy", L), column("uz", L), "rx [rad]", "ry [rad]", "rz [rad]"});
  for (Eigen::Index k = 0; k < r.times.size(); ++k)
    for (int n : run.output_nodes) {
      h.row().add(r.times(k)).add(model.nodes[static_cast<std::size_t>(n)].id);
      for (int d = 0; d < fem::kDofsPerNode; ++d) h.add(r.displacement(fem::kDofsPerNode * n + d, k) * (d < 3 ? lf : 1.0));
    }
  folder.write_text("displacement_history.csv", h.str());

  // Section forces at the element ends (docs/theory/fem.md section 24).
  const EndForceHistory forces = transient_end_forces(model, result);
  const auto scale = [&](int k) { return k < 3 ? ff : mf; };
  CsvTable sf({"time [s]", "element", "end", column("N", F), column("Vy", F), column("Vz", F), column("T", M), column("My", M), column("Mz", M)});
  for (std::size_t k = 0; k < forces.size(); ++k)
    for (int b : run.output_beams)
      for (int end = 0; end < 2; ++end) {
        sf.row().add(r.times(static_cast<Eigen::Index>(k))).add(model.beams[static_cast<std::size_t>(b)].id).add(end + 1);
        const fem::SectionForces& s = forces[k][2 * static_cast<std::size_t>(b) + static_cast<std::size_t>(end)];
        for (int c = 0; c < 6; ++c) sf.add(component(s, c) * scale(c));
      }
  folder.write_text("section_force_history.csv", sf.str());

  if (run.paraview) {
    // transient.xdmf + transient.h5: per node the displacement and rotation,
    // per element the end forces under static.vtu's names (N_end1 ... Mz_end2).
    XdmfSeries series(folder, "transient", model, lf, static_cast<int>(r.times.size()));
    for (Eigen::Index k = 0; k < r.times.size(); ++k) {
      VtuField disp{"displacement [" + L + "]", 3, {}}, rot{"rotation [rad]", 3, {}};
      for (std::size_t n = 0; n < model.nodes.size(); ++n)
        for (int d = 0; d < 3; ++d) {
          disp.values.push_back(r.displacement(static_cast<Eigen::Index>(fem::kDofsPerNode * n) + d, k) * lf);
          rot.values.push_back(r.displacement(static_cast<Eigen::Index>(fem::kDofsPerNode * n) + 3 + d, k));
        }
      std::vector<VtuField> cells;
      for (int end = 0; end < 2; ++end)
        for (int c = 0; c < 6; ++c) {
          VtuField f{fmt::format("{}_end{} [{}]", kForceNames[c], end + 1, c < 3 ? F : M), 1, {}};
          for (std::size_t b = 0; b < model.beams.size(); ++b) f.values.push_back(component(forces[static_cast<std::size_t>(k)][2 * b + static_cast<std::size_t>(end)], c) * scale(c));
          cells.push_back(std::move(f));
        }
      series.add(r.times(k), {disp, rot}, cells);
    }
    series.finish();
  }

  const fem::AnalysisStep& step = model.steps.at(static_cast<std::size_t>(result.step - 1));
  const TransientPeak p = transient_peak(model, r, run.output_nodes);
  const TransientMomentPeak m = transient_moment_peak(model, r, forces, run.output_beams);
  nlohmann::ordered_json j;
  j["framedyn"] = {{"version", FRAMEDYN_VERSION}, {"command", "transient"}};
  j["input"] = {{"mesh", run.mesh_path}, {"units", u.name()}, {"step", result.step}};
  if (!run.element_set.empty()) j["input"]["element_set"] = run.element_set;
  nlohmann::ordered_json t = {{"procedure", result.procedure},
                              {"scheme", result.scheme},
                              {"time_increment", {{"value", step.transient->time_increment}, {"unit", "s"}}},
                              {"time_period", {{"value", step.transient->time_period}, {"unit", "s"}}},
                              {"output_times", r.times.size()}};
  if (result.frequency_step > 0) {
    t["frequency_step"] = result.frequency_step;
    t["mode_frequencies"] = {{"value", std::vector<double>(r.frequencies_hz.data(), r.frequencies_hz.data() + r.frequencies_hz.size())}, {"unit", "Hz"}};
    t["damping_ratios"] = std::vector<double>(r.damping_ratios.data(), r.damping_ratios.data() + r.damping_ratios.size());
  }
  t["max_displacement"] = {{"value", p.value * lf}, {"unit", L}, {"node", p.node}, {"dof", fem::dof_name(p.dof)}, {"time", p.time}};
  t["max_bending_moment"] = {{"value", m.value * mf}, {"unit", M}, {"element", m.element}, {"end", m.end}, {"time", m.time}};
  j["frame"] = {{"nodes", model.nodes.size()}, {"beam_elements", model.beams.size()}, {"transient", t}};
  add_warnings(j, model.reader_warnings);
  return j;
}

}  // namespace framedyn::report
