// The text of one event of a rigid-body response (events.csv): the system's
// description and, where it gives one, the length that goes with it (the
// blade's position) in the study's length unit, e.g. "blade backs off at
// x5 = 0.0157331 in".
#pragma once

#include <string>

#include "core/units.h"
#include "rigid/time_integration.h"

namespace framedyn::report {

std::string event_text(const rigid::Trajectory::Event& event, const core::UnitSystem& units);

}  // namespace framedyn::report
