// A study run's time series and envelopes as plain arrays in the study's units,
// for callers that compute with them rather than read files (the Python
// module's Results, docs/user-guide.md "Python"): the rigid-body response
// (time, coordinates by name, recovered series such as the plow force and the
// element forces, frame loads at the load points) and, for the pipeline, the
// frame transient's rail series, rail bending-moment envelopes and the hot
// spots' stress histories. The same numbers as response.csv, frame_loads.csv,
// frame_rail_series.csv, frame_rails.csv and frame_stress_histories.csv.
#pragma once

#include <string>
#include <vector>

#include "report/study_run.h"

namespace framedyn::report {

struct NamedSeries {
  std::string name;
  std::string unit;
  std::vector<double> values;
};

struct RailEnvelope {
  std::string rail;                     // the element-set output's name (left_rail, ...)
  std::vector<double> x, y, z;          // station points, length unit
  std::vector<double> bending_moment;   // max over time of the resultant |M| per station, moment unit
  std::vector<double> normal_stress;    // max over time and corners per station, stress unit
  std::string length_unit, moment_unit, stress_unit;
};

struct HotSpotHistory {
  std::string name;                     // "<output> X=<x> <point>": where, for a legend
  double x = 0.0;                       // length unit
  std::vector<double> von_mises;        // total (static + dynamic), stress unit, over frame_time
  std::vector<double> normal_stress;
  std::string length_unit, stress_unit;
};

struct StudySeries {
  std::string units;                    // the study's unit system
  std::vector<double> time;             // s: the rigid-body response's samples (empty without a response)
  std::vector<NamedSeries> coordinates; // one per rigid-body coordinate
  std::vector<NamedSeries> recovered;   // the response's recovered series (blade, plow, element and chain forces)
  std::vector<NamedSeries> frame_loads; // "<point>.FX" ... "<point>.MZ" (3-D), "<load>.FX", "<load>.FZ", "<load>.MY" (2-D)
  std::vector<NamedSeries> rail_stress; // 2-D (frame_output): the rail top-fiber stress at each output point
  std::vector<double> frame_time;       // s: the frame transient's output times (pipeline)
  std::vector<NamedSeries> rail_series; // pipeline: "<rail>.bending_moment", "<rail>.normal_stress" over frame_time
  std::vector<RailEnvelope> rail_envelopes;
  std::vector<HotSpotHistory> hot_spots;  // by steady peak von Mises, as summary.json's frame.hot_spots
};

StudySeries study_series(const StudyRun& run);

// Every number of a summary (summary.json's content) by key path: a {value,
// unit} object as "rigid.response.peak_plow_force" with its unit, a plain
// number with none; list items as [index]. In the summary's order: the
// columns of a table of runs (the Python module's batch).
struct SummaryNumber {
  std::string path;
  std::string unit;
  double value = 0.0;
};
std::vector<SummaryNumber> summary_numbers(const nlohmann::ordered_json& summary);

}  // namespace framedyn::report
