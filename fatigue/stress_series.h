// A measured or computed stress history from a CSV file (`framedyn rainflow`, docs/user-guide.md
// "framedyn rainflow"): a header row of columns "name [unit]", then one row per sample, cells
// separated by commas; blank lines and lines starting with '#' are skipped. A column named
// "time" (any unit) is the sample times and must increase row by row; every other column is a
// stress history whose unit, in its header, is one of core::stress_unit_labels().
#pragma once

#include <string>
#include <vector>

namespace framedyn::fatigue {

struct StressSeries {
  std::string file;
  std::string header;              // the column's header, e.g. "stress [psi]"
  std::string unit;                // e.g. "psi"
  double pascals_per_unit = 1.0;   // 6894.76 for psi
  std::vector<double> values;      // in `unit`, in the order of the rows
};

// Reads the column `column` (its name, or its whole header); "" reads the only column that is
// not "time". Throws core::InputError naming the file, line and column (docs/errors.md CLI-41 to CLI-45, CLI-47, CLI-48).
StressSeries read_stress_series(const std::string& path, const std::string& column);

}  // namespace framedyn::fatigue
