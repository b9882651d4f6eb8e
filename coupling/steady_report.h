// Steady operation of a vehicle run and its peaks before and in it
// (docs/theory/rigid.md, section 12; docs/user-guide.md, "Steady operation"),
// the same in 2-D and 3-D: the detector (rigid/steady_operation.h) watches the
// blade's motion and every frame load component; the peaks of every recovered
// time history (plow force, element forces, blade motion, frame loads; the
// pipeline's rail stresses in apps/run_3d.cpp) are split at reached_at. Also
// gathers the validity warnings of the response (coupling/validity_warnings.h).
#pragma once

#include <string>
#include <vector>

#include "core/units.h"
#include "rigid/steady_operation.h"

namespace framedyn::rigid {
struct VehicleModel;
struct VehicleRunState;
}

namespace framedyn::coupling {

struct SteadyPeak {
  std::string name;
  core::Quantity quantity = core::Quantity::force;
  rigid::PeakSplit split;  // SI
};

struct SteadyReport {
  bool assessed = false;
  std::string not_assessed;          // why not (no shaker: a chain, a machine without attachment)
  rigid::SteadyCriterion criterion;
  rigid::SteadyOperation operation;
  std::vector<std::string> watched;  // the signals of Eq. 12.1
  std::vector<SteadyPeak> peaks;
};

struct RigidStudy;
struct RigidResults;

// After the response (and its series and frame loads) is in `r`: sets
// r.steady and appends the validity warnings (rotation range, chattering,
// shaker near a mode, steady not reached) to r.warnings.
// `model` is the study's model, `run` the state its response left.
void assess_response(const RigidStudy& study, const rigid::VehicleModel& model, const rigid::VehicleRunState& run, RigidResults& r);

}  // namespace framedyn::coupling
