// Figures of a design study; see design_figures.h.
#include "report/design_figures.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <map>

namespace framedyn::report {

namespace {

// An output's key path as a file name part: letters, digits, '.', '_' and '-' kept, anything else '_'.
std::string file_part(const std::string& key) {
  std::string s = key;
  for (char& c : s)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '_' && c != '-') c = '_';
  return s;
}

PanelFigure panels_for(const DesignTable& t, const std::string& title) {
  PanelFigure f;
  f.title = title;
  const int n = static_cast<int>(t.parameters.size());
  f.columns = std::min(n, 3);
  f.rows = (n + f.columns - 1) / f.columns;
  f.width = 500 * f.columns + 100;
  f.height = 400 * f.rows + 100;
  return f;
}

LinePlot panel(const DesignTable& t, std::size_t p, std::size_t o, const std::string& y_label) {
  LinePlot plot;
  plot.title = t.parameters[p];
  plot.x_label = t.parameters[p];
  plot.x_unit = t.parameter_units[p];
  plot.y_label = y_label;
  plot.y_unit = t.output_units[o];
  plot.mark_points = true;
  plot.key = false;
  return plot;
}

}  // namespace

std::vector<DesignFigure> design_figures(const DesignTable& t) {
  std::vector<DesignFigure> out;
  std::vector<DesignFigure> effects;
  for (std::size_t o = 0; o < t.outputs.size(); ++o) {
    const std::string name = fmt::format("{}_{}.png", o + 1, file_part(t.outputs[o]));
    DesignFigure scatter{"scatter_" + name, panels_for(t, fmt::format("{} against each parameter: {}", t.outputs[o], t.title))};
    DesignFigure main{"main_effects_" + name, panels_for(t, fmt::format("Main effects on {} (mean over the other parameters): {}", t.outputs[o], t.title))};
    bool any = false;
    for (std::size_t p = 0; p < t.parameters.size(); ++p) {
      LinePlot s = panel(t, p, o, t.outputs[o]);
      PlotSeries points{t.outputs[o], {}, {}};
      points.points_only = true;
      std::map<double, std::pair<double, int>> levels;  // parameter value -> (sum, count)
      for (std::size_t r = 0; r < t.parameter_values.size(); ++r) {
        const std::optional<double>& y = t.output_values[r][o];
        if (!y) continue;
        const double x = t.parameter_values[r][p];
        points.x.push_back(x);
        points.y.push_back(*y);
        levels[x].first += *y;
        ++levels[x].second;
      }
      if (points.x.empty()) break;  // no done run gives this output
      any = true;
      s.series.push_back(std::move(points));
      scatter.figure.panels.push_back(std::move(s));
      LinePlot m = panel(t, p, o, "mean " + t.outputs[o]);
      PlotSeries means{"mean", {}, {}};
      for (const auto& [x, sum] : levels) {
        means.x.push_back(x);
        means.y.push_back(sum.first / sum.second);
      }
      m.series.push_back(std::move(means));
      main.figure.panels.push_back(std::move(m));
    }
    if (!any) continue;
    out.push_back(std::move(scatter));
    if (t.grid) effects.push_back(std::move(main));
  }
  for (DesignFigure& f : effects) out.push_back(std::move(f));
  return out;
}

}  // namespace framedyn::report
