// The frame mesh as the one source of the frame structure's mass; see frame_mass_source.h (Eq. 9.4).
#include "coupling/frame_mass_source.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>

#include "coupling/frame_balance.h"

namespace framedyn::coupling {

namespace {

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

// True when the mesh has an element set named like the part that holds point masses.
bool carried_by(const fem::FrameModel& mesh, const std::string& part) {
  const auto set = mesh.element_sets.find(upper(part));
  if (set == mesh.element_sets.end()) return false;
  for (int id : set->second)
    for (const fem::PointMass& m : mesh.point_masses)
      if (m.element_id == id) return true;
  return false;
}

}  // namespace

FrameMassSources frame_mass_from_mesh(const std::vector<StudyFramePart>& parts, const fem::FrameModel& mesh, const std::string& mesh_file,
                                      const core::InputLocation& parts_at, const core::UnitSystem& u, const FrameMassTolerance& tol) {
  // The structure: the part marked from: frame_mesh, else the one named frame_structure.
  int structure = -1;
  for (std::size_t i = 0; i < parts.size() && structure < 0; ++i)
    if (parts[i].from_mesh) structure = static_cast<int>(i);
  for (std::size_t i = 0; i < parts.size() && structure < 0; ++i)
    if (parts[i].part.name == "frame_structure") structure = static_cast<int>(i);
  if (structure < 0) {
    std::string names;
    for (std::size_t i = 0; i < parts.size(); ++i) names += (i ? ", " : "") + parts[i].part.name;
    throw core::InputError(parts_at,
                           fmt::format("a frame part with from: frame_mesh (or named frame_structure): the part the frame mesh {} models, whose "
                                       "mass, c.g. and inertia the vehicle model takes from the mesh",
                                       mesh_file),
                           "parts " + names);
  }
  const RigidBodyMass body = frame_rigid_body_mass(mesh);
  FrameMassSources out;
  out.structure_part = parts[static_cast<std::size_t>(structure)].part.name;
  out.structure = {out.structure_part, body.mass, body.cg, body.inertia};
  const StudyFramePart& given = parts[static_cast<std::size_t>(structure)];
  if (given.has_values) {
    Eigen::Vector3d lo = mesh.nodes.front().position, hi = lo;
    for (const fem::Node& n : mesh.nodes) {
      lo = lo.cwiseMin(n.position);
      hi = hi.cwiseMax(n.position);
    }
    const double extent = (hi - lo).maxCoeff();
    const double dm = std::abs(given.part.mass - body.mass) / body.mass;
    const double dc = (given.part.cg - body.cg).norm();
    const double di = (given.part.inertia - body.inertia).norm() / body.inertia.norm();
    if (dm > tol.mass || dc > tol.cg * extent || di > tol.inertia) {
      using core::Quantity;
      const double lf = 1.0 / u.to_si_factor(Quantity::length);
      const std::string L = u.label(Quantity::length);
      // Round-off (a centreline c.g. at 1e-15) printed as 0, so the message is the same on every CPU.
      const auto clean = [&](double v) { return std::abs(v) < 1e-9 * extent ? 0.0 : v * lf; };
      const auto xyz = [&](const Eigen::Vector3d& x) { return fmt::format("[{:.4g}, {:.4g}, {:.4g}] {}", clean(x.x()), clean(x.y()), clean(x.z()), L); };
      throw core::InputError(
          given.where,
          fmt::format("the frame structure's mass, c.g. and inertia as the frame mesh {} has them, within {:g} % (mass), {:.3g} {} (c.g.: {:g} % "
                      "of the mesh's largest extent) and {:g} % (inertia about the c.g.); or from: frame_mesh in place of the values",
                      mesh_file, 100 * tol.mass, tol.cg * extent * lf, L, 100 * tol.cg, 100 * tol.inertia),
          fmt::format("mass {:.5g} against the mesh's {:.5g} {} ({:.2g} %), c.g. {} against {} ({:.3g} {} apart), inertia {:.0f} % off",
                      u.from_si(given.part.mass, Quantity::mass), u.from_si(body.mass, Quantity::mass), u.label(Quantity::mass), 100 * dm,
                      xyz(given.part.cg), xyz(body.cg), dc * lf, L, 100 * di));
    }
  }
  for (std::size_t i = 0; i < parts.size(); ++i) {
    if (static_cast<int>(i) == structure) {
      out.vehicle_parts.push_back(out.structure);
      continue;
    }
    if (carried_by(mesh, parts[i].part.name)) {
      out.carried_by_mesh.push_back(parts[i].part.name);
      continue;
    }
    out.vehicle_parts.push_back(parts[i].part);
    out.mounted.push_back({parts[i].part, parts[i].mounts, parts[i].mounts_where});
  }
  return out;
}

}  // namespace framedyn::coupling
