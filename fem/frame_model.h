// The beam model of a frame: nodes, beam elements with their sections and
// materials, point masses, springs, supports, nodal loads and named sets.
// All values are SI (m, N, s, kg); readers convert from the input's units.
// The model is plain data: algorithms take it by const reference and keep
// their results elsewhere, so many analyses can share one model.
//
// Degrees of freedom: node i (index into `nodes`) owns global DOFs 6i..6i+5,
// in the order ux, uy, uz, rx, ry, rz (Abaqus DOFs 1..6), global axes.
#pragma once

#include <Eigen/Dense>

#include <map>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/units.h"
#include "core/warnings.h"
#include "fem/beam_section.h"
#include "fem/member_releases.h"

namespace framedyn::fem {

constexpr int kDofsPerNode = 6;

struct Node {
  int id = 0;                    // the mesh's node number
  Eigen::Vector3d position;      // m
};

struct Material {
  std::string name;
  double youngs_modulus = 0.0;   // E, Pa
  double poisson_ratio = 0.0;    // nu (G = E / (2 (1 + nu)) unless given directly)
  double shear_modulus = 0.0;    // G, Pa
  double density = 0.0;          // kg/m^3
};

enum class BeamTheory {
  euler_bernoulli,  // Abaqus B33: no shear deformation, no rotary inertia in bending
  timoshenko,       // Abaqus B31: shear deformation (shear areas) and rotary inertia
};

// A section assignment: properties, material and the approximate local
// 1-direction n1 (the *BEAM SECTION orientation line; Abaqus default (0,0,-1)).
struct SectionAssignment {
  std::string element_set;
  SectionProperties properties;  // SI
  Material material;             // SI; for GENERAL sections E, G, density come from the section
  Eigen::Vector3d n1_direction{0.0, 0.0, -1.0};
  // Euler-Bernoulli elements of this section get the bending rotary inertia
  // rho I11, rho I22 (a Rayleigh beam; section parameter RAYLEIGH).
  bool bending_rotary_inertia = false;
};

struct BeamElement {
  int id = 0;                    // the mesh's element number
  int node_a = 0, node_b = 0;    // indices into FrameModel::nodes
  int section = -1;              // index into FrameModel::sections
  BeamTheory theory = BeamTheory::timoshenko;
  // Three-node elements (Abaqus B32, B32R): the midside node (index into
  // nodes), -1 for two-node elements; node_a and node_b are the end nodes.
  // They are Timoshenko beams; fem/quadratic_beam_element.h has their matrices.
  int node_m = -1;
  bool reduced_integration = false;  // B32R: 2-point Gauss rule (B32: 3-point)

