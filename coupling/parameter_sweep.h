// Parameter sweeps' typed results: one point per run of a vehicle study (the
// thesis's Chapter V studies of the ground stiffness K5, 20,000 to 60,000
// lbf/in, and damping C5, 100 to 500 lbf*s/in: Figures 9 and 10). The runs
// themselves are the batch engine's (batch/sweep_runs.h,
// batch::run_one_parameter_sweep: the study run once per value of a key path,
// on the engine's workers); report/sweep_outputs.h writes the tables and figures.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/units.h"
#include "coupling/rigid_study.h"

namespace framedyn::coupling {

// What one run of a sweep gives (SI).
struct SweepPoint {
  double value = 0.0;                               // the parameter
  std::optional<double> plow_vertical_pp;           // m, as RigidResults
  std::optional<double> peak_cutting_force;         // N
  std::optional<double> peak_backing_force;         // N
  std::optional<double> average_peak_cutting_force;  // N, as RigidResults
  std::optional<double> average_peak_backing_force;  // N
  std::vector<double> frequencies_hz;               // natural frequencies, lowest first
  std::vector<std::string> dominant;                // the dominant coordinate of each
};

// What one run of either model gives the sweep (SI): a 2-D or 3-D result is a VehicleResults.
SweepPoint sweep_point(const VehicleResults& r, double value);

struct SweepResult {
  std::string parameter;
  core::Quantity quantity = core::Quantity::dimensionless;  // of the parameter
  std::vector<SweepPoint> points;  // in the order of the requested values
  // The run at the study file's own value of the parameter, the reference of
  // the relative changes; reference_index is its place in `points`, or -1
  // when that value was not among the swept ones (it was run on its own).
  SweepPoint reference;
  int reference_index = -1;
};

// (value - reference) / reference, or nothing if either is missing or the reference is 0.
std::optional<double> relative_change(const std::optional<double>& value, const std::optional<double>& reference);

}  // namespace framedyn::coupling
