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
#include <vector>

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

// One fiber-stress output: a stress point of a section at one end of a beam
// element. Without loads between the nodes the section forces are linear
// along an element, so |sigma(x)| of a complex amplitude, convex in x, is
// largest at an end: the two ends cover the whole element.
struct FiberPoint {
  int element_id = 0;
  int end = 0;          // 0: node a, 1: node b
  int stress_point = 0; // index into the section's stress points
};
// Fiber stresses (Pa) at both ends of every beam (fem/section_forces' recovery); `points` labels the rows.
LinearOutputs fiber_stress_outputs(const FrameModel& model, const ModalFrequencyResponse& response, std::vector<FiberPoint>& points);

}  // namespace framedyn::fem
