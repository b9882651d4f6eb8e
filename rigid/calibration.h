// Calibration: fit chosen model parameters so that the vehicle's natural
// frequencies match targets (frequencies a user measured on the machine, or
// the thesis's Tables IV and V), within bounds, and report what the targets
// can and cannot determine. docs/theory/rigid.md, section 9.
//
// Levenberg-Marquardt on the logarithms x = ln p of the parameters (which
// keeps them positive and makes the steps scale-free), each step projected
// onto the bounds ln lower <= x <= ln upper, with a central-difference
// Jacobian, after a continuation that walks the targets from the model's own
// frequencies in eight stages (the last given ten times the iterations). Residual: the log-frequency errors r_t = ln(f_t / target_t) of
// the targets' modes (9.1), and, only when a regularisation weight w > 0 is
// asked for, w (x - x0) (Tikhonov towards the nominal values, 9.2).
// Identifiability: the scaled sensitivity matrix S = d r / d x (targets x
// parameters, dimensionless) and its singular values s_1 >= ... ; the number
// of independent targets is the number of s_i > 1e-3 s_1 (9.3); a fit with
// fewer independent targets than parameters is refused unless w > 0. The
// linearised uncertainty of ln p_i is sqrt(sigma^2 [(S^T S + w^2 1)^-1]_ii)
// with sigma^2 the residual's variance per degree of freedom, and never below
// the stated target uncertainty (9.4).
// The dominant coordinates of the targets are never fitted: targets are paired
// with modes by frequency order (match_targets: the k-th lowest target with a
// lower mode than the (k+1)-th, least total log-frequency distance), among the
// modes of CalibrationOptions::admissible when a family is given (a study's
// calibration.pair_with: symmetric_modes admits the modes symmetric about a
// symmetric machine's X-Z plane; docs/theory/rigid.md, section 14), and the
// labels are checked afterwards, as a prediction (labels_match per target).
// Measured shapes are fitted (9.6) but do not choose the pairing either.
// The last stage stopped by its iteration limit is reported
// (iteration_limit_reached), never as a converged fit.
// A target may also carry a measured mode shape (components at chosen
// coordinates or frame points, as an accelerometer survey gives them): its
// residual is the part of the measured unit shape s that the model's observed
// unit shape p does not explain, sign(c) (s - c p) with c = s.p, whose squared
// norm is 1 - MAC(s, p) (9.6), weighted by the target's shape weight. The
// modal assurance criterion of every shaped target is reported.
#pragma once

#include <Eigen/Dense>

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "rigid/rigid_modes.h"

namespace framedyn::rigid {

// A measured mode shape: `measured` (m components) against observation * phi,
// the model's mode phi (all coordinates) seen at the same m places.
struct ShapeTarget {
  Eigen::MatrixXd observation;  // m x n
  Eigen::VectorXd measured;     // m, SI (translations m, rotations rad)
  double weight = 1.0;          // of the shape residual against the log-frequency residual
};

struct FrequencyTarget {
  double frequency_hz = 0.0;
  std::string dominant;  // the coordinate the mode is expected to be led by (checked, never fitted); may be empty
  std::optional<ShapeTarget> shape;  // a measured mode shape, fitted through its MAC (9.6)
};

// Modal assurance criterion of two shapes: (a.b)^2 / ((a.a)(b.b)), in [0, 1],
// 1 when one is a multiple of the other; 0 if either is zero.
double modal_assurance(const Eigen::VectorXd& a, const Eigen::VectorXd& b);

// A family of modes (true: admitted), e.g. those symmetric about a symmetric
// machine's plane.
using ModeFamily = std::function<bool(const RigidMode&)>;

// The modes of the model with parameter values p (positive).
using ModesOfParameters = std::function<std::vector<RigidMode>(const std::vector<double>& p)>;

// A calibration that the targets cannot determine (fewer independent targets
// than parameters, or more targets than modes): an input error of the study.
struct UnderdeterminedFit : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

struct CalibrationOptions {
  int max_iterations = 100;
  double tolerance = 1e-10;  // on the relative frequency errors' norm
  // Bounds per parameter (same units as the parameters; 0 < lower <= initial
  // <= upper). Empty: no bounds.
  std::vector<double> lower, upper;
  // Tikhonov weight w on ln(p / p_initial) (9.2). 0: none, and a fit that the
  // targets cannot determine is refused.
  double regularization = 0.0;
  // The relative uncertainty of each target frequency, the floor of the
  // residual's standard deviation in the uncertainty of the parameters (9.4).
  double target_relative_uncertainty = 1e-3;
  // The family of modes the targets are paired with (match_targets); empty: all modes.
  ModeFamily admissible;
};

struct CalibrationResult {
  std::vector<double> initial, fitted;
  std::vector<double> lower, upper;         // the bounds used
  std::vector<bool> at_bound;               // fitted within 1e-6 (relative) of a bound
  std::vector<double> uncertainty;          // linearised standard deviation of each fitted parameter (its units)
  std::vector<double> achieved_hz;          // per target, with the fitted parameters
  std::vector<std::string> achieved_dominant;
  std::vector<bool> label_matches;          // per target: its mode is led by the target's coordinate (prediction)
  double max_relative_error = 0.0;          // max |f - target| / target
  bool labels_match = false;                // every labelled target's mode has the target's dominant coordinate
  int iterations = 0;
  // The last stage of the fit stopped at options.max_iterations with the
  // residual still falling: the fitted values are not a converged minimum.
  bool iteration_limit_reached = false;
  std::vector<double> mac;                  // per target: MAC of the measured and the fitted shape (-1: no shape)
  // Identifiability at the fitted values (9.3).
  Eigen::VectorXd singular_values;          // of S, largest first
  int independent_targets = 0;              // singular values above 1e-3 of the largest
  std::vector<Eigen::VectorXd> unresolved;  // right singular vectors (in ln p) of the others and of the missing ones
  bool underdetermined = false;             // fewer independent targets than parameters (only with regularisation)
  // The pieces of information the targets carry (a frequency each, m - 1 per
  // measured shape of m components) less the parameters: with none to spare
  // (<= 0) the fit can always meet its targets if it converges inside its
  // bounds, so a match is guaranteed by construction and is no evidence (docs/theory/rigid.md, Eq. 14.1).
  int information = 0;
  int degrees_of_freedom = 0;
  bool agreement_guaranteed = false;        // degrees_of_freedom <= 0
  double regularization = 0.0;              // the weight used
};

// Pairs each target with a distinct mode preserving frequency order (the
// k-th lowest target with a lower mode than the (k+1)-th), the modes chosen
// by least total log-frequency distance; labels play no part. -1 for every
// target when the model has fewer modes than targets.
// `admissible`, when given, restricts the candidate modes to a family (e.g.
// the modes symmetric about a symmetric machine's plane, whose targets a
// planar table lists); labels still play no part.
std::vector<int> match_targets(const std::vector<RigidMode>& modes, const std::vector<FrequencyTarget>& targets, const ModeFamily& admissible = {});

// The independent-target count of singular values s (largest first): those
// above kIndependentRatio times the largest.
constexpr double kIndependentRatio = 1e-3;
int independent_count(const Eigen::VectorXd& s);

// Throws UnderdeterminedFit (without a regularisation weight) when the
// targets cannot determine the parameters at the initial values.
CalibrationResult calibrate(const ModesOfParameters& modes_of, const std::vector<double>& initial,
                            const std::vector<FrequencyTarget>& targets, const CalibrationOptions& options = {});

}  // namespace framedyn::rigid
