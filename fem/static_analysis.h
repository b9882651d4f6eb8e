// Linear static solve under nodal loads, the consistent nodal loads of
// distributed loads (fem/distributed_loads.h) and prescribed displacements:
// K_ff u_f = f_f - K_fc u_c on a CHOLMOD factorisation, then reactions
// R = K u - f at the constrained DOFs (with rigid links: T^T (K u - f), so a
// supported reference node carries its tied nodes' loads; rigid_links.h).
// A singular stiffness (a mechanism) is reported with the nodes that can
// move freely. A frame whose supports leave rigid motions free (free-free,
// on one pin, held in its plane; fem/rigid_body_modes.h) is solved when the
// loads do no work on those motions, on auxiliary supports that fix them
// (the result is then one solution; any free rigid motion may be added), and
// refused with UnbalancedLoadError naming the motion otherwise; with inertia
// relief the unbalanced part is taken by rigid-body accelerations
// (d'Alembert) and the elastic part returned (docs/theory/fem.md, section 19).
#pragma once

#include <Eigen/Dense>

#include <functional>
#include <string>
#include <vector>

#include "fem/frame_model.h"

namespace framedyn::fem {

struct StaticResult {
  Eigen::VectorXd displacement;  // all DOFs (m, rad)
  Eigen::VectorXd applied;       // nodal loads on all DOFs, with the consistent loads of *DLOAD (N, N m)
  Eigen::VectorXd reaction;      // all DOFs; nonzero only at constrained DOFs (N, N m)
  double relative_residual = 0.0;  // ||K_ff u_f - f_f|| / ||f_f||
  // Partially supported or free frames (section 19):
  int free_rigid_motions = 0;      // rigid motions the supports leave free
  std::string free_motions;        // FreeRigidMotions::describe: which parts keep how many
  std::vector<int> auxiliary_dofs; // global DOFs held by the auxiliary supports (Eq. 19.3)
  bool inertia_relief = false;
  // With inertia relief: the rigid-body acceleration on all DOFs (m/s^2,
  // rad/s^2), M R a = the unbalanced load (Eq. 19.5); empty otherwise.
  Eigen::VectorXd rigid_acceleration;
};

struct StaticOptions {
  // Take the loads' unbalanced part by the rigid-body accelerations of the
  // free rigid motions (d'Alembert) instead of refusing it; needs mass.
  bool inertia_relief = false;
};

// The applied load vector on all DOFs (N, N m): the model's nodal loads
// (*CLOAD, GRAV on point masses) and the consistent nodal loads of the beams'
// line loads (*DLOAD, fem/distributed_loads.h). The static solve and the frequency-domain analyses
// (harmonic_response, random_response) take their loads from here, so a load
// type added to the model reaches all of them.
Eigen::VectorXd applied_loads(const FrameModel& model);

StaticResult solve_static(const FrameModel& model, const std::function<void(const std::string&)>& progress = {},
                          const StaticOptions& options = {});

// Several load cases of one frame (the static steps of a multi-step deck,
// fem::with_step): the same nodes, elements and rigid links, each case with
// its loads and prescribed values. Consecutive cases that support the same
// DOFs share one factorisation of K_ff (docs/theory/fem.md section 18);
// `factorisations`, if given, receives how many were made.
std::vector<StaticResult> solve_static_cases(const std::vector<FrameModel>& cases, const std::function<void(const std::string&)>& progress = {},
                                             const StaticOptions& options = {}, int* factorisations = nullptr);

// The load cases of `framedyn static`: one per static step of a multi-step deck
// (with_step; docs/theory/fem.md section 18), else the model itself (step 0).
// Throws core::InputError naming `source` and *CLOAD when a case has no load.
struct StaticLoadCase {
  FrameModel model;
  int step = 0;  // the step's number; 0 for a deck with one static case
};
std::vector<StaticLoadCase> static_load_cases(const FrameModel& model, const std::string& source);

}  // namespace framedyn::fem
