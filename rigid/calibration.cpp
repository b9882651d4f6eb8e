// Bounded, identifiability-checked frequency calibration; see calibration.h
// and docs/theory/rigid.md, section 9.
#include "rigid/calibration.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace framedyn::rigid {

namespace {
std::vector<int> match_targets_in(const std::vector<RigidMode>& modes, const std::vector<FrequencyTarget>& targets);
}  // namespace

std::vector<int> match_targets(const std::vector<RigidMode>& all_modes, const std::vector<FrequencyTarget>& targets, const ModeFamily& admissible) {
  // Only the admissible modes are candidates; their indices are mapped back.
  std::vector<RigidMode> family;
  std::vector<int> index;
  for (std::size_t i = 0; i < all_modes.size(); ++i)
    if (!admissible || admissible(all_modes[i])) family.push_back(all_modes[i]), index.push_back(static_cast<int>(i));
  std::vector<int> match = match_targets_in(family, targets);
  for (int& m : match)
    if (m >= 0) m = index[static_cast<std::size_t>(m)];
  return match;
}

namespace {
std::vector<int> match_targets_in(const std::vector<RigidMode>& modes, const std::vector<FrequencyTarget>& targets) {
  // Order-preserving: the targets sorted by frequency go to modes in
  // increasing frequency, choosing which modes by least total log-distance
  // (dynamic programming), so that no target is sent past another's mode.
  const std::size_t nt = targets.size(), nm = modes.size();
  std::vector<int> match(nt, -1);
  if (nt == 0 || nm < nt) return match;
  std::vector<std::size_t> order(nt), mode_order(nm);
  for (std::size_t i = 0; i < nt; ++i) order[i] = i;
  for (std::size_t i = 0; i < nm; ++i) mode_order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return targets[a].frequency_hz < targets[b].frequency_hz; });
  std::stable_sort(mode_order.begin(), mode_order.end(), [&](std::size_t a, std::size_t b) { return modes[a].frequency_hz < modes[b].frequency_hz; });
  auto dist = [&](std::size_t t, std::size_t m) {
    return std::abs(std::log(std::max(modes[mode_order[m]].frequency_hz, 1e-300) / targets[order[t]].frequency_hz));
  };
  const double inf = std::numeric_limits<double>::infinity();
  // cost[t][m]: best total for sorted targets 0..t with target t on sorted mode m.
  std::vector<std::vector<double>> cost(nt, std::vector<double>(nm, inf));
  std::vector<std::vector<std::size_t>> from(nt, std::vector<std::size_t>(nm, 0));
  for (std::size_t m = 0; m < nm; ++m) cost[0][m] = dist(0, m);
  for (std::size_t t = 1; t < nt; ++t) {
    double best = inf;
    std::size_t arg = 0;
    for (std::size_t m = t; m < nm; ++m) {
      if (cost[t - 1][m - 1] < best) best = cost[t - 1][m - 1], arg = m - 1;
      if (best < inf) cost[t][m] = best + dist(t, m), from[t][m] = arg;
    }
  }
  std::size_t m = nt - 1;
  for (std::size_t k = nt - 1; k < nm; ++k)
    if (cost[nt - 1][k] < cost[nt - 1][m]) m = k;
  for (std::size_t t = nt; t-- > 0;) {
    match[order[t]] = static_cast<int>(mode_order[m]);
    if (t > 0) m = from[t][m];
  }
  return match;
}
}  // namespace

double modal_assurance(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  const double aa = a.squaredNorm(), bb = b.squaredNorm();
  if (!(aa > 0 && bb > 0)) return 0.0;
  const double ab = a.dot(b);
  return ab * ab / (aa * bb);
}

int independent_count(const Eigen::VectorXd& s) {
  if (s.size() == 0 || !(s(0) > 0)) return 0;
  int n = 0;
  for (Eigen::Index i = 0; i < s.size(); ++i)
    if (s(i) > kIndependentRatio * s(0)) ++n;
  return n;
}

