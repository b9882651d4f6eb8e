// Mapping of the vehicle model's named load points onto the frame mesh.
//
// Each load point (a force F and a moment M at a location p) becomes nodal
// forces and moments on the frame:
//  - at the node of the mesh's node set of the same name, when p coincides
//    with one of the set's nodes;
//  - otherwise through a rigid spider (an RBE3-like weighted distribution) to
//    the set's nodes, or, when the mesh has no node set of that name, to the
//    `nearest_nodes` nodes nearest to p. With one spider node this is the
//    rigid-link transfer F, M + (p - x) x F.
// Either way the nodal loads have the same resultant force as the point load
// and the same moment about every point (docs/theory/coupling.md, "Load
// mapping", Eqs. C.1-C.4).
//
// The result is a load-distribution matrix B (all DOFs x 6 n_points, column
// 6 j + c = component c (FX FY FZ MX MY MZ) of point j), so that the nodal
// load vector at time t is F(t) = B p(t) with p(t) the stacked components.
#pragma once

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <string>
#include <vector>

#include "fem/assembly.h"
#include "fem/frame_model.h"

namespace framedyn::coupling {

struct LoadPointLocation {
  std::string name;               // node-set name (case-insensitive, sets are stored upper case)
  Eigen::Vector3d location;       // m
};

struct LoadMappingOptions {
  double coincidence_tolerance = 1e-6;  // m: a point this close to a set node is applied at that node
  int nearest_nodes = 3;                // spider size for a point whose name is not a node set
};

struct MappedLoadPoint {
  std::string name;
  Eigen::Vector3d location;       // m
  std::vector<int> nodes;         // node indices that receive the load
  bool at_node = false;           // true: applied directly at nodes[0]
  bool from_node_set = false;     // the spider nodes are the named node set (else the nearest nodes)
  double spider_length = 0.0;     // m, largest distance from the point to a spider node
};

struct LoadMapping {
  fem::SparseMatrix distribution;  // model.dof_count() x 6 n_points (N or N m per unit component)
  std::vector<MappedLoadPoint> points;
};

// Throws core::InputError (key "load point NAME") when a point cannot be
// mapped: an empty node set, or a mesh with no nodes.
LoadMapping map_load_points(const fem::FrameModel& model, const std::vector<LoadPointLocation>& points,
                            const LoadMappingOptions& options = {});

// The 6 x 6 block that sends a point load (F, M) at p to equal-weight spider
// nodes: rows 6 i .. 6 i + 5 of the returned (6 n x 6) matrix are node i's
// force and moment. Exposed for tests.
Eigen::MatrixXd spider_distribution(const Eigen::Vector3d& point, const std::vector<Eigen::Vector3d>& nodes);

}  // namespace framedyn::coupling
