// The rigid-body motions a frame's supports leave free, from geometry alone.
// Beam elements join all six DOFs of their nodes and resist every motion but
// a rigid one, so the zero-energy motions of a frame are the rigid motions
// of its connected parts (nodes joined by beam elements) that the supports
// and springs do not restrain: per part, the six motions
//     u_i = t + theta x (x_i - c),  rotation theta       (docs/theory/fem.md, Eq. 7.2)
// about the part's centroid c, less the rank of the restraints on them
// (fixed DOFs, grounded springs, springs between two DOFs). A part with no
// restraint keeps six; a frame pinned at one node keeps its three rotations
// about that node; a plane frame restrained to its plane keeps the three
// in-plane rigid motions. Used to deflate the eigensolver and to tell rigid-
// body modes from mechanisms.
#pragma once

#include <Eigen/Dense>

#include <string>
#include <vector>

#include "fem/frame_model.h"

namespace framedyn::fem {

struct FreeRigidMotions {
  // dof_count x p: a basis of the free rigid motions, zero at fixed DOFs
  // (columns not orthonormalised).
  Eigen::MatrixXd shapes;
  int parts = 0;                     // connected parts (beam elements and rigid links join nodes)
  std::vector<int> part_of_node;     // node index -> part
  // Motions left free per part (6 - rank of its restraints); parts joined by
  // springs between them are counted together, under the first of them.
  std::vector<int> free_per_part;
  // Column j of `shapes` moves the part (or the group of parts joined by
  // springs) counted under part_of_shape[j].
  std::vector<int> part_of_shape;
  // "part 2 (41 nodes, node 42 among them): 6 free; ..." for the parts with
  // free motions (at most five named), for messages.
  std::string describe(const FrameModel& model) const;
};

FreeRigidMotions free_rigid_motions(const FrameModel& model);

}  // namespace framedyn::fem
