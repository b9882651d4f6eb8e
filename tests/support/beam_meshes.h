// Hand-built beam models for tests: straight beams along any direction,
// supports and nodal loads, built in C++ without mesh files. SI units
// throughout (m, N, s, kg). Every builder leaves the model indexed
// (fem::FrameModel::index() called), so node_index() and beam_index() work.
//
// Node and element numbering of a straight beam of n elements: node indices
// 0..n from the start to the end (mesh ids 1..n+1), element indices 0..n-1
// (ids 1..n), element k joining nodes k and k+1, all with section 0.
//
// Note for test code inside `namespace framedyn`: this header declares
// `framedyn::testing`, which hides GoogleTest's `::testing` there; write
// `::testing::Test` in such code.
#pragma once

#include <Eigen/Dense>

#include <initializer_list>
#include <string>
#include <vector>

#include "fem/beam_section.h"
#include "fem/frame_model.h"

namespace framedyn::testing {

// An isotropic material with G = E / (2 (1 + nu)). E in Pa, density in kg/m^3.
fem::Material isotropic_material(const std::string& name, double youngs_modulus, double poisson_ratio, double density);
// Structural steel: E = 210 GPa, nu = 0.3, rho = 7850 kg/m^3.
fem::Material steel();

// A straight prismatic beam from `start` along `direction` (any non-zero
// vector; normalised by the builder), of `length` m, cut into `elements`
// equal elements of one section, material, theory and orientation n1.
struct StraightBeamSpec {
  Eigen::Vector3d start = Eigen::Vector3d::Zero();
  Eigen::Vector3d direction = Eigen::Vector3d::UnitX();
  double length = 1.0;
  int elements = 10;
  fem::SectionProperties section;
  fem::Material material;
  fem::BeamTheory theory = fem::BeamTheory::euler_bernoulli;
  Eigen::Vector3d n1_direction = Eigen::Vector3d(0.0, 0.0, -1.0);
};

// The beam alone: no supports, loads or point masses.
fem::FrameModel straight_beam(const StraightBeamSpec& spec);

// Local axes of the elements of `spec`'s beam, rows (t, n1, n2) in global
// components, as fem::beam_local_axes computes them.
Eigen::Matrix3d straight_beam_axes(const StraightBeamSpec& spec);

// Appends a node at `position` with the next free mesh id; returns its index.
int add_node(fem::FrameModel& model, const Eigen::Vector3d& position);
// Appends a section assignment; returns its index.
int add_section(fem::FrameModel& model, const fem::SectionProperties& section, const fem::Material& material,
                const Eigen::Vector3d& n1_direction);
// Appends a straight line of `elements` equal beam elements from the
// existing node `start_node` to a new node at `end`, with section
// `section` and theory `theory`; new nodes and elements get the next free
// ids. Returns the node indices along the line, start_node first.
std::vector<int> add_beam_line(fem::FrameModel& model, int start_node, const Eigen::Vector3d& end, int elements, int section,
                               fem::BeamTheory theory);

// Supports: all six DOFs of `node` fixed (zero displacement), or the listed
// DOFs (0..5 = ux, uy, uz, rx, ry, rz, global axes).
void clamp_node(fem::FrameModel& model, int node);
void pin_dofs(fem::FrameModel& model, int node, std::initializer_list<int> dofs);

// Nodal loads in global components: a force (N) on DOFs 0..2 and a moment
// (N m) on DOFs 3..5 of `node`. Zero components are not stored.
void add_nodal_force(fem::FrameModel& model, int node, const Eigen::Vector3d& force);
void add_nodal_moment(fem::FrameModel& model, int node, const Eigen::Vector3d& moment);

}  // namespace framedyn::testing
