// What the vehicle's contacts (tires, bounce tire) did over a response
// (docs/theory/rigid.md section 4a; docs/user-guide.md, rigid.contacts): the
// normal force each transmitted, compression positive (the static force plus
// the spring-damper's, Eq. 4a.2, or zero while contact is lost), its least and
// largest value, the fraction of the output samples in which it pulled
// (tension_fraction: possible only under contacts: linear) and in which the
// contact was lost (lift_off_fraction: only under contacts: unilateral), and a
// `contact_in_tension` warning for every contact that pulled.
#pragma once

#include <string>
#include <vector>

#include "core/units.h"
#include "core/warnings.h"
#include "rigid/time_integration.h"
#include "rigid/unilateral_contact.h"

namespace framedyn::coupling {

struct ContactSummary {
  std::string name;
  double min_force = 0.0, max_force = 0.0;  // N, compression positive
  double min_force_time = 0.0;              // s
  double tension_fraction = 0.0;            // of the output samples with the normal force < 0
  double lift_off_fraction = 0.0;           // of the output samples with the contact lost
};

// Machine: rigid::Machine2D or Machine3D after the run that gave `tr` (its contact log).
template <class Machine>
std::vector<ContactSummary> summarize_contacts(const Machine& machine, const rigid::Trajectory& tr) {
  const rigid::UnilateralContacts& contacts = machine.contacts();
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

// A `contact_in_tension` warning for every contact with tension_fraction > 0
// (forces in the study's units).
std::vector<core::Warning> contact_warnings(const std::vector<ContactSummary>& contacts, const core::UnitSystem& units);

}  // namespace framedyn::coupling
