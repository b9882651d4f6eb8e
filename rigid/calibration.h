// Calibration: fit chosen model parameters so that the vehicle's natural
// frequencies match targets (frequencies a user measured on the machine, or
// the thesis's Tables IV and V), each target tied to the mode with its
// dominant coordinate. Levenberg-Marquardt on the logarithms of the
// parameters (which keeps them positive and makes the steps scale-free), with
// a finite-difference Jacobian. docs/theory/rigid.md, section 9.
#pragma once

#include <Eigen/Dense>

#include <functional>
#include <string>
#include <vector>

#include "rigid/rigid_modes.h"

namespace framedyn::rigid {

struct FrequencyTarget {
  double frequency_hz = 0.0;
  std::string dominant;  // coordinate name; empty: match by frequency only
};

// The modes of the model with parameter values p (positive).
using ModesOfParameters = std::function<std::vector<RigidMode>(const std::vector<double>& p)>;

struct CalibrationOptions {
  int max_iterations = 100;
  double tolerance = 1e-10;  // on the relative frequency errors' norm
  // The coordinate names that index RigidMode::energy_share. When given, a
  // target's dominant coordinate is part of what is fitted, not only used to
  // pair it with a mode: a target whose mode is led by another coordinate adds
  // the shortfall of its own coordinate's energy share (plus a 1 % margin) to
  // the residual, so that among the parameter sets that reach the frequencies
  // the fit moves to one whose modes carry the target's labels.
  std::vector<std::string> coordinates;
};

struct CalibrationResult {
  std::vector<double> initial, fitted;
  std::vector<double> achieved_hz;          // per target, with the fitted parameters
  std::vector<std::string> achieved_dominant;
  double max_relative_error = 0.0;          // max |f - target| / target
  bool labels_match = false;                // every target's mode has the target's dominant coordinate
  int iterations = 0;
};

// Pairs each target with a distinct mode: the nearest in frequency among the
// modes whose dominant coordinate is the target's, else the nearest unused.
std::vector<int> match_targets(const std::vector<RigidMode>& modes, const std::vector<FrequencyTarget>& targets);

CalibrationResult calibrate(const ModesOfParameters& modes_of, const std::vector<double>& initial,
                            const std::vector<FrequencyTarget>& targets, const CalibrationOptions& options = {});

}  // namespace framedyn::rigid
