// Rainflow counting against ASTM E1049-85 (docs/validation.md V14.1, V14.2): the
// standard's worked example (Fig. 6) counted event by event, the same history closed as
// a repeated block counted by hand, a repeated block's count invariant under rotation of
// its start point, turning points (plateaus, monotone runs) and the range-mean histogram.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <tuple>
#include <vector>

#include "fatigue/rainflow.h"
#include "fatigue/range_mean_histogram.h"

namespace {

using namespace framedyn::fatigue;

// The history of ASTM E1049-85 Fig. 6(a) (peaks and valleys in "units").
const std::vector<double> kAstmFig6 = {-2, 1, -3, 5, -1, 3, -4, 4, -2};

// Range -> total count, as the standard's Fig. 6(f) table lists them.
double count_of(const std::vector<Cycle>& cycles, double range) {
  double n = 0.0;
  for (const Cycle& c : cycles)
    if (c.range == range) n += c.count;
  return n;
}

TEST(AstmE1049, WorkedExampleFig6CountsAsTheStandardLists) {
  CycleList list;
  const RainflowSummary s = count_cycles(kAstmFig6, Residue::half_cycles, list);
  // Fig. 6(f): range 10: 0, 9: 0.5, 8: 1.0, 7: 0, 6: 0.5, 5: 0, 4: 1.5, 3: 0.5 (4 cycles in all).
  const std::vector<std::pair<double, double>> table = {{10, 0}, {9, 0.5}, {8, 1.0}, {7, 0}, {6, 0.5}, {5, 0}, {4, 1.5}, {3, 0.5}, {2, 0}, {1, 0}};
  for (const auto& [range, count] : table) EXPECT_EQ(count_of(list.cycles, range), count) << "range " << range;
  EXPECT_EQ(s.cycles, 4.0);
  EXPECT_EQ(s.max_range, 9.0);
  EXPECT_EQ(s.turning_points, 9u);
  // Event by event, Fig. 6(b)-(e): the half cycles -2..1 and 1..-3 (Y holds S), the full cycle
  // -1..3, the half cycle -3..5, then the residue 5..-4, -4..4, 4..-2 as half cycles.
  const std::vector<Cycle> events = {{3, -0.5, 0.5}, {4, -1, 0.5}, {4, 1, 1.0}, {8, 1, 0.5}, {9, 0.5, 0.5}, {8, 0, 0.5}, {6, 1, 0.5}};
  ASSERT_EQ(list.cycles.size(), events.size());
  for (std::size_t i = 0; i < events.size(); ++i) {
    EXPECT_EQ(list.cycles[i].range, events[i].range) << "event " << i;
    EXPECT_EQ(list.cycles[i].mean, events[i].mean) << "event " << i;
    EXPECT_EQ(list.cycles[i].count, events[i].count) << "event " << i;
  }
}

TEST(AstmE1049, SamplesBetweenTurningPointsAndPlateausDoNotChangeTheCount) {
  // Fig. 6's history sampled finely (straight lines between its points, repeated samples
  // at every peak): only the peaks and valleys count.
  std::vector<double> fine;
  for (std::size_t i = 0; i + 1 < kAstmFig6.size(); ++i)
    for (int k = 0; k < 4; ++k) fine.push_back(kAstmFig6[i] + (kAstmFig6[i + 1] - kAstmFig6[i]) * k / 4.0);
  fine.push_back(kAstmFig6.back());
  fine.insert(fine.begin() + 12, fine[12]);  // a plateau at the peak 5
  CycleList coarse, dense;
  count_cycles(kAstmFig6, Residue::half_cycles, coarse);
  const RainflowSummary s = count_cycles(fine, Residue::half_cycles, dense);
  EXPECT_EQ(s.turning_points, 9u);
  ASSERT_EQ(dense.cycles.size(), coarse.cycles.size());
  for (std::size_t i = 0; i < coarse.cycles.size(); ++i) EXPECT_EQ(dense.cycles[i].range, coarse.cycles[i].range);
}

TEST(AstmE1049, RepeatedBlockClosesEveryCycleCountedByHand) {
  // Fig. 6's history as a block repeated for ever, started at its absolute maximum 5:
  // 5,-1,3,-4,4,-2,-2,1,-3,5 closes the cycles -1..3 (4), -2..1 (3), 4..-3 (7), 5..-4 (9).
  CycleList list;
  const RainflowSummary s = count_cycles(kAstmFig6, Residue::repeated_block, list);
  EXPECT_EQ(s.residue, Residue::repeated_block);
  std::vector<double> ranges;
  for (const Cycle& c : list.cycles) {
    EXPECT_EQ(c.count, 1.0);
    ranges.push_back(c.range);
  }
  EXPECT_EQ(ranges, (std::vector<double>{4, 3, 7, 9}));
  EXPECT_EQ(s.cycles, 4.0);
}

std::vector<std::tuple<double, double, double>> sorted_cycles(const std::vector<double>& block) {
  CycleList list;
  count_cycles(block, Residue::repeated_block, list);
  std::vector<std::tuple<double, double, double>> out;
  for (const Cycle& c : list.cycles) out.emplace_back(c.range, c.mean, c.count);
  std::sort(out.begin(), out.end());
  return out;
}

TEST(RepeatedBlock, CountIsInvariantUnderRotationOfTheStartPoint) {
  // A block of 200 seeded random values (integers / 8, so that ranges and means are exact):
  // every rotation is the same periodic history, so the same cycles (exactly: each range is
  // the difference of the same two turning points).
  std::mt19937_64 gen(20261203);
  std::vector<double> block(200);
  for (double& x : block) x = static_cast<double>(static_cast<std::int64_t>(gen() % 1601) - 800) / 8.0;
  const auto reference = sorted_cycles(block);
  ASSERT_GT(reference.size(), 50u);
  for (std::size_t k = 1; k < block.size(); k += 7) {
    std::vector<double> rotated(block.begin() + static_cast<std::ptrdiff_t>(k), block.end());
    rotated.insert(rotated.end(), block.begin(), block.begin() + static_cast<std::ptrdiff_t>(k));
    EXPECT_EQ(sorted_cycles(rotated), reference) << "rotation by " << k;
  }
}

TEST(RangeMeanHistogram, BinsCyclesByRangeAndMeanAndKeepsThoseOutside) {
  RangeMeanHistogram h({0, 5, 10}, {-1, 0, 1});
  count_cycles(kAstmFig6, Residue::half_cycles, h);
  // Events of Fig. 6: (3,-0.5,.5) (4,-1,.5) (4,1,1) (8,1,.5) (9,.5,.5) (8,0,.5) (6,1,.5):
  // range bin 0 holds 3 and 4 (means -0.5, -1 -> bin 0; 1 -> bin 1), range bin 1 holds 6, 8, 8, 9.
  EXPECT_EQ(h.count(0, 0), 1.0);
  EXPECT_EQ(h.count(0, 1), 1.0);
  EXPECT_EQ(h.count(1, 0), 0.0);
  EXPECT_EQ(h.count(1, 1), 2.0);
  EXPECT_EQ(h.outside(), 0.0);
  RangeMeanHistogram narrow({0, 5}, {-1, 0});
  count_cycles(kAstmFig6, Residue::half_cycles, narrow);
  EXPECT_EQ(narrow.total(), 1.0);   // (3, -0.5) and (4, -1)
  EXPECT_EQ(narrow.outside(), 3.0);  // the other 3 of the 4 cycles
}

}  // namespace
