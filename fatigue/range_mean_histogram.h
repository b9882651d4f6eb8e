// Range-mean histogram of rainflow cycles (a CycleSink): the caller gives the bin edges
// of range and of mean, in the history's unit, increasing. A cycle falls in bin
// [edge_i, edge_i+1) (the last bin includes its upper edge); cycles outside every bin
// are summed in `outside` so that nothing is lost unseen (docs/theory/fatigue.md, section 2).
#pragma once

#include <vector>

#include "fatigue/rainflow.h"

namespace framedyn::fatigue {

class RangeMeanHistogram : public CycleSink {
 public:
  // Throws std::invalid_argument unless each edge list has >= 2 finite, strictly increasing values.
  RangeMeanHistogram(std::vector<double> range_edges, std::vector<double> mean_edges);
  void add(double range, double mean, double count) override;

  const std::vector<double>& range_edges() const { return range_edges_; }
  const std::vector<double>& mean_edges() const { return mean_edges_; }
  // Count in range bin i, mean bin j.
  double count(std::size_t i, std::size_t j) const { return counts_[i * (mean_edges_.size() - 1) + j]; }
  double outside() const { return outside_; }
  double total() const;  // every count in the bins (not `outside`)

 private:
  std::vector<double> range_edges_, mean_edges_, counts_;
  double outside_ = 0.0;
};

}  // namespace framedyn::fatigue
