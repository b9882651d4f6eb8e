// Free rigid motions of a frame's connected parts (see rigid_body_modes.h).
#include "fem/rigid_body_modes.h"

#include <fmt/format.h>

#include <algorithm>
#include <numeric>

namespace framedyn::fem {

namespace {

struct UnionFind {
  std::vector<int> parent;
  explicit UnionFind(int n) : parent(static_cast<std::size_t>(n)) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int i) {
    while (parent[static_cast<std::size_t>(i)] != i) {
      parent[static_cast<std::size_t>(i)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(i)])];
      i = parent[static_cast<std::size_t>(i)];
    }
    return i;
  }
  void join(int a, int b) { parent[static_cast<std::size_t>(find(a))] = find(b); }
};

// A restraint on the rigid motions: the DOF (node, dof) or the difference
// of two DOFs (a spring between them) must not move.
struct Restraint {
  int node_a, dof_a, node_b, dof_b;  // node_b < 0: one DOF
};

}  // namespace

FreeRigidMotions free_rigid_motions(const FrameModel& model) {
  const int nn = static_cast<int>(model.nodes.size());
  FreeRigidMotions out;
  UnionFind parts(nn);
  for (const BeamElement& b : model.beams) {
    parts.join(b.node_a, b.node_b);
    if (b.is_quadratic()) parts.join(b.node_a, b.node_m);  // the midside node of a B32/B32R
  }
  // A rigid link (*RIGID BODY, *MPC BEAM) makes its nodes one rigid piece:
  // a rigid motion of the reference node moves the tied nodes rigidly with it.
  for (const RigidLink& link : model.rigid_links)
    for (int s : link.slave_nodes) parts.join(link.reference_node, s);
  // A distributing coupling's reference node moves with its mounts (Eqs. R.6-R.8 are exact for rigid motions).
  for (const DistributingCoupling& c : model.distributing_couplings)
    for (int m : c.mount_nodes) parts.join(c.reference_node, m);
  out.part_of_node.assign(static_cast<std::size_t>(nn), -1);
  std::vector<int> root_part(static_cast<std::size_t>(nn), -1);
  for (int i = 0; i < nn; ++i) {
    const int r = parts.find(i);
    if (root_part[static_cast<std::size_t>(r)] < 0) root_part[static_cast<std::size_t>(r)] = out.parts++;
    out.part_of_node[static_cast<std::size_t>(i)] = root_part[static_cast<std::size_t>(r)];
  }
  // Centroid and size of each part: rotations about the centroid, scaled by
  // the size so that the six candidate motions have translations of order
  // one (the rank decision below then compares like with like).
  const int np = out.parts;
  std::vector<Eigen::Vector3d> centre(static_cast<std::size_t>(np), Eigen::Vector3d::Zero());
  std::vector<int> count(static_cast<std::size_t>(np), 0);
  for (int i = 0; i < nn; ++i) {
    const int p = out.part_of_node[static_cast<std::size_t>(i)];
    centre[static_cast<std::size_t>(p)] += model.nodes[static_cast<std::size_t>(i)].position;
    ++count[static_cast<std::size_t>(p)];
  }
  for (int p = 0; p < np; ++p) centre[static_cast<std::size_t>(p)] /= count[static_cast<std::size_t>(p)];
  std::vector<double> size(static_cast<std::size_t>(np), 0.0);
  for (int i = 0; i < nn; ++i) {
    const int p = out.part_of_node[static_cast<std::size_t>(i)];
    size[static_cast<std::size_t>(p)] =
        std::max(size[static_cast<std::size_t>(p)], (model.nodes[static_cast<std::size_t>(i)].position - centre[static_cast<std::size_t>(p)]).norm());
  }
  for (double& s : size) s = s > 0.0 ? s : 1.0;
  // Value of candidate motion k (0..5: x, y, z, rx, ry, rz) of node i's part at DOF d.
  auto motion = [&](int i, int d, int k) {
    const int p = out.part_of_node[static_cast<std::size_t>(i)];
    if (k < 3) return d == k ? 1.0 : 0.0;
    const double s = size[static_cast<std::size_t>(p)];
    Eigen::Vector3d axis = Eigen::Vector3d::Zero();
    axis(k - 3) = 1.0 / s;  // a rotation of 1/size rad
    if (d >= 3) return axis(d - 3);
    return axis.cross(model.nodes[static_cast<std::size_t>(i)].position - centre[static_cast<std::size_t>(p)])(d);
  };

  // Restraints, and groups of parts joined by springs (solved together).
  std::vector<Restraint> restraints;
  for (const Constraint& c : model.constraints) restraints.push_back({c.node, c.dof, -1, 0});
  UnionFind groups(np);
  for (const Spring& s : model.springs) {
    if (s.stiffness == 0.0) continue;
    restraints.push_back({s.node_a, s.dof_a, s.node_b, s.dof_b});
    if (s.node_b >= 0) groups.join(out.part_of_node[static_cast<std::size_t>(s.node_a)], out.part_of_node[static_cast<std::size_t>(s.node_b)]);
  }
  std::vector<std::vector<int>> group_parts(static_cast<std::size_t>(np));
  for (int p = 0; p < np; ++p) group_parts[static_cast<std::size_t>(groups.find(p))].push_back(p);
  std::vector<std::vector<const Restraint*>> group_restraints(static_cast<std::size_t>(np));
  for (const Restraint& r : restraints)
    group_restraints[static_cast<std::size_t>(groups.find(out.part_of_node[static_cast<std::size_t>(r.node_a)]))].push_back(&r);

  out.free_per_part.assign(static_cast<std::size_t>(np), 0);
  std::vector<Eigen::MatrixXd> kernels;
  std::vector<int> kernel_group;
  for (int g = 0; g < np; ++g) {
    const std::vector<int>& gp = group_parts[static_cast<std::size_t>(g)];
    if (gp.empty()) continue;
    const int nc = 6 * static_cast<int>(gp.size());
    auto column_of = [&](int part) {
      return 6 * static_cast<int>(std::find(gp.begin(), gp.end(), part) - gp.begin());
    };
    const auto& rs = group_restraints[static_cast<std::size_t>(g)];
    Eigen::MatrixXd b = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(rs.size()), nc);
    for (std::size_t r = 0; r < rs.size(); ++r) {
      const Restraint& x = *rs[r];
      const int ca = column_of(out.part_of_node[static_cast<std::size_t>(x.node_a)]);
      for (int k = 0; k < 6; ++k) b(static_cast<Eigen::Index>(r), ca + k) += motion(x.node_a, x.dof_a, k);
      if (x.node_b >= 0) {
        const int cb = column_of(out.part_of_node[static_cast<std::size_t>(x.node_b)]);
        for (int k = 0; k < 6; ++k) b(static_cast<Eigen::Index>(r), cb + k) -= motion(x.node_b, x.dof_b, k);
      }
    }
    // Kernel of b: the combinations no restraint sees. Rank by the singular
    // values relative to the largest (entries are of order one).
    Eigen::MatrixXd kernel;
    if (b.rows() == 0) {
      kernel = Eigen::MatrixXd::Identity(nc, nc);
    } else {
      Eigen::JacobiSVD<Eigen::MatrixXd> svd(b, Eigen::ComputeFullV);
      const Eigen::VectorXd sv = svd.singularValues();
      int rank = 0;
      for (Eigen::Index i = 0; i < sv.size(); ++i)
        if (sv(i) > 1e-9 * sv(0)) ++rank;
      kernel = svd.matrixV().rightCols(nc - rank);
    }
    // Parts joined by springs share their motions: counted under the first.
    out.free_per_part[static_cast<std::size_t>(gp[0])] = static_cast<int>(kernel.cols());
    kernels.push_back(kernel);
    kernel_group.push_back(g);
  }
  int p_total = 0;
  for (const Eigen::MatrixXd& k : kernels) p_total += static_cast<int>(k.cols());
  out.shapes = Eigen::MatrixXd::Zero(model.dof_count(), p_total);
  std::vector<std::vector<int>> nodes_of_part(static_cast<std::size_t>(np));
  for (int i = 0; i < nn; ++i) nodes_of_part[static_cast<std::size_t>(out.part_of_node[static_cast<std::size_t>(i)])].push_back(i);
  int col = 0;
  for (std::size_t q = 0; q < kernels.size(); ++q) {
    const std::vector<int>& gp = group_parts[static_cast<std::size_t>(kernel_group[q])];
    for (Eigen::Index j = 0; j < kernels[q].cols(); ++j, ++col) {
      out.part_of_shape.push_back(gp[0]);
      for (std::size_t pi = 0; pi < gp.size(); ++pi)
        for (int i : nodes_of_part[static_cast<std::size_t>(gp[pi])])
          for (int d = 0; d < 6; ++d) {
            double v = 0.0;
            for (int k = 0; k < 6; ++k) v += motion(i, d, k) * kernels[q](static_cast<Eigen::Index>(6 * pi) + k, j);
            out.shapes(kDofsPerNode * i + d, col) = v;
          }
    }
  }
  // Exactly zero at fixed DOFs (the kernel makes them zero to round-off).
  for (const Constraint& c : model.constraints) out.shapes.row(kDofsPerNode * c.node + c.dof).setZero();
  return out;
}

