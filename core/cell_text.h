// Reading the cells of framedyn's CSV inputs (load PSDs, stress histories): the text of a
// cell without its surrounding blanks, and a cell that must hold one finite number.
#pragma once

#include <string>

namespace framedyn::core {

// `s` without leading and trailing blanks, tabs and carriage returns.
std::string trim(const std::string& s);
// True, with `value` set, if the trimmed text is exactly one finite number (strtod's syntax).
bool parse_number(const std::string& text, double& value);

}  // namespace framedyn::core
