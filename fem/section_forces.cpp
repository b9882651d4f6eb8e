// Recovery of section forces and fiber stresses; see section_forces.h.
#include "fem/section_forces.h"

#include <stdexcept>
#include <string>

#include "fem/quadratic_beam_element.h"

namespace framedyn::fem {

Vector12d element_end_forces(const BeamGeometry& g, const BeamElement& beam, const Eigen::VectorXd& u) {
  if (beam.is_quadratic())
    throw std::invalid_argument("beam element " + std::to_string(beam.id) +
                                " has three nodes (B32, B32R): its section forces come from recover_stations, not from two end forces");
  Vector12d ue;
  ue.head<6>() = u.segment<6>(kDofsPerNode * beam.node_a);
  ue.tail<6>() = u.segment<6>(kDofsPerNode * beam.node_b);
  return beam_local_stiffness(g.data) * (beam_transformation(g.axes) * ue);
}

SectionForces section_forces_at(const Vector12d& f, double x) {
  SectionForces s;
  s.n = -f(0);
  s.vy = -f(1);
  s.vz = -f(2);
  s.t = -f(3);
  s.my = -f(4) - x * f(2);
  s.mz = -f(5) + x * f(1);
  return s;
}

SectionForces section_forces_at(const Vector12d& f, double x, const Eigen::Vector3d& q) {
  SectionForces s = section_forces_at(f, x);
  s.n -= q.x() * x;
  s.vy -= q.y() * x;
  s.vz -= q.z() * x;
  s.my -= q.z() * x * x / 2;
  s.mz += q.y() * x * x / 2;
  return s;
}

std::vector<double> fiber_stresses(const SectionProperties& sec, const SectionForces& f) {
  std::vector<double> out;
  out.reserve(sec.stress_points.size());
  for (const Eigen::Vector2d& p : sec.stress_points)
    out.push_back(f.n / sec.area + f.my * p.y() / sec.i11 - f.mz * p.x() / sec.i22);
  return out;
}

std::vector<StationResult> beam_stations(const FrameModel& model, int beam_index, const Eigen::VectorXd& u, int stations, const BeamLineLoad& load) {
  if (stations < 2) throw std::invalid_argument("at least two stations per element (the ends) are needed");
  const BeamElement& beam = model.beams.at(static_cast<std::size_t>(beam_index));
  if (beam.is_quadratic()) return quadratic_beam_stations(model, beam, u, stations, load);
  const BeamGeometry g = beam_geometry(model, beam);
  const Eigen::Vector3d q = g.axes * load.global;
  Vector12d f = element_end_forces(g, beam, u);
  if (!q.isZero(0.0)) f -= beam_local_uniform_load(g.data, q);
  const Eigen::Vector3d& a = model.nodes[static_cast<std::size_t>(beam.node_a)].position;
  const Eigen::Vector3d& b = model.nodes[static_cast<std::size_t>(beam.node_b)].position;
  std::vector<StationResult> out;
  out.reserve(static_cast<std::size_t>(stations));
  for (int s = 0; s < stations; ++s) {
    StationResult r;
    r.element_id = beam.id;
    r.station = s;
    const double xi = static_cast<double>(s) / (stations - 1);
    r.x = xi * g.data.length;
    r.point = a + xi * (b - a);
    r.forces = section_forces_at(f, r.x, q);
    r.fiber_stress = fiber_stresses(g.data.section, r.forces);
    out.push_back(std::move(r));
  }
  return out;
}

std::vector<StationResult> recover_stations(const FrameModel& model, const Eigen::VectorXd& u, int stations) {
  if (stations < 2) throw std::invalid_argument("at least two stations per element (the ends) are needed");
  std::vector<StationResult> out;
  out.reserve(model.beams.size() * static_cast<std::size_t>(stations));
  const std::vector<BeamLineLoad> line_loads = beam_line_loads(model);
  for (std::size_t i = 0; i < model.beams.size(); ++i)
    for (StationResult& r : beam_stations(model, static_cast<int>(i), u, stations, line_loads[i])) out.push_back(std::move(r));
  return out;
}

}  // namespace framedyn::fem
