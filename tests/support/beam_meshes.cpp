// Hand-built beam models for tests; see beam_meshes.h.
#include "beam_meshes.h"

#include <algorithm>
#include <stdexcept>

#include "fem/beam_element.h"

namespace framedyn::testing {

namespace {

int next_node_id(const fem::FrameModel& model) {
  int id = 0;
  for (const fem::Node& n : model.nodes) id = std::max(id, n.id);
  return id + 1;
}

int next_beam_id(const fem::FrameModel& model) {
  int id = 0;
  for (const fem::BeamElement& b : model.beams) id = std::max(id, b.id);
  return id + 1;
}

void check_node(const fem::FrameModel& model, int node) {
  if (node < 0 || node >= static_cast<int>(model.nodes.size())) throw std::out_of_range("node index out of range");
}

}  // namespace

fem::Material isotropic_material(const std::string& name, double youngs_modulus, double poisson_ratio, double density) {
  fem::Material m;
  m.name = name;
  m.youngs_modulus = youngs_modulus;
  m.poisson_ratio = poisson_ratio;
  m.shear_modulus = youngs_modulus / (2.0 * (1.0 + poisson_ratio));
  m.density = density;
  return m;
}

fem::Material steel() { return isotropic_material("STEEL", 210.0e9, 0.3, 7850.0); }

fem::FrameModel straight_beam(const StraightBeamSpec& spec) {
  if (spec.elements < 1) throw std::invalid_argument("a beam needs at least one element");
  if (!(spec.length > 0.0)) throw std::invalid_argument("beam length must be positive");
  if (!(spec.direction.norm() > 0.0)) throw std::invalid_argument("beam direction is zero");
  fem::FrameModel model;
  const int first = add_node(model, spec.start);
  const int section = add_section(model, spec.section, spec.material, spec.n1_direction);
  add_beam_line(model, first, spec.start + spec.length * spec.direction.normalized(), spec.elements, section, spec.theory);
  return model;
}

Eigen::Matrix3d straight_beam_axes(const StraightBeamSpec& spec) {
  return fem::beam_local_axes(spec.start, spec.start + spec.length * spec.direction.normalized(), spec.n1_direction);
}

int add_node(fem::FrameModel& model, const Eigen::Vector3d& position) {
  fem::Node n;
  n.id = next_node_id(model);
  n.position = position;
  model.nodes.push_back(n);
  model.index();
  return static_cast<int>(model.nodes.size()) - 1;
}

int add_section(fem::FrameModel& model, const fem::SectionProperties& section, const fem::Material& material,
                const Eigen::Vector3d& n1_direction) {
  fem::SectionAssignment sa;
  sa.element_set = "SECTION_" + std::to_string(model.sections.size() + 1);
  sa.properties = section;
  sa.material = material;
  sa.n1_direction = n1_direction;
  model.sections.push_back(sa);
  return static_cast<int>(model.sections.size()) - 1;
}

std::vector<int> add_beam_line(fem::FrameModel& model, int start_node, const Eigen::Vector3d& end, int elements, int section,
                               fem::BeamTheory theory) {
  check_node(model, start_node);
  if (elements < 1) throw std::invalid_argument("a beam line needs at least one element");
  if (section < 0 || section >= static_cast<int>(model.sections.size())) throw std::out_of_range("section index out of range");
  const Eigen::Vector3d start = model.nodes[static_cast<std::size_t>(start_node)].position;
  std::vector<int> line{start_node};
  std::vector<int>& set = model.element_sets[model.sections[static_cast<std::size_t>(section)].element_set];
  for (int k = 1; k <= elements; ++k) {
    // Positions by interpolation from the ends (not by accumulating steps),
    // so the last node lands on `end` to round-off.
    const double s = static_cast<double>(k) / elements;
    const int node = add_node(model, (1.0 - s) * start + s * end);
    fem::BeamElement beam;
    beam.id = next_beam_id(model);
    beam.node_a = line.back();
    beam.node_b = node;
    beam.section = section;
    beam.theory = theory;
    model.beams.push_back(beam);
    set.push_back(beam.id);
    line.push_back(node);
  }
  model.index();
  return line;
}

void clamp_node(fem::FrameModel& model, int node) { pin_dofs(model, node, {0, 1, 2, 3, 4, 5}); }

void pin_dofs(fem::FrameModel& model, int node, std::initializer_list<int> dofs) {
  check_node(model, node);
  for (int dof : dofs) {
    if (dof < 0 || dof >= fem::kDofsPerNode) throw std::out_of_range("DOF must be 0..5");
    model.constraints.push_back({node, dof, 0.0});
  }
}

void add_nodal_force(fem::FrameModel& model, int node, const Eigen::Vector3d& force) {
  check_node(model, node);
  for (int k = 0; k < 3; ++k)
    if (force(k) != 0.0) model.loads.push_back({node, k, force(k)});
}

void add_nodal_moment(fem::FrameModel& model, int node, const Eigen::Vector3d& moment) {
  check_node(model, node);
  for (int k = 0; k < 3; ++k)
    if (moment(k) != 0.0) model.loads.push_back({node, 3 + k, moment(k)});
}

}  // namespace framedyn::testing
