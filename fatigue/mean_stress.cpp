// Mean-stress correction (Goodman); see mean_stress.h and docs/theory/fatigue.md section 4.
#include "fatigue/mean_stress.h"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "core/error.h"

namespace framedyn::fatigue {

MeanStressCorrection MeanStressCorrection::goodman(double su) {
  if (!(su > 0.0) || !std::isfinite(su)) throw std::invalid_argument("Goodman correction: the ultimate strength must be positive");
  MeanStressCorrection c;
  c.ultimate_strength_pa_ = su;
  return c;
}

double MeanStressCorrection::equivalent_range(double range, double mean) const {
  if (is_none() || mean <= 0.0) return range;
  if (mean >= ultimate_strength_pa_)
    throw core::NumericalError(fmt::format("Goodman correction: a cycle's mean stress {:g} MPa reaches the ultimate strength {:g} MPa", mean / 1e6,
                                           ultimate_strength_pa_ / 1e6));
  return range / (1.0 - mean / ultimate_strength_pa_);  // F.10
}

std::string MeanStressCorrection::describe() const {
  return is_none() ? "none (as-welded)" : fmt::format("Goodman, S_u = {:g} MPa", ultimate_strength_pa_ / 1e6);
}

}  // namespace framedyn::fatigue
