// Mean-stress correction of a cycle's range (docs/theory/fatigue.md, section 4, Eq. F.10).
// none: as-welded details, whose S-N curves hold for any mean stress (IIW and EN 1993-1-9
// assume high tensile residual stresses); Goodman, for base metal: a cycle of range S and
// tensile mean S_m does the damage of a zero-mean cycle of range S / (1 - S_m / S_u), with
// S_u the ultimate tensile strength; a compressive mean is not credited (range unchanged).
#pragma once

#include <string>

namespace framedyn::fatigue {

class MeanStressCorrection {
 public:
  static MeanStressCorrection none() { return MeanStressCorrection(); }
  // Throws std::invalid_argument unless S_u > 0 (Pa).
  static MeanStressCorrection goodman(double ultimate_strength_pa);

  // The zero-mean range equivalent to (range, mean), both in Pa; throws core::NumericalError
  // for a tensile mean at or above S_u (the cycle breaks the part at once).
  double equivalent_range(double range_pa, double mean_pa) const;
  bool is_none() const { return ultimate_strength_pa_ == 0.0; }
  std::string describe() const;  // "none (as-welded)" or "Goodman, S_u = 400 MPa"

 private:
  double ultimate_strength_pa_ = 0.0;  // 0: no correction
};

}  // namespace framedyn::fatigue
