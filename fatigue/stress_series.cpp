// The stress-history CSV reader; see stress_series.h.
#include "fatigue/stress_series.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "core/cell_text.h"
#include "core/error.h"
#include "core/number_text.h"
#include "core/stress_unit.h"

namespace framedyn::fatigue {

namespace {

using core::InputError;
using core::parse_number;
using core::trim;

std::vector<std::string> cells_of(const std::string& line) {
  std::vector<std::string> cells;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = line.find(',', start);
    cells.push_back(trim(line.substr(start, comma == std::string::npos ? std::string::npos : comma - start)));
    if (comma == std::string::npos) return cells;
    start = comma + 1;
  }
}

// "stress [psi]" -> name "stress", unit "psi"; no bracket: unit "".
void split_header(const std::string& h, std::string& name, std::string& unit) {
  const std::size_t open = h.rfind('[');
  if (open == std::string::npos || h.back() != ']') {
    name = h;
    unit.clear();
    return;
  }
  name = trim(h.substr(0, open));
  unit = trim(h.substr(open + 1, h.size() - open - 2));
}

}  // namespace

StressSeries read_stress_series(const std::string& path, const std::string& column) {
  std::ifstream in(path);
  std::error_code ec;
  if (!in || std::filesystem::is_directory(path, ec))
    throw InputError({path, 0, ""}, "cannot open " + path + (std::filesystem::exists(path, ec) ? " (not a readable file)" : " (no such file)"));
  StressSeries s;
  s.file = path;
  std::vector<std::string> headers;
  int time_col = -1, col = -1;
  double last_time = 0.0;
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    const std::string t = trim(line);
    if (t.empty() || t[0] == '#') continue;
    const std::vector<std::string> cells = cells_of(t);
    if (headers.empty()) {
      headers = cells;
      std::vector<int> stress_cols;
      for (std::size_t i = 0; i < headers.size(); ++i) {
        std::string name, unit;
        split_header(headers[i], name, unit);
        if (name == "time") time_col = static_cast<int>(i);
        else stress_cols.push_back(static_cast<int>(i));
        if (!column.empty() && (column == name || column == headers[i])) col = static_cast<int>(i);
      }
      std::string listed;
      for (int i : stress_cols) listed += (listed.empty() ? "" : ", ") + headers[static_cast<std::size_t>(i)];
      if (!column.empty() && (col < 0 || col == time_col))
        throw InputError({path, n, "--column"}, "a stress column of the header (" + listed + ")", "'" + column + "'");
      if (column.empty()) {
        if (stress_cols.size() != 1)
          throw InputError({path, n, "--column"}, "--column naming one of the stress columns (" + listed + ")",
                           fmt::format("no --column (the file has {} stress columns)", stress_cols.size()));
        col = stress_cols.front();
      }
      s.header = headers[static_cast<std::size_t>(col)];
      std::string name;
      split_header(s.header, name, s.unit);
      s.pascals_per_unit = core::pascals_per_stress_unit(s.unit);
      if (s.pascals_per_unit == 0.0)
        throw InputError({path, n, s.header}, fmt::format("a stress unit in the column's header 'name [unit]' ({})", fmt::join(core::stress_unit_labels(), ", ")),
                         s.unit.empty() ? std::string("no unit") : "'" + s.unit + "'");
      continue;
    }
    if (cells.size() != headers.size())
      throw InputError({path, n, ""}, fmt::format("{} cells, as the header has", headers.size()), fmt::format("{} in '{}'", cells.size(), t));
    double v = 0.0;
    if (!parse_number(cells[static_cast<std::size_t>(col)], v))
      throw InputError({path, n, s.header}, "a number", "'" + cells[static_cast<std::size_t>(col)] + "'");
    if (time_col >= 0) {
      const std::string& header = headers[static_cast<std::size_t>(time_col)];
      double time = 0.0;
      if (!parse_number(cells[static_cast<std::size_t>(time_col)], time)) throw InputError({path, n, header}, "a number", "'" + cells[static_cast<std::size_t>(time_col)] + "'");
      if (!s.values.empty() && !(time > last_time))
        throw InputError({path, n, header}, "times increasing row by row", fmt::format("{} after {}", core::format_number(time), core::format_number(last_time)));
      last_time = time;
    }
    s.values.push_back(v);
  }
  if (headers.empty()) throw InputError({path, 0, "header"}, "a header row of columns 'name [unit]'", "an empty file");
  return s;
}

}  // namespace framedyn::fatigue
