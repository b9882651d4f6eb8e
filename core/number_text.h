// The one text form of a number in framedyn's files and messages: 10
// significant digits, locale-free, -0 as 0, so that two runs of the same
// input give byte-identical files and a message quotes a value as a file has it.
#pragma once

#include <string>

namespace framedyn::core {

std::string format_number(double value);

}  // namespace framedyn::core
