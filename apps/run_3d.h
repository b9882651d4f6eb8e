// The console of `framedyn run` for 3-D rigid-body studies (model: rigid_3d) and the pipeline; see run_3d.cpp.
#pragma once

#include <string>

#include "report/study_run.h"

namespace framedyn::apps {

// Prints the run's tables (report::run_study_file ran it and wrote `out_dir`). Returns the exit code.
int print_run_3d(const std::string& study_file, const report::StudyRun& run, bool figures, const std::string& out_dir);

}  // namespace framedyn::apps
