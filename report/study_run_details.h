// The typed study and results of a run_study_document call (report/study_run.h),
// for callers that print more than the summary (apps/: the console's tables).
// One member pair is set, by the study's model.
#pragma once

#include <optional>

#include "coupling/duty_cycle.h"
#include "coupling/frame_study.h"
#include "coupling/rigid_study.h"
#include "coupling/rigid_study_3d.h"
#include "report/study_run.h"

namespace framedyn::report {

struct StudyRunDetails {
  std::optional<coupling::RigidStudy> study_2d;
  std::optional<coupling::RigidResults> results_2d;
  std::optional<coupling::RigidStudy3D> study_3d;
  std::optional<coupling::RigidResults3D> results_3d;
  std::optional<coupling::FrameStudyResults> frame;  // the pipeline's frame transient (rigid_3d with frame_response)
  std::optional<coupling::DutyCycleRequest> duty_cycle;
  std::optional<coupling::DutyCycleResults> duty_cycle_results;
};

}  // namespace framedyn::report
