// Rainflow cycle counting as ASTM E1049-85 (reapproved 2017) §5.4.4 defines it
// (docs/theory/fatigue.md, section 1, Eqs. F.1-F.3). The history is reduced to its
// turning points (peaks and valleys; the first and last samples count as turning
// points, a plateau as one), then ranges are counted with the standard's three-point
// rule. What is left at the end (the residue) is counted
//   - as half cycles (Residue::half_cycles, §5.4.4 step 6), or
//   - by closing the history as a repeated block (Residue::repeated_block): the
//     history is rotated to start at its absolute maximum |x| (the lowest sample index
//     among exactly equal ones) and closed at that point again, so that every cycle
//     closes and the count is that of the block repeated for ever (F.3).
// Counting streams: RainflowCounter holds only the turning points not yet counted
// (the residue, a few dozen for any real history) and hands each cycle to a
// CycleSink as it is found, so a history of 10^8 samples needs no memory of its own.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace framedyn::fatigue {

// How the residue of a history is counted.
enum class Residue { half_cycles, repeated_block };
// "half cycles (ASTM E1049-85 5.4.4 step 6)" or "repeated block (closed at the absolute maximum)".
std::string describe(Residue r);

// One counted range: range = |peak - valley| >= 0, mean = (peak + valley) / 2, both in the
// history's unit; count 1 (a full cycle) or 0.5 (a half cycle).
struct Cycle {
  double range = 0.0;
  double mean = 0.0;
  double count = 1.0;
};

// Receives cycles as they are counted (a list, a histogram, a damage sum).
class CycleSink {
 public:
  virtual ~CycleSink() = default;
  virtual void add(double range, double mean, double count) = 0;
};

// Keeps every cycle in counting order.
class CycleList : public CycleSink {
 public:
  void add(double range, double mean, double count) override { cycles.push_back({range, mean, count}); }
  std::vector<Cycle> cycles;
};

// What a count found besides its cycles.
struct RainflowSummary {
  Residue residue = Residue::half_cycles;
  std::size_t samples = 0;
  std::size_t turning_points = 0;
  double cycles = 0.0;     // total count (full cycles + half cycles / 2)
  double max_range = 0.0;  // largest counted range
};

// Streaming counter with half-cycle residue: push every sample in order, then finish().
class RainflowCounter {
 public:
  explicit RainflowCounter(CycleSink& sink) : sink_(sink) {}
  void push(double x);
  // Counts the residue as half cycles (step 6) and returns the summary; the counter is then spent.
  RainflowSummary finish();

 private:
  friend RainflowSummary count_cycles(const std::vector<double>&, Residue, CycleSink&);
  void turning_point(double x);
  void emit(double a, double b, double count);
  CycleSink& sink_;
  std::vector<double> stack_;  // turning points not yet counted; stack_[0] is the starting point S
  bool closed_ = false;        // repeated block: every range counts as a full cycle (S is the extreme)
  std::size_t samples_ = 0, turning_points_ = 0;
  double last_ = 0.0;
  int direction_ = 0;          // +1 rising, -1 falling, 0 not yet known
  double cycles_ = 0.0, max_range_ = 0.0;
};

// Counts a whole history (rotating it first for Residue::repeated_block).
RainflowSummary count_cycles(const std::vector<double>& history, Residue residue, CycleSink& sink);

}  // namespace framedyn::fatigue
