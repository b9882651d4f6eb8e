// `framedyn run` for duty cycles (model: duty_cycle); see duty_cycle_command.cpp.
#pragma once

#include <string>

#include "apps/progress.h"

namespace framedyn::apps {

// Runs every scenario of the duty cycle and writes DIR/life_map.csv, frame_life.vtu,
// summary.json (and frame_life.png with figures). Returns the exit code.
int run_duty_cycle_study(const std::string& file, const std::string& out, bool figures, const ProgressFlags& flags);

}  // namespace framedyn::apps
