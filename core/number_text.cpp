// The text form of a number; see number_text.h.
#include "core/number_text.h"

#include <fmt/format.h>

namespace framedyn::core {

std::string format_number(double value) {
  if (value == 0.0) return "0";  // also folds -0 into 0
  return fmt::format("{:.10g}", value);
}

}  // namespace framedyn::core
