// Steady-state response of a frame to a load pattern F e^{i omega t} by mode
// superposition, with a static (residual-flexibility) correction for the
// modes left out; the common part of the harmonic and the random response.
// Theory: docs/theory/fem.md, "Harmonic response", Eqs. (H.1)-(H.6).
//
// With M-orthonormal modes phi_j (eigenvalues omega_j^2) and modal damping
// c_j = 2 zeta_j omega_j (Rayleigh: alpha + beta omega_j^2), the displacement
// amplitude is
//   u(omega) = sum_j phi_j q_j(omega) + r,                                  (H.2)
//   q_j(omega) = phi_j^T F / (omega_j^2 - omega^2 + i c_j omega),           (H.3)
//   r = G F - sum_{elastic j} phi_j phi_j^T F / omega_j^2,                  (H.4)
// G the static flexibility (for a free-free frame, of the relieved load on
// the elastic part, as in modal_transient). r is the quasi-static response
// of the modes left out: exact at omega = 0 and in error by O(omega^2 /
// omega_{N+1}^2) relative to their contribution.
//
// Any output y that is linear in u (a displacement, a fiber stress) is then
// y(omega) = Y_modal q(omega) + y_residual, with the per-mode values Y_modal
// computed once: a sweep over many frequencies costs one small complex
// product per frequency, not one solve.
//
// Vectors on "all DOFs" follow FrameModel (6 per node: ux uy uz rx ry rz),
// zero at constrained DOFs (supports do not move), SI units.
#pragma once

#include <Eigen/Dense>

#include <complex>
#include <string>
#include <vector>

#include "fem/distributed_loads.h"
#include "fem/frame_model.h"
#include "fem/modal_transient.h"

namespace framedyn::fem {

struct FrequencyResponseOptions {
  ModalDamping damping = ModalDamping::ratio(0.02);
  int mode_count = -1;           // modes of the basis used, lowest first (rigid-body ones included); -1: all
  bool static_correction = true;  // add r of Eq. (H.4)
};

// The modal model of the response to one load pattern.
struct ModalFrequencyResponse {
  Eigen::VectorXd eigenvalues;   // omega_j^2 of the modes used (0 for rigid-body modes), rad^2/s^2
  Eigen::VectorXd damping;       // c_j, 1/s
  Eigen::VectorXd modal_forces;  // p_j = phi_j^T F (modal forces of the M-normalised modes)
  Eigen::MatrixXd shapes;        // all DOFs x modes used, zero at constrained DOFs
  Eigen::VectorXd residual;      // r of Eq. (H.4) on all DOFs (zero without the static correction)
  bool static_correction = false;
  int rigid_body_modes = 0;
  std::vector<bool> rigid_body;  // per mode used: a rigid-body mode

  int mode_count() const { return static_cast<int>(eigenvalues.size()); }
  // q(omega) of Eq. (H.3); omega in rad/s, > 0 when there are rigid-body modes.
  Eigen::VectorXcd modal_coordinates(double omega) const;
  // u(omega) on all DOFs (Eq. H.2).
  Eigen::VectorXcd displacement(double omega) const;
};

// F on all DOFs (N, N m; entries at constrained DOFs are ignored). Throws
// std::invalid_argument for a load of the wrong size or a basis with no mode.
ModalFrequencyResponse modal_frequency_response(const FrameDynamics& frame, const ModalBasis& basis, const Eigen::VectorXd& load,
                                                const FrequencyResponseOptions& options);

// The response without the rigid-body modes' terms: the elastic part
// u_e = u - R R^T M u of Eq. (H.2) (inertia relief, Eq. S.6). The residual is
// kept: it is already the relieved one (Eq. H.4, G of the relieved load).
ModalFrequencyResponse elastic_part(const ModalFrequencyResponse& response);

// Outputs linear in the displacement: row k is y_k = (Y_modal q + y_residual)_k.
struct LinearOutputs {
  Eigen::MatrixXd modal;      // outputs x modes
  Eigen::VectorXd residual;   // outputs
  Eigen::Index size() const { return residual.size(); }
  // Complex amplitudes of the outputs at each column of q (modes x frequencies): outputs x frequencies.
  Eigen::MatrixXcd evaluate(const Eigen::MatrixXcd& q) const;
};

// The displacements at the given global DOFs.
LinearOutputs displacement_outputs(const ModalFrequencyResponse& response, const std::vector<int>& global_dofs);

// One fiber-stress output: a stress point of a section at one station of a
// beam element. The stations cover each element's peak (Eq. H.7):
//   - a two-node beam without a line load: its two ends. Its section forces
//     are linear along it, so |sigma(x)| of a complex amplitude, convex in x,
//     is largest at an end;
//   - a three-node beam without a line load: its ends and its middle (the
//     midside node, when it sits at the middle of the arc): the forces are
//     linear on each half, with a kink where the midside node's force acts;
//   - any beam with a line load: 9 stations (eighths). The load adds the
//     parabola q x (L - x)/2 to the moment; sampling at spacing L/8 misses a
//     parabola's peak by at most q (L/16)^2 / 2 = q L^2/512, 1/64 of the
//     element's own sag q L^2/8.
struct FiberPoint {
  int element_id = 0;
  int station = 0;      // 0 (node a) .. stations - 1 (node b), evenly spaced in arc length
  int stations = 2;     // stations of this element
  int stress_point = 0; // index into the section's stress points
};
// "end 1", "end 2" on an element with two stations, else "station 3 of 9", for legends.
std::string describe_station(const FiberPoint& point);
// Stations per element of the frequency-domain stress outputs (see FiberPoint).
int frequency_response_stations(const BeamElement& beam, const BeamLineLoad& load);

// Fiber stresses (Pa) at the stations of every beam; `points` labels the rows.
// The load pattern's line loads (*DLOAD on beams) act with the same complex
// amplitude as the nodal loads, so their fixed-end terms (the statics of the
// load between the nodes and the consistent loads taken off the nodal forces,
// section_forces.h) go into the residual row y_residual, which multiplies the
// load's amplitude (Eq. H.8); the mode shapes' rows carry none.
LinearOutputs fiber_stress_outputs(const FrameModel& model, const ModalFrequencyResponse& response, std::vector<FiberPoint>& points);

}  // namespace framedyn::fem
