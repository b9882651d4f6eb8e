// Outputs of a transient step run; see transient_step_outputs.h.
#include "report/transient_step_outputs.h"

#include <cmath>

#include "core/units.h"
#include "report/csv_writer.h"

namespace framedyn::report {

using core::Quantity;

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

nlohmann::ordered_json write_transient_step_results(const fem::FrameModel& model, const fem::TransientStepResult& result,
                                                    const TransientStepRun& run, const core::ResultsFolder& folder) {
  const core::UnitSystem& u = model.units;
  const double lf = 1.0 / u.to_si_factor(Quantity::length);
  const std::string L = u.label(Quantity::length);
  const fem::TransientResult& r = result.response;

  CsvTable h({"time [s]", "node", column("ux", L), column("uy", L), column("uz", L), "rx [rad]", "ry [rad]", "rz [rad]"});
  for (Eigen::Index k = 0; k < r.times.size(); ++k)
    for (int n : run.output_nodes) {
      h.row().add(r.times(k)).add(model.nodes[static_cast<std::size_t>(n)].id);
      for (int d = 0; d < fem::kDofsPerNode; ++d) h.add(r.displacement(fem::kDofsPerNode * n + d, k) * (d < 3 ? lf : 1.0));
    }
  folder.write_text("displacement_history.csv", h.str());

  const fem::AnalysisStep& step = model.steps.at(static_cast<std::size_t>(result.step - 1));
  const TransientPeak p = transient_peak(model, r, run.output_nodes);
  nlohmann::ordered_json j;
  j["framedyn"] = {{"version", FRAMEDYN_VERSION}, {"command", "transient"}};
  j["input"] = {{"mesh", run.mesh_path}, {"units", u.name()}, {"step", result.step}};
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
  j["frame"] = {{"nodes", model.nodes.size()}, {"beam_elements", model.beams.size()}, {"transient", t}};
  return j;
}

}  // namespace framedyn::report
