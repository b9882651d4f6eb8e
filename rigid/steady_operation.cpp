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

// Eq. 17.1: a value interpolated between two samples with a switch of the
// law between them (or on either) is no value of the signal: a force that
// jumps at the switch would be read part-way through its jump, and an orbit
// that repeats exactly would show a change of up to the jump. Such a
// comparison is left out; `breaks` sorted.
bool straddles_break(const std::vector<double>& time, const Bracket& b, const std::vector<double>& breaks) {
  if (breaks.empty() || b.beyond || b.exact) return false;
  const auto it = std::lower_bound(breaks.begin(), breaks.end(), time[b.i - 1]);
  return it != breaks.end() && *it <= time[b.i];
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
  const auto start = std::lower_bound(time.begin(), time.end(), from - 1e-9 * period);
  for (std::size_t i = static_cast<std::size_t>(start - time.begin()); i < time.size(); ++i) {
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

namespace {

// Eq. 12.1 for the periods k = first, first + 1, ... that have a period k + n
// (entry j of the result is period first + j). The detector asks first for the
// last window only, and for the whole run only for a multiple that passes: a
// multiple that fails costs W periods of samples, not the run's.
// The largest magnitude of each group over the run (Eq. 12.2), the same for every n.
std::map<int, double> group_largest_of(const std::vector<WatchedSignal>& signals) {
  std::map<int, double> group_largest;
  for (const WatchedSignal& s : signals)
    for (double v : *s.values) group_largest[s.group] = std::max(group_largest[s.group], std::abs(v));
  return group_largest;
}

CycleChanges changes_from(const std::vector<double>& time, const std::vector<WatchedSignal>& signals, double period, int n,
                          const SteadyCriterion& criterion, long first, const std::vector<double>& breaks,
                          std::map<int, double>& group_largest) {
  CycleChanges out;
  if (time.size() < 2 || !(period > 0) || n < 1) return out;
  const double t0 = time.front(), lag = n * period;
  // Eq. 12.1 compares period k with period k + n: both must be whole in the run.
  const long periods = period_index(time.back(), t0, period) - n;
  if (periods <= 0) return out;
  first = std::clamp(first, 0L, periods);
  std::vector<double> scale(signals.size());
  for (std::size_t s = 0; s < signals.size(); ++s)
    scale[s] = signal_scale(time, *signals[s].values, group_largest[signals[s].group], period, n, criterion);
  std::vector<std::vector<double>> per_signal(static_cast<std::size_t>(periods - first), std::vector<double>(signals.size(), 0.0));
  // The first sample of period `first` (to round-off, as period_index places it).
  const double from = t0 + static_cast<double>(first) * period - 1e-6 * period;
  for (std::size_t i = static_cast<std::size_t>(std::lower_bound(time.begin(), time.end(), from) - time.begin()); i < time.size(); ++i) {
    const long k = period_index(time[i], t0, period);
    if (k < first) continue;
    if (k >= periods) break;
    const Bracket later = bracket_at(time, time[i] + lag);  // the same for every signal (one time axis)
    if (straddles_break(time, later, breaks)) continue;
    for (std::size_t s = 0; s < signals.size(); ++s) {
      if (!(scale[s] > 0)) continue;  // a signal that is zero throughout never changes
      const std::vector<double>& x = *signals[s].values;
      const double d = std::abs(value_at(later, x) - x[i]) / scale[s];
      double& m = per_signal[static_cast<std::size_t>(k - first)][s];
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

long comparable_periods(const std::vector<double>& time, double period, int n) {
  if (time.size() < 2 || !(period > 0) || n < 1) return 0;
  return std::max(0L, period_index(time.back(), time.front(), period) - n);
}

// Eq. 17.2: whether the closest multiple's change still shrinks, and at what
// rate: its largest change over the last W periods against the W periods that
// end half-way through the comparisons, as exp(-rate t).
void settling_trend(const std::vector<double>& time, const std::vector<WatchedSignal>& signals, double period,
                    const SteadyCriterion& c, const std::vector<double>& breaks, std::map<int, double>& group_largest, SteadyOperation& r) {
  const int n = r.remaining_period_multiple;
  const CycleChanges cc = changes_from(time, signals, period, n, c, 0, breaks, group_largest);
  const long K = static_cast<long>(cc.change.size()), W = c.window_periods;
  const long mid_end = K / 2;  // the earlier window: periods [mid_end - W, mid_end)
  if (mid_end < W || K - mid_end < W) return;
  const auto window_max = [&](long end) { return *std::max_element(cc.change.begin() + (end - W), cc.change.begin() + end); };
  const double early = window_max(mid_end), late = window_max(K);
  if (!(early > 0) || !(late > 0)) return;
  r.trend_span = static_cast<double>(K - mid_end) * period;
  r.trend_earlier_change = early;
  r.change_decay_rate = std::log(early / late) / r.trend_span;
  // Shrinking by more than round-off, with a time constant no longer than the
  // run (a slower trend is no evidence of settling): projected from the last
  // window's start, where a decaying change is largest.
  const double run = time.back() - time.front();
  if (early > late * (1 + 1e-6) && 1.0 / r.change_decay_rate <= run)
    r.projected_reached_at = time.front() + static_cast<double>(K - W) * period + std::log(late / c.tolerance) / r.change_decay_rate;
}

}  // namespace

CycleChanges cycle_changes(const std::vector<double>& time, const std::vector<WatchedSignal>& signals, double period, int n,
                           const SteadyCriterion& criterion, const std::vector<double>& breaks) {
  std::map<int, double> group_largest = group_largest_of(signals);
  return changes_from(time, signals, period, n, criterion, 0, breaks, group_largest);
}

SteadyOperation detect_steady_operation(const std::vector<double>& time, const std::vector<WatchedSignal>& signals, double shaker_period,
                                        const SteadyCriterion& c, const std::vector<double>& breaks) {
  SteadyOperation r;
  r.shaker_period = shaker_period;
  r.enough_data = false;
  std::optional<double> closest;  // the least remaining change among the n tried (Eq. 12.4)
  const long W = c.window_periods;
  std::map<int, double> group_largest = group_largest_of(signals);
  for (int n = 1; n <= c.max_period_multiple; ++n) {
    const long K = comparable_periods(time, shaker_period, n);
    if (K < W) break;  // a larger n has fewer comparisons still
    r.enough_data = true;
    r.largest_multiple_tried = n;
    // The last window's largest change (Eq. 12.3) and the signal that sets it.
    const CycleChanges last = changes_from(time, signals, shaker_period, n, c, K - W, breaks, group_largest);
    if (static_cast<long>(last.change.size()) < W) continue;
    const std::size_t at = static_cast<std::size_t>(leading_index(last.change));
    const double remaining = last.change[at];
    const int lead = last.leader[at];
    if (remaining < c.tolerance) {
      const CycleChanges cc = changes_from(time, signals, shaker_period, n, c, 0, breaks, group_largest);
      std::size_t k = cc.change.size();
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
  if (closest) settling_trend(time, signals, shaker_period, c, breaks, group_largest, r);
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
