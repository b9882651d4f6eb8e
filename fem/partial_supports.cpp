// Balance of the loads on the free rigid motions, auxiliary supports; see partial_supports.h.
#include "fem/partial_supports.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace framedyn::fem {

namespace {

using core::Quantity;

// Round-off-sized components printed as 0 (no "-1.2e-17" that differs between CPUs).
double clean(double v, double reference) { return std::abs(v) <= 1e-9 * reference ? 0.0 : v + 0.0; }

std::string vec(const Eigen::Vector3d& v, double factor, double reference) {
  return fmt::format("({:.6g}, {:.6g}, {:.6g})", clean(v.x(), reference) * factor, clean(v.y(), reference) * factor,
                     clean(v.z(), reference) * factor);
}

// A direction with its sign fixed by a stable rule: the first component
// beyond 1e-6 is positive (no near-tie decides anything).
Eigen::Vector3d canonical(Eigen::Vector3d d) {
  d.normalize();
  for (int k = 0; k < 3; ++k)
    if (std::abs(d(k)) > 1e-6) {
      if (d(k) < 0.0) d = -d;
      break;
    }
  return d;
}

// "the z axis" for a direction within 1e-9 of a coordinate axis, else "the direction (a, b, c)".
std::string axis_name(const Eigen::Vector3d& d) {
  for (int k = 0; k < 3; ++k)
    if (std::abs(d(k)) >= 1.0 - 1e-9) return fmt::format("the {} axis", "xyz"[k]);
  return "the direction " + vec(d, 1.0, 1.0);
}

}  // namespace

std::vector<UnbalancedPart> unbalanced_loads(const FrameModel& model, const FreeRigidMotions& motions, const Eigen::VectorXd& f) {
  std::vector<UnbalancedPart> out;
  const core::UnitSystem& u = model.units;
  const double lf = 1.0 / u.to_si_factor(Quantity::length), ff = 1.0 / u.to_si_factor(Quantity::force),
               mf = 1.0 / u.to_si_factor(Quantity::moment);
  const int nn = static_cast<int>(model.nodes.size());
  for (int p = 0; p < motions.parts; ++p) {
    std::vector<Eigen::Index> cols;
    for (std::size_t j = 0; j < motions.part_of_shape.size(); ++j)
      if (motions.part_of_shape[j] == p) cols.push_back(static_cast<Eigen::Index>(j));
    if (cols.empty()) continue;
    // Is the group one part? (Parts joined by springs share their columns.)
    std::vector<int> nodes;
    bool single = true;
    for (int i = 0; i < nn; ++i) {
      const bool in_part = motions.part_of_node[static_cast<std::size_t>(i)] == p;
      if (in_part) nodes.push_back(i);
      if (!in_part)
        for (Eigen::Index j : cols)
          if (motions.shapes.block(kDofsPerNode * i, j, kDofsPerNode, 1).cwiseAbs().maxCoeff() > 0.0) single = false;
    }
    UnbalancedPart up;
    up.part = p;
    up.free_motions = static_cast<int>(cols.size());
    if (!single) {
      // Parts joined by springs: the work of each free motion on all DOFs (Eq. 19.1).
      bool unbalanced = false;
      for (Eigen::Index j : cols) {
        const double work = motions.shapes.col(j).dot(f);
        const double scale = motions.shapes.col(j).cwiseAbs().dot(f.cwiseAbs());
        unbalanced = unbalanced || std::abs(work) > 1e-9 * scale;
      }
      if (!unbalanced) continue;
      up.motion = "a rigid motion of the parts joined to it by springs";
      up.unbalanced = "the loads do work on it";
      out.push_back(up);
      continue;
    }
    // Centroid and size of the part, as fem/rigid_body_modes.cpp measures them.
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (int i : nodes) c += model.nodes[static_cast<std::size_t>(i)].position;
    c /= static_cast<double>(nodes.size());
    double s = 0.0;
    for (int i : nodes) s = std::max(s, (model.nodes[static_cast<std::size_t>(i)].position - c).norm());
    if (!(s > 0.0)) s = 1.0;
    // Each free motion as (t, s theta) about the centroid (Eq. 7.2), read at the part's first node.
    const int i0 = nodes.front();
    const Eigen::Vector3d x0 = model.nodes[static_cast<std::size_t>(i0)].position - c;
    Eigen::MatrixXd cmat(6, static_cast<Eigen::Index>(cols.size()));
    for (std::size_t j = 0; j < cols.size(); ++j) {
      const Eigen::Vector3d theta = motions.shapes.block<3, 1>(kDofsPerNode * i0 + 3, cols[j]);
      const Eigen::Vector3d t = motions.shapes.block<3, 1>(kDofsPerNode * i0, cols[j]) - theta.cross(x0);
      cmat.block<3, 1>(0, static_cast<Eigen::Index>(j)) = t;
      cmat.block<3, 1>(3, static_cast<Eigen::Index>(j)) = s * theta;
    }
    // The loads' resultant about the centroid and their own magnitude.
    Eigen::Vector3d force = Eigen::Vector3d::Zero(), moment = Eigen::Vector3d::Zero();
    double magnitude = 0.0;
    for (int i : nodes) {
      const Eigen::Vector3d fi = f.segment<3>(kDofsPerNode * i), mi = f.segment<3>(kDofsPerNode * i + 3);
      const Eigen::Vector3d xi = model.nodes[static_cast<std::size_t>(i)].position - c;
      force += fi;
      moment += xi.cross(fi) + mi;
      magnitude += fi.norm() * (1.0 + xi.norm() / s) + mi.norm() / s;
    }
    Eigen::Matrix<double, 6, 1> g;
    g << force, moment / s;
    // The motion of largest work per unit size (Eq. 19.2): g projected on the free motions.
    const Eigen::HouseholderQR<Eigen::MatrixXd> qr(cmat);
    const Eigen::MatrixXd q = qr.householderQ() * Eigen::MatrixXd::Identity(6, cmat.cols());
    const Eigen::Matrix<double, 6, 1> driven = q * (q.transpose() * g);
    if (!(driven.norm() > 1e-9 * magnitude)) continue;
    const Eigen::Vector3d t = driven.head<3>(), theta = driven.tail<3>() / s;
    if (theta.norm() * s <= 1e-6 * driven.norm()) {
      const Eigen::Vector3d d = canonical(t);
      up.motion = "translation along " + axis_name(d);
      up.unbalanced = fmt::format("unbalanced force {:.6g} {} along it (resultant force {} {})", clean(force.dot(d), magnitude) * ff,
                                  u.label(Quantity::force), vec(force, ff, magnitude), u.label(Quantity::force));
    } else {
      const Eigen::Vector3d a = canonical(theta);
      Eigen::Vector3d point = c + theta.cross(t) / theta.squaredNorm();  // the axis' point nearest the centroid
      std::string through = "through " + vec(point, lf, s) + " " + u.label(Quantity::length);
      for (int i : nodes) {  // a node on the axis names it (the lowest index: a stable rule)
        const Eigen::Vector3d v = model.nodes[static_cast<std::size_t>(i)].position - point;
        if ((v - v.dot(a) * a).norm() <= 1e-6 * s) {
          point = model.nodes[static_cast<std::size_t>(i)].position;
          through = fmt::format("through node {}", model.nodes[static_cast<std::size_t>(i)].id);
          break;
        }
      }
      const Eigen::Vector3d m_point = moment + (c - point).cross(force);
      up.motion = "rotation about " + axis_name(a) + " " + through;
      up.unbalanced = fmt::format("unbalanced moment {:.6g} {} about that axis (resultant force {} {})", clean(m_point.dot(a), magnitude * s) * mf,
                                  u.label(Quantity::moment), vec(force, ff, magnitude), u.label(Quantity::force));
    }
    out.push_back(up);
  }
  return out;
}