std::string FreeRigidMotions::describe(const FrameModel& model) const {
  std::vector<int> first(static_cast<std::size_t>(parts), -1), nodes(static_cast<std::size_t>(parts), 0);
  for (std::size_t i = 0; i < part_of_node.size(); ++i) {
    const int p = part_of_node[i];
    if (first[static_cast<std::size_t>(p)] < 0) first[static_cast<std::size_t>(p)] = model.nodes[i].id;
    ++nodes[static_cast<std::size_t>(p)];
  }
  // Parts with free motions first, at most five named.
  std::string out;
  int named = 0, rest = 0;
  for (int p = 0; p < parts; ++p) {
    if (free_per_part[static_cast<std::size_t>(p)] == 0) continue;
    if (named == 5) {
      ++rest;
      continue;
    }
    out += fmt::format("{}part {} ({} nodes, node {} among them): {} free", named ? "; " : "", p + 1,
                       nodes[static_cast<std::size_t>(p)], first[static_cast<std::size_t>(p)], free_per_part[static_cast<std::size_t>(p)]);
    ++named;
  }
  if (rest > 0) out += fmt::format("; {} more part(s) with free motions", rest);
  if (out.empty()) out = parts == 1 ? "the frame is held against every rigid motion" : fmt::format("{} parts, each held against every rigid motion", parts);
  return out;
}

}  // namespace framedyn::fem
