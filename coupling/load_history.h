// Load histories: the time-dependent loads that the vehicle model applies to
// the frame at named load points, and the file that carries them from the
// rigid-body run to the frame run.
//
// File format (text, one record a line; docs/user-guide.md, "Load-history files"):
//
//   # framedyn load history, version 1
//   # units: in-lbf-s
//   # point P24_REEL -25 0 0
//   # point P25_FRONT_AXLE_PIN 0 0 0
//   time [s],P24_REEL.FX [lbf],P24_REEL.FY [lbf],P24_REEL.FZ [lbf],P24_REEL.MX [lbf*in],...
//   0,12.5,...
//
// Line 1 names the format and its version; line 2 the unit system (a name
// core::UnitSystem knows); then one `# point NAME x y z` line per load point
// (location in the system's length unit, vehicle axes; NAME is the name of a
// node set of the frame mesh); then the CSV header with all six components of
// every point, in the order of the point lines and FX FY FZ MX MY MZ within a
// point, each labelled with the unit core::UnitSystem::label prints; then one
// row per time, times strictly increasing.
//
// In memory everything is SI: s, m, N, N m.
#pragma once

#include <Eigen/Dense>

#include <filesystem>
#include <string>
#include <vector>

#include "core/units.h"

namespace framedyn::coupling {

// Component order of a load point, columns 0..5 of LoadPointHistory::values.
inline constexpr const char* kLoadComponents[6] = {"FX", "FY", "FZ", "MX", "MY", "MZ"};

struct LoadPointHistory {
  std::string name;               // node-set name of the frame mesh (e.g. "P24_REEL")
  Eigen::Vector3d location;       // m, vehicle axes (X rearward, Y right, Z up)
  Eigen::MatrixXd values;         // n_times x 6: FX, FY, FZ (N), MX, MY, MZ (N m), vehicle axes;
                                  // the load the vehicle applies TO the frame at `location`
  int line = 0;                   // its '# point' line in the file (0: made in memory), for messages
};

struct LoadHistory {
  Eigen::VectorXd times;          // s, strictly increasing
  std::vector<LoadPointHistory> points;
  core::UnitSystem units = core::UnitSystem::si();  // the system the file was written in (values are SI)

  int time_count() const { return static_cast<int>(times.size()); }
  // The component values of all points at time index k, as one vector of 6 * points (SI).
  Eigen::VectorXd components_at(int k) const;
  // All components, (6 * points) x n_times: column k = components_at(k).
  Eigen::MatrixXd component_matrix() const;
};

// Strict reader: throws core::InputError naming the file, the line (and the
// column or header name), what was expected and what was found, for an
// unknown format or version, an unknown unit system, a unit label that does
// not match the declared system, a missing or misplaced component, a column
// for an undeclared point, a ragged row, a number that is not finite, and
// times that do not increase.
LoadHistory read_load_history(const std::filesystem::path& path);
// The same from text in memory; `name` is used as the file name in messages.
LoadHistory parse_load_history(const std::string& text, const std::string& name);

// The file text in `units` (10 significant digits, as core::format_number).
std::string format_load_history(const LoadHistory& history, const core::UnitSystem& units);
void write_load_history(const std::filesystem::path& path, const LoadHistory& history, const core::UnitSystem& units);

}  // namespace framedyn::coupling
