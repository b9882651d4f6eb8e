// The outputs of `framedyn transient` (a *MODAL DYNAMIC or *DYNAMIC step of a
// deck): displacement_history.csv (time, node, ux..rz of the output nodes at
// every output time) and summary.json (key "frame.transient": procedure,
// scheme, increment, period, modes used, and the largest translation with its
// node, DOF and time), in the mesh's units.
#pragma once

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "core/results_folder.h"
#include "fem/transient_step.h"

namespace framedyn::report {

struct TransientStepRun {
  std::string mesh_path;
  std::vector<int> output_nodes;  // node indices
};

// The largest translation component |u| over the output nodes and times. Of
// entries within 1e-6 relative of the largest the earliest time, then the
// lowest node index, then the lowest DOF is named, so that round-off never
// picks between near-equal peaks.
struct TransientPeak {
  double value = 0.0;  // SI, signed
  int node = 0;        // mesh node number
  int dof = 0;         // 0..2
  double time = 0.0;   // s
};
TransientPeak transient_peak(const fem::FrameModel& model, const fem::TransientResult& r, const std::vector<int>& output_nodes);

// Writes displacement_history.csv and returns summary.json's content (the
// caller adds the run's warnings and writes it).
nlohmann::ordered_json write_transient_step_results(const fem::FrameModel& model, const fem::TransientStepResult& result,
                                                    const TransientStepRun& run, const core::ResultsFolder& folder);

}  // namespace framedyn::report
