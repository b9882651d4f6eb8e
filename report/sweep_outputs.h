// The outputs of `framedyn sweep` (a study run once per value of one machine
// parameter, coupling/parameter_sweep.h): sweep.csv, summary.json, the PNG
// figures (blade amplitude against the parameter, thesis Figure 9; peak
// cutting and backing force, Figure 10; their relative change against the
// run at the study file's value; the natural frequencies) and the console's
// table, every number in the study's units. apps/ parses the options, calls
// these and prints. docs/user-guide.md, "framedyn sweep".
#pragma once

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "core/results_folder.h"
#include "coupling/parameter_sweep.h"

namespace framedyn::report {

// One sweep as the outputs see it: the study, the result, the values as the
// user gave them (the study's units) and the command's settings.
struct SweepReport {
  std::string study_file;  // as given on the command line
  std::string study_name;
  core::UnitSystem units;  // the study's
  const coupling::SweepResult* result = nullptr;
  std::vector<double> values;  // the study's units, as given
  std::string parameter_unit;  // the parameter's unit label
  int jobs = 1;
};

// sweep.csv's text: the parameter, the five figures, their changes [%], then
// frequency_<i> [Hz] and dominant_<i>; a figure a run does not give is empty.
std::string sweep_csv(const SweepReport& sweep);
// Writes the PNG figures into `folder` (gnuplot); returns the files written.
std::vector<std::string> write_sweep_figures(const SweepReport& sweep, const core::ResultsFolder& folder);
// summary.json: framedyn, input, sweep {parameter, values, jobs, reference,
// runs, relative_spread, figures}; a figure a run does not give is left out.
nlohmann::ordered_json sweep_summary(const SweepReport& sweep, const std::vector<std::string>& figures);
// The console's report: the reference, the table of runs, the spreads and the figures.
std::string sweep_console_text(const SweepReport& sweep, const std::vector<std::string>& figures);

}  // namespace framedyn::report
