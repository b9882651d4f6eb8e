// A frame whose supports leave rigid motions free (a plane frame held in its
// plane, a frame on one pin, a symmetry half-model; fem/rigid_body_modes.h):
// the loads' work on those motions, and the minimal set of auxiliary
// supports that removes them from the stiffness matrix (docs/theory/fem.md,
// section 19, Eqs. 19.1-19.6).
//
//   - Balance (Eq. 19.1): a static solution exists only if the loads do no
//     work on every free rigid motion r, r^T f = 0. `unbalanced_loads` says,
//     per part, which rigid motion the loads drive (the free motion of largest
//     work per unit size, Eq. 19.2: a translation along an axis or a rotation
//     about an axis through a point, a node when one lies on it) and the
//     unbalanced force or moment.
//   - Auxiliary supports (Eq. 19.3): p equations, one per free rigid motion,
//     chosen greedily on the rows of the rigid motions so that fixing them
//     fixes every rigid motion; a balanced load gives them zero reactions,
//     so the solution on them is one solution of the singular system, and
//     any other differs from it by a free rigid motion.
//   - Inertia relief (Eq. 19.5): f - M R (R^T M R)^-1 R^T f is balanced for
//     any f; R^T M R a'' = R^T f gives the rigid-body accelerations.
#pragma once

#include <Eigen/Dense>

#include <stdexcept>
#include <string>
#include <vector>

#include "core/error.h"
#include "fem/assembly.h"
#include "fem/frame_model.h"
#include "fem/rigid_body_modes.h"

namespace framedyn::fem {

// One part (or group of parts joined by springs) whose free rigid motions the loads do work on.
struct UnbalancedPart {
  int part = 0;               // index of the part (FreeRigidMotions::part_of_node numbering)
  int free_motions = 0;       // its free rigid motions
  std::string motion;         // "rotation about the z axis through node 1", "translation along x", ...
  std::string unbalanced;     // "moment 2000 N m about that axis (resultant force (0, 0, 1000) N, ...)"
};

// The parts on whose free rigid motions the all-DOF load vector `loads` does
// work beyond round-off (relative 1e-9 of the loads' own magnitude). Empty: balanced.
std::vector<UnbalancedPart> unbalanced_loads(const FrameModel& model, const FreeRigidMotions& motions, const Eigen::VectorXd& loads);

// "part 1 (3 nodes, node 1 among them; 3 free rigid motions): the loads drive its rotation ...; ...", for messages.
std::string describe(const FrameModel& model, const FreeRigidMotions& motions, const std::vector<UnbalancedPart>& parts);

// Thrown by the static solve for loads that do work on a free rigid motion
// (the caller names the input file; apps/static_command.cpp).
class UnbalancedLoadError : public core::NumericalError {
 public:
  explicit UnbalancedLoadError(const std::string& what) : core::NumericalError(what) {}
};

// The free rigid motions restricted to the free DOFs (equations of `dofs`).
Eigen::MatrixXd rigid_motions_on_equations(const DofMap& dofs, const Eigen::MatrixXd& shapes_all);

// Equation numbers of p auxiliary supports (p = rigid.cols()) that fix every
// column of `rigid` (free DOFs x p): greedy, at each step the row of largest
// norm after removing the directions already fixed; among rows within 1e-6
// relative of the largest, the lowest equation number (Eq. 19.3). Sorted.
// Throws std::invalid_argument when the columns are dependent.
std::vector<int> auxiliary_supports(const Eigen::MatrixXd& rigid);

// K with the auxiliary rows and columns replaced by its diagonal there (1
// where that is not positive), lower triangle like `k_lower` (Eq. 19.4).
SparseMatrix with_auxiliary_supports(const SparseMatrix& k_lower, const std::vector<int>& auxiliary);

}  // namespace framedyn::fem
