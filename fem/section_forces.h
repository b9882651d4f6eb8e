// Section forces along beam elements and fiber normal stresses.
//
// Section forces act on the positive face of a cut (outward normal +t) in the
// element's local axes: N along t, Vy along n1, Vz along n2, T about t, My
// about n1, Mz about n2 (Abaqus SF1, SF2, SF3, SM3, SM1, SM2 in other names).
// From the element end forces f = k u - p (p the consistent nodal loads of
// the element's uniform line load q, local components; f = k u without one),
// a cut at distance x from node a carries, by the statics of the piece [0, x]:
// N = -Fa_x - q_x x, Vy = -Fa_y - q_y x, Vz = -Fa_z - q_z x, T = -Ma_x,
// My = -Ma_y - x Fa_z - q_z x^2/2, Mz = -Ma_z + x Fa_y + q_y x^2/2;
// exact for a uniform load (e.g. wL^2/12 at the ends and wL^2/24 at the
// middle of a clamped-clamped span, from one element).
// Fiber stress at (x1, x2): sigma = N/A + My x2 / I11 - Mz x1 / I22.
// Theory: docs/theory/fem.md, "Recovery".
#pragma once

#include <Eigen/Dense>

#include <vector>

#include "fem/beam_element.h"
#include "fem/distributed_loads.h"
#include "fem/frame_model.h"

namespace framedyn::fem {

struct SectionForces {
  double n = 0.0, vy = 0.0, vz = 0.0;  // N
  double t = 0.0, my = 0.0, mz = 0.0;  // N m
};

// Local end forces k_local T u_e of an element: forces the nodes exert on the element.
Vector12d element_end_forces(const BeamGeometry& geometry, const BeamElement& beam, const Eigen::VectorXd& u);
SectionForces section_forces_at(const Vector12d& local_end_forces, double x);
// The same with the element's uniform line load q (N/m, local t, n1, n2);
// local_end_forces must then be k u - p (element_end_forces minus beam_local_uniform_load).
SectionForces section_forces_at(const Vector12d& local_end_forces, double x, const Eigen::Vector3d& q_local);
// Stress at each of the section's stress points (Pa).
std::vector<double> fiber_stresses(const SectionProperties& section, const SectionForces& f);

struct StationResult {
  int element_id = 0;
  int station = 0;               // 0 .. stations-1, from node a to node b
  double x = 0.0;                // distance from node a, m
  Eigen::Vector3d point;         // global position, m
  SectionForces forces;
  std::vector<double> fiber_stress;  // Pa, one per section stress point
};

// Section forces at `stations` evenly spaced points (>= 2, ends included,
// evenly in arc length on a three-node beam) of the beam model.beams[beam_index],
// of either kind, with the fixed-end terms of its line load `load` (none: zero).
std::vector<StationResult> beam_stations(const FrameModel& model, int beam_index, const Eigen::VectorXd& u, int stations,
                                         const BeamLineLoad& load = {});

// Section forces at `stations` evenly spaced points (>= 2, ends included) of
// every beam, with the fixed-end terms of the model's element loads.
std::vector<StationResult> recover_stations(const FrameModel& model, const Eigen::VectorXd& u, int stations);

}  // namespace framedyn::fem
