// One stress history counted and, with an S-N curve, its Palmgren-Miner damage:
// what `framedyn rainflow` and the Python module's framedyn.rainflow compute
// (docs/theory/fatigue.md, Eqs. F.1-F.3 for the count, the damage sum and the
// equivalent range at 2e6 cycles of its section on Miner's rule). As-welded
// details: no mean-stress correction.
#pragma once

#include <optional>
#include <vector>

#include "fatigue/rainflow.h"
#include "fatigue/sn_curve.h"

namespace framedyn::fatigue {

struct CountedHistory {
  RainflowSummary summary;
  std::vector<Cycle> cycles;                // in the history's unit
  std::optional<double> damage;             // with a curve
  std::optional<double> equivalent_range;   // with a curve and damage above the cut-off's; in the history's unit
};

// pascals_per_unit: what one unit of `history` is in Pa (1e6 for MPa).
CountedHistory count_history(const std::vector<double>& history, Residue residue, const std::optional<SnCurve>& curve,
                             double pascals_per_unit);

}  // namespace framedyn::fatigue
