// The frame assembly's parts on the beam model of the frame (docs/theory/coupling.md,
// section 9, Eqs. 9.1-9.4). The vehicle model holds its frame assembly rigid: the
// frame structure (the mesh's tubes) and the parts bolted to it (engine, pumps,
// ballast, fuel tank, hitch box, ...). For the frame model, inertia relief and the
// frame's own dynamics to see the same mass in the same places, each part becomes:
//   - a node at the part's c.g. carrying a point mass m with its rotary inertia
//     tensor J_c about the c.g. (global axes, products included), and
//   - a rigid link (*MPC BEAM) from the frame node nearest that c.g., which the
//     c.g. node follows: u_c = u_n + theta_n x (c - x_n), theta_c = theta_n (Eq. 9.1).
// The c.g. node is the link's slave, so a part adds mass and no stiffness, and a
// clamp or a load on the frame node is untouched. Reduced by the link, the part is
// the rigid body's mass matrix about the frame node (Eq. 9.2), and the model's
// rigid-body mass T^T M T is the tubes' plus the parts' by the parallel-axis
// theorem: the vehicle model's frame assembly (Eq. 9.3). A c.g. on a frame node
// (within 1e-6 m) puts the mass on that node, without a link.
//
// The frame node is the nearest node that a beam element uses (never another
// part's c.g. node); among nodes within 1e-9 relative of the nearest distance,
// the lowest mesh node number (a stable rule, not a floating-point near-tie).
//
// A part with `mounts` (the study's part block: node numbers of the mesh, or
// points snapped to the nearest beam node by the same rule) is joined to them
// instead (Eqs. 9.5-9.6): with one mount, by a rigid link from that node; with
// two or more, by a distributing coupling (RBE3-like, fem/rigid_links.h, Eqs.
// R.6-R.8, uniform weights): the c.g. node follows the mounts' least-squares
// rigid motion, so the part's inertia reaches the frame at every mount and the
// part adds no stiffness between them. The mounts must be distinct nodes, not
// all on one line.
#pragma once

#include <Eigen/Dense>

#include <string>
#include <vector>

#include "core/error.h"
#include "core/units.h"
#include "coupling/frame_balance.h"
#include "fem/frame_model.h"
#include "rigid/machine_3d.h"

namespace framedyn::coupling {

// One of a part's mounting points as the study gives it: a node number of the
// mesh, or a point (SI) that goes to the nearest beam node.
struct PartMount {
  int node = 0;                  // the mesh's node number (when !by_point)
  bool by_point = false;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  core::InputLocation where;     // the entry, for messages
};

// A part for the frame model: its body and where it is mounted (none: the nearest frame node).
struct FramePart {
  rigid::RigidPart3D part;
  std::vector<PartMount> mounts;
  core::InputLocation mounts_where;  // the part's `mounts` key, for messages
};

// A part as placed on the beam model.
struct MountedPart {
  rigid::RigidPart3D part;   // SI: mass, c.g., inertia about the c.g.
  int mass_node = -1;        // index of the node that carries the point mass (the c.g. node or the frame node)
  int frame_node = -1;       // index of the frame node it is joined to (the first mount with several)
  bool linked = false;       // true: a new c.g. node joined to the frame (a rigid link or a coupling); false: the mass is on frame_node
  std::vector<int> mount_nodes;  // indices of the mounts of a distributing coupling (empty: one frame node)
  double arm = 0.0;          // m, |c.g. - frame node| (several mounts: |c.g. - the mounts' centroid|)
};

// Index of the frame node nearest `x` (nodes that beam elements use; ties to the lowest node number).
int nearest_frame_node(const fem::FrameModel& model, const Eigen::Vector3d& x);

// Adds each part to `model` (new nodes after the mesh's, point masses, rigid
// links and distributing couplings, element numbers above the mesh's). Throws
// std::invalid_argument for a part without mass or a model without beam
// elements; core::InputError, naming the mount's entry and `mesh_name`, for a
// mount node number that no beam element of the mesh uses (STUDY-111), mounts
// on one line (STUDY-112), two mounts at one node (STUDY-113).
std::vector<MountedPart> mount_frame_parts(fem::FrameModel& model, const std::vector<FramePart>& parts, const std::string& mesh_name = "the frame mesh");
// Parts without mounts: each on its nearest frame node.
std::vector<MountedPart> mount_frame_parts(fem::FrameModel& model, const std::vector<rigid::RigidPart3D>& parts);

// The parts as an .inp fragment in the mesh's units (*NODE for the c.g. nodes,
// MASS and ROTARYI elements in element sets named after the parts, *MPC BEAM
// links): *INCLUDE it after the mesh for the frame model the run used, e.g. in
// a `framedyn frame-response` study on the run's frame_loads.csv. A 3-D study
// whose mesh includes it counts those parts as carried by the mesh.
std::string frame_parts_inp(const fem::FrameModel& model, const std::vector<MountedPart>& parts);


}  // namespace framedyn::coupling
