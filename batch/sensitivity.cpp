// Standardised regression coefficients and Spearman rank correlations; see sensitivity.h.
#include "batch/sensitivity.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace framedyn::batch {

namespace {

// (v - mean) / standard deviation; false if v does not vary.
bool standardise(Eigen::VectorXd& v) {
  const double n = static_cast<double>(v.size());
  const double mean = v.sum() / n;
  v.array() -= mean;
  const double sd = std::sqrt(v.squaredNorm() / (n - 1.0));
  if (!(sd > 1e-300) || sd <= 1e-12 * std::abs(mean)) return false;
  v /= sd;
  return true;
}

double pearson(Eigen::VectorXd a, Eigen::VectorXd b) {
  a.array() -= a.mean();
  b.array() -= b.mean();
  return a.dot(b) / std::sqrt(a.squaredNorm() * b.squaredNorm());
}

}  // namespace

std::optional<std::vector<double>> standardised_regression_coefficients(const std::vector<std::vector<double>>& x, const std::vector<double>& y) {
  const std::size_t n = y.size();
  if (n == 0) return std::nullopt;
  const std::size_t p = x.front().size();
  if (n < p + 2) return std::nullopt;
  Eigen::VectorXd ys = Eigen::Map<const Eigen::VectorXd>(y.data(), static_cast<Eigen::Index>(n));
  if (!standardise(ys)) return std::nullopt;
  std::vector<std::size_t> varying;
  Eigen::MatrixXd xs(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(p));
  for (std::size_t j = 0; j < p; ++j) {
    Eigen::VectorXd c(static_cast<Eigen::Index>(n));
    for (std::size_t r = 0; r < n; ++r) c(static_cast<Eigen::Index>(r)) = x[r][j];
    if (standardise(c)) {
      xs.col(static_cast<Eigen::Index>(varying.size())) = c;
      varying.push_back(j);
    }
  }
  std::vector<double> beta(p, 0.0);
  if (varying.empty()) return beta;
  const Eigen::MatrixXd a = xs.leftCols(static_cast<Eigen::Index>(varying.size()));
  const Eigen::VectorXd b = a.colPivHouseholderQr().solve(ys);
  for (std::size_t k = 0; k < varying.size(); ++k) beta[varying[k]] = b(static_cast<Eigen::Index>(k));
  return beta;
}

std::vector<double> average_ranks(const std::vector<double>& v) {
  std::vector<std::size_t> order(v.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return v[a] < v[b]; });
  std::vector<double> rank(v.size());
  for (std::size_t i = 0; i < order.size();) {
    std::size_t j = i;
    while (j + 1 < order.size() && v[order[j + 1]] == v[order[i]]) ++j;
    const double r = 0.5 * static_cast<double>(i + j) + 1.0;  // the average of ranks i+1 .. j+1
    for (std::size_t k = i; k <= j; ++k) rank[order[k]] = r;
    i = j + 1;
  }
  return rank;
}

std::optional<double> spearman(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() < 3 || a.size() != b.size()) return std::nullopt;
  const std::vector<double> ra = average_ranks(a), rb = average_ranks(b);
  const Eigen::Map<const Eigen::VectorXd> va(ra.data(), static_cast<Eigen::Index>(ra.size())), vb(rb.data(), static_cast<Eigen::Index>(rb.size()));
  if (va.maxCoeff() == va.minCoeff() || vb.maxCoeff() == vb.minCoeff()) return std::nullopt;
  return pearson(va, vb);
}

std::vector<std::size_t> ranking(const std::vector<double>& c) {
  double top = 0.0;
  for (double v : c) top = std::max(top, std::abs(v));
  const double tol = 1e-6 * top;
  // Repeatedly the lowest index among those within tol of the largest left: a stable rule, not a float tie.
  std::vector<std::size_t> left(c.size()), order;
  std::iota(left.begin(), left.end(), 0);
  while (!left.empty()) {
    double best = 0.0;
    for (std::size_t k : left) best = std::max(best, std::abs(c[k]));
    const auto it = std::find_if(left.begin(), left.end(), [&](std::size_t k) { return std::abs(c[k]) >= best - tol; });
    order.push_back(*it);
    left.erase(it);
  }
  return order;
}

}  // namespace framedyn::batch
