// Section forces and corner stresses along the rails over time; see rail_stress.h.
#include "coupling/rail_stress.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <stdexcept>

#include "core/error.h"
#include "fem/beam_element.h"
#include "fem/beam_section.h"
#include "fem/section_forces.h"

namespace framedyn::coupling {

namespace {

void update(RailPeak& p, double v, double t, int element, int station, const Eigen::Vector3d& x, int fiber = -1) {
  if (std::abs(v) > std::abs(p.value) || (p.element_id == 0 && p.value == 0.0)) p = {v, t, element, station, x, fiber};
}

// What an element of the set needs at every output time, built once: a
// two-node beam's local stiffness and transformation (fem::element_end_forces
// builds both at each call) and the section whose corners are stressed.
struct ElementRecovery {
  fem::BeamGeometry geometry;              // two-node beams
  fem::Matrix12d stiffness, transformation;  // two-node beams: beam_local_stiffness, beam_transformation
  fem::SectionProperties section;
};

// fem::element_end_forces with the element's matrices built once: the same
// products in the same order, k (T u_e), so the same numbers.
fem::Vector12d end_forces(const ElementRecovery& r, const fem::BeamElement& beam, const Eigen::MatrixXd& u, Eigen::Index j) {
  fem::Vector12d ue;
  ue.head<6>() = u.col(j).segment<6>(fem::kDofsPerNode * beam.node_a);
  ue.tail<6>() = u.col(j).segment<6>(fem::kDofsPerNode * beam.node_b);
  return r.stiffness * (r.transformation * ue);
}

// fem::fiber_stresses into a buffer kept across calls (the same expression per point).
void fiber_stresses(const fem::SectionProperties& sec, const fem::SectionForces& f, std::vector<double>& out) {
  out.clear();
  for (const Eigen::Vector2d& p : sec.stress_points) out.push_back(f.n / sec.area + f.my * p.y() / sec.i11 - f.mz * p.x() / sec.i22);
}

}  // namespace

std::vector<RailRecovery> recover_rails(const fem::FrameModel& model, const Eigen::VectorXd& times,
                                        const Eigen::MatrixXd& u, const std::vector<RailSpec>& rails, int stations,
                                        const std::vector<std::vector<std::vector<double>>>* static_stress) {
  if (stations < 2) throw std::invalid_argument("at least two stations per element (the ends) are needed");
  if (u.rows() != model.dof_count() || u.cols() != times.size())
    throw std::invalid_argument("the displacement history does not match the model or the times");
  std::vector<RailRecovery> out;
  if (static_stress && static_stress->size() != rails.size()) throw std::invalid_argument("recover_rails: one static stress set per rail");
  for (const RailSpec& spec : rails) {
    const std::vector<std::vector<double>>* statics = static_stress ? &(*static_stress)[out.size()] : nullptr;
    std::string key = spec.element_set;
    for (char& c : key) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    const auto set = model.element_sets.find(key);
    if (set == model.element_sets.end())
      throw core::InputError({"", 0, "rails." + spec.name}, "an element set of the mesh", "'" + spec.element_set + "'");
    std::vector<int> beams;
    for (int id : set->second)
      if (model.beam_index(id) >= 0) beams.push_back(model.beam_index(id));
    if (beams.empty())
      throw core::InputError({"", 0, "rails." + spec.name}, "an element set with beam elements", "'" + spec.element_set + "' without any");
    RailRecovery r;
    r.spec = spec;
    std::vector<ElementRecovery> elements(beams.size());
    for (std::size_t i = 0; i < beams.size(); ++i) {
      const int b = beams[i];
      const fem::BeamElement& beam = model.beams[static_cast<std::size_t>(b)];
      if (beam.is_quadratic()) {  // B32, B32R: stations evenly in arc length along the (possibly curved) element
        elements[i].section = fem::section_geometry(model, beam.section, fem::BeamTheory::timoshenko).data.section;
        for (const fem::StationResult& st : fem::beam_stations(model, b, Eigen::VectorXd::Zero(model.dof_count()), stations)) {
          r.station_element_ids.push_back(beam.id);
          r.station_points.push_back(st.point);
        }
        continue;
      }
      ElementRecovery& er = elements[i];
      er.geometry = fem::beam_geometry(model, beam);
      er.stiffness = fem::beam_local_stiffness(er.geometry.data);
      er.transformation = fem::beam_transformation(er.geometry.axes);
      er.section = er.geometry.data.section;
      const Eigen::Vector3d& a = model.nodes[static_cast<std::size_t>(beam.node_a)].position;
      const Eigen::Vector3d& e = model.nodes[static_cast<std::size_t>(beam.node_b)].position;
      for (int s = 0; s < stations; ++s) {
        r.station_element_ids.push_back(beam.id);
        r.station_points.push_back(a + (static_cast<double>(s) / (stations - 1)) * (e - a));
      }
    }
    const Eigen::Index ns = static_cast<Eigen::Index>(r.station_points.size());
    r.envelope_bending_moment = r.envelope_mz = r.envelope_my = r.envelope_normal_stress = Eigen::VectorXd::Zero(ns);
    r.series_bending_moment = r.series_normal_stress = Eigen::VectorXd::Zero(times.size());
    Eigen::MatrixXd total;  // stations x times: max |sigma_s + sigma_d(t)| over the section points
    if (statics) {
      if (statics->size() != static_cast<std::size_t>(ns)) throw std::invalid_argument("recover_rails: the static stresses do not match the stations");
      r.static_normal_stress = Eigen::VectorXd::Zero(ns);
      for (Eigen::Index k = 0; k < ns; ++k)
        for (double v : (*statics)[static_cast<std::size_t>(k)]) r.static_normal_stress(k) = std::max(r.static_normal_stress(k), std::abs(v));
      total = Eigen::MatrixXd::Zero(ns, times.size());
    }
    const bool quadratic = std::any_of(beams.begin(), beams.end(), [&](int b) { return model.beams[static_cast<std::size_t>(b)].is_quadratic(); });
    std::vector<fem::SectionForces> forces;  // one element's stations at one time
    std::vector<double> sigma;               // one station's corner stresses
    Eigen::VectorXd u_now;                   // the displacements at one time (three-node beams' statics)
    for (Eigen::Index j = 0; j < times.size(); ++j) {
      if (quadratic) u_now = u.col(j);
      const double t = times(j);
      for (std::size_t e = 0; e < beams.size(); ++e) {
        const fem::BeamElement& beam = model.beams[static_cast<std::size_t>(beams[e])];
        // Section forces at the element's stations: from the two end forces of a
        // two-node beam, by statics of the nodal forces on a three-node one.
        const ElementRecovery& er = elements[e];
        const fem::SectionProperties& sec = er.section;
        forces.clear();
        if (beam.is_quadratic()) {
          for (const fem::StationResult& st : fem::beam_stations(model, beams[e], u_now, stations)) forces.push_back(st.forces);
        } else {
          const fem::Vector12d f = end_forces(er, beam, u, j);
          for (int s = 0; s < stations; ++s)
            forces.push_back(fem::section_forces_at(f, (static_cast<double>(s) / (stations - 1)) * er.geometry.data.length));
        }
        for (int s = 0; s < stations; ++s) {
          const Eigen::Index k = static_cast<Eigen::Index>(e) * stations + s;
          const Eigen::Vector3d& x = r.station_points[static_cast<std::size_t>(k)];
          const fem::SectionForces& sf = forces[static_cast<std::size_t>(s)];
          const double m = std::hypot(sf.my, sf.mz);
          r.envelope_bending_moment(k) = std::max(r.envelope_bending_moment(k), m);
          r.envelope_mz(k) = std::max(r.envelope_mz(k), std::abs(sf.mz));
          r.envelope_my(k) = std::max(r.envelope_my(k), std::abs(sf.my));
          r.series_bending_moment(j) = std::max(r.series_bending_moment(j), m);
          update(r.peak_bending_moment, m, t, beam.id, s, x);
          update(r.peak_axial_force, sf.n, t, beam.id, s, x);
          update(r.peak_shear_y, sf.vy, t, beam.id, s, x);
          update(r.peak_shear_z, sf.vz, t, beam.id, s, x);
          update(r.peak_torque, sf.t, t, beam.id, s, x);
          update(r.peak_my, sf.my, t, beam.id, s, x);
          update(r.peak_mz, sf.mz, t, beam.id, s, x);
          fiber_stresses(sec, sf, sigma);
          for (std::size_t c = 0; c < sigma.size(); ++c) {
            if (statics) total(k, j) = std::max(total(k, j), std::abs((*statics)[static_cast<std::size_t>(k)].at(c) + sigma[c]));
            const double a = std::abs(sigma[c]);
            r.envelope_normal_stress(k) = std::max(r.envelope_normal_stress(k), a);
            r.series_normal_stress(j) = std::max(r.series_normal_stress(j), a);
            if (a > std::abs(r.peak_normal_stress.value) || r.peak_normal_stress.element_id == 0) {
              update(r.peak_normal_stress, sigma[c], t, beam.id, s, x, static_cast<int>(c));
              r.forces_at_peak_stress = sf;
              const Eigen::Vector2d& p = sec.stress_points[c];
              // Eq. (C.6): sigma = N/A + (My x2 / I11 - Mz x1 / I22).
              r.axial_stress_at_peak = sf.n / sec.area;
              r.bending_stress_at_peak = sf.my * p.y() / sec.i11 - sf.mz * p.x() / sec.i22;
            }
          }
        }
      }
    }
    if (statics) {
      r.envelope_total_normal_stress = total.rowwise().maxCoeff();
      r.series_total_normal_stress = total.colwise().maxCoeff().transpose();
      // The peak by a stable rule: the first station, then the earliest time, within 1e-6 relative of the largest.
      const double largest = total.size() > 0 ? total.maxCoeff() : 0.0;
      bool found = false;
      for (Eigen::Index k = 0; k < ns && !found; ++k)
        for (Eigen::Index j = 0; j < times.size() && !found; ++j) {
          if (total(k, j) < largest * (1.0 - 1e-6)) continue;
          found = true;
          // The signed total at the section point of largest magnitude there.
          const std::vector<double>& st = (*statics)[static_cast<std::size_t>(k)];
          const std::size_t e = static_cast<std::size_t>(k / stations);
          const int s_index = static_cast<int>(k % stations);
          const fem::BeamElement& beam = model.beams[static_cast<std::size_t>(beams[e])];
          const Eigen::VectorXd uj = u.col(j);
          fem::SectionForces sf;
          fem::SectionProperties sec;
          if (beam.is_quadratic()) {
            sf = fem::beam_stations(model, beams[e], uj, stations)[static_cast<std::size_t>(s_index)].forces;
            sec = fem::section_geometry(model, beam.section, fem::BeamTheory::timoshenko).data.section;
          } else {
            const fem::BeamGeometry& g = elements[e].geometry;
            sf = fem::section_forces_at(fem::element_end_forces(g, beam, uj), (static_cast<double>(s_index) / (stations - 1)) * g.data.length);
            sec = g.data.section;
          }
          const std::vector<double> sigma = fem::fiber_stresses(sec, sf);
          std::size_t best = 0;
          for (std::size_t c = 0; c < sigma.size(); ++c)
            if (std::abs(st.at(c) + sigma[c]) >= total(k, j) * (1.0 - 1e-6)) {
              best = c;
              break;
            }
          r.peak_total_normal_stress = {st.at(best) + sigma[best], times(j), beam.id, s_index, r.station_points[static_cast<std::size_t>(k)],
                                        static_cast<int>(best)};
        }
    }
    const double denom = std::abs(r.axial_stress_at_peak) + std::abs(r.bending_stress_at_peak);
    r.bending_share = denom > 0.0 ? std::abs(r.bending_stress_at_peak) / denom : 0.0;
    out.push_back(std::move(r));
  }
  return out;
}

}  // namespace framedyn::coupling
