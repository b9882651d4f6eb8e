// Two-node 3-D beam element: Euler-Bernoulli (B33) and Timoshenko (B31).
//
// Local axes (x, y, z) = (t, n1, n2): t from node a to node b, n1 the section's
// local 1-direction made orthogonal to t, n2 = t x n1 (Abaqus convention).
// Local DOFs per node: u, v, w, theta_x, theta_y, theta_z.
// Stiffness: Przemieniecki (1968), with Phi = 12 E I / (G A_s L^2) for the
// Timoshenko element and Phi = 0 for Euler-Bernoulli. Consistent mass:
// Przemieniecki's shear-deformable beam mass (translational and rotary
// inertia, Phi-dependent) for Timoshenko; the classical cubic-Hermite mass
// without rotary inertia for Euler-Bernoulli; torsional inertia rho Ip in both.
// Lumped mass: half the element's mass and section rotary inertia at each node.
// Euler-Bernoulli with bending rotary inertia (a Rayleigh beam, the section
// parameter RAYLEIGH): the cubic-Hermite mass plus the consistent rotary
// inertia rho I / (30 L) [36, 3L, -36, 3L; 3L, 4L^2, -3L, -L^2; ...]
// (Przemieniecki's Phi = 0 terms). Released member ends (member_releases.h)
// are condensed out of stiffness, mass and loads alike.
// Equations: docs/theory/fem.md, "Beam elements".
#pragma once

#include <Eigen/Dense>

#include "fem/frame_model.h"
#include "fem/member_releases.h"

namespace framedyn::fem {

using Matrix12d = Eigen::Matrix<double, 12, 12>;
using Vector12d = Eigen::Matrix<double, 12, 1>;

enum class MassFormulation { consistent, lumped };

// Rotation whose rows are the local axes (t, n1, n2) in global components.
// Throws std::invalid_argument if the element has zero length or n1 is parallel to it.
Eigen::Matrix3d beam_local_axes(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& n1_direction);

// Everything an element matrix needs, in SI.
struct BeamElementData {
  double length = 0.0;
  double youngs_modulus = 0.0, shear_modulus = 0.0, density = 0.0;
  SectionProperties section;
  BeamTheory theory = BeamTheory::timoshenko;
  bool bending_rotary_inertia = false;  // Euler-Bernoulli only: include rho I in bending (Timoshenko always does)
  ReleaseMask released = 0;             // local DOFs released at the ends (*RELEASE)
};

Matrix12d beam_local_stiffness(const BeamElementData& e);
Matrix12d beam_local_mass(const BeamElementData& e, MassFormulation formulation);
// The release transformation T of the element (identity without releases).
Matrix12d beam_release_transformation(const BeamElementData& e);
// Consistent nodal loads (local axes, forces and moments on the nodes) of a
// uniform force per length q (local components t, n1, n2): the fixed-end
// reactions with their sign reversed, exact for the Hermite and the
// Timoshenko element alike (v: qL/2, +-qL^2/12), condensed for releases.
Vector12d beam_local_uniform_load(const BeamElementData& e, const Eigen::Vector3d& q_local);
// 12x12 block-diagonal transformation, local = T * global.
Matrix12d beam_transformation(const Eigen::Matrix3d& local_axes);

// The data and axes of element `beam` of `model` (principal axes if the
// section has a product of inertia).
struct BeamGeometry {
  BeamElementData data;
  Eigen::Matrix3d axes;  // rows t, n1, n2 (principal)
};
BeamGeometry beam_geometry(const FrameModel& model, const BeamElement& beam);

// The same in two steps, for loops over many elements of few sections: the
// section's data in principal axes (length left 0) with the angle of its
// principal 1-axis from n1, then one element's axes.
struct SectionGeometry {
  BeamElementData data;
  double principal_angle = 0.0;  // rad, about t, from n1 to the principal 1-axis
};
SectionGeometry section_geometry(const FrameModel& model, int section, BeamTheory theory);
Eigen::Matrix3d element_axes(const FrameModel& model, const BeamElement& beam, const SectionGeometry& section);

}  // namespace framedyn::fem
