// The samples of a design study (docs/theory/coupling.md section 13):
//   grid             every combination of the parameters' `values` (full factorial),
//                    the first parameter varying slowest;
//   latin_hypercube  n samples; each parameter's range cut into n strata of equal
//                    probability, each stratum sampled exactly once (Eq. 13.1);
//   monte_carlo      n independent samples from each parameter's distribution.
// Uniform numbers come from std::mt19937_64 (fully specified by the C++ standard)
// as u = (k + 0.5) / 2^53 with k its top 53 bits; distributions by the inverse of
// their CDF written here (never std::*_distribution, whose algorithms the standard
// leaves open), so that a seed gives the same samples on every platform.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace framedyn::batch {

enum class Distribution { uniform, normal, lognormal, truncated_normal };

// One varied parameter. Either `values` (grid) or a distribution:
//   uniform           on [low, high];
//   normal            mean, std_dev;
//   lognormal         the variable's own median and the std_dev of its log (log_std);
//   truncated_normal  mean, std_dev, cut to [low, high].
struct ParameterSpec {
  std::string key;
  std::vector<double> values;
  Distribution distribution = Distribution::uniform;
  double low = 0.0, high = 0.0, mean = 0.0, std_dev = 0.0, median = 0.0, log_std = 0.0;
};

enum class SamplingMethod { grid, latin_hypercube, monte_carlo };

struct Sampling {
  SamplingMethod method = SamplingMethod::grid;
  std::size_t samples = 0;  // latin_hypercube, monte_carlo
  std::uint64_t seed = 1;
};

// The standard normal's inverse CDF (Acklam's rational approximation refined by
// one Halley step on an erfc written here; |error| < 1e-13 for p in (0, 1)).
double standard_normal_quantile(double p);
double standard_normal_cdf(double z);

// The parameter's value at probability p in (0, 1) (its inverse CDF).
double quantile(const ParameterSpec& p, double u);

// The design's samples: one row per run, one value per parameter, in run order.
std::vector<std::vector<double>> draw_samples(const Sampling& s, const std::vector<ParameterSpec>& params);

// The stratum (0 .. n-1) of probability u among n equal strata.
std::size_t stratum_of(double u, std::size_t n);
// A parameter's probability for a value (its CDF), to check strata in tests.
double cdf(const ParameterSpec& p, double x);

}  // namespace framedyn::batch
