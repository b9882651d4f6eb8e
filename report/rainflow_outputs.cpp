// cycles.csv and summary.json of `framedyn rainflow`; see rainflow_outputs.h.
#include "report/rainflow_outputs.h"

#include <nlohmann/json.hpp>

#include "report/csv_writer.h"

namespace framedyn::report {

void write_rainflow_results(const RainflowRun& run, const core::ResultsFolder& folder) {
  CsvTable cycles({column("range", run.unit), column("mean", run.unit), "count"});
  for (const fatigue::Cycle& c : run.cycles) cycles.row().add(c.range).add(c.mean).add(c.count);
  folder.write_text("cycles.csv", cycles.str());

  nlohmann::ordered_json j;
  j["framedyn"] = {{"version", FRAMEDYN_VERSION}, {"command", "rainflow"}};
  j["input"] = {{"series", run.series_file}, {"column", run.column}, {"unit", run.unit}, {"samples", run.summary.samples}};
  j["rainflow"] = {{"cycles", run.summary.cycles},
                   {"max_range", {{"value", run.summary.max_range}, {"unit", run.unit}}},
                   {"turning_points", run.summary.turning_points},
                   {"residue", fatigue::describe(run.summary.residue)},
                   {"standard", "ASTM E1049-85 5.4.4"}};
  if (run.curve) {
    // No value where no range has that damage in 2e6 cycles (a curve with a cut-off: any range at or
    // above it does more, any below none); a null would be refused as a broken-down number.
    nlohmann::ordered_json eq;
    if (run.equivalent_range) eq["value"] = *run.equivalent_range;
    eq["unit"] = run.unit;
    eq["cycles"] = fatigue::kReferenceCycles;
    if (!run.equivalent_range) eq["none"] = "no range does this damage in 2e6 cycles: at or above the curve's cut-off any does more, below it none";
    j["fatigue"] = {{"code", run.curve->code()},
                    {"curve", run.curve->name()},
                    {"mean_stress", run.mean_stress},
                    {"damage", run.damage},
                    {"equivalent_range", eq}};
  }
  folder.write_text("summary.json", j.dump(2) + "\n");
}

}  // namespace framedyn::report
