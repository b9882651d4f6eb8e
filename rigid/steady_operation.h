// Steady operation of a shaken machine (docs/theory/rigid.md, section 12):
// when the response has stopped changing from one shaker cycle to the next
// (Eqs. 12.1-12.4), with the motion allowed to repeat only every n shaker
// periods (a subharmonic response, n = 1..SteadyCriterion::max_period_multiple), and the peaks
// of a time history over the start-up and over steady operation apart
// (Eq. 12.5). Pure signal processing: the signals (blade motion, frame loads)
// are chosen by the caller (coupling/steady_report.h).
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace framedyn::rigid {

// The detector's settings (docs/user-guide.md, "Steady operation").
struct SteadyCriterion {
  double tolerance = 0.01;     // largest cycle-to-cycle change, as a fraction of each signal's scale (Eq. 12.2)
  int window_periods = 3;      // steady only if every comparison over at least this many shaker periods passes (Eq. 12.3)
  int max_period_multiple = 128; // n = 1..this tried, the least that passes taken (Eq. 12.4); 128 (7.0 s at 18.33 Hz): the
                                 // shipped 3-D straight plow settles on a 110-period orbit, the offset plow on a 14-period one
                                 // (docs/theory/coupling.md section 19, docs/theory/rigid.md section 17)
  double scale_floor = 0.01;   // a signal's scale is at least this fraction of the largest magnitude in its group (Eq. 12.2)
};

struct WatchedSignal {
  std::string name;
  const std::vector<double>* values = nullptr;  // at the detector's sample times, SI
  int group = 0;  // signals of one quantity (lengths, forces, moments): the scale floor is the group's (Eq. 12.2)
};

struct SteadyOperation {
  std::optional<double> reached_at;  // s: the start of the first shaker period from which every later change is under tolerance
  int period_multiple = 0;           // n with which it was reached (0 if not reached)
  // The largest change over the last window, for the n that comes closest
  // (when not reached), or for the n found (when reached); as a fraction of the
  // signal's scale; with the signal that sets it.
  double remaining_change = 0.0;
  int remaining_period_multiple = 1;
  std::string leading_signal;
  double shaker_period = 0.0;        // s
  bool enough_data = true;           // false if the run is shorter than window_periods + n periods for every n
  int largest_multiple_tried = 0;    // the largest n the run was long enough to try (at most max_period_multiple)
  // When not reached (Eq. 17.2): the trend of the closest multiple's change,
  // its largest change over the last window against the window that ends
  // half-way through the comparisons, trend_span earlier: the change goes as
  // exp(-change_decay_rate t); a positive rate projects when it would fall
  // under the tolerance. Zero (and no projection) when it cannot be judged.
  double change_decay_rate = 0.0;    // 1/s; <= 0: the change does not shrink (a drift, a torus, an irregular motion)
  double trend_earlier_change = 0.0; // the earlier window's largest change, as a fraction of the scale
  double trend_span = 0.0;           // s between the two windows
  std::optional<double> projected_reached_at;  // s
};

// The cycle-to-cycle change d_n(k) of Eq. 12.1 for shaker periods k = 0, 1, ...
// (each the largest over the signals and the samples of [kT, (k+1)T), relative
// to the signal's scale), for one multiple n; `leader[k]` the signal index that
// sets it (the lowest index among those within 1e-6 relative of the largest).
struct CycleChanges {
  std::vector<double> change;
  std::vector<int> leader;
};
// `breaks` (sorted, s): the times at which the signals may jump (the switches
// of the soil law and the contacts): a value interpolated across one is left
// out of Eq. 12.1 (Eq. 17.1).
CycleChanges cycle_changes(const std::vector<double>& time, const std::vector<WatchedSignal>& signals, double period, int n,
                           const SteadyCriterion& criterion = {}, const std::vector<double>& breaks = {});

SteadyOperation detect_steady_operation(const std::vector<double>& time, const std::vector<WatchedSignal>& signals, double shaker_period,
                                        const SteadyCriterion& criterion = {}, const std::vector<double>& breaks = {});

// The value of largest magnitude (with its sign) of a time history, and when.
struct Peak {
  double value = 0.0;
  double time = 0.0;
};
// Eq. 12.5: the peak over the start-up (t < reached_at, or the whole run if
// steady operation was not reached) and over steady operation (t >= reached_at).
struct PeakSplit {
  std::optional<Peak> start_up, steady;
};
PeakSplit split_peaks(const std::vector<double>& time, const std::vector<double>& values, std::optional<double> reached_at);

}  // namespace framedyn::rigid
