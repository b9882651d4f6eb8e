// `framedyn batch --figures`: the design's scatter and main-effect figures
// (report/design_figures.h) added to its results folder, drawn from runs.csv
// as written, so that they show exactly the table's numbers.
// docs/user-guide.md, "framedyn batch".
#pragma once

#include <string>
#include <vector>

#include "batch/design.h"
#include "batch/engine.h"
#include "report/design_figures.h"

namespace framedyn::batch {

// The done runs of `rows` (runs.csv's records) as the figures' table.
report::DesignTable design_table(const BatchDesign& design, const std::vector<RunRecord>& rows);

// Reads options.out/runs.csv back and writes the results folder again (whole
// or nothing: core/results_folder) with runs.csv, summary.json and the PNG
// figures; returns the figures' file names. Throws report::PlotError when
// gnuplot fails.
std::vector<std::string> write_batch_figures(const BatchDesign& design, const BatchOptions& options);

}  // namespace framedyn::batch
