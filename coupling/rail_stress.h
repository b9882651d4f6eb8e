// Recovery along the frame's rails over time: the six section forces at
// stations of every element of a rail's element set, the fiber normal stress
// at the tube's corners (fem/section_forces), the peak of each with where
// (X, rail, element, station) and when, and the share of the peak normal
// stress that comes from bending. Theory: docs/theory/coupling.md, "Rail
// stresses", Eqs. (C.5)-(C.7).
#pragma once

#include <Eigen/Dense>

#include <string>
#include <vector>

#include "fem/frame_model.h"
#include "fem/section_forces.h"

namespace framedyn::coupling {

// An element set recovered along its stations: a rail of the trencher
// frame, or any element set a study names as an output.
struct RailSpec {
  std::string name;          // for reports, e.g. "left_rail"
  std::string element_set;   // mesh element set, e.g. "LEFT_RAIL" (case-insensitive)
  bool history = false;      // also write the section-force history at every station (frame_sections_<name>.csv)
};

// Where and when a peak occurs. `value` is signed (the value whose magnitude is largest).
struct RailPeak {
  double value = 0.0;        // SI (N, N m or Pa)
  double time = 0.0;         // s
  int element_id = 0;        // mesh element number
  int station = 0;           // 0 .. stations-1 from the element's node a
  Eigen::Vector3d point = Eigen::Vector3d::Zero();  // m
  int fiber = -1;            // stress point index (stresses only)
};

struct RailRecovery {
  RailSpec spec;
  // Stations, element by element in the set's order, `stations` per element.
  std::vector<int> station_element_ids;
  std::vector<Eigen::Vector3d> station_points;   // m
  // Envelopes over time, per station: max |.|.
  Eigen::VectorXd envelope_bending_moment;       // resultant sqrt(My^2 + Mz^2), N m
  Eigen::VectorXd envelope_mz;                   // about n2 (vertical bending for rails with n1 = +Z), N m
  Eigen::VectorXd envelope_my;                   // about n1 (lateral bending), N m
  Eigen::VectorXd envelope_normal_stress;        // max over the corners, Pa
  // Time series over the rail: max over the stations at each output time.
  Eigen::VectorXd series_bending_moment;         // N m
  Eigen::VectorXd series_normal_stress;          // Pa
  // Peaks over stations and times.
  RailPeak peak_bending_moment;                  // resultant (value >= 0)
  RailPeak peak_axial_force, peak_shear_y, peak_shear_z, peak_torque, peak_my, peak_mz;
  RailPeak peak_normal_stress;
  fem::SectionForces forces_at_peak_stress;
  double axial_stress_at_peak = 0.0;             // N / A there, Pa
  double bending_stress_at_peak = 0.0;           // My x2 / I11 - Mz x1 / I22 there, Pa
  double bending_share = 0.0;                    // |bending| / (|axial| + |bending|) at the peak (Eq. C.7)
  // With a static state (coupling/frame_dead_load.h; empty without): total =
  // static + dynamic at every section point before the envelope (Eq. 11.4).
  Eigen::VectorXd static_normal_stress;          // per station: max |sigma_s| over the section points, Pa
  Eigen::VectorXd envelope_total_normal_stress;  // per station: max over time and points of |sigma_s + sigma_d(t)|, Pa
  Eigen::VectorXd series_total_normal_stress;    // per output time: max over stations and points, Pa
  // Largest |total|; among values within 1e-6 relative of it, the first station
  // (set order) and then the earliest time: no round-off near-tie picks the place.
  RailPeak peak_total_normal_stress;
  bool has_static() const { return static_normal_stress.size() > 0; }
};

// `displacement`: all DOFs x outputs (m, rad), `times` its output times.
// Throws core::InputError (key "rails.<name>") for an element set the mesh
// does not have or that holds no beam element.
// `static_stress` (optional): per rail, per station (the order above), the
// static normal stress at each section point (Pa; StaticStations::fiber_stress).
std::vector<RailRecovery> recover_rails(const fem::FrameModel& model, const Eigen::VectorXd& times,
                                        const Eigen::MatrixXd& displacement, const std::vector<RailSpec>& rails, int stations,
                                        const std::vector<std::vector<std::vector<double>>>* static_stress = nullptr);

}  // namespace framedyn::coupling