namespace {

std::vector<double> from_log(const Eigen::VectorXd& x) {
  std::vector<double> p(static_cast<std::size_t>(x.size()));
  for (Eigen::Index i = 0; i < x.size(); ++i) p[static_cast<std::size_t>(i)] = std::exp(x(i));
  return p;
}

// The number of data residuals: one per target frequency, plus one per
// component of each measured shape (9.6).
Eigen::Index data_rows(const std::vector<FrequencyTarget>& targets) {
  Eigen::Index n = static_cast<Eigen::Index>(targets.size());
  for (const FrequencyTarget& t : targets)
    if (t.shape) n += t.shape->measured.size();
  return n;
}

// The information the targets carry: a frequency each, and a measured shape
// of m components m - 1 more (its scale is not information).
Eigen::Index information_count(const std::vector<FrequencyTarget>& targets) {
  Eigen::Index n = static_cast<Eigen::Index>(targets.size());
  for (const FrequencyTarget& t : targets)
    if (t.shape) n += std::max<Eigen::Index>(t.shape->measured.size() - 1, 0);
  return n;
}

// The shape residual sign(c) (s - c p) of unit shapes s (measured) and p
// (observed), c = s.p: its squared norm is 1 - MAC (9.6).
Eigen::VectorXd shape_residual(const ShapeTarget& shape, const Eigen::VectorXd& phi) {
  const Eigen::VectorXd observed = shape.observation * phi;
  const double no = observed.norm(), nm = shape.measured.norm();
  if (!(no > 0) || !(nm > 0)) return shape.measured.normalized();  // nothing observed: the whole shape unexplained
  const Eigen::VectorXd s = shape.measured / nm, p = observed / no;
  const double c = s.dot(p);
  return (c < 0 ? -1.0 : 1.0) * (s - c * p);
}

// The log-frequency errors (9.1), the shape residuals (9.6), then w (x - x0)
// when regularised (9.2).
Eigen::VectorXd residuals(const ModesOfParameters& modes_of, const std::vector<FrequencyTarget>& targets, const Eigen::VectorXd& x,
                          const Eigen::VectorXd& x0, double w, const ModeFamily& family) {
  const std::vector<RigidMode> modes = modes_of(from_log(x));
  const std::vector<int> match = match_targets(modes, targets, family);
  const Eigen::Index nt = static_cast<Eigen::Index>(targets.size()), nd = data_rows(targets);
  Eigen::VectorXd r = Eigen::VectorXd::Zero(nd + (w > 0 ? x.size() : 0));
  Eigen::Index row = nt;
  for (std::size_t t = 0; t < targets.size(); ++t) {
    if (match[t] < 0)
      throw UnderdeterminedFit(fmt::format("{} target frequencies but the model has {} modes{}", targets.size(), modes.size(), family ? " in the targets' family" : ""));
    const RigidMode& m = modes[static_cast<std::size_t>(match[t])];
    r(static_cast<Eigen::Index>(t)) = std::log(m.frequency_hz / targets[t].frequency_hz);
    if (const auto& shape = targets[t].shape) {
      r.segment(row, shape->measured.size()) = shape->weight * shape_residual(*shape, m.shape);
      row += shape->measured.size();
    }
  }
  if (w > 0) r.tail(x.size()) = w * (x - x0);
  return r;
}

// Central-difference Jacobian of the residuals in ln p. A step that would
// leave the bounds is taken one-sided.
Eigen::MatrixXd jacobian(const ModesOfParameters& modes_of, const std::vector<FrequencyTarget>& targets, const Eigen::VectorXd& x,
                         const Eigen::VectorXd& x0, double w, const Eigen::VectorXd& lo, const Eigen::VectorXd& hi, const ModeFamily& family) {
  const double h = 1e-6;
  const Eigen::VectorXd r0 = residuals(modes_of, targets, x, x0, w, family);
  Eigen::MatrixXd j(r0.size(), x.size());
  for (Eigen::Index k = 0; k < x.size(); ++k) {
    Eigen::VectorXd xp = x, xm = x;
    xp(k) = std::min(x(k) + h, hi(k));
    xm(k) = std::max(x(k) - h, lo(k));
    if (xp(k) - xm(k) <= 0) xp(k) = x(k) + h, xm(k) = x(k) - h;  // a degenerate interval: the sensitivity is still wanted
    j.col(k) = (residuals(modes_of, targets, xp, x0, w, family) - residuals(modes_of, targets, xm, x0, w, family)) / (xp(k) - xm(k));
  }
  return j;
}

struct StageResult {
  int iterations = 0;
  bool limit_reached = false;  // stopped by max_iterations, still improving
};

StageResult fit_stage(const ModesOfParameters& modes_of, const std::vector<FrequencyTarget>& targets, Eigen::VectorXd& x, const Eigen::VectorXd& x0,
                      const Eigen::VectorXd& lo, const Eigen::VectorXd& hi, const CalibrationOptions& options) {
  const double w = options.regularization;
  const ModeFamily& family = options.admissible;
  const Eigen::Index nd = data_rows(targets);
  Eigen::VectorXd r = residuals(modes_of, targets, x, x0, w, family);
  double lambda = 1e-3;
  StageResult stage;
  int& iterations = stage.iterations;
  bool stalled = false;
  std::vector<double> history;  // |r| at the start of each iteration
  for (int it = 0; it < options.max_iterations && r.head(nd).norm() > options.tolerance; ++it) {
    iterations = it + 1;
    const Eigen::MatrixXd j = jacobian(modes_of, targets, x, x0, w, lo, hi, family);
    // First-order optimality on the bounds (KKT): the gradient J^T r with the
    // components that push a parameter out through the bound it sits on
    // removed. Below 1e-10 of |J| |r| the fit is a constrained minimum, even
    // with a residual that cannot reach zero.
    Eigen::VectorXd g = j.transpose() * r;
    for (Eigen::Index i = 0; i < g.size(); ++i)
      if ((x(i) - lo(i) < 1e-9 && g(i) > 0) || (hi(i) - x(i) < 1e-9 && g(i) < 0)) g(i) = 0;
    if (g.norm() <= 1e-10 * j.norm() * r.norm()) {
      stalled = true;
      break;
    }
    // A plateau: the residual fell by less than 1e-7 of itself over the last
    // 50 iterations (a flat valley the data barely resolve): converged as far
    // as the targets can tell.
    history.push_back(r.norm());
    if (history.size() > 50 && history[history.size() - 51] - r.norm() < 1e-7 * r.norm()) {
      stalled = true;
      break;
    }
    bool improved = false;
    for (int attempt = 0; attempt < 20 && !improved; ++attempt) {
      Eigen::MatrixXd a = j.transpose() * j;
      a.diagonal() += lambda * (a.diagonal().array() + 1e-12).matrix();
      Eigen::VectorXd step = a.ldlt().solve(-j.transpose() * r);
      // Keep a single step within a factor of e in every parameter.
      const double largest = step.cwiseAbs().maxCoeff();
      if (largest > 1.0) step /= largest;
      const Eigen::VectorXd trial = (x + step).cwiseMax(lo).cwiseMin(hi);  // projected onto the bounds
      Eigen::VectorXd r_trial;
      try {
        r_trial = residuals(modes_of, targets, trial, x0, w, family);
      } catch (const UnderdeterminedFit&) {
        throw;
      } catch (const std::exception&) {
        lambda *= 10;
        continue;
      }
      if (r_trial.norm() < r.norm() * (1 - 1e-12)) {
        x = trial;
        r = r_trial;
        lambda = std::max(lambda / 10, 1e-12);
        improved = true;
      } else {
        lambda *= 10;
      }
    }
    if (!improved) {
      stalled = true;  // a (local) minimum of the residual: converged, if not to zero
      break;
    }
  }
  stage.limit_reached = !stalled && iterations == options.max_iterations && r.head(nd).norm() > options.tolerance;
  return stage;
}

}  // namespace

