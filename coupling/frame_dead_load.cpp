// The static state of the frame model (gravity and the static loads); see frame_dead_load.h.
#include "coupling/frame_dead_load.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <stdexcept>

#include "coupling/frame_balance.h"
#include "fem/distributed_loads.h"
#include "fem/rigid_body_modes.h"
#include "fem/rigid_links.h"
#include "fem/static_analysis.h"

namespace framedyn::coupling {

fem::FrameModel with_gravity(const fem::FrameModel& model, const Eigen::Vector3d& gravity) {
  fem::FrameModel out = model;
  out.loads.clear();
  out.element_loads.clear();
  for (std::size_t b = 0; b < out.beams.size(); ++b) {
    const fem::SectionAssignment& sa = out.sections[static_cast<std::size_t>(out.beams[b].section)];
    const double mass_per_length = sa.material.density * sa.properties.area;
    if (mass_per_length > 0.0) out.element_loads.push_back({static_cast<int>(b), mass_per_length * gravity, Eigen::Vector2d::Zero()});
  }
  for (const fem::PointMass& pm : out.point_masses)
    for (int k = 0; k < 3; ++k)
      if (pm.mass * gravity(k) != 0.0) out.loads.push_back({pm.node, k, pm.mass * gravity(k)});
  return out;
}

FrameStaticState frame_static_state(const fem::FrameModel& model, const Eigen::Vector3d& gravity, const fem::SparseMatrix* distribution,
                                    const Eigen::VectorXd* static_components, const std::vector<RailSpec>& outputs, int stations) {
  const fem::FrameDynamics frame(model);
  return frame_static_state(frame, frame_rigid_body_mass(model), gravity, distribution, static_components, outputs, stations);
}

FrameStaticState frame_static_state(const fem::FrameDynamics& frame, const RigidBodyMass& body, const Eigen::Vector3d& gravity,
                                    const fem::SparseMatrix* distribution, const Eigen::VectorXd* static_components, const std::vector<RailSpec>& outputs,
                                    int stations) {
  if (stations < 2) throw std::invalid_argument("at least two stations per element (the ends) are needed");
  fem::FrameModel model = with_gravity(frame.model(), gravity);
  if (distribution && static_components) {
    if (distribution->rows() != model.dof_count() || distribution->cols() != static_components->size())
      throw std::invalid_argument("frame_static_state: the distribution does not match the model or the static loads");
    const Eigen::VectorXd f = *distribution * *static_components;
    for (Eigen::Index g = 0; g < f.size(); ++g)
      if (f(g) != 0.0) model.loads.push_back({static_cast<int>(g / fem::kDofsPerNode), static_cast<int>(g % fem::kDofsPerNode), f(g)});
  }
  FrameStaticState out;
  out.gravity = gravity;
  // Eq. 11.2 on the frame's own factor (the one the dynamic response uses: K, or
  // K on the auxiliary supports for the rigid motions left free), no second
  // assembly or factorisation; the free rigid motions take the round-off
  // imbalance only (inertia relief, Eq. 11.3 reports it), as fem::solve_static's.
  const fem::DofMap& dofs = frame.dofs();
  out.applied = fem::applied_loads(model);  // nodal loads and the consistent loads of *DLOAD
  Eigen::VectorXd prescribed = Eigen::VectorXd::Zero(model.dof_count());
  for (const fem::Constraint& c : model.constraints) prescribed(fem::kDofsPerNode * c.node + c.dof) = c.value;
  fem::fill_slave_dofs(dofs.links, prescribed);
  const Eigen::VectorXd rhs = fem::restrict_load(dofs, out.applied - fem::internal_force(model, prescribed));
  const Eigen::VectorXd uf = frame.static_response(frame.relieve(rhs));
  out.displacement = fem::expand_free(dofs, uf, prescribed);
  Eigen::VectorXd residual_all = fem::internal_force(model, out.displacement) - out.applied;
  fem::fold_slave_forces(dofs.links, residual_all);  // a supported reference node also carries its slaves' share (Eq. R.4)
  out.reaction = Eigen::VectorXd::Zero(model.dof_count());
  for (int g : dofs.constrained_dofs) out.reaction(g) = residual_all(g);
  out.free_rigid_motions = frame.rigid_count();

  // Eq. 11.3: the resultant of f_s about the model's c.g., relative to W and W L.
  out.weight = body.mass * gravity.norm();
  out.resultant = fem::rigid_body_vectors(model, body.cg).transpose() * out.applied;
  Eigen::Vector3d lo = model.nodes.front().position, hi = lo;
  for (const fem::Node& n : model.nodes) {
    lo = lo.cwiseMin(n.position);
    hi = hi.cwiseMax(n.position);
  }
  out.extent = (hi - lo).maxCoeff();
  if (out.weight > 0.0) {
    out.force_residual = out.resultant.head<3>().norm() / out.weight;
    out.moment_residual = out.extent > 0.0 ? out.resultant.tail<3>().norm() / (out.weight * out.extent) : 0.0;
  }

  // The stations of every element-set output, in rail_stress.h's order, with the beams' own weight.
  const std::vector<fem::BeamLineLoad> line_loads = fem::beam_line_loads(model);
  for (const RailSpec& spec : outputs) {
    std::string key = spec.element_set;
    for (char& c : key) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    const auto set = model.element_sets.find(key);
    if (set == model.element_sets.end()) throw std::invalid_argument("frame_static_state: no element set " + spec.element_set);
    StaticStations st;
    st.output = spec.name;
    for (int id : set->second) {
      const int b = model.beam_index(id);
      if (b < 0) continue;
      for (fem::StationResult& r : fem::beam_stations(model, b, out.displacement, stations, line_loads[static_cast<std::size_t>(b)])) {
        st.element_ids.push_back(r.element_id);
        st.station.push_back(r.station);
        st.points.push_back(r.point);
        st.forces.push_back(r.forces);
        st.fiber_stress.push_back(std::move(r.fiber_stress));
      }
    }
    st.max_abs_normal_stress = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(st.points.size()));
    for (std::size_t k = 0; k < st.fiber_stress.size(); ++k)
      for (double v : st.fiber_stress[k]) st.max_abs_normal_stress(static_cast<Eigen::Index>(k)) = std::max(st.max_abs_normal_stress(static_cast<Eigen::Index>(k)), std::abs(v));
    out.outputs.push_back(std::move(st));
  }
  // The peak: the largest |sigma_s|, then the first (output, station, point order) within 1e-6 relative of
  // it, so that a symmetric frame's near-equal rails do not trade places with the round-off.
  double largest = 0.0;
  for (const StaticStations& st : out.outputs)
    if (st.max_abs_normal_stress.size() > 0) largest = std::max(largest, st.max_abs_normal_stress.maxCoeff());
  bool found = false;
  for (const StaticStations& st : out.outputs) {
    for (std::size_t k = 0; k < st.fiber_stress.size() && !found; ++k)
      for (std::size_t c = 0; c < st.fiber_stress[k].size() && !found; ++c)
        if (std::abs(st.fiber_stress[k][c]) >= largest * (1.0 - 1e-6)) {
          out.peak_normal_stress = {st.fiber_stress[k][c], 0.0, st.element_ids[k], st.station[k], st.points[k], static_cast<int>(c)};
          out.peak_output = st.output;
          found = true;
        }
    if (found) break;
  }
  return out;
}

}  // namespace framedyn::coupling
