// summary.json's warnings list; see summary_warnings.h.
#include "report/summary_warnings.h"

namespace framedyn::report {

void add_warnings(nlohmann::ordered_json& summary, const std::vector<core::Warning>& warnings, const std::function<void(const core::Warning&)>& console) {
  if (!summary.contains("warnings")) summary["warnings"] = nlohmann::ordered_json::array();
  for (const core::Warning& w : warnings) {
    nlohmann::ordered_json jw = {{"code", w.code}, {"message", w.message}};
    if (!w.figures.empty()) {
      nlohmann::ordered_json figures = nlohmann::ordered_json::object();
      for (const core::WarningFigure& f : w.figures) figures[f.name] = {{"value", f.value}, {"unit", f.unit}};
      jw["figures"] = figures;
    }
    summary["warnings"].push_back(jw);
    if (console) console(w);
  }
}

}  // namespace framedyn::report
