// Validity warnings of a vehicle response: see validity_warnings.h and
// docs/theory/coupling.md, section 8.
#include "coupling/validity_warnings.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

namespace framedyn::coupling {

namespace {

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

// The switching law an event's part names, or empty for none (a scheduled change).
std::string law_of(const std::string& part) {
  if (part == "blade backs off" || part == "blade cuts again") return "soil";
  for (const char* tail : {" loses contact", " touches again"}) {
    const std::string t(tail);
    if (part.size() > t.size() && part.compare(part.size() - t.size(), t.size(), t) == 0) return part.substr(0, part.size() - t.size());
  }
  return {};
}

}  // namespace

LargestRotation largest_body_rotation(const rigid::Multibody& model, const rigid::Trajectory& tr) {
  // Candidates: the bodies' rotations |R_b q|, then the angle coordinates
  // (psi turns the plow linkage's massless arms, which are no bodies).
  const std::vector<rigid::Body>& bodies = model.bodies();
  const std::vector<std::string>& names = model.coordinate_names();
  const std::vector<core::Quantity>& quantities = model.coordinate_quantities();  // which coordinates are angles
  std::vector<std::string> what;
  std::vector<int> coordinate;  // -1 for a body
  for (const rigid::Body& b : bodies) {
    what.push_back("body " + b.name);
    coordinate.push_back(-1);
  }
  for (std::size_t c = 0; c < names.size(); ++c)
    if (quantities[c] == core::Quantity::angle) {
      what.push_back("coordinate " + names[c]);
      coordinate.push_back(static_cast<int>(c));
    }
  std::vector<double> angle(what.size(), 0.0), when(what.size(), 0.0);
  for (std::size_t i = 0; i < tr.time.size(); ++i)
    for (std::size_t k = 0; k < what.size(); ++k) {
      const double a = coordinate[k] < 0 ? (bodies[k].rotation * tr.q[i]).norm() : std::abs(tr.q[i](coordinate[k]));
      if (a > angle[k]) {
        angle[k] = a;
        when[k] = tr.time[i];
      }
    }
  LargestRotation r;
  if (what.empty()) return r;
  const double top = *std::max_element(angle.begin(), angle.end());
  for (std::size_t k = 0; k < what.size(); ++k)
    if (angle[k] >= top * (1 - 1e-6)) {  // the first among the near-equal largest
      r = {angle[k], what[k], when[k]};
      break;
    }
  return r;
}

std::optional<core::Warning> rotation_warning(const LargestRotation& r) {
  const double x = r.angle, cos_error = 0.5 * x * x, sin_error = x > 0 ? 1.0 - std::sin(x) / x : 0.0;
  if (!(cos_error > kLinearisationErrorLimit)) return std::nullopt;
  core::Warning w;
  w.code = "rotation_beyond_linear_range";
  w.message = fmt::format("{} rotates by {:.4g} rad ({:.3g} deg) at t = {:.4g} s, beyond the range where the linearised kinematics hold: "
                          "a point on it moves 1 - cos x = {:.2g} of its arm in a direction the model neglects, and its motion across "
                          "the arm errs by 1 - sin(x)/x = {:.2g} (limit: x^2/2 = {:g}, i.e. {:.4g} rad). Forces and stresses from "
                          "the response carry errors of that order; the motion is too large for a small-motion model",
                          r.body, x, x * 180.0 / M_PI, r.time, cos_error, sin_error, kLinearisationErrorLimit, std::sqrt(2 * kLinearisationErrorLimit));
  w.figures = {{"largest_rotation", x, "rad"}, {"time", r.time, "s"}, {"arm_error_x2_over_2", cos_error, "1"},
               {"sin_error_1_minus_sinx_over_x", sin_error, "1"}, {"limit", kLinearisationErrorLimit, "1"}};
  return w;
}

double switching_window(double shaker_hz) { return shaker_hz > 0 ? 1.0 / shaker_hz : 0.1; }

std::vector<SwitchingActivity> switching_activity(const std::vector<rigid::Trajectory::Event>& events, double window) {
  std::vector<std::string> order;
  std::map<std::string, std::vector<double>> times;
  for (const rigid::Trajectory::Event& e : events) {
    std::size_t from = 0;
    while (from <= e.what.size()) {
      const std::size_t to = std::min(e.what.find("; ", from), e.what.size());
      const std::string law = law_of(e.what.substr(from, to - from));
      if (!law.empty()) {
        if (!times.count(law)) order.push_back(law);
        times[law].push_back(e.time);
      }
      from = to + 2;
    }
  }
  std::vector<SwitchingActivity> out;
  for (const std::string& law : order) {
    const std::vector<double>& t = times[law];
    SwitchingActivity a;
    a.law = law;
    a.switches = static_cast<int>(t.size());
    std::vector<double> chattering_intervals, all_intervals;
    for (std::size_t i = 1; i < t.size(); ++i) all_intervals.push_back(t[i] - t[i - 1]);
    // Group the switches by period (the 1e-9 keeps a switch at kT, to round-off, in period k).
    std::size_t i = 0;
    while (i < t.size()) {
      const long k = static_cast<long>(std::floor(t[i] / window + 1e-9));
      std::size_t j = i;
      while (j < t.size() && static_cast<long>(std::floor(t[j] / window + 1e-9)) == k) ++j;
      const int count = static_cast<int>(j - i);
      a.most_in_one_period = std::max(a.most_in_one_period, count);
      std::vector<double> intervals;
      for (std::size_t m = i + 1; m < j; ++m) intervals.push_back(t[m] - t[m - 1]);
      if (count > kChatterSwitchesPerPeriod && median(intervals) < kChatterIntervalFraction * window) {
        if (a.chattering_periods == 0) a.first = t[i];
        a.last = t[j - 1];
        ++a.chattering_periods;
        a.switches_in_chattering += count;
        chattering_intervals.insert(chattering_intervals.end(), intervals.begin(), intervals.end());
      }
      i = j;
    }
    a.median_interval = median(a.chattering_periods > 0 ? chattering_intervals : all_intervals);
    out.push_back(a);
  }
  return out;
}

std::vector<core::Warning> chattering_warnings(const std::vector<SwitchingActivity>& activity, double window, bool event_located, double rk4_step,
                                               bool shaker) {
  std::vector<core::Warning> out;
  for (const SwitchingActivity& a : activity) {
    if (a.chattering_periods == 0) continue;
    const std::string treated =
        event_located ? "Treated by following it: every switch is located and the integrator restarts there (no sliding model replaces "
                        "the two laws), so the motion through the regime is the limit of fast switching, accurate to the integrator's "
                        "tolerance; the number of switches depends on that tolerance, each costs a restart, and a force sampled there "
                        "may fall on either law"
                      : fmt::format("Treated by RK4 at its step ({:.4g} s): it switches at most once a step, so the regime is smeared "
                                    "over the step and the switch count is the integrator's, not the machine's; method: event_located "
                                    "follows it switch by switch",
                                    rk4_step);
    core::Warning w;
    w.code = "switching_law_chattering";
    w.message = fmt::format("the {} law switches {} times, {} of them in {} {}{} of {:.4g} s with more than {} switches each (at most "
                            "{} in one), a median {:.3g} s apart, between t = {:.4g} and {:.4g} s: a sliding regime, where neither "
                            "side of the law can hold and the motion slides along the switching surface. {}",
                            a.law == "soil" ? std::string("soil's") : a.law + " contact", a.switches, a.switches_in_chattering,
                            a.chattering_periods, shaker ? "shaker period" : "window", a.chattering_periods == 1 ? "" : "s", window,
                            kChatterSwitchesPerPeriod, a.most_in_one_period, a.median_interval, a.first, a.last, treated);
    w.figures = {{"switches", static_cast<double>(a.switches), "1"},
                 {"chattering_periods", static_cast<double>(a.chattering_periods), "1"},
                 {"switches_in_chattering_periods", static_cast<double>(a.switches_in_chattering), "1"},
                 {"most_in_one_period", static_cast<double>(a.most_in_one_period), "1"},
                 {"median_interval", a.median_interval, "s"},
                 {"period", window, "s"},
                 {"first", a.first, "s"},
                 {"last", a.last, "s"}};
    out.push_back(w);
  }
  return out;
}

namespace {

// (f_shaker - f) / f when the shaker lies within Eq. 8.3's band of f (f > 0).
std::optional<double> offset_in_band(double shaker_hz, double f) {
  if (!(shaker_hz > 0) || !(f > 0)) return std::nullopt;
  const double offset = (shaker_hz - f) / f;
  if (std::abs(offset) > kResonanceBand) return std::nullopt;
  return offset;
}

}  // namespace

std::vector<core::Warning> resonance_warnings(double shaker_hz, const std::vector<rigid::RigidMode>& modes, const std::string& modes_label) {
  std::vector<core::Warning> out;
  for (std::size_t i = 0; i < modes.size(); ++i) {
    const double f = modes[i].frequency_hz;
    const std::optional<double> near = offset_in_band(shaker_hz, f);
    if (!near) continue;
    const double offset = *near;
    core::Warning w;
    w.code = "shaker_near_mode";
    w.message = fmt::format("the shaker's {:.4g} Hz is {:+.1f} % from mode {} ({:.4g} Hz, {}; modes {}): within {:.0f} % of a natural "
                            "frequency the response is set by the damping, which the model knows least well, and small changes of "
                            "stiffness or mass move it a lot",
                            shaker_hz, 100.0 * offset, i + 1, f, modes[i].dominant, modes_label, 100.0 * kResonanceBand);
    w.figures = {{"shaker_frequency", shaker_hz, "Hz"}, {"mode", static_cast<double>(i + 1), "1"}, {"mode_frequency", f, "Hz"},
                 {"relative_offset", offset, "1"}, {"band", kResonanceBand, "1"}};
    out.push_back(w);
  }
  return out;
}

std::vector<core::Warning> frame_resonance_warnings(double shaker_hz, const std::vector<double>& frame_modes_hz, const std::string& mesh_name) {
  std::vector<core::Warning> out;
  for (std::size_t i = 0; i < frame_modes_hz.size(); ++i) {
    const double f = frame_modes_hz[i];
    const std::optional<double> near = offset_in_band(shaker_hz, f);
    if (!near) continue;
    core::Warning w;
    w.code = "shaker_near_frame_mode";
    w.message = fmt::format("the shaker's {:.4g} Hz is {:+.1f} % from elastic mode {} of the frame model ({:.4g} Hz, {}): within {:.0f} % "
                            "of a natural frequency the frame's stresses are set by its modal damping, which the model knows least "
                            "well; check what the mode is (frame_modes.csv, the ParaView series) before using the stress peaks",
                            shaker_hz, 100.0 * *near, i + 1, f, mesh_name, 100.0 * kResonanceBand);
    w.figures = {{"shaker_frequency", shaker_hz, "Hz"}, {"mode", static_cast<double>(i + 1), "1"}, {"mode_frequency", f, "Hz"},
                 {"relative_offset", *near, "1"}, {"band", kResonanceBand, "1"}};
    out.push_back(w);
  }
  return out;
}

std::optional<core::Warning> steady_warning(const rigid::SteadyOperation& s, const rigid::SteadyCriterion& c, double duration) {
  if (s.reached_at) return std::nullopt;
  core::Warning w;
  w.code = "steady_not_reached";
  const double periods = s.shaker_period > 0 ? duration / s.shaker_period : 0.0;
  if (!s.enough_data) {
    w.message = fmt::format("steady operation cannot be judged: the run lasts {:.4g} s ({:.3g} shaker periods), fewer than the {} + 1 "
                            "periods the comparison needs; every peak reported is a start-up peak. Run longer",
                            duration, periods, c.window_periods);
  } else {
    w.message = fmt::format("steady operation not reached in {:.4g} s ({:.3g} shaker periods): over the last {} periods {} still changes "
                            "by {:.3g} % of its scale between one cycle and the next (a cycle of {} shaker period{}, the closest of the cycles of 1 to {} "
                            "periods this run can show, of up to {}; tolerance {:g} %); every peak reported is a start-up peak. Run longer, or "
                            "the motion does not settle",
                            duration, periods, c.window_periods, s.leading_signal, 100.0 * s.remaining_change, s.remaining_period_multiple,
                            s.remaining_period_multiple == 1 ? "" : "s", s.largest_multiple_tried, c.max_period_multiple, 100.0 * c.tolerance);
  }
  w.figures = {{"remaining_change", s.remaining_change, "1"}, {"period_multiple", static_cast<double>(s.remaining_period_multiple), "1"},
               {"tolerance", c.tolerance, "1"}, {"duration", duration, "s"}, {"shaker_periods", periods, "1"}};
  // The trend of the change (Eq. 17.2): a transient still dying out, with when
  // it would be over, or a change that does not shrink.
  if (s.enough_data && s.trend_span > 0) {
    w.figures.push_back({"earlier_change", s.trend_earlier_change, "1"});
    w.figures.push_back({"trend_span", s.trend_span, "s"});
    if (s.projected_reached_at) {
      w.figures.push_back({"change_time_constant", 1.0 / s.change_decay_rate, "s"});
      const double needed = *s.projected_reached_at + (c.window_periods + s.remaining_period_multiple) * s.shaker_period;
      w.message += fmt::format(". The change still shrinks ({:.3g} % {:.3g} s earlier; as exp(-t / {:.3g} s)): at that rate steady "
                               "operation from about {:.3g} s, shown by a run of at least {:.3g} s (an extrapolation from a cycle of {} period{}: a "
                               "longer cycle or a slower mode may show only in the longer run)",
                               100.0 * s.trend_earlier_change, s.trend_span, 1.0 / s.change_decay_rate, *s.projected_reached_at, needed,
                               s.remaining_period_multiple, s.remaining_period_multiple == 1 ? "" : "s");
      w.figures.push_back({"projected_reached_at", *s.projected_reached_at, "s"});
      w.figures.push_back({"projected_duration_needed", needed, "s"});
    } else {
      w.message += fmt::format(". The change does not shrink, or more slowly than over the run's length ({:.3g} % {:.3g} s earlier): "
                               "the motion may not settle at any multiple "
                               "up to {} (a drift, a longer cycle, a torus or an irregular motion); the start-up peaks are those of the whole run",
                               100.0 * s.trend_earlier_change, s.trend_span, s.largest_multiple_tried);
    }
  }
  return w;
}

}  // namespace framedyn::coupling
