// Master-slave rows of rigid links; see rigid_links.h and docs/theory/fem.md, "Rigid links".
#include "fem/rigid_links.h"

#include <fmt/format.h>

#include <algorithm>
#include <utility>

namespace framedyn::fem {

RigidLinkError::RigidLinkError(int link, std::string expected, std::string found)
    : std::invalid_argument(fmt::format("rigid link {}: expected {}, found {}", link + 1, expected, found)),
      link_(link),
      expected_(std::move(expected)),
      found_(std::move(found)) {}

RigidLinkConstraints rigid_link_constraints(const FrameModel& model) {
  RigidLinkConstraints out;
  if (model.rigid_links.empty()) return out;
  const int nodes = static_cast<int>(model.nodes.size());
  const auto id = [&](int i) { return model.nodes[static_cast<std::size_t>(i)].id; };
  // Which link each node is a slave of (-1: none).
  std::vector<int> slave_link(static_cast<std::size_t>(nodes), -1);
  for (std::size_t li = 0; li < model.rigid_links.size(); ++li) {
    const RigidLink& link = model.rigid_links[li];
    const int l = static_cast<int>(li);
    if (link.reference_node < 0 || link.reference_node >= nodes)
      throw RigidLinkError(l, "a reference node of the model", fmt::format("node index {}", link.reference_node));
    if (link.slave_nodes.empty()) throw RigidLinkError(l, "at least one node tied to the reference node", "none");
    for (int s : link.slave_nodes) {
      if (s < 0 || s >= nodes) throw RigidLinkError(l, "slave nodes of the model", fmt::format("node index {}", s));
      if (s == link.reference_node)
        throw RigidLinkError(l, "slave nodes other than the reference node", fmt::format("node {} in both roles", id(s)));
      int& owner = slave_link[static_cast<std::size_t>(s)];
      if (owner >= 0 && owner != l)
        throw RigidLinkError(l, "each node tied to one rigid link only",
                             fmt::format("node {} already tied by {}", id(s),
                                         model.rigid_links[static_cast<std::size_t>(owner)].source.empty()
                                             ? fmt::format("rigid link {}", owner + 1)
                                             : model.rigid_links[static_cast<std::size_t>(owner)].source));
      owner = l;
    }
  }
  // A reference node that is itself a slave would need T applied twice; refused (R.5).
  for (std::size_t li = 0; li < model.rigid_links.size(); ++li) {
    const RigidLink& link = model.rigid_links[li];
    const int owner = slave_link[static_cast<std::size_t>(link.reference_node)];
    if (owner >= 0)
      throw RigidLinkError(static_cast<int>(li), "a reference node that is not tied to another rigid link (chains of rigid links are not resolved)",
                           fmt::format("reference node {}, tied by {}", id(link.reference_node),
                                       model.rigid_links[static_cast<std::size_t>(owner)].source.empty()
                                           ? fmt::format("rigid link {}", owner + 1)
                                           : model.rigid_links[static_cast<std::size_t>(owner)].source));
  }

  out.slave_of.assign(static_cast<std::size_t>(model.dof_count()), -1);
  for (std::size_t li = 0; li < model.rigid_links.size(); ++li) {
    const RigidLink& link = model.rigid_links[li];
    const int r = link.reference_node;
    const Eigen::Vector3d& xr = model.nodes[static_cast<std::size_t>(r)].position;
    for (int s : link.slave_nodes) {
      const Eigen::Vector3d d = model.nodes[static_cast<std::size_t>(s)].position - xr;
      // Eq. (R.1): u_s,k = u_r,k + (theta_r x d)_k, with (theta x d)_k = sum_j e_kjl ... written out:
      //   x: theta_y dz - theta_z dy,  y: theta_z dx - theta_x dz,  z: theta_x dy - theta_y dx.
      const int rotation_a[3] = {4, 5, 3}, rotation_b[3] = {5, 3, 4};
      const double coef_a[3] = {d.z(), d.x(), d.y()}, coef_b[3] = {-d.y(), -d.z(), -d.x()};
      for (int k = 0; k < (link.slave_rotations ? 6 : 3); ++k) {
        SlaveDof sd;
        sd.dof = kDofsPerNode * s + k;
        sd.master[0] = kDofsPerNode * r + k;
        sd.coefficient[0] = 1.0;
        sd.count = 1;
        if (k < 3) {
          if (coef_a[k] != 0.0) {
            sd.master[static_cast<std::size_t>(sd.count)] = kDofsPerNode * r + rotation_a[k];
            sd.coefficient[static_cast<std::size_t>(sd.count++)] = coef_a[k];
          }
          if (coef_b[k] != 0.0) {
            sd.master[static_cast<std::size_t>(sd.count)] = kDofsPerNode * r + rotation_b[k];
            sd.coefficient[static_cast<std::size_t>(sd.count++)] = coef_b[k];
          }
        }
        out.slave_of[static_cast<std::size_t>(sd.dof)] = static_cast<int>(out.slaves.size());
        out.slaves.push_back(sd);
      }
    }
  }
  // A support on a slave DOF would fix a combination of the reference node's DOFs: refused.
  for (const Constraint& c : model.constraints) {
    if (c.node < 0 || c.node >= nodes) continue;
    const int g = kDofsPerNode * c.node + c.dof;
    if (out.slave_of[static_cast<std::size_t>(g)] < 0) continue;
    const int l = slave_link[static_cast<std::size_t>(c.node)];
    throw RigidLinkError(l, fmt::format("no *BOUNDARY on the nodes the link ties (support the reference node {} instead)",
                                        id(model.rigid_links[static_cast<std::size_t>(l)].reference_node)),
                         fmt::format("a *BOUNDARY on {}", model.describe_dof(g)));
  }
  std::sort(out.slaves.begin(), out.slaves.end(), [](const SlaveDof& a, const SlaveDof& b) { return a.dof < b.dof; });
  for (std::size_t i = 0; i < out.slaves.size(); ++i) out.slave_of[static_cast<std::size_t>(out.slaves[i].dof)] = static_cast<int>(i);
  return out;
}

void fill_slave_dofs_columns(const RigidLinkConstraints& links, Eigen::MatrixXd& u) {
  // Masters are never slaves (chains are refused), so one pass is exact.
  for (const SlaveDof& s : links.slaves)
    for (Eigen::Index c = 0; c < u.cols(); ++c) {
      double v = 0.0;
      for (int k = 0; k < s.count; ++k) v += s.coefficient[static_cast<std::size_t>(k)] * u(s.master[static_cast<std::size_t>(k)], c);
      u(s.dof, c) = v;
    }
}

void fill_slave_dofs(const RigidLinkConstraints& links, Eigen::VectorXd& u) {
  for (const SlaveDof& s : links.slaves) {
    double v = 0.0;
    for (int k = 0; k < s.count; ++k) v += s.coefficient[static_cast<std::size_t>(k)] * u(s.master[static_cast<std::size_t>(k)]);
    u(s.dof) = v;
  }
}

void fold_slave_forces(const RigidLinkConstraints& links, Eigen::VectorXd& f) {
  for (const SlaveDof& s : links.slaves) {
    for (int k = 0; k < s.count; ++k) f(s.master[static_cast<std::size_t>(k)]) += s.coefficient[static_cast<std::size_t>(k)] * f(s.dof);
    f(s.dof) = 0.0;
  }
}

}  // namespace framedyn::fem
