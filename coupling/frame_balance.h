// Rigid-body balance of the loads on a frame model (issue 17, "every load on
// the frame reaches the frame model"). With T the six rigid-body motions of
// the mesh about its centre of gravity c (fem::rigid_body_vectors) and M the
// mesh's mass matrix (supports ignored):
//
//   M_r = T^T M T                 the frame model's rigid-body mass (6 x 6)   (C.9)
//   R(t) = T^T B p(t)             resultant force and moment about c of the
//                                 loads applied to the model                (C.10)
//   a_r(t) = M_r^-1 R(t)          the rigid-body acceleration (of c, and the
//                                 angular acceleration) that inertia relief
//                                 gives the free-free model                 (C.11)
//
// With inertia relief the applied loads minus the inertia forces M (T a_r +
// u_el'') have zero resultant at every time (T^T M u_el'' = 0: the elastic
// modes are M-orthogonal to the rigid-body motions). a_r equals the vehicle
// model's frame acceleration only if every load on the frame is applied AND
// the model carries the frame assembly's whole mass where the vehicle model
// has it. docs/theory/coupling.md, section 7.
#pragma once

#include <Eigen/Dense>

#include "coupling/load_history.h"
#include "coupling/load_mapping.h"
#include "fem/frame_model.h"

namespace framedyn::coupling {

using Vector6d = Eigen::Matrix<double, 6, 1>;
using Matrix6d = Eigen::Matrix<double, 6, 6>;

struct RigidBodyMass {
  double mass = 0.0;                                     // kg
  Eigen::Vector3d cg = Eigen::Vector3d::Zero();          // m
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();     // kg m^2 about the c.g., global axes
  Matrix6d matrix = Matrix6d::Zero();                    // M_r about the c.g. (Eq. C.9)
};

// The model's rigid-body mass from its assembled mass matrix (beams, point
// masses; constraints ignored: the frame as built, not as supported).
RigidBodyMass frame_rigid_body_mass(const fem::FrameModel& model);

struct LoadResultants {
  Eigen::VectorXd times;            // s, the load history's
  Eigen::MatrixXd resultant;        // 6 x times: force (N) and moment about the c.g. (N m) of B p(t) (Eq. C.10)
  Eigen::MatrixXd acceleration;     // 6 x times: a_r of Eq. C.11, m/s^2 at the c.g. and rad/s^2
};

// The loads as the model receives them (through `mapping`'s distribution
// matrix), their resultant about `body.cg` and the inertia-relief rigid-body
// acceleration. The model must be the one `mapping` was built on.
LoadResultants applied_load_resultants(const fem::FrameModel& model, const RigidBodyMass& body, const LoadMapping& mapping,
                                       const LoadHistory& loads);

}  // namespace framedyn::coupling
