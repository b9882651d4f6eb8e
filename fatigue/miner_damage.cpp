// Palmgren-Miner damage and the equivalent range; see miner_damage.h and docs/theory/fatigue.md section 5.
#include "fatigue/miner_damage.h"

#include <cmath>
#include <stdexcept>

namespace framedyn::fatigue {

MinerDamage::MinerDamage(SnCurve curve, double pascals_per_unit, MeanStressCorrection mean_stress)
    : curve_(std::move(curve)), pascals_per_unit_(pascals_per_unit), mean_stress_(mean_stress) {
  if (!(pascals_per_unit_ > 0.0) || !std::isfinite(pascals_per_unit_)) throw std::invalid_argument("Miner damage: the history's unit must be a positive number of Pa");
}

void MinerDamage::add(double range, double mean, double count) {
  const double s = mean_stress_.equivalent_range(range * pascals_per_unit_, mean * pascals_per_unit_);
  const double n = curve_.cycles_to_failure(s);
  if (std::isfinite(n)) damage_ += count / n;  // F.11; below a cut-off: no damage
}

std::optional<double> equivalent_range(const SnCurve& curve, double damage, double n_ref) {
  if (!(damage >= 0.0) || !std::isfinite(damage)) return std::nullopt;
  if (damage == 0.0) return curve.single_slope() ? std::optional<double>(0.0) : std::nullopt;
  return curve.range_at(n_ref / damage);  // F.12-F.13
}

}  // namespace framedyn::fatigue