  bool is_quadratic() const { return node_m >= 0; }
  ReleaseMask released = 0;      // member-end releases (*RELEASE), local rotation DOFs
};

struct PointMass {
  int element_id = 0;
  int node = 0;                  // index into nodes
  double mass = 0.0;             // kg
  Eigen::Matrix3d rotary_inertia = Eigen::Matrix3d::Zero();  // kg m^2, global axes
};

// A linear spring on one DOF to ground (node_b < 0) or between two DOFs.
struct Spring {
  int element_id = 0;
  int node_a = 0, dof_a = 0;     // dof 0..5
  int node_b = -1, dof_b = 0;
  double stiffness = 0.0;        // N/m or N m/rad
};

// A prescribed displacement (zero for a fixed support).
struct Constraint {
  int node = 0;
  int dof = 0;                   // 0..5
  double value = 0.0;            // m or rad
};

struct NodalLoad {
  int node = 0;
  int dof = 0;                   // 0..5
  double value = 0.0;            // N or N m
};

// A uniform line load on a beam element (*DLOAD PX, PY, PZ, P1, P2 and the
// weight of the beam under GRAV), force per length in global components.
// P1 and P2 on a three-node beam follow the section's axes as written (n1,
// n2 = t x n1), which turn along a curved element: they are kept in those
// axes (section_force_per_length) and resolved at each point of the element.
// On a two-node beam the reader resolves them into force_per_length.
struct ElementLoad {
  int beam = 0;                  // index into FrameModel::beams
  Eigen::Vector3d force_per_length = Eigen::Vector3d::Zero();  // N/m, global axes
  Eigen::Vector2d section_force_per_length = Eigen::Vector2d::Zero();  // N/m along n1, n2 (three-node beams only)
};

// A rigid link (*RIGID BODY, *MPC BEAM): the slave nodes follow the small
// rigid motion of the reference node, u_s = u_r + theta_r x (x_s - x_r) and,
// when `slave_rotations`, theta_s = theta_r (docs/theory/fem.md, "Rigid links").
struct RigidLink {
  int reference_node = 0;          // index into nodes
  std::vector<int> slave_nodes;    // indices into nodes
  bool slave_rotations = true;     // false for a PIN NSET: only the translations follow
  std::string source;              // where it was defined ("*RIGID BODY at f.inp:12"), for messages
};

// A distributing coupling (RBE3-like; docs/theory/fem.md, "Distributing
// couplings", Eqs. R.6-R.8): the reference node follows the weighted
// least-squares rigid motion of the mount nodes' translations, so a mass on
// it reaches the mounts as forces in proportion to the weights and the
// coupling adds no stiffness between the mounts. The mounts must not all lie
// on one line (their rigid fit would leave a rotation undetermined).
struct DistributingCoupling {
  int reference_node = 0;          // index into nodes: its six DOFs follow the mounts
  std::vector<int> mount_nodes;    // indices into nodes, at most kMaxCouplingMounts
  std::vector<double> weights;     // one per mount, > 0 (uniform: all 1)
  std::string source;              // what defined it ("frame part engine"), for messages
};
inline constexpr int kMaxCouplingMounts = 8;

// A tabular *AMPLITUDE (TIME=STEP TIME): the load factor at step time t,
// linear between the points and held at the first and last value outside
// them, as CalculiX and Abaqus read it (docs/theory/fem.md section 22).
struct Amplitude {
  std::vector<double> times;   // s, non-decreasing
  std::vector<double> values;  // load factors, one per time
  double at(double t) const;
};

// *MODAL DAMPING as CalculiX defines it: ratios of critical damping over
// ranges of mode numbers (modes outside every range undamped), or RAYLEIGH
// C = alpha M + beta K (docs/theory/fem.md section 22).
struct ModalDampingRange {
  int first_mode = 1, last_mode = 1;  // 1-based, inclusive
  double ratio = 0.0;
};

// What a transient step (*MODAL DYNAMIC, *DYNAMIC) prescribes beyond its loads.
struct TransientSettings {
  double time_increment = 0.0;  // s: the fixed output and integration interval
  double time_period = 0.0;     // s: the step's duration
  std::vector<ModalDampingRange> damping_ranges;
  bool rayleigh = false;
  double rayleigh_alpha = 0.0;  // 1/s
  double rayleigh_beta = 0.0;   // s
};

// One analysis step of the input (*STEP ... *END STEP): its procedure and the
// supports and loads in force during it, those of the steps before carried
// over as CalculiX does (docs/theory/fem.md section 18).
struct AnalysisStep {
  int number = 0;                        // 1, 2, ... in the order of the input
  std::string procedure;                 // "STATIC" (also a step that names none), "FREQUENCY", "MODAL DYNAMIC" or "DYNAMIC"
  std::optional<int> requested_modes;    // *FREQUENCY's number of eigenvalues
  std::vector<Constraint> constraints;
  std::vector<NodalLoad> loads;
  // Parallel to loads: the *CLOAD's AMPLITUDE name (upper case), empty for a
  // load constant in the step.
  std::vector<std::string> load_amplitudes;
  std::vector<ElementLoad> element_loads;
  std::optional<TransientSettings> transient;  // *MODAL DYNAMIC and *DYNAMIC steps
};

struct FrameModel {
  std::vector<Node> nodes;
  std::vector<BeamElement> beams;
  std::vector<SectionAssignment> sections;
  std::vector<PointMass> point_masses;
  std::vector<Spring> springs;
  std::vector<Constraint> constraints;
  std::vector<NodalLoad> loads;                // *CLOAD, and GRAV on point masses
  std::vector<ElementLoad> element_loads;     // *DLOAD on beams (see fem/distributed_loads.h)
  std::vector<RigidLink> rigid_links;
  std::vector<DistributingCoupling> distributing_couplings;
  std::map<std::string, std::vector<int>> node_sets;     // upper-case name -> node indices
  std::map<std::string, std::vector<int>> element_sets;  // upper-case name -> element ids (beams and others)
  core::UnitSystem units = core::UnitSystem::si();       // the unit system the input was written in
  std::optional<int> requested_modes;                    // from a *FREQUENCY step, if any
  // The input's steps, in order; empty for a deck without *STEP. The fields
  // constraints, loads and element_loads above hold the first step's.
  std::vector<AnalysisStep> steps;
  std::map<std::string, Amplitude> amplitudes;  // *AMPLITUDE by upper-case name
  // What the reader noticed about the input that may change the answer (a
  // SECTION=CIRC read without a dialect): copies of the model keep them, and
  // every command's summary.json lists them under `warnings`.
  std::vector<core::Warning> reader_warnings;

  int dof_count() const { return kDofsPerNode * static_cast<int>(nodes.size()); }
  // Index of the node with mesh number `id`, or -1.
  int node_index(int id) const;
  // Index into `beams` of the element with number `id`, or -1.
  int beam_index(int id) const;
  // "node 12 (uy)" for messages.
  std::string describe_dof(int global_dof) const;

  // Rebuilds the id lookups; call after changing `nodes` or `beams` by hand.
  void index();

 private:
  std::vector<int> node_lookup_;  // id -> index (dense, ids are usually compact)
  std::map<int, int> sparse_node_lookup_;
  std::unordered_map<int, int> beam_lookup_;
};

// A copy of `model` whose supports and loads are those of steps[step] (an
// index into model.steps).
FrameModel with_step(const FrameModel& model, std::size_t step);
// The model as its first *FREQUENCY step has it (supports, loads, number of
// modes), for `framedyn modes`; `model` itself when no step is a *FREQUENCY step.
FrameModel with_frequency_step(const FrameModel& model);

// Name of a DOF 0..5: "ux", "uy", "uz", "rx", "ry", "rz".
const char* dof_name(int dof);

}  // namespace framedyn::fem
