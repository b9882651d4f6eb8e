// Member-end releases (Abaqus *RELEASE): moments that a beam element's end
// does not transmit to its node (a pin or hinge at the member end).
//
// A released local DOF r of the element (a rotation at end a or b, local
// axes) is condensed out statically: with the element's stiffness split into
// kept (c) and released (r) DOFs, the released rotation follows the kept
// ones, u_r = -K_rr^-1 K_rc u_c (the end moment there is zero), i.e.
// u = T u_c with T = [I; -K_rr^-1 K_rc]. The released element then has
// K* = T^T K T (= K_cc - K_cr K_rr^-1 K_rc), mass M* = T^T M T (the same
// kinematic assumption as Guyan reduction, so mass and stiffness agree) and
// consistent loads p* = T^T p. Its end forces K* u_c - p* equal those of the
// unreleased element with the released rotation recovered, and vanish at the
// released DOFs. Theory: docs/theory/fem.md, "Member-end releases".
#pragma once

#include <Eigen/Dense>

#include <cstdint>
#include <string>
#include <vector>

namespace framedyn::fem {

// Bit i set: local DOF i (0..11; u v w rx ry rz at end a, then at end b) released.
using ReleaseMask = std::uint16_t;

// Local rotation DOFs: torsion (T) about t, bending M1 about n1, M2 about n2.
constexpr int kReleaseTorsion = 3, kReleaseM1 = 4, kReleaseM2 = 5;
constexpr ReleaseMask release_bit(int end, int local_rotation) { return static_cast<ReleaseMask>(1u << (6 * end + local_rotation)); }

// T (12 x 12, columns of released DOFs zero) for element stiffness `k` and
// released DOFs `released`; the identity for no releases. Throws
// std::invalid_argument if the released DOFs leave the element free to move
// (K_rr singular: torsion released at both ends).
Eigen::Matrix<double, 12, 12> release_transformation(const Eigen::Matrix<double, 12, 12>& k, ReleaseMask released);

// The same for any element stiffness `k` (n x n) and the indices of its
// released DOFs (the three-node beams condense their end rotations, taken in
// the local axes at the element's ends, this way).
Eigen::MatrixXd release_transformation(const Eigen::MatrixXd& k, const std::vector<int>& released_dofs, ReleaseMask released);

// "S1: M1, T" for messages and reports.
std::string describe_releases(ReleaseMask released);

}  // namespace framedyn::fem
