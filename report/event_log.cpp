// Event texts in the study's units; see event_log.h.
#include "report/event_log.h"

#include <fmt/format.h>

namespace framedyn::report {

std::string event_text(const rigid::Trajectory::Event& event, const core::UnitSystem& units) {
  if (event.length_name.empty()) return event.what;
  return fmt::format("{} at {} = {:.6g} {}", event.what, event.length_name, units.from_si(event.length, core::Quantity::length),
                     units.label(core::Quantity::length));
}

}  // namespace framedyn::report
