// Formatting of input-error messages: "file:line: key: expected ..., found ...".
#include "core/error.h"

#include <fmt/format.h>

namespace framedyn::core {

std::string format_location(const InputLocation& where) {
  std::string text = where.file.empty() ? std::string("<input>") : where.file;
  if (where.line > 0) text += fmt::format(":{}", where.line);
  if (!where.key.empty()) text += ": " + where.key;
  return text;
}

InputError::InputError(InputLocation where, const std::string& expected, const std::string& found)
    : std::runtime_error(fmt::format("{}: expected {}, found {}", format_location(where), expected, found)),
      where_(std::move(where)) {}

InputError::InputError(InputLocation where, const std::string& message)
    : std::runtime_error(fmt::format("{}: {}", format_location(where), message)), where_(std::move(where)) {}

}  // namespace framedyn::core
