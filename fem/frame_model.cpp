// Look-ups on the frame model.
#include "fem/frame_model.h"

#include <fmt/format.h>

#include <algorithm>

namespace framedyn::fem {

const char* dof_name(int dof) {
  static const char* names[] = {"ux", "uy", "uz", "rx", "ry", "rz"};
  return (dof >= 0 && dof < 6) ? names[dof] : "?";
}

void FrameModel::index() {
  node_lookup_.clear();
  sparse_node_lookup_.clear();
  int max_id = 0;
  for (const Node& n : nodes) max_id = std::max(max_id, n.id);
  const bool dense = max_id <= 4 * static_cast<int>(nodes.size()) + 1024;
  if (dense) {
    node_lookup_.assign(static_cast<std::size_t>(max_id) + 1, -1);
    for (std::size_t i = 0; i < nodes.size(); ++i)
      if (nodes[i].id >= 0) node_lookup_[static_cast<std::size_t>(nodes[i].id)] = static_cast<int>(i);
  } else {
    for (std::size_t i = 0; i < nodes.size(); ++i) sparse_node_lookup_[nodes[i].id] = static_cast<int>(i);
  }
  beam_lookup_.clear();
  for (std::size_t i = 0; i < beams.size(); ++i) beam_lookup_[beams[i].id] = static_cast<int>(i);
}

int FrameModel::node_index(int id) const {
  if (!node_lookup_.empty()) {
    if (id < 0 || id >= static_cast<int>(node_lookup_.size())) return -1;
    return node_lookup_[static_cast<std::size_t>(id)];
  }
  auto it = sparse_node_lookup_.find(id);
  if (it != sparse_node_lookup_.end()) return it->second;
  // Not indexed yet: linear search keeps small hand-built models working.
  for (std::size_t i = 0; i < nodes.size(); ++i)
    if (nodes[i].id == id) return static_cast<int>(i);
  return -1;
}

int FrameModel::beam_index(int id) const {
  auto it = beam_lookup_.find(id);
  if (it != beam_lookup_.end()) return it->second;
  for (std::size_t i = 0; i < beams.size(); ++i)
    if (beams[i].id == id) return static_cast<int>(i);
  return -1;
}

std::string FrameModel::describe_dof(int global_dof) const {
  const int node = global_dof / kDofsPerNode;
  const int dof = global_dof % kDofsPerNode;
  if (node < 0 || node >= static_cast<int>(nodes.size())) return fmt::format("dof {}", global_dof);
  return fmt::format("node {} ({})", nodes[static_cast<std::size_t>(node)].id, dof_name(dof));
}

double Amplitude::at(double t) const {
  if (times.empty()) return 1.0;
  if (t <= times.front()) return values.front();
  if (t >= times.back()) return values.back();
  // The last point at or before t (a repeated time is a jump: the later value holds from it on).
  const std::size_t i = static_cast<std::size_t>(std::upper_bound(times.begin(), times.end(), t) - times.begin()) - 1;
  if (times[i + 1] == times[i]) return values[i + 1];
  return values[i] + (values[i + 1] - values[i]) * (t - times[i]) / (times[i + 1] - times[i]);
}

FrameModel with_step(const FrameModel& model, std::size_t step) {
  FrameModel m = model;
  const AnalysisStep& s = model.steps.at(step);
  m.constraints = s.constraints;
  m.loads = s.loads;
  m.element_loads = s.element_loads;
  if (s.requested_modes) m.requested_modes = s.requested_modes;
  return m;
}

FrameModel with_frequency_step(const FrameModel& model) {
  for (std::size_t i = 0; i < model.steps.size(); ++i)
    if (model.steps[i].procedure == "FREQUENCY") return with_step(model, i);
  return model;
}

}  // namespace framedyn::fem
