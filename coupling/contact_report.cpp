// Contact summaries and their warnings: see contact_report.h.
#include "coupling/contact_report.h"

#include <fmt/format.h>

namespace framedyn::coupling {

std::vector<ContactSummary> summarize_contacts(const rigid::VehicleRunState& run, const rigid::Trajectory& tr) {
  const rigid::UnilateralContacts& contacts = run.contacts;
  std::vector<ContactSummary> out;
  const std::size_t ns = tr.time.size();
  for (std::size_t c = 0; c < contacts.contacts().size(); ++c) {
    ContactSummary s;
    s.name = contacts.contacts()[c].name;
    if (ns == 0) {
      out.push_back(s);
      continue;
    }
    const int e = contacts.contacts()[c].normal;
    std::size_t pulling = 0, lost = 0;
    for (std::size_t i = 0; i < ns; ++i) {
      const double f = contacts.transmitted_force(e, tr.time[i], tr.q[i], tr.v[i]);
      if (i == 0 || f < s.min_force) {
        s.min_force = f;
        s.min_force_time = tr.time[i];
      }
      if (i == 0 || f > s.max_force) s.max_force = f;
      if (f < 0.0) ++pulling;
      if (!contacts.touching_at(static_cast<int>(c), tr.time[i])) ++lost;
    }
    s.tension_fraction = static_cast<double>(pulling) / static_cast<double>(ns);
    s.lift_off_fraction = static_cast<double>(lost) / static_cast<double>(ns);
    out.push_back(s);
  }
  return out;
}

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
