// Pictures of a frame model's mode shapes (docs/user-guide.md, "Mode-shape
// figures"): one row per mode, three views of the model, plan (X-Y), side
// (X-Z) and end (Y-Z), the undeformed members in grey and the deformed ones
// in colour. A mode shape has no amplitude of its own: each mode's
// translations are drawn at the scale that makes its largest one 10 % of the
// model's largest dimension, and the panel says so. Drawn by report/plot.
#pragma once

#include <Eigen/Dense>

#include <string>
#include <vector>

#include "fem/frame_model.h"
#include "report/plot.h"

namespace framedyn::report {

// The deformed position of every node, in the model's units: x + s * u_mode,
// with s chosen so that max |u_mode| * s = 0.1 * the bounding box's largest side.
// `shape`: all DOFs of the model (kDofsPerNode per node; translations first).
// Returns the undeformed positions when the shape has no translation.
std::vector<Eigen::Vector3d> deformed_positions(const fem::FrameModel& model, const Eigen::VectorXd& shape, double* scale = nullptr);

// The figure: the first min(max_modes, shapes.cols()) columns of `shapes`
// (all DOFs x modes), titled with their frequencies (Hz). Three-node beams are
// drawn as two straight segments through their midside node.
PanelFigure mode_shape_figure(const fem::FrameModel& model, const Eigen::MatrixXd& shapes, const std::vector<double>& frequencies_hz,
                              const std::string& title, int max_modes = 4);

}  // namespace framedyn::report
