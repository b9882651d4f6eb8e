// Line plots as PNG images, drawn by gnuplot (Debian's gnuplot-nox, installed
// by install-deps.sh). A plot is plain data — a title, two labelled axes with
// their units and named series of (x, y) values; write_png writes the values
// and a gnuplot script into a private temporary folder, runs `gnuplot` on it
// and leaves only the PNG. The picture holds no date or file name, so the
// same plot gives the same PNG bytes on the same machine.
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace framedyn::report {

struct PlotSeries {
  std::string name;       // legend entry
  std::vector<double> x;  // same length as y, finite, in the axis' unit
  std::vector<double> y;
  // Points taken in pairs, one line segment per pair (a mesh's elements):
  // an even number of points, no line from one pair to the next.
  bool segments = false;
  std::string colour = {};  // "#rrggbb"; empty: the plot's palette by position
  bool points_only = false;  // markers and no line (a scatter plot)
};

struct LinePlot {
  std::string title;
  std::string x_label, x_unit;  // axis title "x_label [x_unit]"; unit "" or "1" for none
  std::string y_label, y_unit;
  std::vector<PlotSeries> series;
  bool mark_points = false;     // a marker at every value (sweeps with a few values)
  bool log_x = false, log_y = false;  // logarithmic axes (spectra); their values must be positive
  bool equal_axes = false;  // a unit as long on x as on y (views of a structure)
  bool key = true;          // the legend below the plot
  // Fixed axis ranges [low, high] (low < high); none: from the data.
  std::optional<std::array<double, 2>> x_range, y_range;
  int width = 1000, height = 620;  // pixels
};

// Several plots in one image, `rows` x `columns` panels filled row by row
// (gnuplot's multiplot); each panel's own width and height are ignored.
struct PanelFigure {
  std::string title;
  int rows = 1, columns = 1;
  std::vector<LinePlot> panels;  // at most rows x columns, each a valid LinePlot
  int width = 1500, height = 1000;  // pixels
};

// gnuplot could not be started, or it failed on a script (its message is included).
class PlotError : public std::runtime_error {
 public:
  explicit PlotError(const std::string& what) : std::runtime_error(what) {}
};

// Throws InputError (key: the plot's title) for a plot with no series, an
// empty series, x and y of different lengths, a non-finite value, a value
// that is not positive on a logarithmic axis, or a size outside 100..10000 pixels.
void check_plot(const LinePlot& plot);

// The gnuplot script that draws `plot` from `data_file` (one block per
// series, written by write_png) into `png`.
std::string gnuplot_script(const LinePlot& plot, const std::filesystem::path& data_file, const std::filesystem::path& png);

// Draws `plot` into `png` (replacing it) with the program `gnuplot` (looked up
// on PATH unless it contains a '/'). Throws InputError for a bad plot, PlotError
// when gnuplot is missing or fails.
void write_png(const LinePlot& plot, const std::filesystem::path& png, const std::string& gnuplot = "gnuplot");

// The same for a figure of panels: every panel is checked as a plot, and
// there must be at least one and at most rows x columns.
void check_figure(const PanelFigure& figure);
std::string gnuplot_script(const PanelFigure& figure, const std::filesystem::path& data_file, const std::filesystem::path& png);
void write_png(const PanelFigure& figure, const std::filesystem::path& png, const std::string& gnuplot = "gnuplot");

// Whether `gnuplot` can be run (it answers `--version`).
bool gnuplot_available(const std::string& gnuplot = "gnuplot");

}  // namespace framedyn::report
