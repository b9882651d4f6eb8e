// Distributed loads on beam elements (*DLOAD PX, PY, PZ, P1, P2, GRAV): the
// consistent nodal loads they put into the load vector, and the line load
// each element carries for the recovery of its section forces.
// Three-node beams (B32, B32R): p = int N^T q ds by Gauss integration over the
// (possibly curved) element, quadratic_beam_consistent_load.
//
// A uniform force per length q on an element of length L is replaced by its
// consistent nodal loads p = integral N^T q dx: qL/2 at each node and the end
// moments +-qL^2/12 of the transverse components (beam_local_uniform_load),
// which are the fixed-end reactions with their sign reversed. With them the
// nodal displacements are exact; the section forces inside the element are
// exact once the element's own load is added back by statics (section_forces.h).
// Theory: docs/theory/fem.md, "Distributed loads".
#pragma once

#include <Eigen/Dense>

#include <vector>

#include "fem/frame_model.h"

namespace framedyn::fem {

// The consistent nodal loads of the model's element loads on all DOFs (N, N m, global).
Eigen::VectorXd element_load_vector(const FrameModel& model);

// Everything the model applies: its nodal loads (*CLOAD, GRAV on point
// masses) plus element_load_vector. What a static solve balances and what
// a harmonic or transient run uses as the mesh's load pattern.
Eigen::VectorXd applied_load_vector(const FrameModel& model);

// The summed uniform line load of a beam: `global` (N/m, global components)
// plus `section` (N/m along the section's axes as written, n1 and n2 = t x n1;
// only on three-node beams, whose axes turn along a curved element).
struct BeamLineLoad {
  Eigen::Vector3d global = Eigen::Vector3d::Zero();
  Eigen::Vector2d section = Eigen::Vector2d::Zero();
  bool is_zero() const { return global.isZero(0.0) && section.isZero(0.0); }
};

// The summed line load of every beam (index as model.beams).
std::vector<BeamLineLoad> beam_line_loads(const FrameModel& model);

}  // namespace framedyn::fem
