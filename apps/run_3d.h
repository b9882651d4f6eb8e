// `framedyn run` for 3-D rigid-body studies (model: rigid_3d); see run_3d.cpp.
#pragma once

#include <string>

#include "apps/progress.h"

namespace framedyn::apps {

// Runs a rigid_3d study and writes DIR/summary.json, rigid_modes.csv and, with a
// response, response.csv, events.csv and frame_loads.csv (the load-history format of
// coupling/load_history.h). Returns the exit code.
int run_study_3d(const std::string& study_file, const std::string& out, bool figures, const ProgressFlags& flags);

}  // namespace framedyn::apps
