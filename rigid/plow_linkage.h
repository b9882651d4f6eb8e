// The plow's four-bar linkage in the plane (thesis Appendix A and B), by
// exact small-motion kinematics instead of the thesis's small-angle formula.
//
// Pins 6 (upper arm) and 11 (lower arm) are on the frame; the upper arm
// 6-9 and the lower arm 11-10 carry the shank 9-10, on which the plow's mass,
// the blade point, the bounce tire and the shaker sit. For small motions the
// upper arm turns by psi about +Y, and the loop closure at pin 10,
//     d9 + phi_s  y x (r10 - r9) = d11 + phi_l  y x (r10 - r11),
// is linear in the shank's and lower arm's rotations phi_s, phi_l: solving it
// gives the shank rotation as a linear function of (frame motion, psi). With
// the frame held, phi_s = CB psi (CB the linkage's velocity ratio, Eq. A.9);
// a rigid rotation of frame and arm together turns the shank by the same
// angle, so phi_s = CB psi + (1 - CB) theta_y, the thesis's Eq. A.10 in the
// +Y sense. docs/theory/rigid.md, section 3.
#pragma once

#include <Eigen/Dense>

namespace framedyn::rigid {

// Positions in the X-Z plane (X rearward, Z up), m.
struct FourBarGeometry {
  Eigen::Vector2d upper_pivot;   // pin 6, on the frame
  Eigen::Vector2d lower_pivot;   // pin 11, on the frame
  Eigen::Vector2d upper_joint;   // pin 9, upper arm to shank
  Eigen::Vector2d lower_joint;   // pin 10, lower arm to shank
};

// Rotations (about +Y) of the shank and the lower arm per unit rotation of the
// upper arm, the frame held: (CB, lower-arm ratio). Throws std::invalid_argument
// when the shank and lower arm are in line (a toggle position, no unique motion).
Eigen::Vector2d four_bar_velocity_ratios(const FourBarGeometry& g);

}  // namespace framedyn::rigid
