// A keyword argument the Python module refuses (docs/errors.md, "Python module":
// PY-06 to PY-09): raised as framedyn.Error with key = the argument's name and
// file None (the call is at fault, not a file). Thrown by framedyn_module.cpp and
// framedyn_study.cpp, translated in framedyn_module.cpp.
#pragma once

#include <stdexcept>
#include <string>
#include <utility>

namespace framedyn::python {

struct ArgumentError : std::runtime_error {
  ArgumentError(std::string argument, const std::string& message) : std::runtime_error(argument + ": " + message), key(std::move(argument)) {}
  std::string key;
};

}  // namespace framedyn::python