std::string describe(const FrameModel& model, const FreeRigidMotions& motions, const std::vector<UnbalancedPart>& parts) {
  std::string out;
  for (const UnbalancedPart& p : parts) {
    int first = -1, count = 0;
    for (std::size_t i = 0; i < motions.part_of_node.size(); ++i)
      if (motions.part_of_node[i] == p.part) {
        if (first < 0) first = model.nodes[i].id;
        ++count;
      }
    out += fmt::format("{}part {} ({} nodes, node {} among them; {} free rigid motion{}): the loads drive its {}, {}", out.empty() ? "" : "; ",
                       p.part + 1, count, first, p.free_motions, p.free_motions == 1 ? "" : "s", p.motion, p.unbalanced);
  }
  return out;
}

Eigen::MatrixXd rigid_motions_on_equations(const DofMap& dofs, const Eigen::MatrixXd& shapes_all) {
  Eigen::MatrixXd r(dofs.free_count(), shapes_all.cols());
  for (int e = 0; e < dofs.free_count(); ++e) r.row(e) = shapes_all.row(dofs.free_dofs[static_cast<std::size_t>(e)]);
  return r;
}

std::vector<int> auxiliary_supports(const Eigen::MatrixXd& rigid) {
  Eigen::MatrixXd a = rigid;
  const Eigen::Index n = a.rows();
  std::vector<int> chosen;
  double first = 0.0;
  for (Eigen::Index step = 0; step < rigid.cols(); ++step) {
    const Eigen::VectorXd norms = a.rowwise().norm();
    const double largest = n > 0 ? norms.maxCoeff() : 0.0;
    if (step == 0) first = largest;
    if (!(largest > 1e-9 * first) || !(largest > 0.0))
      throw std::invalid_argument(fmt::format("the free rigid motions are dependent: {} of {} fixed", step, rigid.cols()));
    Eigen::Index pick = 0;
    while (norms(pick) < (1.0 - 1e-6) * largest) ++pick;  // lowest equation among the near-largest
    chosen.push_back(static_cast<int>(pick));
    const Eigen::RowVectorXd dir = a.row(pick) / norms(pick);
    a -= (a * dir.transpose()) * dir;  // the motions this support fixes are gone from every row
  }
  std::sort(chosen.begin(), chosen.end());
  return chosen;
}

SparseMatrix with_auxiliary_supports(const SparseMatrix& k, const std::vector<int>& auxiliary) {
  const Eigen::Index n = k.rows();
  std::vector<char> is_aux(static_cast<std::size_t>(n), 0);
  for (int e : auxiliary) is_aux[static_cast<std::size_t>(e)] = 1;
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(static_cast<std::size_t>(k.nonZeros()));
  for (int col = 0; col < k.outerSize(); ++col)
    for (SparseMatrix::InnerIterator it(k, col); it; ++it) {
      const bool aux = is_aux[static_cast<std::size_t>(it.row())] || is_aux[static_cast<std::size_t>(col)];
      if (!aux) t.emplace_back(static_cast<int>(it.row()), col, it.value());
      else if (it.row() == col) t.emplace_back(col, col, it.value() > 0.0 ? it.value() : 1.0);
    }
  for (int e : auxiliary)  // a DOF with no stiffness entry at all still gets its diagonal
    if (k.coeff(e, e) == 0.0) t.emplace_back(e, e, 1.0);
  SparseMatrix ks(n, n);
  ks.setFromTriplets(t.begin(), t.end());
  return ks;
}

}  // namespace framedyn::fem
