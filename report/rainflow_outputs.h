// The results of `framedyn rainflow` (docs/user-guide.md, "framedyn rainflow"):
// DIR/cycles.csv, one row per counted range in counting order ("range [unit]", "mean [unit]",
// "count": 1 or 0.5), and DIR/summary.json: rainflow.cycles (total count), rainflow.max_range
// {value, unit}, rainflow.residue, and with an S-N curve fatigue.code, fatigue.curve,
// fatigue.mean_stress, fatigue.damage and fatigue.equivalent_range {value (null where no
// range does that damage in 2e6 cycles), unit, cycles}. Units are those of the series.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/results_folder.h"
#include "fatigue/rainflow.h"
#include "fatigue/sn_curve.h"

namespace framedyn::report {

struct RainflowRun {
  std::string series_file, column, unit;
  std::vector<fatigue::Cycle> cycles;
  fatigue::RainflowSummary summary;
  // With an S-N curve:
  std::optional<fatigue::SnCurve> curve;
  std::string mean_stress;            // fatigue::MeanStressCorrection::describe()
  double damage = 0.0;
  std::optional<double> equivalent_range;  // in the series' unit
};

void write_rainflow_results(const RainflowRun& run, const core::ResultsFolder& folder);

}  // namespace framedyn::report
