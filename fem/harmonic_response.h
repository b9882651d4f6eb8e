// Harmonic response of a frame: the steady-state amplitude and phase of every
// displacement and every fiber stress under the load pattern F cos(omega t)
// (the model's nodal loads as amplitudes, all in phase), swept over a list of
// frequencies by mode superposition with a static correction
// (modal_frequency_response.h). Reports the frequency response at chosen DOFs
// and the largest translation and fiber-stress amplitudes over the sweep.
// Theory: docs/theory/fem.md, "Harmonic response", Eqs. (H.1)-(H.6).
#pragma once

#include <Eigen/Dense>

#include <vector>

#include "fem/modal_frequency_response.h"

namespace framedyn::fem {

struct HarmonicOptions {
  FrequencyResponseOptions response;
  std::vector<double> frequencies_hz;  // > 0 (> 0 is needed for a free-free frame's rigid-body modes)
  std::vector<int> output_dofs;        // global DOFs whose complex amplitude is kept at every frequency
};

struct HarmonicResult {
  std::vector<double> frequencies_hz;
  std::vector<int> output_dofs;
  Eigen::MatrixXcd output;             // output DOFs x frequencies: u = |u| e^{i phase} (m, rad)

  // Largest translation amplitude |u_d| over all nodes, directions and frequencies.
  double max_displacement = 0.0;       // m
  int max_displacement_dof = -1;       // global DOF (translation)
  int max_displacement_frequency = -1; // index into frequencies_hz
  Eigen::VectorXcd max_displacement_frf;  // that DOF over all frequencies (m)

  // Largest fiber-stress amplitude over all beam ends, stress points and frequencies.
  double max_fiber_stress = 0.0;       // Pa
  FiberPoint max_fiber_stress_point;
  int max_fiber_stress_frequency = -1;
  Eigen::VectorXd max_fiber_stress_spectrum;  // |sigma| at that point over all frequencies (Pa)

  int modes_used = 0;
  int rigid_body_modes = 0;
  bool static_correction = false;
};

// Throws std::invalid_argument for an empty or non-positive frequency list or
// an output DOF out of range.
HarmonicResult harmonic_response(const FrameDynamics& frame, const ModalBasis& basis, const Eigen::VectorXd& load,
                                 const HarmonicOptions& options);

// Translational DOFs that are free (not constrained): where displacement maxima are looked for.
std::vector<int> free_translation_dofs(const FrameDynamics& frame);

}  // namespace framedyn::fem
