// Rainflow counting, ASTM E1049-85 §5.4.4; see rainflow.h and docs/theory/fatigue.md section 1.
#include "fatigue/rainflow.h"

#include <cmath>

namespace framedyn::fatigue {

std::string describe(Residue r) {
  return r == Residue::half_cycles ? "half cycles (ASTM E1049-85 5.4.4 step 6)"
                                   : "repeated block (history closed at its absolute maximum)";
}

void RainflowCounter::push(double x) {
  if (samples_++ == 0) {  // the first sample is the starting point S
    turning_point(x);
    last_ = x;
    return;
  }
  if (x == last_) return;  // a plateau is one turning point
  const int d = x > last_ ? 1 : -1;
  if (direction_ != 0 && d != direction_) turning_point(last_);  // a reversal: the last sample was a peak or a valley
  direction_ = d;
  last_ = x;
}

void RainflowCounter::emit(double a, double b, double count) {
  const double range = std::abs(a - b);
  sink_.add(range, 0.5 * (a + b), count);
  cycles_ += count;
  if (range > max_range_) max_range_ = range;
}

// Steps 2-5 of §5.4.4 after each new peak or valley. X is the most recent range, Y the one
// before it; Y contains the starting point S exactly when only three points remain.
void RainflowCounter::turning_point(double x) {
  ++turning_points_;
  stack_.push_back(x);
  while (stack_.size() >= 3) {
    const std::size_t n = stack_.size();
    const double X = std::abs(stack_[n - 1] - stack_[n - 2]);
    const double Y = std::abs(stack_[n - 2] - stack_[n - 3]);
    if (X < Y) break;  // step 3(a): read the next point
    if (n == 3 && !closed_) {
      // Step 5: Y contains S: half a cycle; S moves to Y's second point.
      emit(stack_[0], stack_[1], 0.5);
      stack_.erase(stack_.begin());
    } else {
      // Step 4 (and, in a block closed at its extreme, Y at S too: it closes at the block's end).
      emit(stack_[n - 3], stack_[n - 2], 1.0);
      stack_[n - 3] = stack_[n - 1];  // Y's two points go; X's end stays
      stack_.resize(n - 2);
    }
  }
}

RainflowSummary RainflowCounter::finish() {
  if (direction_ != 0) turning_point(last_);  // the last sample ends the history
  // Step 6: every range not yet counted is half a cycle (none is left of a closed block).
  for (std::size_t i = 0; i + 1 < stack_.size(); ++i) emit(stack_[i], stack_[i + 1], 0.5);
  stack_.clear();
  RainflowSummary s;
  s.residue = closed_ ? Residue::repeated_block : Residue::half_cycles;
  s.samples = samples_;
  s.turning_points = turning_points_;
  s.cycles = cycles_;
  s.max_range = max_range_;
  return s;
}

RainflowSummary count_cycles(const std::vector<double>& history, Residue residue, CycleSink& sink) {
  RainflowCounter counter(sink);
  if (residue == Residue::half_cycles || history.empty()) {
    for (double x : history) counter.push(x);
    RainflowSummary s = counter.finish();
    s.residue = residue;
    return s;
  }
  // Repeated block (F.3): start at the absolute maximum (the lowest index among exact
  // ties, so the start does not depend on round-off), run once round, end there again.
  // Starting at the extreme, no range Y at S can be smaller than the X after it.
  std::size_t k = 0;
  for (std::size_t i = 1; i < history.size(); ++i)
    if (std::abs(history[i]) > std::abs(history[k])) k = i;
  counter.closed_ = true;
  for (std::size_t i = k; i < history.size(); ++i) counter.push(history[i]);
  for (std::size_t i = 0; i <= k; ++i) counter.push(history[i]);
  RainflowSummary s = counter.finish();
  s.samples = history.size();  // the closing sample is not a sample of the history
  return s;
}

}  // namespace framedyn::fatigue
