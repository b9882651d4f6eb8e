// Output sets of a frame transient study: the mesh's node sets whose nodal
// histories (displacement, velocity, acceleration per DOF) and element sets
// whose section-force and fiber-stress histories a study asks for by name.
// Element sets are recovered by coupling/rail_stress (the rails of the
// pipeline are two such sets); this file adds the node sets and the
// section-force history of an element set at its stations.
//
// Velocities and accelerations come from the modal coordinates of a modal
// method (mode superposition, Eq. T.7): u' = Phi q', u'' = Phi q'' with
// q'' = p(t) - c q' - omega^2 q of each mode (Eq. T.2). The static
// correction of the mode-acceleration method (Eq. T.8, (G - Phi Lambda^-1
// Phi^T) F(t)) is quasi-static: its velocity is that matrix times the slope of
// the piecewise-linear load over the interval ending at the output time (zero
// at the first time), its acceleration zero (F'' = 0 inside the intervals).
// The direct method gives displacements only.
#pragma once

#include <Eigen/Dense>

#include <functional>
#include <string>
#include <vector>

#include "fem/frame_model.h"
#include "fem/modal_transient.h"
#include "fem/section_forces.h"

namespace framedyn::coupling {

struct NodeOutputSpec {
  std::string name;      // the output's name in the study (file names, summary keys)
  std::string node_set;  // mesh node set (case-insensitive)
};

// Where and when the largest translational value of one quantity occurs.
struct NodalPeak {
  double value = 0.0;    // signed, SI (m, m/s, m/s^2)
  double time = 0.0;     // s
  int node_id = 0;       // mesh node number
  int dof = 0;           // 0 ux, 1 uy, 2 uz
};

struct NodalHistory {
  NodeOutputSpec spec;
  std::vector<int> nodes;             // node indices, in the set's order
  std::vector<int> node_ids;          // mesh node numbers
  // Rows 6 k + d: node k, DOF d (ux uy uz rx ry rz); columns: output times.
  Eigen::MatrixXd displacement;       // m, rad
  Eigen::MatrixXd velocity;           // m/s, rad/s (empty for the direct method)
  Eigen::MatrixXd acceleration;       // m/s^2, rad/s^2 (empty for the direct method)
  NodalPeak peak_displacement, peak_velocity, peak_acceleration;
};

// The node set's nodes of `model` (throws std::invalid_argument for a set the
// mesh lacks: the study checks the names first, with file and line).
std::vector<int> output_nodes(const fem::FrameModel& model, const std::string& node_set);

// Velocities and accelerations, on all DOFs (rows) at the output times of
// fem::modal_transient(frame, basis, input, options) (columns), by the same
// exact piecewise-linear recurrence (Eq. T.5) and the same initial state.
struct ModalRates {
  Eigen::MatrixXd velocity;       // all DOFs x outputs
  Eigen::MatrixXd acceleration;   // all DOFs x outputs
  Eigen::MatrixXd modal_coordinates;  // elastic modes used x outputs (equal to modal_transient's)
};
ModalRates modal_rates(const fem::FrameDynamics& frame, const fem::ModalBasis& basis, const fem::TransientInput& input,
                       const fem::ModalTransientOptions& options);

// A node set's history from the transient result; `rates` may be null (direct method).
NodalHistory nodal_history(const fem::FrameModel& model, const NodeOutputSpec& spec, const fem::TransientResult& response,
                           const ModalRates* rates);

// The six section forces (fem::SectionForces, local axes) and the largest
// fiber stress at `stations` stations of every beam of an element set, at
// every output time: rows of `values` are (time j, station k) in the order
// j * station_count + k, columns N, Vy, Vz, T, My, Mz, max |sigma|.
struct SectionHistory {
  std::vector<int> element_ids;      // per station
  std::vector<int> station_index;    // 0 .. stations-1 from node a, per station
  std::vector<double> station_x;     // distance from node a, m, per station
  Eigen::MatrixXd values;            // (outputs * stations) x 7, SI (N, N m, Pa)
};
// `share`: idle workers of a pool may take output times (the same numbers without).
SectionHistory section_history(const fem::FrameModel& model, const Eigen::MatrixXd& displacement, const std::string& element_set,
                               int stations, core::WorkShare* share = nullptr);

// The same stations without the history (values left empty).
SectionHistory section_stations(const fem::FrameModel& model, const std::string& element_set, int stations);

// The same section forces handed over one at a time, without a table: put(j, k, forces,
// largest |sigma| or 0 when `fiber_max` is false) at every output j and station k (in
// section_stations' order), from any of `share`'s threads, each (j, k) once.
using StationForcesSink = std::function<void(Eigen::Index j, Eigen::Index k, const fem::SectionForces& forces, double max_fiber_stress)>;
void for_section_forces(const fem::FrameModel& model, const Eigen::MatrixXd& displacement, const std::string& element_set, int stations,
                        bool fiber_max, core::WorkShare* share, const StationForcesSink& put);

}  // namespace framedyn::coupling
