// The frame assembly's parts on the beam model; see frame_parts.h (Eqs. 9.1-9.3).
#include "coupling/frame_parts.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cctype>
#include <stdexcept>

#include "fem/rigid_links.h"

namespace framedyn::coupling {

int nearest_frame_node(const fem::FrameModel& model, const Eigen::Vector3d& x) {
  std::vector<bool> on_beam(model.nodes.size(), false);
  for (const fem::BeamElement& b : model.beams)
    for (int n : {b.node_a, b.node_b, b.node_m})
      if (n >= 0) on_beam[static_cast<std::size_t>(n)] = true;
  double nearest = -1.0;
  for (std::size_t i = 0; i < model.nodes.size(); ++i)
    if (on_beam[i]) {
      const double d = (model.nodes[i].position - x).norm();
      if (nearest < 0.0 || d < nearest) nearest = d;
    }
  if (nearest < 0.0) throw std::invalid_argument("the frame model has no beam elements to mount a part on");
  // Every node within 1e-9 relative (and 1e-12 m) of the nearest distance is a tie: the lowest node number wins.
  const double within = nearest * (1.0 + 1e-9) + 1e-12;
  int best = -1;
  for (std::size_t i = 0; i < model.nodes.size(); ++i)
    if (on_beam[i] && (model.nodes[i].position - x).norm() <= within && (best < 0 || model.nodes[i].id < model.nodes[static_cast<std::size_t>(best)].id))
      best = static_cast<int>(i);
  return best;
}

namespace {

// The beam node a mount names: its number (STUDY-111 when no beam element uses it) or the node nearest its point.
int mount_node(const fem::FrameModel& model, const PartMount& m, const std::string& mesh_name) {
  if (m.by_point) return nearest_frame_node(model, m.point);
  const int i = model.node_index(m.node);
  bool on_beam = false;
  if (i >= 0)
    for (const fem::BeamElement& b : model.beams) on_beam = on_beam || b.node_a == i || b.node_b == i || b.node_m == i;
  if (!on_beam)
    throw core::InputError(m.where, fmt::format("a node number of {} that a beam element uses", mesh_name),
                           fmt::format("node {}{}", m.node, i < 0 ? ", not in the mesh" : ", on no beam element"));
  return i;
}

}  // namespace

std::vector<MountedPart> mount_frame_parts(fem::FrameModel& model, const std::vector<rigid::RigidPart3D>& parts) {
  std::vector<FramePart> without_mounts;
  for (const rigid::RigidPart3D& p : parts) without_mounts.push_back({p, {}, {}});
  return mount_frame_parts(model, without_mounts);
}

std::vector<MountedPart> mount_frame_parts(fem::FrameModel& model, const std::vector<FramePart>& parts, const std::string& mesh_name) {
  std::vector<MountedPart> out;
  if (parts.empty()) return out;
  // New node and element numbers above the mesh's.
  int node_id = 0, element_id = 0;
  for (const fem::Node& n : model.nodes) node_id = std::max(node_id, n.id);
  for (const fem::BeamElement& b : model.beams) element_id = std::max(element_id, b.id);
  for (const fem::PointMass& m : model.point_masses) element_id = std::max(element_id, m.element_id);
  for (const fem::Spring& s : model.springs) element_id = std::max(element_id, s.element_id);
  constexpr double kOnNode = 1e-6;  // m: a c.g. this close to the frame node is on it
  // The mounts resolve against the mesh's beam nodes only: resolve them all before any c.g. node is added.
  std::vector<std::vector<int>> mounts(parts.size());
  for (std::size_t k = 0; k < parts.size(); ++k) {
    for (std::size_t i = 0; i < parts[k].mounts.size(); ++i) {
      const int n = mount_node(model, parts[k].mounts[i], mesh_name);
      for (std::size_t j = 0; j < i; ++j)
        if (mounts[k][j] == n)
          throw core::InputError(parts[k].mounts[i].where, "mounts at distinct nodes of " + mesh_name,
                                 fmt::format("mounts[{}] and mounts[{}] both at node {}", j, i, model.nodes[static_cast<std::size_t>(n)].id));
      mounts[k].push_back(n);
    }
  }
  for (std::size_t k = 0; k < parts.size(); ++k) {
    const rigid::RigidPart3D& p = parts[k].part;
    if (!(p.mass > 0.0)) throw std::invalid_argument("frame part " + p.name + ": no mass");
    MountedPart m;
    m.part = p;
    if (mounts[k].size() >= 2) {
      // A distributing coupling from the mounts to a new node at the c.g. (Eqs. 9.5-9.6).
      m.frame_node = mounts[k].front();
      m.mount_nodes = mounts[k];
      m.linked = true;
      model.nodes.push_back({++node_id, p.cg});
      m.mass_node = static_cast<int>(model.nodes.size()) - 1;
      fem::DistributingCoupling c;
      c.reference_node = m.mass_node;
      c.mount_nodes = mounts[k];
      c.weights.assign(mounts[k].size(), 1.0);
      c.source = "frame part " + p.name;
      Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
      for (int n : mounts[k]) centroid += model.nodes[static_cast<std::size_t>(n)].position / static_cast<double>(mounts[k].size());
      m.arm = (p.cg - centroid).norm();
      try {
        (void)fem::distributing_coupling_rows(model, c);
      } catch (const std::invalid_argument&) {
        std::string ids;
        for (std::size_t i = 0; i < mounts[k].size(); ++i) ids += (i ? ", " : "") + std::to_string(model.nodes[static_cast<std::size_t>(mounts[k][i])].id);
        throw core::InputError(parts[k].mounts_where,
                               "one mount, or mounts that do not all lie on one line (their least-squares rigid motion must fix the part's rotation)",
                               fmt::format("{} mounts on one line, nodes {}", mounts[k].size(), ids));
      }
      model.distributing_couplings.push_back(c);
      model.point_masses.push_back({++element_id, m.mass_node, p.mass, p.inertia});
      out.push_back(m);
      continue;
    }
    m.frame_node = mounts[k].empty() ? nearest_frame_node(model, p.cg) : mounts[k].front();
    m.arm = (p.cg - model.nodes[static_cast<std::size_t>(m.frame_node)].position).norm();
    m.linked = m.arm > kOnNode;
    if (m.linked) {
      model.nodes.push_back({++node_id, p.cg});
      m.mass_node = static_cast<int>(model.nodes.size()) - 1;
      fem::RigidLink link;
      link.reference_node = m.frame_node;
      link.slave_nodes = {m.mass_node};
      link.source = "frame part " + p.name;
      model.rigid_links.push_back(link);
    } else {
      m.mass_node = m.frame_node;
    }
    // The point mass at the c.g. with the part's rotary inertia about it (global axes, products included).
    model.point_masses.push_back({++element_id, m.mass_node, p.mass, p.inertia});
    out.push_back(m);
  }
  model.index();
  return out;
}

std::string frame_parts_inp(const fem::FrameModel& model, const std::vector<MountedPart>& parts) {
  using core::Quantity;
  const core::UnitSystem& u = model.units;
  const double lf = 1.0 / u.to_si_factor(Quantity::length);
  std::string out = fmt::format(
      "** The frame assembly's parts as framedyn's frame model carried them (coupling/frame_parts.h), in {}:\n"
      "** *INCLUDE this file after the mesh for the same frame model.\n",
      u.name());
  int element_id = 0;
  for (const fem::BeamElement& b : model.beams) element_id = std::max(element_id, b.id);
  for (const fem::PointMass& m : model.point_masses) element_id = std::max(element_id, m.element_id);
  for (const fem::Spring& s : model.springs) element_id = std::max(element_id, s.element_id);
  for (const MountedPart& m : parts) {
    const fem::Node& at = model.nodes[static_cast<std::size_t>(m.mass_node)];
    const std::string set = [&] {
      std::string n;
      for (char c : m.part.name) n += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
      return n;
    }();
    out += fmt::format("** {}\n", m.part.name);
    if (m.linked) out += fmt::format("*NODE\n{}, {:.17g}, {:.17g}, {:.17g}\n", at.id, at.position.x() * lf, at.position.y() * lf, at.position.z() * lf);
    const Eigen::Matrix3d j = m.part.inertia / u.to_si_factor(Quantity::rotary_inertia);
    out += fmt::format("*ELEMENT, TYPE=MASS, ELSET={}\n{}, {}\n*MASS, ELSET={}\n{:.17g}\n", set, ++element_id, at.id, set,
                       u.from_si(m.part.mass, Quantity::mass));
    out += fmt::format("*ELEMENT, TYPE=ROTARYI, ELSET={}_INERTIA\n{}, {}\n*ROTARY INERTIA, ELSET={}_INERTIA\n{:.17g}, {:.17g}, {:.17g}, {:.17g}, {:.17g}, {:.17g}\n",
                       set, ++element_id, at.id, set, j(0, 0), j(1, 1), j(2, 2), j(0, 1), j(0, 2), j(1, 2));
    if (!m.mount_nodes.empty()) {
      // A distributing coupling as Abaqus and CalculiX write it: a DCOUP3D element on the reference node, its mounts and weights.
      out += fmt::format("*ELEMENT, TYPE=DCOUP3D, ELSET={}_MOUNTS\n{}, {}\n*DISTRIBUTING COUPLING, ELSET={}_MOUNTS\n", set, ++element_id, at.id, set);
      for (int n : m.mount_nodes) out += fmt::format("{}, 1\n", model.nodes[static_cast<std::size_t>(n)].id);
    } else if (m.linked) {
      out += fmt::format("*MPC\nBEAM, {}, {}\n", at.id, model.nodes[static_cast<std::size_t>(m.frame_node)].id);
    }
  }
  return out;
}


}  // namespace framedyn::coupling
