// Contact summaries and their warnings: see contact_report.h.
#include "coupling/contact_report.h"

#include <fmt/format.h>

namespace framedyn::coupling {

std::vector<core::Warning> contact_warnings(const std::vector<ContactSummary>& contacts, const core::UnitSystem& units) {
  std::vector<core::Warning> w;
  for (const ContactSummary& c : contacts) {
    if (!(c.tension_fraction > 0.0)) continue;
    core::add_warning(w, "contact_in_tension",
                      fmt::format("{} pulls on the ground in {:.1f} % of the output samples (least force {:.4g} {} at t = {:.4g} s): "
                                  "a contact cannot pull, so the response and the loads from it are not physical there. "
                                  "contacts: linear keeps the thesis's bilateral springs; contacts: unilateral lets the contact lift off",
                                  c.name, 100.0 * c.tension_fraction, units.from_si(c.min_force, core::Quantity::force),
                                  units.label(core::Quantity::force), c.min_force_time));
  }
  return w;
}

}  // namespace framedyn::coupling
