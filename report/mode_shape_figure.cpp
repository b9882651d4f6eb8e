// Mode-shape pictures of a frame model; see mode_shape_figure.h.
#include "report/mode_shape_figure.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>

namespace framedyn::report {

namespace {

// The model's largest dimension: the longest side of its nodes' bounding box (m).
double model_size(const fem::FrameModel& model) {
  if (model.nodes.empty()) return 0.0;
  Eigen::Vector3d lo = model.nodes.front().position, hi = lo;
  for (const fem::Node& n : model.nodes) {
    lo = lo.cwiseMin(n.position);
    hi = hi.cwiseMax(n.position);
  }
  return (hi - lo).maxCoeff();
}

// The members as segments between node indices.
std::vector<std::array<int, 2>> member_segments(const fem::FrameModel& model) {
  std::vector<std::array<int, 2>> s;
  for (const fem::BeamElement& b : model.beams) {
    if (b.is_quadratic()) {
      s.push_back({b.node_a, b.node_m});
      s.push_back({b.node_m, b.node_b});
    } else {
      s.push_back({b.node_a, b.node_b});
    }
  }
  return s;
}

}  // namespace

std::vector<Eigen::Vector3d> deformed_positions(const fem::FrameModel& model, const Eigen::VectorXd& shape, double* scale) {
  double largest = 0.0;
  for (std::size_t i = 0; i < model.nodes.size(); ++i)
    largest = std::max(largest, shape.segment<3>(fem::kDofsPerNode * static_cast<Eigen::Index>(i)).norm());
  const double s = largest > 0.0 ? 0.1 * model_size(model) / largest : 0.0;
  if (scale) *scale = s;
  std::vector<Eigen::Vector3d> x;
  for (std::size_t i = 0; i < model.nodes.size(); ++i)
    x.push_back(model.nodes[i].position + s * shape.segment<3>(fem::kDofsPerNode * static_cast<Eigen::Index>(i)));
  return x;
}

PanelFigure mode_shape_figure(const fem::FrameModel& model, const Eigen::MatrixXd& shapes, const std::vector<double>& frequencies_hz,
                              const std::string& title, int max_modes) {
  const core::UnitSystem& u = model.units;
  const double lf = 1.0 / u.to_si_factor(core::Quantity::length);
  const std::string L = u.label(core::Quantity::length);
  const std::vector<std::array<int, 2>> segments = member_segments(model);
  // The three views: (horizontal axis, vertical axis) of X, Y, Z.
  struct View {
    const char* name;
    int h, v;
  };
  const View views[3] = {{"plan", 0, 1}, {"side", 0, 2}, {"end", 1, 2}};
  const char* axis_names[3] = {"X", "Y", "Z"};
  auto series = [&](const std::string& name, const std::vector<Eigen::Vector3d>& x, const View& view, const std::string& colour) {
    PlotSeries s{name, {}, {}, true, colour};
    for (const auto& seg : segments)
      for (int end : seg) {
        s.x.push_back(x[static_cast<std::size_t>(end)](view.h) * lf);
        s.y.push_back(x[static_cast<std::size_t>(end)](view.v) * lf);
      }
    return s;
  };
  std::vector<Eigen::Vector3d> undeformed;
  for (const fem::Node& n : model.nodes) undeformed.push_back(n.position);

  PanelFigure f;
  f.title = title;
  const int modes = std::max(0, std::min<int>(max_modes, static_cast<int>(shapes.cols())));
  f.rows = std::max(1, modes);
  f.columns = 3;
  f.width = 1500;
  f.height = std::max(400, 330 * f.rows);
  for (int m = 0; m < modes; ++m) {
    double scale = 0.0;
    const std::vector<Eigen::Vector3d> deformed = deformed_positions(model, shapes.col(m), &scale);
    const double hz = m < static_cast<int>(frequencies_hz.size()) ? frequencies_hz[static_cast<std::size_t>(m)] : 0.0;
    for (const View& view : views) {
      LinePlot p;
      p.title = fmt::format("mode {}, {:.4g} Hz: {} view", m + 1, hz, view.name);
      p.x_label = axis_names[view.h];
      p.x_unit = L;
      p.y_label = axis_names[view.v];
      p.y_unit = L;
      p.equal_axes = true;
      p.key = false;
      p.series = {series("undeformed", undeformed, view, "#b0b0b0"), series(fmt::format("mode {}", m + 1), deformed, view, "#0072B2")};
      // A view in which the drawing is flat (a planar frame seen edge on, a
      // mode with no motion out of its plane) gets a range of a fifth of the
      // model's size around it, so that the axis shows lengths, not round-off.
      const double span = 0.2 * model_size(model) * lf;
      for (int axis = 0; axis < 2 && span > 0.0; ++axis) {
        double lo = 0.0, hi = 0.0;
        bool first = true;
        for (const PlotSeries& s : p.series)
          for (double v : axis == 0 ? s.x : s.y) {
            lo = first ? v : std::min(lo, v);
            hi = first ? v : std::max(hi, v);
            first = false;
          }
        if (hi - lo < 0.5 * span) {
          const double mid = 0.5 * (lo + hi);
          (axis == 0 ? p.x_range : p.y_range) = std::array<double, 2>{mid - span, mid + span};
        }
      }
      f.panels.push_back(p);
    }
  }
  return f;
}

}  // namespace framedyn::report
