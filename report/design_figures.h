// Figures of a design study (`framedyn batch --figures`, issue 19), drawn as
// the other figures are (report/plot.h, gnuplot):
//   - scatter plots: for each output, one panel per parameter, the output of
//     every done run against the parameter's value (scatter_<k>_<output>.png);
//   - main-effect plots (grid designs): for each output, one panel per
//     parameter, the mean of the output over the done runs at each level of
//     the parameter, the other parameters averaged out (main_effects_<k>_<output>.png).
// The numbers are the table's (runs.csv) as read back, so a figure shows what
// the table holds. docs/user-guide.md, "framedyn batch".
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "report/plot.h"

namespace framedyn::report {

// The done runs of a design, as runs.csv holds them.
struct DesignTable {
  std::string title;                         // names the design in the figures' titles
  std::vector<std::string> parameters, parameter_units;
  std::vector<std::string> outputs, output_units;
  std::vector<std::vector<double>> parameter_values;              // per done run, per parameter
  std::vector<std::vector<std::optional<double>>> output_values;  // per done run, per output (none: the run did not give it)
  bool grid = false;                         // a full factorial grid: main effects are drawn
};

struct DesignFigure {
  std::string file;  // PNG file name in the results folder
  PanelFigure figure;
};

// The figures of `table`, with their file names, in order: every output's
// scatter plot, then (grid) every output's main effects. An output no done run
// gives has no figure.
std::vector<DesignFigure> design_figures(const DesignTable& table);

}  // namespace framedyn::report
