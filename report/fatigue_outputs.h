// The fatigue life map's outputs (coupling/frame_fatigue.h computes it;
// docs/user-guide.md "Fatigue"): life_map.csv (every station and section point:
// its detail's S-N curve, damage per hour, life in hours, damage over the study's
// hours), frame_life.vtu (per element the largest damage per hour, a ParaView cell
// field), the summary's "fatigue" object (code, min_life, damage_per_hour, which
// detail categories were assumed where) and the life along the rails as a figure.
#pragma once

#include <nlohmann/json.hpp>

#include "core/results_folder.h"
#include "coupling/frame_study.h"
#include "report/plot.h"

namespace framedyn::report {

// Nothing without results.life.
void write_life_map(const coupling::FrameStudyResults& results, const coupling::FrameStudyRequest& request, const core::ResultsFolder& folder);
// summary.json's "fatigue": code, hours, min_life {value, unit: h, element, station, point, set, X},
// damage_per_hour {value, unit: 1/h}, damage (over fatigue.hours), block, details_assumed.
nlohmann::ordered_json fatigue_summary(const coupling::FrameStudyResults& results, const coupling::FrameStudyRequest& request);
// The shortest life over the section points at every station, along X, one series per
// element-set output, logarithmic life axis (stations without damage are left out).
LinePlot life_along_rails_figure(const coupling::FrameStudyResults& results, const core::UnitSystem& units);
// The same from any damage-per-hour table over the stations and points of `stress` (a duty cycle's).
LinePlot life_along_rails_figure(const coupling::StressHistories& stress, const std::vector<std::vector<double>>& damage_per_hour, const std::string& code,
                                 const core::UnitSystem& units);
// frame_life.vtu: the mesh with the cell field fatigue_damage_per_hour [1/h] (per element the largest).
void write_life_vtu(const fem::FrameModel& model, const coupling::StressHistories& stress, const std::vector<std::vector<double>>& damage_per_hour,
                    const core::UnitSystem& units, const core::ResultsFolder& folder);

}  // namespace framedyn::report
