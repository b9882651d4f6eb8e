// The rigid-body modes as a run writes them, the same for 2-D and 3-D
// studies: summary.json's rigid.modes[i] {mode, frequency_hz, dominant,
// energy_share per coordinate} and rigid_modes.csv.
#pragma once

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "core/results_folder.h"
#include "rigid/rigid_modes.h"

namespace framedyn::report {

// Writes rigid_modes.csv into `folder` and returns the JSON array of the modes.
nlohmann::ordered_json write_rigid_modes(const std::vector<std::string>& coordinates, const std::vector<rigid::RigidMode>& modes,
                                         const core::ResultsFolder& folder);

}  // namespace framedyn::report
