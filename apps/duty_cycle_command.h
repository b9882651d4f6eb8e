// The console of `framedyn run` for duty cycles (model: duty_cycle); see duty_cycle_command.cpp.
#pragma once

#include <string>

#include "report/study_run.h"

namespace framedyn::apps {

// Prints the cycle's lines (report::run_study_file ran it and wrote `out_dir`). Returns the exit code.
int print_duty_cycle_run(const std::string& file, const report::StudyRun& run, bool figures, const std::string& out_dir);

}  // namespace framedyn::apps
