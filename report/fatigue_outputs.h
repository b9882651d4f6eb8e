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
#include "report/vtu_writer.h"

namespace framedyn::report {

// What the life map counts, for summaries.
inline constexpr const char* kStressDescription =
    "normal stress range and signed shear stress range (torsion + transverse shear) at every section point (static + dynamic), "
    "each on its S-N curve, combined as the code says (combination)";
// {normal, shear, combined, unit}: the damage of each stress alone and combined.
nlohmann::ordered_json damage_parts(double normal, double shear, double combined, const std::string& unit);

// {measure, correlation, comparison_value, why, life_proportional {value, unit: h, cv},
// life_non_proportional {...}}: which IIW CV was applied at a location and why, and the life
// under each (F.32-F.34); `damage_proportional` / `damage_non_proportional` over `hours_per_damage`
// hours (1 for a damage per hour, the cycle's hours for a damage per cycle).
nlohmann::ordered_json proportionality_summary(coupling::FatigueCode code, double correlation, double comparison_value, double damage_proportional,
                                               double damage_non_proportional, double hours_per_damage);
// "CV 1 (|r| = 0.998 >= 0.95: proportional)": why a CV was applied.
std::string comparison_value_reason(coupling::FatigueCode code, double correlation, double comparison_value);
// Why a life is unlimited: no cycle at any point of the life map does damage.
inline constexpr const char* kUnlimitedLifeReason =
    "unlimited: no cycle does damage (every stress range below its S-N curve's cut-off, or no stress range)";
// A life of `hours_per_damage` / `damage` hours as {value, unit: h}; an unlimited life (no
// damage) as {unit: h, none: kUnlimitedLifeReason}, the summaries' shape for a quantity without a
// value (framedyn writes no null, infinity or NaN).
nlohmann::ordered_json life_json(double hours_per_damage, double damage);
// An empty cell for an unlimited life (no damage): framedyn writes no "inf".
std::string life_text(double hours_per_damage, double damage);

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
// The life map as cell fields: fatigue_damage_per_hour [1/h] (per element the largest over its
// stations and points, 0 off the outputs) and fatigue_life [h] (its inverse, at most kUnlimitedLife),
// added to every step of the frame's ParaView series (report/frame_outputs.cpp).
inline constexpr double kUnlimitedLife = 1e12;  // h: an element without damage (no infinity in the files)
std::vector<VtuField> life_cell_fields(const fem::FrameModel& model, const coupling::StressHistories& stress,
                                       const std::vector<std::vector<double>>& damage_per_hour);
// frame_life.vtu: the mesh with the cell field fatigue_damage_per_hour [1/h] (per element the largest);
// kept beside the series for the duty cycle (which has no series) and scripts that read it.
void write_life_vtu(const fem::FrameModel& model, const coupling::StressHistories& stress, const std::vector<std::vector<double>>& damage_per_hour,
                    const core::UnitSystem& units, const core::ResultsFolder& folder);

}  // namespace framedyn::report
