// Linear static solve under nodal loads, the consistent nodal loads of
// distributed loads (fem/distributed_loads.h) and prescribed displacements:
// K_ff u_f = f_f - K_fc u_c on a CHOLMOD factorisation, then reactions
// R = K u - f at the constrained DOFs (with rigid links: T^T (K u - f), so a
// supported reference node carries its tied nodes' loads; rigid_links.h).
// A singular stiffness (a mechanism, a frame without supports) is reported
// with the nodes that can move freely.
#pragma once

#include <Eigen/Dense>

#include <functional>
#include <string>

#include "fem/frame_model.h"

namespace framedyn::fem {

struct StaticResult {
  Eigen::VectorXd displacement;  // all DOFs (m, rad)
  Eigen::VectorXd applied;       // nodal loads on all DOFs, with the consistent loads of *DLOAD (N, N m)
  Eigen::VectorXd reaction;      // all DOFs; nonzero only at constrained DOFs (N, N m)
  double relative_residual = 0.0;  // ||K_ff u_f - f_f|| / ||f_f||
};

// The applied load vector on all DOFs (N, N m): the model's nodal loads
// (*CLOAD, GRAV on point masses) and the consistent nodal loads of the beams'
// line loads (*DLOAD, fem/distributed_loads.h). The static solve and the frequency-domain analyses
// (harmonic_response, random_response) take their loads from here, so a load
// type added to the model reaches all of them.
Eigen::VectorXd applied_loads(const FrameModel& model);

StaticResult solve_static(const FrameModel& model, const std::function<void(const std::string&)>& progress = {});

}  // namespace framedyn::fem
