// The calibration as a run writes it, the same for 2-D and 3-D studies:
// summary.json's rigid.calibration {parameters[i] {name, unit, initial,
// fitted, lower, upper, at_bound, uncertainty, bounds_basis}, targets[i],
// independent_targets, singular_values, unresolved, underdetermined,
// regularization_weight, residual_max, labels_match (per target), ...},
// calibration.csv, and the console lines (docs/user-guide.md).
#pragma once

#include <nlohmann/json.hpp>

#include <functional>
#include <string>

#include "core/results_folder.h"
#include "core/units.h"
#include "coupling/rigid_study.h"
#include "rigid/calibration.h"

namespace framedyn::report {

// Writes calibration.csv into `folder` and returns the JSON object.
nlohmann::ordered_json write_calibration(const coupling::CalibrationRequest& request, const rigid::CalibrationResult& result,
                                         const core::UnitSystem& units, const std::function<core::Quantity(const std::string&)>& quantity,
                                         const core::ResultsFolder& folder);

void print_calibration(const coupling::CalibrationRequest& request, const rigid::CalibrationResult& result);

// summary.json's calibration.fit_status: "not_converged" (stopped at its
// iteration limit with the residual still falling: its values are no fit),
// "targets_met" (converged, every target within kTargetsMetTolerance relative)
// or "best_within_bounds" (converged to the least residual its bounds allow,
// missing a target by more: the miss is a finding, not a failure to hide).
constexpr double kTargetsMetTolerance = 1e-6;
std::string fit_status(const rigid::CalibrationResult& result);

}  // namespace framedyn::report
