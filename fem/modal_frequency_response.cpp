// Modal frequency response with static correction; see modal_frequency_response.h.
#include "fem/modal_frequency_response.h"

#include <fmt/format.h>

#include <stdexcept>

#include "fem/section_forces.h"

namespace framedyn::fem {

namespace {

// Free-DOF vector to all DOFs, zero at the constrained ones (the supports do not vibrate).
Eigen::VectorXd to_all_dofs(const FrameDynamics& frame, const Eigen::VectorXd& free) {
  Eigen::VectorXd all = Eigen::VectorXd::Zero(frame.model().dof_count());
  const DofMap& dofs = frame.dofs();
  for (int e = 0; e < dofs.free_count(); ++e) all(dofs.free_dofs[static_cast<std::size_t>(e)]) = free(e);
  return all;
}

}  // namespace

ModalFrequencyResponse modal_frequency_response(const FrameDynamics& frame, const ModalBasis& basis, const Eigen::VectorXd& load,
                                                const FrequencyResponseOptions& options) {
  const FrameModel& model = frame.model();
  const DofMap& dofs = frame.dofs();
  if (load.size() != model.dof_count())
    throw std::invalid_argument(fmt::format("load vector has {} entries, the model {} DOFs", load.size(), model.dof_count()));
  const int available = static_cast<int>(basis.eigenvalues.size());
  const int m = options.mode_count < 0 ? available : std::min(options.mode_count, available);
  if (m < 1) throw std::invalid_argument("the frequency response needs at least one mode");

  Eigen::VectorXd f(dofs.free_count());
  for (int e = 0; e < dofs.free_count(); ++e) f(e) = load(dofs.free_dofs[static_cast<std::size_t>(e)]);

  ModalFrequencyResponse r;
  r.eigenvalues.resize(m);
  r.damping.resize(m);
  r.modal_forces.resize(m);
  r.shapes.resize(model.dof_count(), m);
  int elastic = 0;
  for (int j = 0; j < m; ++j) {
    const bool rigid = basis.rigid_body[static_cast<std::size_t>(j)];
    const double lambda = rigid ? 0.0 : basis.eigenvalues(j);
    r.eigenvalues(j) = lambda;
    // Damping ratios count the elastic modes (ModalDamping's convention); a rigid-body mode has only Rayleigh's alpha.
    r.damping(j) = rigid ? (options.damping.rayleigh ? options.damping.alpha : 0.0)
                         : options.damping.coefficient(elastic++, std::sqrt(std::max(lambda, 0.0)));
    r.modal_forces(j) = basis.shapes.col(j).dot(f);
    r.shapes.col(j) = to_all_dofs(frame, basis.shapes.col(j));
    r.rigid_body.push_back(rigid);
    if (rigid) ++r.rigid_body_modes;
  }

  r.static_correction = options.static_correction;
  r.residual = Eigen::VectorXd::Zero(model.dof_count());
  if (options.static_correction) {
    // r = G F - sum_elastic phi_j p_j / omega_j^2 (Eq. H.4); G of the relieved load for a free-free frame.
    Eigen::VectorXd u = frame.static_response(frame.relieve(f));
    for (int j = 0; j < m; ++j)
      if (!basis.rigid_body[static_cast<std::size_t>(j)]) u -= basis.shapes.col(j) * (r.modal_forces(j) / r.eigenvalues(j));
    r.residual = to_all_dofs(frame, u);
  }
  return r;
}

ModalFrequencyResponse elastic_part(const ModalFrequencyResponse& response) {
  std::vector<Eigen::Index> keep;
  for (Eigen::Index j = 0; j < response.mode_count(); ++j)
    if (!response.rigid_body[static_cast<std::size_t>(j)]) keep.push_back(j);
  ModalFrequencyResponse r = response;
  const Eigen::Index n = static_cast<Eigen::Index>(keep.size());
  r.eigenvalues.resize(n);
  r.damping.resize(n);
  r.modal_forces.resize(n);
  r.shapes.resize(response.shapes.rows(), n);
  for (Eigen::Index k = 0; k < n; ++k) {
    const Eigen::Index j = keep[static_cast<std::size_t>(k)];
    r.eigenvalues(k) = response.eigenvalues(j);
    r.damping(k) = response.damping(j);
    r.modal_forces(k) = response.modal_forces(j);
    r.shapes.col(k) = response.shapes.col(j);
  }
  r.rigid_body.assign(static_cast<std::size_t>(n), false);
  r.rigid_body_modes = 0;
  return r;
}

Eigen::VectorXcd ModalFrequencyResponse::modal_coordinates(double omega) const {
  Eigen::VectorXcd q(mode_count());
  for (int j = 0; j < mode_count(); ++j)
    q(j) = modal_forces(j) / std::complex<double>(eigenvalues(j) - omega * omega, damping(j) * omega);  // Eq. (H.3)
  return q;
}

Eigen::VectorXcd ModalFrequencyResponse::displacement(double omega) const {
  const Eigen::VectorXcd q = modal_coordinates(omega);
  Eigen::VectorXcd u = shapes * q.real() + residual;
  u.imag() = shapes * q.imag();
  return u;
}

Eigen::MatrixXcd LinearOutputs::evaluate(const Eigen::MatrixXcd& q) const {
  // Two real products (BLAS-like kernels) instead of a complex one with a real factor.
  Eigen::MatrixXcd y(modal.rows(), q.cols());
  y.real() = modal * q.real();
  y.real().colwise() += residual;
  y.imag() = modal * q.imag();
  return y;
}

LinearOutputs displacement_outputs(const ModalFrequencyResponse& response, const std::vector<int>& global_dofs) {
  LinearOutputs out;
  const Eigen::Index n = static_cast<Eigen::Index>(global_dofs.size());
  out.modal.resize(n, response.mode_count());
  out.residual.resize(n);
  for (Eigen::Index k = 0; k < n; ++k) {
    const int g = global_dofs[static_cast<std::size_t>(k)];
    out.modal.row(k) = response.shapes.row(g);
    out.residual(k) = response.residual(g);
  }
  return out;
}

std::string describe_station(const FiberPoint& point) {
  if (point.stations == 2) return fmt::format("end {}", point.station + 1);
  return fmt::format("station {} of {}", point.station + 1, point.stations);
}

int frequency_response_stations(const BeamElement& beam, const BeamLineLoad& load) {
  if (!load.is_zero()) return 9;
  return beam.is_quadratic() ? 3 : 2;
}

LinearOutputs fiber_stress_outputs(const FrameModel& model, const ModalFrequencyResponse& response, std::vector<FiberPoint>& points) {
  const std::vector<BeamLineLoad> loads = beam_line_loads(model);
  const BeamLineLoad none;
  // Stresses are linear in u and in the line loads: recover them for each mode
  // shape (no load) and for the residual (with the load pattern's line loads).
  auto stresses = [&](const Eigen::VectorXd& u, bool with_loads_and_labels) {
    std::vector<double> values;
    for (std::size_t i = 0; i < model.beams.size(); ++i) {
      const int n = frequency_response_stations(model.beams[i], loads[i]);
      for (const StationResult& s : beam_stations(model, static_cast<int>(i), u, n, with_loads_and_labels ? loads[i] : none))
        for (std::size_t p = 0; p < s.fiber_stress.size(); ++p) {
          values.push_back(s.fiber_stress[p]);
          if (with_loads_and_labels) points.push_back({s.element_id, s.station, n, static_cast<int>(p)});
        }
    }
    return Eigen::Map<const Eigen::VectorXd>(values.data(), static_cast<Eigen::Index>(values.size())).eval();
  };
  points.clear();
  LinearOutputs out;
  out.residual = stresses(response.residual, true);
  out.modal.resize(out.residual.size(), response.mode_count());
  for (int j = 0; j < response.mode_count(); ++j) out.modal.col(j) = stresses(response.shapes.col(j), false);
  return out;
}

}  // namespace framedyn::fem
