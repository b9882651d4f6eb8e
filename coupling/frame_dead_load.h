// The static state of the frame model in an operating study (issue 17, "static
// plus dynamic"; docs/theory/coupling.md, section 11, Eqs. 11.1-11.5): the frame
// model under gravity (its tubes' weight rho A g as uniform line loads, every
// point mass's weight m g at its node: the parts the frame model carries,
// coupling/frame_parts.h) and the static loads at the load points (the vehicle
// model's static equilibrium, coupling/frame_loads_3d.h static_frame_loads_3d),
// solved K u_s = f_s on the study's supports:
//
//   f_s = f_g + B p_s                                       (11.1)
//   K u_s = f_s (clamped), or inertia relief (free-free)    (11.2)
//
// Free-free, f_s must balance by itself: the vehicle model's static equilibrium
// holds the frame assembly, whose mass the frame model carries (the mesh's tubes
// and the parts; Eq. 9.4), so the resultant of f_s about the c.g. is round-off.
// It is reported relative to the weight W and W L (L the model's largest extent,
// Eq. 11.3); inertia relief takes only that.
//
// The dynamic loads of the pipeline are measured from the same static
// equilibrium, and the model is linear, so at every station and section point
//   sigma_total(t) = sigma_s + sigma_d(t)                   (11.4)
// (coupling/rail_stress.h adds them corner by corner before taking envelopes).
//
// The static section forces per output station (StaticStations) are the
// interface the section-stress and hot-spot code takes: the same stations, in
// the same order and the same components as the dynamic section forces of
// rail_stress.h / output_sets.h.
#pragma once

#include <Eigen/Dense>

#include <string>
#include <vector>

#include "coupling/frame_balance.h"
#include "coupling/rail_stress.h"
#include "fem/assembly.h"
#include "fem/frame_model.h"
#include "fem/modal_transient.h"
#include "fem/section_forces.h"

namespace framedyn::coupling {

// The static section forces of one element-set output (RailSpec), station by
// station in RailRecovery's order: element by element in the set's order,
// `stations` per element from node a (ends included). forces[k] holds, SI,
//   n  = N  (axial, along t),       vy = V1 (shear along n1),  vz = V2 (shear along n2),
//   t  = T  (torque about t),       my = M1 (moment about n1), mz = M2 (moment about n2),
// as fem::SectionForces (fem/section_forces.h), the layout of the dynamic ones;
// with the element's own weight added back by statics (exact inside the element).
struct StaticStations {
  std::string output;                          // RailSpec::name
  std::vector<int> element_ids;                // mesh element number, per station
  std::vector<int> station;                    // 0 .. stations-1 from node a
  std::vector<Eigen::Vector3d> points;         // m
  std::vector<fem::SectionForces> forces;      // N, N m
  std::vector<std::vector<double>> fiber_stress;  // Pa, per station, one per section stress point (fem::fiber_stresses)
  Eigen::VectorXd max_abs_normal_stress;       // Pa, per station: max over the stress points
};

struct FrameStaticState {
  Eigen::Vector3d gravity = Eigen::Vector3d::Zero();  // m/s^2 in the frame model's axes
  Eigen::VectorXd displacement;                // u_s, all DOFs (m, rad)
  Eigen::VectorXd applied;                     // f_s, all DOFs (N, N m)
  Eigen::VectorXd reaction;                    // at the supports (N, N m)
  double weight = 0.0;                         // N: |gravity| times the model's mass (tubes and parts)
  Eigen::Matrix<double, 6, 1> resultant = Eigen::Matrix<double, 6, 1>::Zero();  // f_s's force (N) and moment about the c.g. (N m)
  double extent = 0.0;                         // m, L of Eq. 11.3
  double force_residual = 0.0;                 // |F| / W (Eq. 11.3)
  double moment_residual = 0.0;                // |M| / (W L)
  int free_rigid_motions = 0;                  // relieved by inertia (free-free: 6)
  std::vector<StaticStations> outputs;         // per element-set output, in the request's order
  RailPeak peak_normal_stress;                 // largest |sigma_s| (time 0); among values within 1e-6 relative of it, the first in output order
  std::string peak_output;                     // the output set it lies on
};

// The model with its loads replaced by gravity (m/s^2, global axes): each
// beam's rho A g as a uniform line load, each point mass's m g at its node.
fem::FrameModel with_gravity(const fem::FrameModel& model, const Eigen::Vector3d& gravity);

// Solves Eqs. 11.1-11.2 on `model` as supported (its constraints; free rigid
// motions relieved by inertia) with `distribution` (dof_count x 6 n, as
// LoadMapping) times `static_components` (6 n) as the load points' static loads
// (both may be null: gravity alone), and recovers the static section forces at
// the stations of `outputs`. Throws core::NumericalError for a failed solve.
FrameStaticState frame_static_state(const fem::FrameModel& model, const Eigen::Vector3d& gravity, const fem::SparseMatrix* distribution,
                                    const Eigen::VectorXd* static_components, const std::vector<RailSpec>& outputs, int stations);
// The same on the frame as the dynamic response assembled and factorised it
// (`frame`, its model with the supports and parts; `body` its rigid-body mass):
// the pipeline's static state costs one solve, no assembly or factorisation
// (issue 17). The model-only form above builds both for a single use.
FrameStaticState frame_static_state(const fem::FrameDynamics& frame, const RigidBodyMass& body, const Eigen::Vector3d& gravity,
                                    const fem::SparseMatrix* distribution, const Eigen::VectorXd* static_components, const std::vector<RailSpec>& outputs,
                                    int stations);

}  // namespace framedyn::coupling
