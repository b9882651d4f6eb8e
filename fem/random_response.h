// Random response of a frame to the load pattern F scaled by a stationary
// random factor a(t) with one-sided PSD S_a(f) (1/Hz; all loads fully
// correlated): response PSDs S_y(f) = |H_y(f)|^2 S_a(f) of every displacement
// and fiber stress, with H_y the harmonic response to F
// (modal_frequency_response.h), and RMS values sigma_y^2 = integral of S_y
// over the PSD's band, by the trapezoidal rule on a frequency grid refined
// around every mode (the half-power band of a mode is 2 zeta f_j wide).
// A frame free to move rigidly has no stationary response; with inertia
// relief its elastic part relative to the rigid motion is computed instead.
// Theory: docs/theory/fem.md, "Random response", Eqs. (S.1)-(S.7).
#pragma once

#include <Eigen/Dense>

#include <vector>

#include "fem/load_psd.h"
#include "fem/modal_frequency_response.h"

namespace framedyn::fem {

struct RandomOptions {
  FrequencyResponseOptions response;
  std::vector<int> output_dofs;  // global DOFs whose response PSD is kept at every grid frequency
  int points_per_decade = 100;   // base log-spaced grid over the band
  double mode_step = 0.03;       // refinement around each mode: the step in s of Eq. (S.5)
  // A frame free to move rigidly (free-free or partially supported): the
  // elastic response relative to its rigid motion, the loads' unbalanced part
  // taken by that motion's inertia (Eq. S.6). Without it such a frame is refused.
  bool inertia_relief = false;
};

struct RandomResult {
  std::vector<double> frequencies_hz;  // the integration grid (ascending, over the PSD's band)
  std::vector<double> load_psd;        // S_a at the grid, 1/Hz
  std::vector<int> output_dofs;
  Eigen::MatrixXd output_psd;          // output DOFs x grid: m^2/Hz (rad^2/Hz)

  Eigen::VectorXd rms;                 // all DOFs (m, rad), zero at constrained DOFs

  double max_displacement_psd = 0.0;   // largest translation PSD over nodes, directions and the grid, m^2/Hz
  int max_displacement_psd_dof = -1;
  int max_displacement_psd_frequency = -1;
  Eigen::VectorXd max_displacement_psd_spectrum;  // that DOF's PSD over the grid

  double max_stress_psd = 0.0;         // largest fiber-stress PSD, Pa^2/Hz
  FiberPoint max_stress_psd_point;
  int max_stress_psd_frequency = -1;
  Eigen::VectorXd max_stress_psd_spectrum;

  double max_displacement_rms = 0.0;   // m
  int max_displacement_rms_dof = -1;
  double max_stress_rms = 0.0;         // Pa
  FiberPoint max_stress_rms_point;

  int modes_used = 0;
  int rigid_body_modes = 0;             // of the basis used; left out of the response with inertia relief
  bool static_correction = false;
  bool inertia_relief = false;          // displacements, PSDs and RMS values are the elastic part (Eq. S.6)
};

// The integration grid: the PSD's rows, a log-spaced grid and, for each
// mode j with frequency f_j and ratio zeta_j, points f_j (1 + zeta_j sinh s)
// with s evenly spaced (Eq. S.5): even steps of a fraction of the half-power
// bandwidth across the peak, growing geometrically away from it, where
// |H|^2 falls like 1/(f - f_j)^2; all clipped to the band.
std::vector<double> random_response_grid(const LoadPsd& psd, const ModalFrequencyResponse& response, const RandomOptions& options);

// Throws std::invalid_argument for an output DOF out of range, a frame free
// to move rigidly without options.inertia_relief (its rigid-body modes have no
// finite mean square), or options.inertia_relief on a frame its supports hold
// against every rigid motion (nothing to relieve).
RandomResult random_response(const FrameDynamics& frame, const ModalBasis& basis, const Eigen::VectorXd& load, const LoadPsd& psd,
                             const RandomOptions& options);

}  // namespace framedyn::fem
