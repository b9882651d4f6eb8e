// Master-slave rows of rigid links; see rigid_links.h and docs/theory/fem.md, "Rigid links".
#include "fem/rigid_links.h"

#include <fmt/format.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <utility>

namespace framedyn::fem {

RigidLinkError::RigidLinkError(int link, std::string expected, std::string found)
    : std::invalid_argument(fmt::format("rigid link {}: expected {}, found {}", link + 1, expected, found)),
      link_(link),
      expected_(std::move(expected)),
      found_(std::move(found)) {}

namespace {

Eigen::Matrix3d cross_matrix(const Eigen::Vector3d& a) {
  Eigen::Matrix3d m;
  m << 0.0, -a.z(), a.y(), a.z(), 0.0, -a.x(), -a.y(), a.x(), 0.0;
  return m;
}

}  // namespace

Eigen::MatrixXd distributing_coupling_rows(const FrameModel& model, const DistributingCoupling& c) {
  const std::size_t n = c.mount_nodes.size();
  double total = 0.0;
  for (double w : c.weights) total += w;
  // Eq. R.6: the weighted centroid of the mounts and the mounts' arms about it.
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < n; ++i) centroid += c.weights[i] / total * model.nodes[static_cast<std::size_t>(c.mount_nodes[i])].position;
  Eigen::Matrix3d a = Eigen::Matrix3d::Zero();
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d r = model.nodes[static_cast<std::size_t>(c.mount_nodes[i])].position - centroid;
    a += c.weights[i] / total * (r.squaredNorm() * Eigen::Matrix3d::Identity() - r * r.transpose());
  }
  // A is singular when the mounts lie on one line: a rotation about it moves none of them.
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(a);
  if (!(eig.eigenvalues()(2) > 0.0) || eig.eigenvalues()(0) < 1e-6 * eig.eigenvalues()(2))
    throw std::invalid_argument(fmt::format("distributing coupling {}: expected mounts that do not all lie on one line, found {} mounts on one line",
                                            c.source, n));
  const Eigen::Matrix3d a_inv = a.inverse();
  const Eigen::Vector3d d = model.nodes[static_cast<std::size_t>(c.reference_node)].position - centroid;
  Eigen::MatrixXd rows(6, 3 * static_cast<Eigen::Index>(n));
  for (std::size_t i = 0; i < n; ++i) {
    const double w = c.weights[i] / total;
    const Eigen::Vector3d r = model.nodes[static_cast<std::size_t>(c.mount_nodes[i])].position - centroid;
    // Eq. R.7: theta = A^-1 sum w_i r_i x u_i;  Eq. R.8: u_ref = sum w_i u_i + theta x d.
    const Eigen::Matrix3d b = w * a_inv * cross_matrix(r);
    const Eigen::Index col = 3 * static_cast<Eigen::Index>(i);
    rows.block<3, 3>(0, col) = w * Eigen::Matrix3d::Identity() - cross_matrix(d) * b;
    rows.block<3, 3>(3, col) = b;
  }
  return rows;
}

DistributingCouplingError::DistributingCouplingError(int coupling, const std::string& source, std::string expected, std::string found)
    : std::invalid_argument(fmt::format("distributing coupling {}: expected {}, found {}", source, expected, found)),
      coupling_(coupling),
      expected_(std::move(expected)),
      found_(std::move(found)) {}

