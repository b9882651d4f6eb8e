// Range-mean histogram; see range_mean_histogram.h.
#include "fatigue/range_mean_histogram.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace framedyn::fatigue {

namespace {

void check_edges(const std::vector<double>& e, const char* what) {
  if (e.size() < 2) throw std::invalid_argument(std::string("histogram: at least two ") + what + " edges are needed");
  for (std::size_t i = 0; i < e.size(); ++i) {
    if (!std::isfinite(e[i])) throw std::invalid_argument(std::string("histogram: ") + what + " edges must be finite");
    if (i > 0 && !(e[i] > e[i - 1])) throw std::invalid_argument(std::string("histogram: ") + what + " edges must increase");
  }
}

// Bin of v among edges e, or -1 outside [e.front(), e.back()].
long bin_of(const std::vector<double>& e, double v) {
  if (!(v >= e.front() && v <= e.back())) return -1;
  if (v == e.back()) return static_cast<long>(e.size()) - 2;
  return static_cast<long>(std::upper_bound(e.begin(), e.end(), v) - e.begin()) - 1;
}

}  // namespace

RangeMeanHistogram::RangeMeanHistogram(std::vector<double> range_edges, std::vector<double> mean_edges)
    : range_edges_(std::move(range_edges)), mean_edges_(std::move(mean_edges)) {
  check_edges(range_edges_, "range");
  check_edges(mean_edges_, "mean");
  counts_.assign((range_edges_.size() - 1) * (mean_edges_.size() - 1), 0.0);
}

void RangeMeanHistogram::add(double range, double mean, double count) {
  const long i = bin_of(range_edges_, range), j = bin_of(mean_edges_, mean);
  if (i < 0 || j < 0) {
    outside_ += count;
    return;
  }
  counts_[static_cast<std::size_t>(i) * (mean_edges_.size() - 1) + static_cast<std::size_t>(j)] += count;
}

double RangeMeanHistogram::total() const { return std::accumulate(counts_.begin(), counts_.end(), 0.0); }

}  // namespace framedyn::fatigue
