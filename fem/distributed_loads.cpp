// Consistent nodal loads of uniform line loads; see distributed_loads.h.
#include "fem/distributed_loads.h"

#include "fem/beam_element.h"

namespace framedyn::fem {

std::vector<Eigen::Vector3d> beam_line_loads(const FrameModel& model) {
  std::vector<Eigen::Vector3d> q(model.beams.size(), Eigen::Vector3d::Zero());
  for (const ElementLoad& l : model.element_loads) q.at(static_cast<std::size_t>(l.beam)) += l.force_per_length;
  return q;
}

Eigen::VectorXd element_load_vector(const FrameModel& model) {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(model.dof_count());
  if (model.element_loads.empty()) return f;
  const std::vector<Eigen::Vector3d> q = beam_line_loads(model);
  for (std::size_t i = 0; i < model.beams.size(); ++i) {
    if (q[i].isZero(0.0)) continue;
    const BeamElement& beam = model.beams[i];
    const BeamGeometry g = beam_geometry(model, beam);
    const Vector12d p_local = beam_local_uniform_load(g.data, g.axes * q[i]);
    const Vector12d p = beam_transformation(g.axes).transpose() * p_local;
    f.segment<6>(kDofsPerNode * beam.node_a) += p.head<6>();
    f.segment<6>(kDofsPerNode * beam.node_b) += p.tail<6>();
  }
  return f;
}

Eigen::VectorXd applied_load_vector(const FrameModel& model) {
  Eigen::VectorXd f = element_load_vector(model);
  for (const NodalLoad& l : model.loads) f(kDofsPerNode * l.node + l.dof) += l.value;
  return f;
}

}  // namespace framedyn::fem