CalibrationResult calibrate(const ModesOfParameters& modes_of, const std::vector<double>& initial,
                            const std::vector<FrequencyTarget>& targets, const CalibrationOptions& options) {
  if (initial.empty()) throw std::invalid_argument("calibration needs at least one parameter");
  if (targets.empty()) throw std::invalid_argument("calibration needs at least one target frequency");
  if (!(options.regularization >= 0)) throw std::invalid_argument("the regularisation weight must be >= 0");
  const Eigen::Index np = static_cast<Eigen::Index>(initial.size());
  const Eigen::Index nt = static_cast<Eigen::Index>(targets.size());
  const double w = options.regularization;
  Eigen::VectorXd x(np), lo(np), hi(np);
  CalibrationResult out;
  out.initial = initial;
  out.regularization = w;
  for (Eigen::Index i = 0; i < np; ++i) {
    const std::size_t k = static_cast<std::size_t>(i);
    if (!(initial[k] > 0)) throw std::invalid_argument("calibrated parameters must start positive");
    const double l = options.lower.empty() ? 0.0 : options.lower.at(k);
    const double u = options.upper.empty() ? std::numeric_limits<double>::infinity() : options.upper.at(k);
    if (!(l >= 0 && l <= initial[k] && initial[k] <= u))
      throw std::invalid_argument(fmt::format("parameter {}: bounds [{}, {}] must hold its start {}", i + 1, l, u, initial[k]));
    x(i) = std::log(initial[k]);
    lo(i) = l > 0 ? std::log(l) : -std::numeric_limits<double>::infinity();
    hi(i) = std::log(u);
    out.lower.push_back(l);
    out.upper.push_back(u);
  }
  const Eigen::VectorXd x0 = x;
  out.information = static_cast<int>(information_count(targets));
  out.degrees_of_freedom = out.information - static_cast<int>(np);
  out.agreement_guaranteed = out.degrees_of_freedom <= 0;

  // Refuse what the targets cannot determine, before fitting (9.3).
  {
    if (information_count(targets) < np && w == 0)
      throw UnderdeterminedFit(fmt::format("{} target frequencies{} for {} parameters: fewer independent targets than parameters "
                                           "(fit fewer parameters, add measured shapes, or ask for regularization)",
                                           nt, information_count(targets) > nt ? fmt::format(" and shapes ({} pieces of information)", information_count(targets)) : "", np));
    const Eigen::MatrixXd s0 = jacobian(modes_of, targets, x, x0, 0.0, lo, hi, options.admissible);
    const int independent = independent_count(Eigen::JacobiSVD<Eigen::MatrixXd>(s0).singularValues());
    if (independent < np && w == 0)
      throw UnderdeterminedFit(fmt::format("{} target frequencies but only {} independent (singular values of the sensitivities above "
                                           "{} of the largest) for {} parameters (fit fewer parameters, or ask for regularization)",
                                           nt, independent, kIndependentRatio, np));
  }

  // Continuation: move the targets from the model's own frequencies to the
  // wanted ones in stages, so that each mode is followed as it moves.
  const std::vector<RigidMode> start_modes = modes_of(initial);
  const std::vector<int> start_match = match_targets(start_modes, targets, options.admissible);
  constexpr int kStages = 8;
  for (int stage = 1; stage <= kStages; ++stage) {
    std::vector<FrequencyTarget> staged = targets;
    for (std::size_t t = 0; t < targets.size(); ++t) {
      if (start_match[t] < 0) throw UnderdeterminedFit("more frequency targets than the model has modes");
      const double f0 = start_modes[static_cast<std::size_t>(start_match[t])].frequency_hz;
      staged[t].frequency_hz = f0 * std::pow(targets[t].frequency_hz / f0, static_cast<double>(stage) / kStages);
    }
    // The intermediate stages only carry the modes along; the last one is
    // the fit, given ten times the iterations to reach its minimum.
    CalibrationOptions stage_options = options;
    if (stage == kStages) stage_options.max_iterations = 10 * options.max_iterations;
    const StageResult r = fit_stage(modes_of, staged, x, x0, lo, hi, stage_options);
    out.iterations += r.iterations;
    if (stage == kStages) out.iteration_limit_reached = r.limit_reached;
  }
  out.fitted = from_log(x);

  // The labels, as a prediction.
  const std::vector<RigidMode> modes = modes_of(out.fitted);
  const std::vector<int> match = match_targets(modes, targets, options.admissible);
  out.labels_match = true;
  for (std::size_t t = 0; t < targets.size(); ++t) {
    const RigidMode& m = modes[static_cast<std::size_t>(match[t])];
    out.achieved_hz.push_back(m.frequency_hz);
    out.achieved_dominant.push_back(m.dominant);
    out.max_relative_error = std::max(out.max_relative_error, std::abs(m.frequency_hz - targets[t].frequency_hz) / targets[t].frequency_hz);
    const bool ok = targets[t].dominant.empty() || m.dominant == targets[t].dominant;
    out.label_matches.push_back(ok);
    out.mac.push_back(targets[t].shape ? modal_assurance(targets[t].shape->measured, targets[t].shape->observation * m.shape) : -1.0);
    out.labels_match = out.labels_match && ok;
  }
  for (Eigen::Index i = 0; i < np; ++i) {
    const double tol = 1e-6;
    out.at_bound.push_back((std::isfinite(lo(i)) && x(i) - lo(i) < tol) || (std::isfinite(hi(i)) && hi(i) - x(i) < tol));
  }

  // Identifiability and uncertainty at the fitted values (9.3, 9.4).
  const Eigen::MatrixXd s = jacobian(modes_of, targets, x, x0, 0.0, lo, hi, options.admissible);
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(s, Eigen::ComputeFullV);
  out.singular_values = svd.singularValues();
  out.independent_targets = independent_count(out.singular_values);
  for (Eigen::Index i = out.independent_targets; i < np; ++i) out.unresolved.push_back(svd.matrixV().col(i));
  out.underdetermined = out.independent_targets < np;
  // The data residual (frequencies and shapes) per degree of freedom (9.4).
  const Eigen::VectorXd data_residual = residuals(modes_of, targets, x, x0, 0.0, options.admissible);
  const double dof = static_cast<double>(std::max<Eigen::Index>(information_count(targets) - np, 0));
  const double variance = std::max(dof > 0 ? data_residual.squaredNorm() / dof : 0.0, std::pow(options.target_relative_uncertainty, 2));
  Eigen::MatrixXd info = s.transpose() * s;
  info.diagonal().array() += w * w;
  // Pseudo-inverse: a direction the targets do not see has no finite uncertainty.
  Eigen::JacobiSVD<Eigen::MatrixXd> isvd(info, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Eigen::VectorXd sv = isvd.singularValues();
  Eigen::VectorXd inv(sv.size());
  for (Eigen::Index i = 0; i < sv.size(); ++i) inv(i) = sv(i) > std::pow(kIndependentRatio, 2) * sv(0) ? 1.0 / sv(i) : std::numeric_limits<double>::infinity();
  for (Eigen::Index i = 0; i < np; ++i) {
    double var = 0.0;
    for (Eigen::Index k = 0; k < sv.size(); ++k) {
      const double v = isvd.matrixV()(i, k);
      if (v * v > 1e-20) var += v * v * inv(k);
    }
    out.uncertainty.push_back(out.fitted[static_cast<std::size_t>(i)] * std::sqrt(variance * var));
  }
  return out;
}

}  // namespace framedyn::rigid
