// One style for every dimensional number in every JSON summary (docs/user-guide.md,
// "Outputs"): an object {"value": v, "unit": "label"}, where v is a number or an
// array of numbers in that one unit, and the label comes from core/units' tables,
// never from a key's name. Dimensionless numbers (counts, fractions, ratios) stay
// bare numbers.
#pragma once

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace framedyn::report {

inline nlohmann::ordered_json quantity(double value, const std::string& unit) {
  return nlohmann::ordered_json{{"value", value}, {"unit", unit}};
}

inline nlohmann::ordered_json quantity(const std::vector<double>& values, const std::string& unit) {
  return nlohmann::ordered_json{{"value", values}, {"unit", unit}};
}

}  // namespace framedyn::report
