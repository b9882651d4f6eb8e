// Consistent nodal loads of uniform line loads; see distributed_loads.h.
#include "fem/distributed_loads.h"

#include "fem/beam_element.h"
#include "fem/quadratic_beam_element.h"

namespace framedyn::fem {

std::vector<BeamLineLoad> beam_line_loads(const FrameModel& model) {
  std::vector<BeamLineLoad> q(model.beams.size());
  for (const ElementLoad& l : model.element_loads) {
    BeamLineLoad& b = q.at(static_cast<std::size_t>(l.beam));
    b.global += l.force_per_length;
    b.section += l.section_force_per_length;
  }
  return q;
}

Eigen::VectorXd element_load_vector(const FrameModel& model) {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(model.dof_count());
  if (model.element_loads.empty()) return f;
  const std::vector<BeamLineLoad> q = beam_line_loads(model);
  for (std::size_t i = 0; i < model.beams.size(); ++i) {
    if (q[i].is_zero()) continue;
    const BeamElement& beam = model.beams[i];
    if (beam.is_quadratic()) {
      const SectionGeometry section = section_geometry(model, beam.section, BeamTheory::timoshenko);
      const Vector18d p = quadratic_beam_consistent_load(model, beam, section, q[i]);
      const std::array<int, 18> dofs = quadratic_beam_dofs(beam);
      for (std::size_t k = 0; k < 18; ++k) f(dofs[k]) += p(static_cast<Eigen::Index>(k));
      continue;
    }
    const BeamGeometry g = beam_geometry(model, beam);
    const Vector12d p_local = beam_local_uniform_load(g.data, g.axes * q[i].global);
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
