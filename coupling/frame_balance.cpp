// Rigid-body balance of the loads on a frame model; see frame_balance.h.
#include "coupling/frame_balance.h"

#include <stdexcept>

#include "fem/assembly.h"

namespace framedyn::coupling {

RigidBodyMass frame_rigid_body_mass(const fem::FrameModel& model) {
  fem::FrameModel bare = model;  // as built: no supports
  bare.constraints.clear();
  const fem::DofMap dofs = fem::make_dof_map(bare);
  fem::AssemblyOptions options;
  options.storage = fem::Storage::full;
  const fem::SparseMatrix mass = fem::assemble_mass(bare, dofs, options);
  // Rigid motions about the origin first: the mass and its first moment give the c.g.
  const auto rigid_about = [&](const Eigen::Vector3d& p) {
    const Eigen::MatrixXd all = fem::rigid_body_vectors(bare, p);
    Eigen::MatrixXd t(dofs.free_count(), 6);
    for (int i = 0; i < dofs.free_count(); ++i) t.row(i) = all.row(dofs.free_dofs[static_cast<std::size_t>(i)]);
    return t;
  };
  const Eigen::MatrixXd t0 = rigid_about(Eigen::Vector3d::Zero());
  const Matrix6d m0 = t0.transpose() * (mass * t0);
  RigidBodyMass out;
  out.mass = m0(0, 0);
  if (!(out.mass > 0.0)) throw std::invalid_argument("the frame model has no mass");
  // A rotation about e_k moves a node at x by e_k x x, so the coupling block is
  // m0(i, 3 + k) = sum m (e_k x x)_i: m0(1, 5) = m c_x, m0(2, 3) = m c_y, m0(0, 4) = m c_z.
  out.cg = Eigen::Vector3d(m0(1, 5), m0(2, 3), m0(0, 4)) / out.mass;
  const Eigen::MatrixXd tc = rigid_about(out.cg);
  out.matrix = tc.transpose() * (mass * tc);
  out.inertia = out.matrix.bottomRightCorner<3, 3>();
  return out;
}

LoadResultants applied_load_resultants(const fem::FrameModel& model, const RigidBodyMass& body, const LoadMapping& mapping,
                                       const LoadHistory& loads) {
  if (mapping.distribution.rows() != model.dof_count() || mapping.distribution.cols() != 6 * static_cast<Eigen::Index>(loads.points.size()))
    throw std::invalid_argument("applied_load_resultants: the mapping does not match the model and the loads");
  const Eigen::MatrixXd t = fem::rigid_body_vectors(model, body.cg);
  // T^T B once (6 x components), then every time at once.
  const Eigen::MatrixXd tb = (mapping.distribution.transpose() * t).transpose();
  LoadResultants out;
  out.times = loads.times;
  out.resultant = tb * loads.component_matrix();
  out.acceleration = body.matrix.ldlt().solve(out.resultant);
  return out;
}

}  // namespace framedyn::coupling
