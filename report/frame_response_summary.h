// summary.json of `framedyn frame-response` (a frame transient study run on
// its own): the top-level keys framedyn {version, command}, input {study,
// name, units, loads}, then report's frame and fatigue objects and the
// warnings. apps/ only parses the options and prints.
// docs/user-guide.md, "framedyn frame-response".
#pragma once

#include <nlohmann/json.hpp>

#include <functional>
#include <string>

#include "core/warnings.h"
#include "coupling/frame_study.h"

namespace framedyn::report {

// `study` is the study file as the user gave it; `console` gets each warning
// (apps/ prints it on stderr) as report::add_warnings hands it on.
nlohmann::ordered_json frame_response_summary(const std::string& study, const coupling::FrameStudyResults& results,
                                              const coupling::FrameStudyRequest& request,
                                              const std::function<void(const core::Warning&)>& console = {});

}  // namespace framedyn::report
