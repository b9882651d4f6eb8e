// Outputs every rigid-body run writes the same way in 2-D and 3-D:
// summary.json's rigid.contacts.<name> {min_force, max_force (compression
// positive) {value, unit}, tension_fraction, lift_off_fraction}; rigid.steady
// (steady operation and the peaks before and in it). The top-level `warnings`
// list: report/summary_warnings.h.
// docs/user-guide.md, "summary.json" and "Warnings".
#pragma once

#include <nlohmann/json.hpp>

#include <functional>
#include <optional>
#include <vector>

#include "core/units.h"
#include "core/warnings.h"
#include "report/summary_warnings.h"  // add_warnings, for the commands that write run summaries
#include "coupling/contact_report.h"
#include "coupling/static_report.h"
#include "coupling/frame_study.h"
#include "coupling/steady_report.h"

namespace framedyn::report {

// rigid.contacts: one entry per contact, forces in the study's units.
nlohmann::ordered_json contacts_json(const std::vector<coupling::ContactSummary>& contacts, const core::UnitSystem& units);

// rigid.static: {contact_forces: {<name>: {value, unit}} (compression
// positive), engaged: [names], lifted: [names]}, the equilibrium the response
// starts from (docs/theory/rigid.md section 11).
nlohmann::ordered_json static_json(const std::vector<coupling::StaticContact>& contacts, const core::UnitSystem& units);

// rigid.modes_by_state: {<state>: {label, frequencies_hz}} for cutting,
// backing_off and contact_lost (Eq. 11.7).
nlohmann::ordered_json modes_by_state_json(const std::vector<coupling::StateModes>& states);
// rigid.steady: reached_at {value, unit} or null, the period multiple, the
// criterion, the remaining change, the watched signals, and every history's
// peak over the start-up and over steady operation (study units).
nlohmann::ordered_json steady_json(const coupling::SteadyReport& steady, const core::UnitSystem& units);

// frame.steady (the pipeline): each rail's peak |normal stress| (its series
// is the largest magnitude over the rail's stations) and resultant bending
// moment over the start-up and over steady operation, split at `reached_at`.
// The console's line on the frame's peak von Mises stress and the steady window of its hot spots
// (docs/theory/coupling.md section 10); nothing without section points.
void print_hot_spot_line(const coupling::FrameStudyResults& frame, const core::UnitSystem& units);
// The fatigue life map's shortest life, where, and the damage over fatigue.hours; nothing without a life map.
void print_fatigue_line(const coupling::FrameStudyResults& frame, const coupling::FrameStudyRequest& request);
nlohmann::ordered_json frame_steady_json(const coupling::FrameStudyResults& frame, std::optional<double> reached_at,
                                         const core::UnitSystem& units);

}  // namespace framedyn::report
