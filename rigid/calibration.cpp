// Levenberg-Marquardt frequency calibration; see calibration.h.
#include "rigid/calibration.h"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace framedyn::rigid {

std::vector<int> match_targets(const std::vector<RigidMode>& modes, const std::vector<FrequencyTarget>& targets) {
  std::vector<int> match(targets.size(), -1);
  std::vector<bool> used(modes.size(), false);
  // First the targets whose label some mode carries, in target order.
  for (int pass = 0; pass < 2; ++pass)
    for (std::size_t t = 0; t < targets.size(); ++t) {
      if (match[t] >= 0) continue;
      double best = std::numeric_limits<double>::infinity();
      for (std::size_t m = 0; m < modes.size(); ++m) {
        if (used[m]) continue;
        if (pass == 0 && (targets[t].dominant.empty() || modes[m].dominant != targets[t].dominant)) continue;
        const double d = std::abs(std::log(std::max(modes[m].frequency_hz, 1e-300) / targets[t].frequency_hz));
        if (d < best) {
          best = d;
          match[t] = static_cast<int>(m);
        }
      }
      if (match[t] >= 0) used[static_cast<std::size_t>(match[t])] = true;
    }
  return match;
}

namespace {

// Log-frequency errors of the matched modes, then a small pull of every
// log-parameter towards its start: with more parameters than targets the fit
// then moves the parameters as little as it can.
constexpr double kRegularisation = 1e-3;
// The lead a target's own coordinate must have in its mode's energy, so that
// the label holds with a margin rather than on a tie.
constexpr double kLabelMargin = 0.01;

// Index of a target's labelled coordinate in the energy shares, -1 if the
// label is not enforced (no names given, no label, or an unknown name).
int label_index(const CalibrationOptions& options, const FrequencyTarget& target) {
  for (std::size_t j = 0; j < options.coordinates.size(); ++j)
    if (!target.dominant.empty() && options.coordinates[j] == target.dominant) return static_cast<int>(j);
  return -1;
}

// Frequency errors (one per target), label shortfalls (one per target when
// labels are enforced), then the pull towards the start (one per parameter).
Eigen::VectorXd residuals(const std::vector<RigidMode>& modes, const std::vector<FrequencyTarget>& targets, const Eigen::VectorXd& x,
                          const Eigen::VectorXd& x0, const CalibrationOptions& options) {
  const std::vector<int> match = match_targets(modes, targets);
  const Eigen::Index nt = static_cast<Eigen::Index>(targets.size());
  const Eigen::Index nl = options.coordinates.empty() ? 0 : nt;
  Eigen::VectorXd r = Eigen::VectorXd::Zero(nt + nl + x.size());
  r.tail(x.size()) = kRegularisation * (x - x0);
  for (std::size_t t = 0; t < targets.size(); ++t) {
    if (match[t] < 0) throw std::invalid_argument("more frequency targets than the model has modes");
    const RigidMode& mode = modes[static_cast<std::size_t>(match[t])];
    // Logarithmic error: symmetric in over- and under-shoot, ~ relative error.
    r(static_cast<Eigen::Index>(t)) = std::log(mode.frequency_hz / targets[t].frequency_hz);
    const int own = label_index(options, targets[t]);
    if (nl == 0 || own < 0 || mode.energy_share.size() != static_cast<Eigen::Index>(options.coordinates.size())) continue;
    double other = 0.0;
    for (Eigen::Index j = 0; j < mode.energy_share.size(); ++j)
      if (j != own) other = std::max(other, mode.energy_share(j));
    r(nt + static_cast<Eigen::Index>(t)) = std::max(0.0, other - mode.energy_share(own) + kLabelMargin);
  }
  return r;
}

int fit_stage(const ModesOfParameters& modes_of, const std::vector<FrequencyTarget>& targets, Eigen::VectorXd& x, const Eigen::VectorXd& x0,
              const CalibrationOptions& options);

std::vector<double> from_log(const Eigen::VectorXd& x) {
  std::vector<double> p(static_cast<std::size_t>(x.size()));
  for (Eigen::Index i = 0; i < x.size(); ++i) p[static_cast<std::size_t>(i)] = std::exp(x(i));
  return p;
}

}  // namespace

