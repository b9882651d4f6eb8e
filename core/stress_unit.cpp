// Stress units of measured series; see stress_unit.h.
#include "core/stress_unit.h"

#include "core/units.h"

namespace framedyn::core {

namespace {

struct StressUnit {
  std::string label;
  double pascals;
};

const std::vector<StressUnit>& units() {
  static const std::vector<StressUnit> table = [] {
    const double psi = UnitSystem::from_name("in-lbf-s").to_si_factor(Quantity::stress);  // lbf/in^2 in Pa
    return std::vector<StressUnit>{{"Pa", 1.0}, {"kPa", 1e3}, {"MPa", 1e6}, {"GPa", 1e9}, {"N/mm^2", 1e6}, {"psi", psi}, {"ksi", 1e3 * psi}};
  }();
  return table;
}

}  // namespace

double pascals_per_stress_unit(const std::string& label) {
  for (const StressUnit& u : units())
    if (label == u.label) return u.pascals;
  return 0.0;
}

const std::vector<std::string>& stress_unit_labels() {
  static const std::vector<std::string> labels = [] {
    std::vector<std::string> l;
    for (const StressUnit& u : units()) l.push_back(u.label);
    return l;
  }();
  return labels;
}

}  // namespace framedyn::core
