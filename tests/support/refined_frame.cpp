// Refined R-100-like frames for the benchmarks; see refined_frame.h.
#include "tests/support/refined_frame.h"

#include <fmt/format.h>

#include <cmath>
#include <map>
#include <stdexcept>

namespace framedyn::testing {

int subdivisions_for(const fem::FrameModel& base, long target_dofs) {
  // DOFs = 6 (nodes + beams (k - 1)).
  const double k = (static_cast<double>(target_dofs) / 6.0 - static_cast<double>(base.nodes.size())) / static_cast<double>(base.beams.size()) + 1.0;
  return std::max(1, static_cast<int>(std::lround(k)));
}

std::string refined_frame_inp(const fem::FrameModel& base, int k, const std::string& clamped_set) {
  using core::Quantity;
  const core::UnitSystem& u = base.units;
  const double lf = 1.0 / u.to_si_factor(Quantity::length);
  std::string out;
  out.reserve(static_cast<std::size_t>(base.beams.size()) * static_cast<std::size_t>(k) * 80 + 4096);
  out += fmt::format("** units: {}\n*HEADING\nRefined R-100-like frame, {} elements per member (framedyn benchmark)\n", u.name(), k);
  out += "*NODE, NSET=NALL\n";
  int next_node = 0;
  for (const fem::Node& n : base.nodes) next_node = std::max(next_node, n.id);
  for (const fem::Node& n : base.nodes)
    out += fmt::format("{}, {:.9g}, {:.9g}, {:.9g}\n", n.id, n.position.x() * lf, n.position.y() * lf, n.position.z() * lf);
  // Interior nodes and elements, grouped by section.
  std::map<int, std::string> elements_by_section;
  int next_element = 0;
  for (const fem::BeamElement& b : base.beams) {
    const Eigen::Vector3d a = base.nodes[static_cast<std::size_t>(b.node_a)].position * lf;
    const Eigen::Vector3d c = base.nodes[static_cast<std::size_t>(b.node_b)].position * lf;
    int prev = base.nodes[static_cast<std::size_t>(b.node_a)].id;
    std::string& els = elements_by_section[b.section];
    for (int s = 1; s <= k; ++s) {
      int id;
      if (s == k) {
        id = base.nodes[static_cast<std::size_t>(b.node_b)].id;
      } else {
        id = ++next_node;
        const Eigen::Vector3d p = a + (c - a) * (static_cast<double>(s) / k);
        out += fmt::format("{}, {:.12g}, {:.12g}, {:.12g}\n", id, p.x(), p.y(), p.z());
      }
      els += fmt::format("{}, {}, {}\n", ++next_element, prev, id);
      prev = id;
    }
  }
  for (const auto& [section, text] : elements_by_section) out += fmt::format("*ELEMENT, TYPE=B31, ELSET=S{}\n{}", section, text);
  const fem::SectionAssignment& first = base.sections.front();
  out += fmt::format("*MATERIAL, NAME=STEEL\n*ELASTIC\n{:.9g}, {:.9g}\n*DENSITY\n{:.9g}\n",
                     u.from_si(first.material.youngs_modulus, Quantity::stress), first.material.poisson_ratio,
                     u.from_si(first.material.density, Quantity::density));
  for (std::size_t s = 0; s < base.sections.size(); ++s) {
    const fem::SectionAssignment& sa = base.sections[s];
    if (sa.properties.dimensions.size() < 2) throw std::invalid_argument("refined_frame_inp: sections need an outline");
    out += fmt::format("*BEAM SECTION, ELSET=S{}, MATERIAL=STEEL, SECTION=RECT\n{:.9g}, {:.9g}\n{:.9g}, {:.9g}, {:.9g}\n", s,
                       sa.properties.dimensions[0] * lf, sa.properties.dimensions[1] * lf, sa.n1_direction.x(), sa.n1_direction.y(),
                       sa.n1_direction.z());
  }
  auto it = base.node_sets.find(clamped_set);
  if (it == base.node_sets.end()) throw std::invalid_argument("refined_frame_inp: no node set " + clamped_set);
  out += "*BOUNDARY\n";
  for (int n : it->second) out += fmt::format("{}, 1, 6\n", base.nodes[static_cast<std::size_t>(n)].id);
  return out;
}

}  // namespace framedyn::testing
