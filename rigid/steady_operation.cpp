// Steady-operation detector and the start-up / steady peak split: see
// steady_operation.h and docs/theory/rigid.md, section 12.
#include "rigid/steady_operation.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace framedyn::rigid {

namespace {

// Linear interpolation at time t (t within the samples) on one time axis:
// where t falls is found once and serves every signal sampled at those times.
struct Bracket {
  std::size_t i = 0;    // the first sample at or after t
  bool beyond = false;  // t after the last sample: the last value
  bool exact = true;    // t is a sample time or before the first: values[i] itself
  double w = 0.0;       // else the weight of values[i] against values[i - 1]
};
Bracket bracket_at(const std::vector<double>& time, double t) {
  auto it = std::lower_bound(time.begin(), time.end(), t);
  if (it == time.end()) return {0, true, true, 0.0};
  const auto i = static_cast<std::size_t>(it - time.begin());
  if (i == 0 || *it == t) return {i, false, true, 0.0};
  return {i, false, false, (t - time[i - 1]) / (time[i] - time[i - 1])};
}
double value_at(const Bracket& b, const std::vector<double>& values) {
  if (b.beyond) return values.back();
  if (b.exact) return values[b.i];
  return values[b.i - 1] + b.w * (values[b.i] - values[b.i - 1]);
}

// The shaker period a sample falls in; the 1e-9 keeps a sample written at
// kT (to round-off) in period k.
long period_index(double t, double t0, double period) { return static_cast<long>(std::floor((t - t0) / period + 1e-9)); }

// Eq. 12.2: the signal's scale: its range over the last (window + n) periods,
// at least `floor` times the largest magnitude of its group over the run (so
// that a component that is round-off throughout, as a symmetric machine's
// lateral load, is judged against the loads of its kind, not against itself).
double signal_scale(const std::vector<double>& time, const std::vector<double>& x, double group_largest, double period, int n,
                    const SteadyCriterion& c) {
  const double from = time.back() - (c.window_periods + n) * period;
  double lo = 0, hi = 0;
  bool any = false;
  for (std::size_t i = 0; i < time.size(); ++i) {
    if (time[i] < from - 1e-9 * period) continue;
    if (!any) lo = hi = x[i];
    lo = std::min(lo, x[i]);
    hi = std::max(hi, x[i]);
    any = true;
  }
  return std::max(hi - lo, c.scale_floor * group_largest);
}

// The lowest index among the entries within 1e-6 relative of the largest:
// a choice that does not depend on round-off among near-equal values.
int leading_index(const std::vector<double>& v) {
  if (v.empty()) return -1;
  const double top = *std::max_element(v.begin(), v.end());
  for (std::size_t i = 0; i < v.size(); ++i)
    if (v[i] >= top - 1e-6 * std::abs(top)) return static_cast<int>(i);
  return 0;
}

}  // namespace

CycleChanges cycle_changes(const std::vector<double>& time, const std::vector<WatchedSignal>& signals, double period, int n,
                           const SteadyCriterion& criterion) {
  CycleChanges out;
  if (time.size() < 2 || !(period > 0) || n < 1) return out;
  const double t0 = time.front(), lag = n * period;
  // Eq. 12.1 compares period k with period k + n: both must be whole in the run.
  const long periods = period_index(time.back(), t0, period) - n;
  if (periods <= 0) return out;
  std::map<int, double> group_largest;
  for (const WatchedSignal& s : signals)
    for (double v : *s.values) group_largest[s.group] = std::max(group_largest[s.group], std::abs(v));
  std::vector<double> scale(signals.size());
  for (std::size_t s = 0; s < signals.size(); ++s)
    scale[s] = signal_scale(time, *signals[s].values, group_largest[signals[s].group], period, n, criterion);
  std::vector<std::vector<double>> per_signal(static_cast<std::size_t>(periods), std::vector<double>(signals.size(), 0.0));
  for (std::size_t i = 0; i < time.size(); ++i) {
    const long k = period_index(time[i], t0, period);
    if (k < 0 || k >= periods) continue;
    const Bracket later = bracket_at(time, time[i] + lag);  // the same for every signal (one time axis)
    for (std::size_t s = 0; s < signals.size(); ++s) {
      if (!(scale[s] > 0)) continue;  // a signal that is zero throughout never changes
      const std::vector<double>& x = *signals[s].values;
      const double d = std::abs(value_at(later, x) - x[i]) / scale[s];
      double& m = per_signal[static_cast<std::size_t>(k)][s];
      if (d > m) m = d;
    }
  }
  for (const std::vector<double>& d : per_signal) {
    const int lead = leading_index(d);
    out.change.push_back(lead < 0 ? 0.0 : d[static_cast<std::size_t>(lead)]);
    out.leader.push_back(lead);
  }
  return out;
}

SteadyOperation detect_steady_operation(const std::vector<double>& time, const std::vector<WatchedSignal>& signals, double shaker_period,
                                        const SteadyCriterion& c) {
  SteadyOperation r;
  r.shaker_period = shaker_period;
  r.enough_data = false;
  std::optional<double> closest;  // the least remaining change among the n tried (Eq. 12.4)
  for (int n = 1; n <= c.max_period_multiple; ++n) {
    const CycleChanges cc = cycle_changes(time, signals, shaker_period, n, c);
    const std::size_t K = cc.change.size();
    if (K < static_cast<std::size_t>(c.window_periods)) continue;
    r.enough_data = true;
    // The last window's largest change (Eq. 12.3) and the signal that sets it.
    const std::vector<double> last(cc.change.end() - c.window_periods, cc.change.end());
    const std::size_t at = K - static_cast<std::size_t>(c.window_periods) + static_cast<std::size_t>(leading_index(last));
    const double remaining = cc.change[at];
    const int lead = cc.leader[at];
    if (remaining < c.tolerance) {
      std::size_t k = K;
      while (k > 0 && cc.change[k - 1] < c.tolerance) --k;
      r.reached_at = time.front() + static_cast<double>(k) * shaker_period;
      r.period_multiple = n;
      r.remaining_change = remaining;
      r.remaining_period_multiple = n;
      r.leading_signal = lead >= 0 ? signals[static_cast<std::size_t>(lead)].name : std::string();
      return r;
    }
    // A larger n must come closer by more than round-off to be named instead.
    if (!closest || remaining < *closest * (1 - 1e-6)) {
      closest = remaining;
      r.remaining_change = remaining;
      r.remaining_period_multiple = n;
      r.leading_signal = lead >= 0 ? signals[static_cast<std::size_t>(lead)].name : std::string();
    }
  }
  return r;
}

PeakSplit split_peaks(const std::vector<double>& time, const std::vector<double>& values, std::optional<double> reached_at) {
  PeakSplit p;
  for (std::size_t i = 0; i < time.size() && i < values.size(); ++i) {
    std::optional<Peak>& slot = (reached_at && time[i] >= *reached_at) ? p.steady : p.start_up;
    if (!slot || std::abs(values[i]) > std::abs(slot->value)) slot = Peak{values[i], time[i]};
  }
  return p;
}

}  // namespace framedyn::rigid
