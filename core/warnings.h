// Validity warnings of a run: a code (stable, for scripts), a message, and
// the figures behind it (each a named value with its unit, in the study's
// units). The library collects them in its results; the command line writes
// them to summary.json's top-level `warnings` list and to stderr
// (report/run_outputs.h, add_warnings). docs/user-guide.md, "Warnings".
#pragma once

#include <string>
#include <vector>

namespace framedyn::core {

// One number a warning rests on: e.g. {"largest_rotation", 0.21, "rad"}.
struct WarningFigure {
  std::string name;
  double value = 0.0;
  std::string unit;  // "1" for a ratio or a count
};

struct Warning {
  std::string code;     // e.g. "contact_in_tension"
  std::string message;  // what, how much, and what to do about it
  std::vector<WarningFigure> figures;
};

inline void add_warning(std::vector<Warning>& warnings, std::string code, std::string message, std::vector<WarningFigure> figures = {}) {
  warnings.push_back({std::move(code), std::move(message), std::move(figures)});
}

}  // namespace framedyn::core
