// A duty cycle (docs/theory/fatigue.md section 9, Eqs. F.23-F.25; docs/user-guide.md
// "Duty cycles"): a study file of its own kind listing scenarios, each a 3-D study with
// a frame_response (straight plowing, offset plowing, chain work, transport over rough
// ground) and the hours the machine spends in it per cycle. Each scenario runs the
// pipeline over its steady window; the cycle's fatigue block (coupling/frame_fatigue.h)
// replaces the scenarios' own, so every scenario is assessed on the same details; the
// damages add with their hours (Miner).
//
//   framedyn_study: 1
//   name: R-100 duty cycle
//   model: duty_cycle
//   scenarios:                       # study files relative to this file
//     - {name: straight, study: straight_plowing.yaml, hours: 500}
//   fatigue: {code: IIW, default: FAT71, details: [...]}
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace YAML { class Node; }

#include "coupling/frame_fatigue.h"
#include "coupling/frame_study.h"

namespace framedyn::coupling {

struct DutyCycleScenarioSpec {
  std::string name;
  std::filesystem::path study;  // resolved against the duty-cycle file's folder
  double hours = 0.0;
  core::InputLocation where;
};

struct DutyCycleRequest {
  std::string file, name;
  std::vector<DutyCycleScenarioSpec> scenarios;
  FatigueRequest fatigue;
  // Each scenario's frame transient over its steady window alone, from a lead-in long enough for
  // the free response of its start to decay to this fraction of its amplitude (FrameStudyRequest::
  // window_lead_in_decay; docs/theory/fatigue.md section 15). Not a key of the file: the cycle's
  // damage at every section point equals the whole record's to the tolerance derived there
  // (tests: DutyCycleWindowOnly). Unset: every scenario's whole record (the reference).
  std::optional<double> lead_in_decay = 1e-6;
};

// Throws core::InputError (STUDY-123, STUDY-124; the fatigue block's STUDY-114 .. STUDY-119).
DutyCycleRequest read_duty_cycle(const std::string& file);
// The same from a parsed document; `file` names it in messages and anchors the scenarios' paths.
DutyCycleRequest read_duty_cycle(const YAML::Node& doc, const std::string& file);

struct DutyCycleScenarioResult {
  std::string name;
  double hours = 0.0;
  std::string study_name;
  double wall_seconds = 0.0;
  FrameStudyResults frame;   // its pipeline run, with the life map (frame.life)
  FrameStudyRequest request; // the scenario's frame_response with the cycle's fatigue block
};

struct DutyCycleResults {
  std::vector<DutyCycleScenarioResult> scenarios;
  DutyLife life;
};

// Runs every scenario (rigid-body model, then the frame) and combines their life maps.
// Throws core::InputError (STUDY-125) when a scenario's frame outputs differ from the first's.
// `stage(name)`: called before each scenario runs (progress; from the scenario's thread, one call
// at a time). `threads`: scenarios run at the same time (each its own pipeline; 0: one per core,
// at most one per scenario; theory/fatigue.md section 13). The results do not depend on it: each
// scenario's run is the same whatever thread runs it, the Miner sum is taken in scenario order
// after all have run, and an error is the first failing scenario's in the file's order.
DutyCycleResults run_duty_cycle(const DutyCycleRequest& request, const std::function<void(const std::string&)>& stage = {}, int threads = 1);

}  // namespace framedyn::coupling
