// Grid, Latin hypercube and Monte Carlo samples; see sampling.h and
// docs/theory/coupling.md section 13 (Eqs. 13.1-13.4).
#include "batch/sampling.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

namespace framedyn::batch {

namespace {

// u in (0, 1) from the generator's top 53 bits, never 0 or 1 (Eq. 13.2).
double uniform01(std::mt19937_64& g) { return (static_cast<double>(g() >> 11) + 0.5) / 9007199254740992.0; }

// erfc by its continued fraction / series (Numerical Recipes' erfcc is too coarse):
// Chebyshev-free form from W. J. Cody's rational approximations would be longer; a
// Taylor series for |x| < 2 and a continued fraction beyond give 1e-15 relative.
double erfc_own(double x) {
  if (x < 0.0) return 2.0 - erfc_own(-x);
  if (x < 2.0) {
    // erf(x) = 2/sqrt(pi) * sum_n (-1)^n x^(2n+1) / (n! (2n+1))
    double term = x, sum = x;
    for (int n = 1; n < 60; ++n) {
      term *= -x * x / n;
      const double add = term / (2 * n + 1);
      sum += add;
      if (std::abs(add) < 1e-17 * std::abs(sum)) break;
    }
    return 1.0 - 1.1283791670955126 * sum;
  }
  // Continued fraction (Lentz): erfc(x) = exp(-x^2)/sqrt(pi) * 1/(x + 1/2/(x + 1/(x + 3/2/(x + ...))))
  double f = x, c = x, d = 0.0;
  for (int n = 1; n < 200; ++n) {
    const double a = n * 0.5;
    d = x + a * d;
    d = d == 0.0 ? 1e-300 : 1.0 / d;
    c = x + a / c;
    if (c == 0.0) c = 1e-300;
    const double delta = c * d;
    f *= delta;
    if (std::abs(delta - 1.0) < 1e-16) break;
  }
  return std::exp(-x * x) / (f * 1.7724538509055160);
}

}  // namespace

double standard_normal_cdf(double z) { return 0.5 * erfc_own(-z / 1.4142135623730951); }

double standard_normal_quantile(double p) {
  if (!(p > 0.0 && p < 1.0)) throw std::invalid_argument("standard_normal_quantile: p must be in (0, 1)");
  // Acklam's coefficients.
  static const double a[] = {-3.969683028665376e+01, 2.209460984245205e+02, -2.759285104469687e+02, 1.383577518672690e+02, -3.066479806614716e+01,
                             2.506628277459239e+00};
  static const double b[] = {-5.447609879822406e+01, 1.615858368580409e+02, -1.556989798598866e+02, 6.680131188771972e+01, -1.328068155288572e+01};
  static const double c[] = {-7.784894002430293e-03, -3.223964580411365e-01, -2.400758277161838e+00, -2.549732539343734e+00, 4.374664141464968e+00,
                             2.938163982698783e+00};
  static const double d[] = {7.784695709041462e-03, 3.224671290700398e-01, 2.445134137142996e+00, 3.754408661907416e+00};
  const double lo = 0.02425, hi = 1.0 - lo;
  double x;
  if (p < lo) {
    const double q = std::sqrt(-2.0 * std::log(p));
    x = (((((c[0] * q + c[1]) * q + c[2]) * q + c[3]) * q + c[4]) * q + c[5]) / ((((d[0] * q + d[1]) * q + d[2]) * q + d[3]) * q + 1.0);
  } else if (p <= hi) {
    const double q = p - 0.5, r = q * q;
    x = (((((a[0] * r + a[1]) * r + a[2]) * r + a[3]) * r + a[4]) * r + a[5]) * q /
        (((((b[0] * r + b[1]) * r + b[2]) * r + b[3]) * r + b[4]) * r + 1.0);
  } else {
    const double q = std::sqrt(-2.0 * std::log(1.0 - p));
    x = -(((((c[0] * q + c[1]) * q + c[2]) * q + c[3]) * q + c[4]) * q + c[5]) / ((((d[0] * q + d[1]) * q + d[2]) * q + d[3]) * q + 1.0);
  }
  // One Halley step (Eq. 13.3): relative error 1.15e-9 -> about 1e-15.
  const double e = standard_normal_cdf(x) - p;
  const double u = e * 2.5066282746310002 * std::exp(0.5 * x * x);
  return x - u / (1.0 + 0.5 * x * u);
}

double quantile(const ParameterSpec& p, double u) {
  switch (p.distribution) {
    case Distribution::uniform: return p.low + u * (p.high - p.low);
    case Distribution::normal: return p.mean + p.std_dev * standard_normal_quantile(u);
    case Distribution::lognormal: return p.median * std::exp(p.log_std * standard_normal_quantile(u));
    case Distribution::truncated_normal: {
      // Eq. 13.4: the normal's CDF mapped onto [F(low), F(high)].
      const double fl = standard_normal_cdf((p.low - p.mean) / p.std_dev), fh = standard_normal_cdf((p.high - p.mean) / p.std_dev);
      const double v = p.mean + p.std_dev * standard_normal_quantile(fl + u * (fh - fl));
      return std::clamp(v, p.low, p.high);
    }
  }
  return 0.0;
}

double cdf(const ParameterSpec& p, double x) {
  switch (p.distribution) {
    case Distribution::uniform: return (x - p.low) / (p.high - p.low);
    case Distribution::normal: return standard_normal_cdf((x - p.mean) / p.std_dev);
    case Distribution::lognormal: return standard_normal_cdf(std::log(x / p.median) / p.log_std);
    case Distribution::truncated_normal: {
      const double fl = standard_normal_cdf((p.low - p.mean) / p.std_dev), fh = standard_normal_cdf((p.high - p.mean) / p.std_dev);
      return (standard_normal_cdf((x - p.mean) / p.std_dev) - fl) / (fh - fl);
    }
  }
  return 0.0;
}

std::size_t stratum_of(double u, std::size_t n) {
  const double k = std::floor(u * static_cast<double>(n));
  return static_cast<std::size_t>(std::clamp(k, 0.0, static_cast<double>(n - 1)));
}

std::vector<std::vector<double>> draw_samples(const Sampling& s, const std::vector<ParameterSpec>& params) {
  std::vector<std::vector<double>> rows;
  if (s.method == SamplingMethod::grid) {
    std::size_t total = params.empty() ? 0 : 1;
    for (const ParameterSpec& p : params) total *= p.values.size();
    for (std::size_t r = 0; r < total; ++r) {
      std::vector<double> row(params.size());
      std::size_t rest = r;
      for (std::size_t j = params.size(); j-- > 0;) {  // the last parameter varies fastest
        row[j] = params[j].values[rest % params[j].values.size()];
        rest /= params[j].values.size();
      }
      rows.push_back(row);
    }
    return rows;
  }
  std::mt19937_64 g(s.seed);
  const std::size_t n = s.samples;
  rows.assign(n, std::vector<double>(params.size()));
  if (s.method == SamplingMethod::monte_carlo) {
    for (std::size_t r = 0; r < n; ++r)
      for (std::size_t j = 0; j < params.size(); ++j) rows[r][j] = quantile(params[j], uniform01(g));
    return rows;
  }
  // Latin hypercube (Eq. 13.1): for each parameter a random permutation of the
  // strata (Fisher-Yates on the generator's own integers, never std::shuffle,
  // whose algorithm is the library's) and a uniform position inside each.
  for (std::size_t j = 0; j < params.size(); ++j) {
    std::vector<std::size_t> perm(n);
    for (std::size_t k = 0; k < n; ++k) perm[k] = k;
    for (std::size_t k = n; k > 1; --k) {
      const std::size_t pick = static_cast<std::size_t>(g() % k);  // modulo bias below 1e-17 for n < 1e3
      std::swap(perm[k - 1], perm[pick]);
    }
    for (std::size_t r = 0; r < n; ++r) rows[r][j] = quantile(params[j], (static_cast<double>(perm[r]) + uniform01(g)) / static_cast<double>(n));
  }
  return rows;
}

}  // namespace framedyn::batch
