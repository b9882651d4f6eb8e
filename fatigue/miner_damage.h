// Palmgren-Miner damage of counted cycles and the equivalent constant-amplitude range
// (docs/theory/fatigue.md, section 5, Eqs. F.11-F.13): D = sum_i n_i / N(S_i) with S_i the
// (mean-stress corrected) range of cycle i; the equivalent range S_eq at N_ref = 2e6 is the
// range whose 2e6 cycles do the damage D: N(S_eq) = N_ref / D, the inverse of the curve
// (closed form on every straight piece; for a one-slope curve S_eq = (sum n_i S_i^m / N_ref)^(1/m)).
#pragma once

#include <optional>

#include "fatigue/mean_stress.h"
#include "fatigue/rainflow.h"
#include "fatigue/sn_curve.h"

namespace framedyn::fatigue {

// Sums the damage of the cycles it receives (a CycleSink, so it streams).
class MinerDamage : public CycleSink {
 public:
  // pascals_per_unit: what one unit of the counted history is in Pa (1e6 for MPa).
  MinerDamage(SnCurve curve, double pascals_per_unit, MeanStressCorrection mean_stress = MeanStressCorrection::none());
  void add(double range, double mean, double count) override;
  double damage() const { return damage_; }
  const SnCurve& curve() const { return curve_; }

 private:
  SnCurve curve_;
  double pascals_per_unit_;
  MeanStressCorrection mean_stress_;
  double damage_ = 0.0;
};

// S_eq (Pa) of damage D at n_ref cycles: nullopt where no range has that damage (a curve
// with a cut-off and D below n_ref / N at the cut-off); 0 for D = 0 on a one-slope curve.
std::optional<double> equivalent_range(const SnCurve& curve, double damage, double n_ref = kReferenceCycles);

}  // namespace framedyn::fatigue
