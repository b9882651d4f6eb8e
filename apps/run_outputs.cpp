// rigid.contacts and the warnings list of summary.json: see run_outputs.h.
#include "apps/run_outputs.h"

#include "apps/progress.h"

#include <fmt/format.h>

#include <cstdio>

namespace framedyn::apps {

nlohmann::ordered_json contacts_json(const std::vector<coupling::ContactSummary>& contacts, const core::UnitSystem& units) {
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  const std::string f = units.label(core::Quantity::force);
  for (const coupling::ContactSummary& c : contacts)
    j[c.name] = {{"min_force", {{"value", units.from_si(c.min_force, core::Quantity::force)}, {"unit", f}}},
                 {"max_force", {{"value", units.from_si(c.max_force, core::Quantity::force)}, {"unit", f}}},
                 {"tension_fraction", c.tension_fraction},
                 {"lift_off_fraction", c.lift_off_fraction}};
  return j;
}

void add_warnings(nlohmann::ordered_json& summary, const std::vector<core::Warning>& warnings) {
  if (!summary.contains("warnings")) summary["warnings"] = nlohmann::ordered_json::array();
  for (const core::Warning& w : warnings) {
    summary["warnings"].push_back({{"code", w.code}, {"message", w.message}});
    if (!quiet_console()) fmt::print(stderr, "framedyn: warning [{}]: {}\n", w.code, w.message);
  }
}

}  // namespace framedyn::apps
