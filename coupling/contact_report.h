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
#include "rigid/vehicle_run.h"

namespace framedyn::coupling {

struct ContactSummary {
  std::string name;
  double min_force = 0.0, max_force = 0.0;  // N, compression positive
  double min_force_time = 0.0;              // s
  double tension_fraction = 0.0;            // of the output samples with the normal force < 0
  double lift_off_fraction = 0.0;           // of the output samples with the contact lost
};

// `run`: the state the run that gave `tr` left (its contact log, rigid/vehicle_run.h).
std::vector<ContactSummary> summarize_contacts(const rigid::VehicleRunState& run, const rigid::Trajectory& tr);

// A `contact_in_tension` warning for every contact with tension_fraction > 0
// (forces in the study's units).
std::vector<core::Warning> contact_warnings(const std::vector<ContactSummary>& contacts, const core::UnitSystem& units);

}  // namespace framedyn::coupling
