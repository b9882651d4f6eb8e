// summary.json's top-level `warnings` list: one {code, message, figures}
// entry per core::Warning, whatever produced it (a study's validity checks,
// the mesh reader's notes kept in fem::FrameModel::reader_warnings). Every
// command's writer goes through add_warnings, so the list has one form.
// docs/user-guide.md, "Warnings".
#pragma once

#include <nlohmann/json.hpp>

#include <functional>
#include <vector>

#include "core/warnings.h"

namespace framedyn::report {

// Appends the warnings to summary["warnings"] (created if absent, so that any
// stage of a run may add its own) and hands each to `console` (apps/ prints it
// on stderr as "framedyn: warning [code]: message"; a batch run prints nothing).
void add_warnings(nlohmann::ordered_json& summary, const std::vector<core::Warning>& warnings,
                  const std::function<void(const core::Warning&)>& console = {});

}  // namespace framedyn::report
