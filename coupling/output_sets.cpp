// Nodal and section-force histories of a study's output sets; see output_sets.h.
#include "coupling/output_sets.h"

#include <fmt/format.h>

#include <cctype>
#include <cmath>
#include <stdexcept>

#include "fem/beam_element.h"
#include "fem/quadratic_beam_element.h"
#include "fem/section_forces.h"

namespace framedyn::coupling {

namespace {

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

void update(NodalPeak& p, double v, double t, int node_id, int dof) {
  if (std::abs(v) > std::abs(p.value) || p.node_id == 0) p = {v, t, node_id, dof};
}

}  // namespace

std::vector<int> output_nodes(const fem::FrameModel& model, const std::string& node_set) {
  const auto set = model.node_sets.find(upper(node_set));
  if (set == model.node_sets.end() || set->second.empty()) throw std::invalid_argument("the mesh has no node set " + node_set);
  return set->second;
}

ModalRates modal_rates(const fem::FrameDynamics& frame, const fem::ModalBasis& basis, const fem::TransientInput& in,
                       const fem::ModalTransientOptions& o) {
  const Eigen::Index nt = in.times.size();
  if (nt < 2 || in.components.cols() != nt || o.output_interval < 1) throw std::invalid_argument("modal_rates: inconsistent input");
  // The elastic modes modal_transient uses, lowest first.
  std::vector<int> used;
  for (int i = 0; i < static_cast<int>(basis.rigid_body.size()); ++i)
    if (!basis.rigid_body[static_cast<std::size_t>(i)]) used.push_back(i);
  if (o.mode_count >= 0 && o.mode_count < static_cast<int>(used.size())) used.resize(static_cast<std::size_t>(o.mode_count));
  const int m = static_cast<int>(used.size());
  Eigen::MatrixXd phi(basis.shapes.rows(), m);
  Eigen::VectorXd w2(m);
  for (int i = 0; i < m; ++i) {
    phi.col(i) = basis.shapes.col(used[static_cast<std::size_t>(i)]);
    w2(i) = basis.eigenvalues(used[static_cast<std::size_t>(i)]);
  }
  const Eigen::MatrixXd b = frame.free_loads(in.distribution);
  const Eigen::MatrixXd pm = phi.transpose() * b;
  const Eigen::MatrixXd p = pm * in.components;

  std::vector<Eigen::Index> outputs;
  for (Eigen::Index k = 0; k < nt; k += o.output_interval)
    if (in.times(k) >= o.outputs_from) outputs.push_back(k);  // modal_transient's outputs
  const Eigen::Index no = static_cast<Eigen::Index>(outputs.size());
  ModalRates r;
  r.modal_coordinates.resize(m, no);
  Eigen::MatrixXd qv(m, no), qa(m, no);
  for (int i = 0; i < m; ++i) {
    const double omega = std::sqrt(std::max(w2(i), 0.0));
    const double c = o.damping.coefficient(i, omega);
    double q = 0.0, v = 0.0;
    if (o.initial == fem::InitialState::static_equilibrium && w2(i) > 0.0) q = p(i, 0) / w2(i);
    double h_prev = -1.0;
    fem::PiecewiseLinearStep step{};
    fem::StepMemo memo;  // the grid's few distinct steps (a long record's rounded times)
    std::size_t next = 0;
    for (Eigen::Index k = 0; k < nt; ++k) {
      if (k > 0) {
        const double h = in.times(k) - in.times(k - 1);
        if (std::abs(h - h_prev) > 1e-12 * h) {
          step = memo.step(w2(i), c, h);
          h_prev = h;
        }
        const double q1 = step.a(0, 0) * q + step.a(0, 1) * v + step.b0(0) * p(i, k - 1) + step.b1(0) * p(i, k);
        const double v1 = step.a(1, 0) * q + step.a(1, 1) * v + step.b0(1) * p(i, k - 1) + step.b1(1) * p(i, k);
        q = q1;
        v = v1;
      }
      if (next < outputs.size() && outputs[next] == k) {
        const Eigen::Index j = static_cast<Eigen::Index>(next++);
        r.modal_coordinates(i, j) = q;
        qv(i, j) = v;
        qa(i, j) = p(i, k) - c * v - w2(i) * q;  // the modal equation q'' + c q' + omega^2 q = p (Eq. T.2)
      }
    }
  }
  // The static correction's rate (mode acceleration): (G - Phi Lambda^-1 Phi^T) B times the load's slope.
  Eigen::MatrixXd correction;
  if (o.method == fem::ResponseMethod::mode_acceleration) {
    correction.resize(b.rows(), b.cols());
    for (Eigen::Index c = 0; c < b.cols(); ++c) correction.col(c) = frame.static_response(b.col(c));
    correction -= phi * (w2.cwiseInverse().asDiagonal() * pm);
  }
  const int dofs = frame.model().dof_count();
  r.velocity.resize(dofs, no);
  r.acceleration.resize(dofs, no);
  for (Eigen::Index j = 0; j < no; ++j) {
    Eigen::VectorXd v = phi * qv.col(j);
    const Eigen::Index k = outputs[static_cast<std::size_t>(j)];
    if (o.method == fem::ResponseMethod::mode_acceleration && k > 0)
      v += correction * ((in.components.col(k) - in.components.col(k - 1)) / (in.times(k) - in.times(k - 1)));
    r.velocity.col(j) = frame.expand(v);
    r.acceleration.col(j) = frame.expand(phi * qa.col(j));
  }
  return r;
}

NodalHistory nodal_history(const fem::FrameModel& model, const NodeOutputSpec& spec, const fem::TransientResult& response,
                           const ModalRates* rates) {
  NodalHistory h;
  h.spec = spec;
  h.nodes = output_nodes(model, spec.node_set);
  const Eigen::Index nt = response.times.size();
  const Eigen::Index rows = fem::kDofsPerNode * static_cast<Eigen::Index>(h.nodes.size());
  h.displacement.resize(rows, nt);
  if (rates) {
    h.velocity.resize(rows, nt);
    h.acceleration.resize(rows, nt);
  }
  for (std::size_t k = 0; k < h.nodes.size(); ++k) {
    const int n = h.nodes[k];
    h.node_ids.push_back(model.nodes[static_cast<std::size_t>(n)].id);
    for (int d = 0; d < fem::kDofsPerNode; ++d) {
      const Eigen::Index row = fem::kDofsPerNode * static_cast<Eigen::Index>(k) + d, g = fem::kDofsPerNode * static_cast<Eigen::Index>(n) + d;
      h.displacement.row(row) = response.displacement.row(g);
      if (rates) {
        h.velocity.row(row) = rates->velocity.row(g);
        h.acceleration.row(row) = rates->acceleration.row(g);
      }
    }
  }
  for (Eigen::Index j = 0; j < nt; ++j)
    for (std::size_t k = 0; k < h.nodes.size(); ++k)
      for (int d = 0; d < 3; ++d) {
        const Eigen::Index row = fem::kDofsPerNode * static_cast<Eigen::Index>(k) + d;
        update(h.peak_displacement, h.displacement(row, j), response.times(j), h.node_ids[k], d);
        if (rates) {
          update(h.peak_velocity, h.velocity(row, j), response.times(j), h.node_ids[k], d);
          update(h.peak_acceleration, h.acceleration(row, j), response.times(j), h.node_ids[k], d);
        }
      }
  return h;
}

namespace {

// An element set's beams and their stations (section_history's rows).
struct SetStations {
  SectionHistory layout;                   // element_ids, station_index, station_x; no values
  std::vector<int> beams;                  // model.beams index per element of the set
  std::vector<fem::BeamGeometry> geometry;  // per beam (empty for a three-node beam)
};

SetStations set_stations(const fem::FrameModel& model, const std::string& element_set, int stations) {
  if (stations < 2) throw std::invalid_argument("at least two stations per element (the ends) are needed");
  const auto set = model.element_sets.find(upper(element_set));
  if (set == model.element_sets.end()) throw std::invalid_argument("the mesh has no element set " + element_set);
  SetStations out;
  SectionHistory& h = out.layout;
  for (int id : set->second) {
    const int b = model.beam_index(id);
    if (b < 0) continue;
    out.beams.push_back(b);
    const fem::BeamElement& beam = model.beams[static_cast<std::size_t>(b)];
    out.geometry.push_back(beam.is_quadratic() ? fem::BeamGeometry{} : fem::beam_geometry(model, beam));
    const double length = beam.is_quadratic() ? fem::quadratic_beam_length(model, beam) : out.geometry.back().data.length;
    for (int s = 0; s < stations; ++s) {
      h.element_ids.push_back(id);
      h.station_index.push_back(s);
      h.station_x.push_back(length * s / (stations - 1));  // arc length on a three-node beam
    }
  }
  return out;
}

}  // namespace

SectionHistory section_stations(const fem::FrameModel& model, const std::string& element_set, int stations) {
  return set_stations(model, element_set, stations).layout;
}

namespace {

// for_section_forces on stations already laid out (section_history lays them out once for both).
void forces_at_stations(const fem::FrameModel& model, const SetStations& at, const Eigen::MatrixXd& u, int stations, bool fiber_max,
                        core::WorkShare* share, const StationForcesSink& put) {
  const std::vector<double>& station_x = at.layout.station_x;
  // Each output time on its own: any share of the times gives the same numbers.
  core::for_ranges(share, static_cast<std::size_t>(u.cols()), 64, [&](std::size_t begin, std::size_t end) {
    Eigen::VectorXd uj;
    for (Eigen::Index j = static_cast<Eigen::Index>(begin); j < static_cast<Eigen::Index>(end); ++j) {
      uj = u.col(j);
      for (std::size_t e = 0; e < at.beams.size(); ++e) {
        const fem::BeamElement& beam = model.beams[static_cast<std::size_t>(at.beams[e])];
        if (beam.is_quadratic()) {  // B32, B32R: stations by statics of the nodal forces
          const std::vector<fem::StationResult> st = fem::beam_stations(model, at.beams[e], uj, stations);
          for (int s = 0; s < stations; ++s) {
            const fem::StationResult& r = st[static_cast<std::size_t>(s)];
            double smax = 0.0;
            if (fiber_max)
              for (double v : r.fiber_stress) smax = std::max(smax, std::abs(v));
            put(j, static_cast<Eigen::Index>(e) * stations + s, r.forces, smax);
          }
          continue;
        }
        const fem::Vector12d f = fem::element_end_forces(at.geometry[e], beam, uj);
        for (int s = 0; s < stations; ++s) {
          const Eigen::Index k = static_cast<Eigen::Index>(e) * stations + s;
          const fem::SectionForces sf = fem::section_forces_at(f, station_x[static_cast<std::size_t>(k)]);
          double smax = 0.0;
          if (fiber_max)
            for (double v : fem::fiber_stresses(at.geometry[e].data.section, sf)) smax = std::max(smax, std::abs(v));
          put(j, k, sf, smax);
        }
      }
    }
  });
}

}  // namespace

void for_section_forces(const fem::FrameModel& model, const Eigen::MatrixXd& u, const std::string& element_set, int stations, bool fiber_max,
                        core::WorkShare* share, const StationForcesSink& put) {
  forces_at_stations(model, set_stations(model, element_set, stations), u, stations, fiber_max, share, put);
}

SectionHistory section_history(const fem::FrameModel& model, const Eigen::MatrixXd& u, const std::string& element_set, int stations,
                               core::WorkShare* share) {
  SetStations at = set_stations(model, element_set, stations);
  SectionHistory h = at.layout;
  const Eigen::Index ns = static_cast<Eigen::Index>(h.element_ids.size());
  h.values.resize(u.cols() * ns, 7);
  forces_at_stations(model, at, u, stations, true, share,
                     [&](Eigen::Index j, Eigen::Index k, const fem::SectionForces& sf, double smax) {
                       h.values.row(j * ns + k) << sf.n, sf.vy, sf.vz, sf.t, sf.my, sf.mz, smax;
                     });
  return h;
}

}  // namespace framedyn::coupling
