// Direct integration of M u'' + C u' + K u = F(t) on the full sparse frame:
// Newmark's average-acceleration rule (gamma = 1/2, beta = 1/4: unconditionally
// stable, second order, no numerical damping) with Rayleigh damping
// C = alpha M + beta K, the effective stiffness factorised once per step size
// by CHOLMOD. The reference against which the modal methods are checked.
// Theory: docs/theory/fem.md, "Direct integration", Eqs. (T.13)-(T.15).
#pragma once

#include "fem/modal_transient.h"

namespace framedyn::fem {

struct NewmarkOptions {
  double rayleigh_alpha = 0.0;  // 1/s
  double rayleigh_beta = 0.0;   // s
  int substeps = 1;             // Newmark steps per interval of the load history (load linear within)
  int output_interval = 1;      // keep every n-th time of the input (the first always)
  InitialState initial = InitialState::static_equilibrium;
  // Drive the frame by the unrelieved loads and return the whole motion,
  // free rigid motions included (Eq. 19.7); false: inertia relief (below).
  bool include_rigid_motion = false;
};

// Same inputs and outputs as modal_transient (no modal coordinates). A
// free-free or partially supported frame is driven by the relieved load and
// its elastic part returned, unless the rigid motion is included.
// Throws core::NumericalError when K_eff cannot be factorised.
TransientResult direct_transient(const FrameDynamics& frame, const TransientInput& input, const NewmarkOptions& options);

}  // namespace framedyn::fem
