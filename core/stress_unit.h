// Stress units a measured series names in a column header ("stress [psi]"), exact letter
// case: Pa, kPa, MPa, GPa, N/mm^2, psi, ksi. The pound-force and the inch are those of
// core/units (exact by definition), so a series in psi and the in-lbf-s system agree.
#pragma once

#include <string>
#include <vector>

namespace framedyn::core {

// Pa per unit, or 0 for a label not among them.
double pascals_per_stress_unit(const std::string& label);
const std::vector<std::string>& stress_unit_labels();

}  // namespace framedyn::core
