// The outputs of a duty cycle (model: duty_cycle; coupling/duty_cycle.h, docs/theory/
// fatigue.md sections 8-9): life_map.csv (per station and section point: damage per
// cycle, life in hours, the dominant scenario, each scenario's damage per hour),
// frame_life.vtu, frame_life.png (with figures) and summary.json's "fatigue" object with
// the scenarios' damage at the worst locations and which detail categories were assumed
// where.
#pragma once

#include <nlohmann/json.hpp>

#include <cstddef>
#include <string>
#include <vector>

#include "core/results_folder.h"
#include "coupling/duty_cycle.h"

namespace framedyn::report {

// How many locations (station, section point) with damage each scenario dominates.
std::vector<std::size_t> locations_dominated(const coupling::DutyLife& life, std::size_t scenarios);

// summary.json's content: input, fatigue {code, min_life, scenarios, worst_locations, ...}.
nlohmann::ordered_json duty_cycle_summary(const std::string& file, const coupling::DutyCycleRequest& q, const coupling::DutyCycleResults& r);

// Writes every output of the cycle into `folder` (not committed), summary.json included; returns the figures written.
std::vector<std::string> write_duty_cycle_outputs(const std::string& file, const coupling::DutyCycleRequest& q, const coupling::DutyCycleResults& r,
                                                  bool figures, core::ResultsFolder& folder);

}  // namespace framedyn::report
