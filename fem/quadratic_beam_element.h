// Three-node shear-deformable beam element: Abaqus B32 (3-point Gauss rule)
// and B32R (2-point, reduced). Isoparametric: the position, displacements u and
// rotations theta are interpolated with the same quadratic Lagrange functions
// N_a = xi (xi - 1)/2, N_m = 1 - xi^2, N_b = xi (xi + 1)/2 on xi in [-1, 1]
// (node a at -1, the midside node m at 0, node b at +1), so the element may be
// curved and its midside node need not lie at the middle (the mapping must not
// fold: dx/dxi keeps its direction and length > 0 along the element).
//
// At a point: t = x,xi / J, J = |x,xi|; local axes (t, n1, n2) as for the
// two-node beams (n1 from the section's direction, principal axes if I12 != 0).
// Generalised strains (Reissner / Timoshenko, linear):
//   gamma = u,s + t x theta  (axial strain and the two shear strains)
//   kappa = theta,s          (twist and the two curvatures)
// and the section law diag(EA, G As1, G As2, GJ, E I11, E I22) on their local
// components. Stiffness K = sum_g B^T D B J w_g; consistent mass
// M = int N^T diag(rho A, rho A, rho A, R^T diag(rho Ip, rho I11, rho I22) R) N J dxi
// (3-point rule for both B32 and B32R); lumped mass: the row sums int N_i dm,
// i.e. 1/6, 2/3, 1/6 of the element's mass and rotary inertia on a straight
// element with its midside node at the middle.
// Equations: docs/theory/fem.md, "Three-node beams".
#pragma once

#include <Eigen/Dense>

#include <array>
#include <vector>

#include "fem/beam_element.h"
#include "fem/distributed_loads.h"
#include "fem/frame_model.h"
#include "fem/section_forces.h"

namespace framedyn::fem {

using Matrix18d = Eigen::Matrix<double, 18, 18>;
using Vector18d = Eigen::Matrix<double, 18, 1>;

// Global DOFs of a three-node element, in the order node a, midside node, node b.
std::array<int, 18> quadratic_beam_dofs(const BeamElement& beam);

// Position, tangent and axes of a three-node element at xi in [-1, 1].
struct QuadraticBeamPoint {
  Eigen::Vector3d position;
  double jacobian = 0.0;   // ds / dxi, m
  Eigen::Matrix3d axes;    // rows t, n1, n2 (principal), global components
};
// Throws std::invalid_argument if the mapping folds there (J <= 0) or n1 is
// parallel to the tangent.
QuadraticBeamPoint quadratic_beam_point(const FrameModel& model, const BeamElement& beam, const SectionGeometry& section, double xi);

// Checks the element's geometry: the tangent keeps its direction and J > 0 from
// end to end (for a straight element: the midside node lies strictly between
// the quarter points of its ends), n1 is never parallel to the axis. Throws
// std::invalid_argument saying what is wrong.
void check_quadratic_beam_geometry(const FrameModel& model, const BeamElement& beam, const SectionGeometry& section);

// Arc length of the element, m.
double quadratic_beam_length(const FrameModel& model, const BeamElement& beam);

// Member-end releases (*RELEASE, beam.released): G (global components, DOFs
// as quadratic_beam_dofs) with the element's displacements u = G u_c, the
// released end rotations following the others. The released rotations are the
// components along the element's local axes at that end (t, n1, n2 at xi = -1
// for S1, +1 for S2): with Q the rotation of the end nodes' rotations into
// those axes, G = Q^T T Q and T the static condensation of member_releases.h.
// The identity without releases. Throws std::invalid_argument if the releases
// leave the element free to turn (torsion released at both ends).
Matrix18d quadratic_beam_release_transformation(const FrameModel& model, const BeamElement& beam, const SectionGeometry& section);

// Element matrices in global components, DOFs as quadratic_beam_dofs, with the
// element's releases condensed out (G^T K G, G^T M G).
Matrix18d quadratic_beam_stiffness(const FrameModel& model, const BeamElement& beam, const SectionGeometry& section);
Matrix18d quadratic_beam_mass(const FrameModel& model, const BeamElement& beam, const SectionGeometry& section,
                              MassFormulation formulation);

// Consistent nodal loads p = G^T int N^T q(s) ds (forces only: the rotations
// are interpolated independently, so a line force does no work on them),
// integrated with a 6-point Gauss rule in xi (exact on a straight element,
// where N_i J is a cubic).
Vector18d quadratic_beam_consistent_load(const FrameModel& model, const BeamElement& beam, const SectionGeometry& section,
                                         const BeamLineLoad& load);

// Section forces at `stations` points evenly spaced in arc length (ends
// included) by statics of the part from node a to the cut: the nodal forces
// K u - p of the nodes on that part plus the line load between node a and the
// cut (its resultant and moment about the cut, 6-point Gauss rule). A station
// exactly at the midside node takes the midside node's force as acting just
// past it.
std::vector<StationResult> quadratic_beam_stations(const FrameModel& model, const BeamElement& beam, const Eigen::VectorXd& u,
                                                   int stations, const BeamLineLoad& load = {});

}  // namespace framedyn::fem