RigidLinkConstraints rigid_link_constraints(const FrameModel& model) {
  RigidLinkConstraints out;
  if (model.rigid_links.empty() && model.distributing_couplings.empty()) return out;
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
  // Distributing couplings (Eqs. R.6-R.8): the reference node is a slave of the mounts' translations.
  // Its node is tied by nothing else, and no mount is a slave (chains are not resolved).
  std::vector<int> coupled(static_cast<std::size_t>(nodes), -1);  // node -> coupling whose reference it is
  for (std::size_t ci = 0; ci < model.distributing_couplings.size(); ++ci) {
    const DistributingCoupling& c = model.distributing_couplings[ci];
    const auto refuse = [&](const std::string& expected, const std::string& found) {
      return DistributingCouplingError(static_cast<int>(ci), c.source, expected, found);
    };
    if (c.reference_node < 0 || c.reference_node >= nodes) throw refuse("a reference node of the model", fmt::format("node index {}", c.reference_node));
    if (c.mount_nodes.empty() || static_cast<int>(c.mount_nodes.size()) > kMaxCouplingMounts)
      throw refuse(fmt::format("1 to {} mounts", kMaxCouplingMounts), fmt::format("{}", c.mount_nodes.size()));
    if (c.weights.size() != c.mount_nodes.size()) throw refuse("one weight per mount", fmt::format("{} weights, {} mounts", c.weights.size(), c.mount_nodes.size()));
    const int ref = c.reference_node;
    if (slave_link[static_cast<std::size_t>(ref)] >= 0 || coupled[static_cast<std::size_t>(ref)] >= 0)
      throw refuse("a reference node tied by nothing else", fmt::format("node {} already tied", id(ref)));
    for (const RigidLink& link : model.rigid_links)
      if (link.reference_node == ref) throw refuse("a reference node tied by nothing else", fmt::format("node {}, a rigid link's reference", id(ref)));
    for (std::size_t i = 0; i < c.mount_nodes.size(); ++i) {
      const int m = c.mount_nodes[i];
      if (m < 0 || m >= nodes) throw refuse("mount nodes of the model", fmt::format("node index {}", m));
      if (m == ref) throw refuse("mounts other than the reference node", fmt::format("node {} in both roles", id(m)));
      if (!(c.weights[i] > 0.0)) throw refuse("positive weights", fmt::format("{} at node {}", c.weights[i], id(m)));
      if (slave_link[static_cast<std::size_t>(m)] >= 0) throw refuse("mounts not tied by a rigid link", fmt::format("node {}", id(m)));
      for (std::size_t j = 0; j < i; ++j)
        if (c.mount_nodes[j] == m) throw refuse("distinct mounts", fmt::format("node {} twice", id(m)));
    }
    coupled[static_cast<std::size_t>(ref)] = static_cast<int>(ci);
  }
  for (std::size_t ci = 0; ci < model.distributing_couplings.size(); ++ci)
    for (int m : model.distributing_couplings[ci].mount_nodes)
      if (coupled[static_cast<std::size_t>(m)] >= 0)
        throw DistributingCouplingError(static_cast<int>(ci), model.distributing_couplings[ci].source, "mounts that no coupling ties",
                                        fmt::format("node {}, the reference of {}", id(m),
                                                    model.distributing_couplings[static_cast<std::size_t>(coupled[static_cast<std::size_t>(m)])].source));
  for (std::size_t ci = 0; ci < model.distributing_couplings.size(); ++ci) {
    const DistributingCoupling& c = model.distributing_couplings[ci];
    Eigen::MatrixXd rows;
    try {
      rows = distributing_coupling_rows(model, c);
    } catch (const std::invalid_argument&) {
      std::string ids;
      for (std::size_t i = 0; i < c.mount_nodes.size(); ++i) ids += (i ? ", " : "") + std::to_string(id(c.mount_nodes[i]));
      throw DistributingCouplingError(static_cast<int>(ci), c.source, "mounts that do not all lie on one line", fmt::format("nodes {}", ids));
    }
    for (int k = 0; k < kDofsPerNode; ++k) {
      SlaveDof sd;
      sd.dof = kDofsPerNode * c.reference_node + k;
      for (std::size_t i = 0; i < c.mount_nodes.size(); ++i)
        for (int j = 0; j < 3; ++j) {
          const double v = rows(k, 3 * static_cast<Eigen::Index>(i) + j);
          if (v == 0.0) continue;
          sd.master[static_cast<std::size_t>(sd.count)] = kDofsPerNode * c.mount_nodes[i] + j;
          sd.coefficient[static_cast<std::size_t>(sd.count++)] = v;
        }
      out.slave_of[static_cast<std::size_t>(sd.dof)] = static_cast<int>(out.slaves.size());
      out.slaves.push_back(sd);
    }
  }
  for (const Constraint& c : model.constraints) {
    if (c.node < 0 || c.node >= nodes || coupled[static_cast<std::size_t>(c.node)] < 0) continue;
    const int ci = coupled[static_cast<std::size_t>(c.node)];
    throw DistributingCouplingError(ci, model.distributing_couplings[static_cast<std::size_t>(ci)].source,
                                    "no *BOUNDARY on its reference node (support a mount instead)",
                                    "a *BOUNDARY on " + model.describe_dof(kDofsPerNode * c.node + c.dof));
  }
  // A support on a slave DOF would fix a combination of the reference node's DOFs: refused.
  for (const Constraint& c : model.constraints) {
    if (c.node < 0 || c.node >= nodes) continue;
    const int g = kDofsPerNode * c.node + c.dof;
    if (out.slave_of[static_cast<std::size_t>(g)] < 0 || slave_link[static_cast<std::size_t>(c.node)] < 0) continue;
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
