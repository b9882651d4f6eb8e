// Stress histories over the frame's element-set outputs and their hot spots:
// at every output station and section point (fem/section_stress.h) the
// normal stress, shear stress and von Mises stress over time, of the total
// state = static + dynamic (the static section forces per station are an
// input, zero when none is given); then the peaks over start-up and over
// steady operation separately, and the stations ranked by their steady peak
// von Mises stress and by their steady range of normal stress.
// Theory: docs/theory/coupling.md section 10, Eqs. (10.1)-(10.5).
//
// Kept in memory compactly: the six section forces per station and output
// time in single precision (24 bytes), from which every point's stresses
// follow exactly by the linear Eqs. (20.1)-(20.9) of docs/theory/fem.md.
#pragma once

#include <Eigen/Dense>

#include <optional>
#include <string>
#include <vector>

#include "core/warnings.h"
#include "core/work_share.h"
#include "fem/frame_model.h"
#include "fem/section_forces.h"
#include "fem/section_stress.h"

namespace framedyn::coupling {

// One output station of the stress histories.
struct StressStation {
  std::string set;             // the output's name (e.g. left_rail)
  int element_id = 0;          // mesh element number
  int station = 0;             // 0 .. stations-1 from node a
  Eigen::Vector3d point = Eigen::Vector3d::Zero();  // m
  int section = 0;             // index into model.sections (and StressHistories::points)
};

struct StressHistories {
  std::vector<StressStation> stations;                  // set by set, element by element, station by station
  std::vector<fem::SectionProperties> sections;         // per model section
  std::vector<std::vector<fem::SectionPoint>> points;   // per model section (fem::section_points)
  // Dynamic section forces: rows 6 s + k for station s and k = N, Vy, Vz, T, My, Mz (N, N m); columns: output times.
  Eigen::MatrixXf forces;
  Eigen::VectorXd times;                                // s

  fem::SectionForces forces_at(std::size_t station, Eigen::Index time) const;
  std::size_t bytes() const { return static_cast<std::size_t>(forces.size()) * sizeof(float); }
};

// The stations of the element sets `sets` (name, mesh element set) at
// `stations` per element, with their dynamic section forces from the history
// `values` of coupling::section_history (rows time * stations + station,
// columns N, Vy, Vz, T, My, Mz, ...), one per set; or, without `values`, from
// the displacements (all DOFs x times) at the stations of section_stations
// (element_set, stations), the same numbers with no double-precision table between.
struct SetHistory {
  std::string name;
  std::vector<int> element_ids;       // per station
  std::vector<int> station_index;     // per station
  std::vector<Eigen::Vector3d> points;  // per station, m
  const Eigen::MatrixXd* values = nullptr;
  const Eigen::MatrixXd* displacement = nullptr;  // without values
  std::string element_set;                        // without values
  int stations = 0;                               // without values
};
// `share`: idle workers of a pool may take output times (the same numbers without).
StressHistories stress_histories(const fem::FrameModel& model, const Eigen::VectorXd& times, const std::vector<SetHistory>& sets,
                                 core::WorkShare* share = nullptr);

// Where steady operation starts (Eq. 10.1) and who said so.
struct SteadyWindow {
  double from = 0.0;           // s: start-up t < from, steady t >= from
  std::string source;          // "rigid-body model's steady report", "frame.steady_from", "last half of the record"
};
// The rigid model's steady report first, then the study's frame.steady_from, else the last half of the record.
SteadyWindow steady_window(std::optional<double> rigid_reached_at, std::optional<double> study_steady_from, const Eigen::VectorXd& times);

// A location's stress at one time: the static, dynamic and total von Mises stress there.
struct HotSpot {
  std::size_t station = 0;     // index into StressHistories::stations
  int point = 0;               // index into the station's section points
  std::string point_name;
  double von_mises_static = 0.0;   // Pa: of the static forces alone
  double von_mises_dynamic = 0.0;  // Pa: of the dynamic forces at `time` alone
  double von_mises_total = 0.0;    // Pa: the steady peak of the total
  double time = 0.0;               // s: when the steady peak occurs
  double normal_stress_range = 0.0;  // Pa: max - min of the total normal stress over steady operation (its worst point)
  int range_point = 0;             // the point of that range
  double startup_peak_von_mises = 0.0;  // Pa: the peak over start-up (total), 0 without start-up times
  double startup_time = 0.0;
};

struct HotSpotReport {
  SteadyWindow window;
  std::size_t steady_times = 0, startup_times = 0;
  // Up to `count` stations, each with its worst point, by steady peak von Mises and by steady normal-stress range.
  std::vector<HotSpot> by_von_mises, by_normal_range;
  // The peak total von Mises stress over the whole record, over start-up and over steady operation.
  HotSpot peak, startup_peak, steady_peak;
  std::size_t memory_bytes = 0;    // the histories in memory
};

// `static_forces`: one per station (StressHistories::stations), or null / empty for zero.
// Ties (values within 1e-6 relative of the largest) go to the lowest station,
// point and time index, so the ranking is the same on every CPU.
// `share`: idle workers of a pool may take stations (the same report without).
HotSpotReport find_hot_spots(const StressHistories& histories, const SteadyWindow& window, int count = 10,
                             const std::vector<fem::SectionForces>* static_forces = nullptr, core::WorkShare* share = nullptr);

// The total (static + dynamic) stress at one station's section point at every
// output time: what frame_stress_histories.csv writes and the hot-spot figure draws.
// `static_forces`: as for find_hot_spots.
std::vector<fem::PointStress> point_stress_history(const StressHistories& histories, std::size_t station, int point,
                                                   const std::vector<fem::SectionForces>* static_forces = nullptr);

// The index of the largest of `values` (lowest index among those within 1e-6 relative of it); -1 if empty.
Eigen::Index stable_argmax(const std::vector<double>& values);

}  // namespace framedyn::coupling
