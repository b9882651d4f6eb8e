// rigid.contacts and the warnings list of summary.json: see run_outputs.h.
#include "apps/run_outputs.h"

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

nlohmann::ordered_json static_json(const std::vector<coupling::StaticContact>& contacts, const core::UnitSystem& units) {
  nlohmann::ordered_json forces = nlohmann::ordered_json::object(), engaged = nlohmann::ordered_json::array(),
                         lifted = nlohmann::ordered_json::array();
  for (const coupling::StaticContact& c : contacts) {
    forces[c.name] = {{"value", units.from_si(c.force, core::Quantity::force)}, {"unit", units.label(core::Quantity::force)}};
    (c.engaged ? engaged : lifted).push_back(c.name);
  }
  return {{"contact_forces", forces}, {"engaged", engaged}, {"lifted", lifted}};
}

nlohmann::ordered_json modes_by_state_json(const std::vector<coupling::StateModes>& states) {
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  for (const coupling::StateModes& s : states) {
    nlohmann::ordered_json f = nlohmann::ordered_json::array();
    for (const rigid::RigidMode& m : s.modes) f.push_back(m.frequency_hz);
    j[s.state] = {{"label", s.label}, {"frequencies_hz", f}};
  }
  return j;
}

void add_warnings(nlohmann::ordered_json& summary, const std::vector<core::Warning>& warnings) {
  if (!summary.contains("warnings")) summary["warnings"] = nlohmann::ordered_json::array();
  for (const core::Warning& w : warnings) {
    summary["warnings"].push_back({{"code", w.code}, {"message", w.message}});
    fmt::print(stderr, "framedyn: warning [{}]: {}\n", w.code, w.message);
  }
}

}  // namespace framedyn::apps
