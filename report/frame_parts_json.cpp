// The summary's frame.parts, frame.total_mass and frame.structure; see frame_parts_json.h.
#include "report/frame_parts_json.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace framedyn::report {

FramePartsSummary frame_parts_summary(const fem::FrameModel& model, const std::vector<coupling::MountedPart>& parts,
                                      const coupling::RigidBodyMass& body,
                                      const std::string& structure_part, const std::string& structure_source,
                                      const std::vector<std::string>& carried_by_mesh, const core::UnitSystem& u) {
  using nlohmann::ordered_json;
  using core::Quantity;
  const double lf = 1.0 / u.to_si_factor(Quantity::length);
  const std::string L = u.label(Quantity::length), Mu = u.label(Quantity::mass), Iu = u.label(Quantity::rotary_inertia);
  const auto point = [&](const Eigen::Vector3d& x) { return ordered_json{{"value", {x.x() * lf, x.y() * lf, x.z() * lf}}, {"unit", L}}; };
  const auto tensor = [&](const Eigen::Matrix3d& j) {
    ordered_json rows = ordered_json::array();
    for (int r = 0; r < 3; ++r) rows.push_back({u.from_si(j(r, 0), Quantity::rotary_inertia), u.from_si(j(r, 1), Quantity::rotary_inertia),
                                                u.from_si(j(r, 2), Quantity::rotary_inertia)});
    return ordered_json{{"value", rows}, {"unit", Iu}};
  };
  FramePartsSummary s;
  s.parts = ordered_json::array();
  for (const coupling::MountedPart& m : parts) {
    const int frame_id = model.nodes[static_cast<std::size_t>(m.frame_node)].id;
    std::vector<int> mount_ids;
    for (int n : m.mount_nodes) mount_ids.push_back(model.nodes[static_cast<std::size_t>(n)].id);
    if (mount_ids.empty()) mount_ids.push_back(frame_id);
    const std::string ids = fmt::format("{}", fmt::join(mount_ids, ", "));
    s.parts.push_back({{"name", m.part.name},
                       {"mass", {{"value", u.from_si(m.part.mass, Quantity::mass)}, {"unit", Mu}}},
                       {"cg", point(m.part.cg)},
                       {"inertia_about_cg", tensor(m.part.inertia)},
                       {"frame_node", frame_id},
                       {"mount_nodes", mount_ids},
                       {"joined_by", !m.mount_nodes.empty() ? fmt::format("distributing coupling from mounts {} (equal weights) to node {} at the c.g.",
                                                                          ids, model.nodes[static_cast<std::size_t>(m.mass_node)].id)
                                     : m.linked ? fmt::format("rigid link from node {} to node {} at the c.g.", frame_id,
                                                            model.nodes[static_cast<std::size_t>(m.mass_node)].id)
                                              : fmt::format("point mass on node {} (the c.g. is on it)", frame_id)},
                       {"arm", {{"value", m.arm * lf}, {"unit", L}}}});
  }
  s.total_mass = {{"value", u.from_si(body.mass, Quantity::mass)}, {"unit", Mu}, {"cg", point(body.cg)}, {"inertia_about_cg", tensor(body.inertia)}};
  const char* meaning = structure_source == "mesh"
                            ? "the vehicle model took the frame structure's mass, c.g. and inertia from the frame mesh"
                        : structure_part.empty() ? "the frame mesh alone (no vehicle model)"
                                                 : "the study's values";
  s.structure = {{"part", structure_part}, {"source", structure_source.empty() ? "mesh" : structure_source}, {"meaning", meaning},
                 {"parts_carried_by_mesh", carried_by_mesh}};
  return s;
}

}  // namespace framedyn::report
