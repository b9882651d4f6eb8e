// Load points to nodal loads; see load_mapping.h and docs/theory/coupling.md, "Load mapping".
#include "coupling/load_mapping.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cctype>
#include <numeric>

#include "core/error.h"

namespace framedyn::coupling {

namespace {

Eigen::Matrix3d cross_matrix(const Eigen::Vector3d& a) {
  Eigen::Matrix3d s;
  s << 0, -a.z(), a.y(), a.z(), 0, -a.x(), -a.y(), a.x(), 0;
  return s;
}

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

}  // namespace

Eigen::MatrixXd spider_distribution(const Eigen::Vector3d& p, const std::vector<Eigen::Vector3d>& x) {
  const int n = static_cast<int>(x.size());
  if (n == 0) throw std::invalid_argument("a spider needs at least one node");
  // Equal weights w_i = 1 (Eq. C.1): centroid c, arms r_i = x_i - c.
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (const auto& xi : x) c += xi;
  c /= n;
  // Moment about c of the point load (Eq. C.2): M_c = M + (p - c) x F.
  Eigen::Matrix<double, 3, 6> to_mc;
  to_mc << cross_matrix(p - c), Eigen::Matrix3d::Identity();
  // J = sum_i (|r_i|^2 I - r_i r_i^T): the spider's "polar inertia" (Eq. C.3).
  Eigen::Matrix3d j = Eigen::Matrix3d::Zero();
  for (const auto& xi : x) {
    const Eigen::Vector3d r = xi - c;
    j += r.squaredNorm() * Eigen::Matrix3d::Identity() - r * r.transpose();
  }
  // Pseudo-inverse of J: the part of M_c that nodal forces can carry (all of
  // it unless the nodes are collinear or a single node).
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(j);
  const double cutoff = 1e-12 * std::max(es.eigenvalues().cwiseAbs().maxCoeff(), 1e-300);
  Eigen::Matrix3d jplus = Eigen::Matrix3d::Zero();
  for (int k = 0; k < 3; ++k)
    if (es.eigenvalues()(k) > cutoff) jplus += es.eigenvectors().col(k) * es.eigenvectors().col(k).transpose() / es.eigenvalues()(k);
  const Eigen::Matrix3d carried = j * jplus;  // projector on the range of J
  // Node i (Eq. C.4): f_i = F / n + theta x r_i with theta = J^+ M_c;
  //                   m_i = (I - J J^+) M_c / n (the remainder, about the line of collinear nodes).
  Eigen::MatrixXd b = Eigen::MatrixXd::Zero(6 * n, 6);
  const Eigen::Matrix<double, 3, 6> theta = jplus * to_mc;
  const Eigen::Matrix<double, 3, 6> rest = (Eigen::Matrix3d::Identity() - carried) * to_mc / n;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d r = x[static_cast<std::size_t>(i)] - c;
    b.block<3, 3>(6 * i, 0) += Eigen::Matrix3d::Identity() / n;
    b.block<3, 6>(6 * i, 0) += -cross_matrix(r) * theta;  // theta x r = -r x theta
    b.block<3, 6>(6 * i + 3, 0) = rest;
  }
  return b;
}

LoadMapping map_load_points(const fem::FrameModel& model, const std::vector<LoadPointLocation>& points,
                            const LoadMappingOptions& options) {
  if (model.nodes.empty()) throw core::InputError({"", 0, "load points"}, "a mesh with nodes", "no nodes");
  LoadMapping out;
  std::vector<Eigen::Triplet<double>> triplets;
  for (std::size_t j = 0; j < points.size(); ++j) {
    const LoadPointLocation& lp = points[j];
    MappedLoadPoint m;
    m.name = lp.name;
    m.location = lp.location;
    const auto set = model.node_sets.find(upper(lp.name));
    if (set != model.node_sets.end()) {
      if (set->second.empty())
        throw core::InputError({"", 0, "load point " + lp.name}, "a node set with at least one node", "an empty node set");
      m.from_node_set = true;
      for (int node : set->second)
        if ((model.nodes[static_cast<std::size_t>(node)].position - lp.location).norm() <= options.coincidence_tolerance) {
          m.nodes = {node};
          m.at_node = true;
          break;
        }
      if (!m.at_node) m.nodes = set->second;
    } else {
      const int k = std::max(1, std::min<int>(options.nearest_nodes, static_cast<int>(model.nodes.size())));
      std::vector<int> order(model.nodes.size());
      std::iota(order.begin(), order.end(), 0);
      auto dist = [&](int a) { return (model.nodes[static_cast<std::size_t>(a)].position - lp.location).squaredNorm(); };
      std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return dist(a) < dist(b); });
      if (std::sqrt(dist(order[0])) <= options.coincidence_tolerance) {
        m.nodes = {order[0]};
        m.at_node = true;
      } else {
        m.nodes.assign(order.begin(), order.begin() + k);
      }
    }
    std::vector<Eigen::Vector3d> x;
    for (int node : m.nodes) {
      x.push_back(model.nodes[static_cast<std::size_t>(node)].position);
      m.spider_length = std::max(m.spider_length, (x.back() - lp.location).norm());
    }
    const Eigen::MatrixXd b = m.at_node ? Eigen::MatrixXd(Eigen::MatrixXd::Identity(6, 6)) : spider_distribution(lp.location, x);
    for (std::size_t i = 0; i < m.nodes.size(); ++i)
      for (int r = 0; r < 6; ++r)
        for (int c = 0; c < 6; ++c) {
          const double v = b(6 * static_cast<Eigen::Index>(i) + r, c);
          if (v != 0.0)
            triplets.emplace_back(fem::kDofsPerNode * m.nodes[i] + r, 6 * static_cast<int>(j) + c, v);
        }
    out.points.push_back(std::move(m));
  }
  out.distribution.resize(model.dof_count(), 6 * static_cast<int>(points.size()));
  out.distribution.setFromTriplets(triplets.begin(), triplets.end());
  return out;
}

}  // namespace framedyn::coupling
