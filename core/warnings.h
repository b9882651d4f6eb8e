// Validity warnings of a run: a code (stable, for scripts) and a message with
// its figures. The library collects them in its results; the command line
// writes them to summary.json's top-level `warnings` list and to stderr
// (apps/warnings_output.h). docs/user-guide.md, "Warnings".
#pragma once

#include <string>
#include <vector>

namespace framedyn::core {

struct Warning {
  std::string code;     // e.g. "contact_in_tension"
  std::string message;  // what, how much, and what to do about it
};

inline void add_warning(std::vector<Warning>& warnings, std::string code, std::string message) {
  warnings.push_back({std::move(code), std::move(message)});
}

}  // namespace framedyn::core
