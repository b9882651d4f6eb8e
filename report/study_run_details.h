// The typed study and results of a run_study_document call (report/study_run.h),
// for callers that print more than the summary (apps/: the console's tables).
// A vehicle study sets study and results, a duty cycle its pair.
#pragma once

#include <optional>

#include "coupling/duty_cycle.h"
#include "coupling/frame_study.h"
#include "coupling/rigid_study.h"
#include "report/study_run.h"

namespace framedyn::report {

struct StudyRunDetails {
  std::optional<coupling::RigidStudy> study;      // rigid_2d or rigid_3d
  std::optional<coupling::RigidResults> results;
  std::optional<coupling::FrameStudyResults> frame;  // the pipeline's frame transient (rigid_3d with frame_response)
  std::optional<coupling::DutyCycleRequest> duty_cycle;
  std::optional<coupling::DutyCycleResults> duty_cycle_results;
};

}  // namespace framedyn::report