CalibrationResult calibrate(const ModesOfParameters& modes_of, const std::vector<double>& initial,
                            const std::vector<FrequencyTarget>& targets, const CalibrationOptions& options) {
  if (initial.empty()) throw std::invalid_argument("calibration needs at least one parameter");
  if (targets.empty()) throw std::invalid_argument("calibration needs at least one target frequency");
  const Eigen::Index np = static_cast<Eigen::Index>(initial.size());
  Eigen::VectorXd x(np);
  for (Eigen::Index i = 0; i < np; ++i) {
    if (!(initial[static_cast<std::size_t>(i)] > 0)) throw std::invalid_argument("calibrated parameters must start positive");
    x(i) = std::log(initial[static_cast<std::size_t>(i)]);
  }
  const Eigen::VectorXd x0 = x;
  CalibrationResult out;
  out.initial = initial;
  // Continuation: move the targets from the model's own frequencies to the
  // wanted ones in stages, so that each mode is followed as it moves and keeps
  // its identity (matching by dominant coordinate is discontinuous where two
  // modes cross).
  const std::vector<RigidMode> start_modes = modes_of(initial);
  const std::vector<int> start_match = match_targets(start_modes, targets);
  constexpr int kStages = 8;
  for (int stage = 1; stage <= kStages; ++stage) {
    std::vector<FrequencyTarget> staged = targets;
    for (std::size_t t = 0; t < targets.size(); ++t) {
      if (start_match[t] < 0) throw std::invalid_argument("more frequency targets than the model has modes");
      const double f0 = start_modes[static_cast<std::size_t>(start_match[t])].frequency_hz;
      staged[t].frequency_hz = f0 * std::pow(targets[t].frequency_hz / f0, static_cast<double>(stage) / kStages);
    }
    out.iterations += fit_stage(modes_of, staged, x, x0, options);
  }
  out.fitted = from_log(x);
  const std::vector<RigidMode> modes = modes_of(out.fitted);
  const std::vector<int> match = match_targets(modes, targets);
  out.labels_match = true;
  for (std::size_t t = 0; t < targets.size(); ++t) {
    const RigidMode& m = modes[static_cast<std::size_t>(match[t])];
    out.achieved_hz.push_back(m.frequency_hz);
    out.achieved_dominant.push_back(m.dominant);
    out.max_relative_error = std::max(out.max_relative_error, std::abs(m.frequency_hz - targets[t].frequency_hz) / targets[t].frequency_hz);
    if (!targets[t].dominant.empty() && m.dominant != targets[t].dominant) out.labels_match = false;
  }
  return out;
}

namespace {

int fit_stage(const ModesOfParameters& modes_of, const std::vector<FrequencyTarget>& targets, Eigen::VectorXd& x, const Eigen::VectorXd& x0,
              const CalibrationOptions& options) {
  const Eigen::Index np = x.size();
  Eigen::VectorXd r = residuals(modes_of(from_log(x)), targets, x, x0, options);
  const Eigen::Index nfit = r.size() - np;  // frequency errors and label shortfalls
  double lambda = 1e-3;
  int iterations = 0;
  for (int it = 0; it < options.max_iterations && r.head(nfit).norm() > options.tolerance; ++it) {
    iterations = it + 1;
    // Jacobian of the log-frequency errors with respect to the log-parameters.
    Eigen::MatrixXd j(r.size(), np);
    const double h = 1e-6;
    for (Eigen::Index k = 0; k < np; ++k) {
      Eigen::VectorXd xp = x, xm = x;
      xp(k) += h;
      xm(k) -= h;
      j.col(k) = (residuals(modes_of(from_log(xp)), targets, xp, x0, options) - residuals(modes_of(from_log(xm)), targets, xm, x0, options)) / (2 * h);
    }
    bool improved = false;
    for (int attempt = 0; attempt < 20 && !improved; ++attempt) {
      Eigen::MatrixXd a = j.transpose() * j;
      a.diagonal() += lambda * (a.diagonal().array() + 1e-12).matrix();
      Eigen::VectorXd step = a.ldlt().solve(-j.transpose() * r);
      // Keep a single step within a factor of e in every parameter.
      const double largest = step.cwiseAbs().maxCoeff();
      if (largest > 1.0) step /= largest;
      const Eigen::VectorXd trial = x + step;
      Eigen::VectorXd r_trial;
      try {
        r_trial = residuals(modes_of(from_log(trial)), targets, trial, x0, options);
      } catch (const std::exception&) {
        lambda *= 10;
        continue;
      }
      if (r_trial.norm() < r.norm()) {
        x = trial;
        r = r_trial;
        lambda = std::max(lambda / 10, 1e-12);
        improved = true;
      } else {
        lambda *= 10;
      }
    }
    if (!improved) break;
  }
  return iterations;
}

}  // namespace

}  // namespace framedyn::rigid
