// Distributed loads on beam elements (*DLOAD PX, PY, PZ, P1, P2, GRAV): the
// consistent nodal loads they put into the load vector, and the line load
// each element carries for the recovery of its section forces.
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

// The summed uniform line load of every beam (index as model.beams), N/m, global components.
std::vector<Eigen::Vector3d> beam_line_loads(const FrameModel& model);

}  // namespace framedyn::fem
