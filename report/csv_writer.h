// Plain CSV tables with a unit in every column header ("frequency [Hz]").
// Numbers are written with 10 significant digits in a fixed locale-free
// format, so that two runs of the same input give byte-identical files.
#pragma once

#include <string>
#include <vector>

#include "core/number_text.h"

namespace framedyn::report {

class CsvTable {
 public:
  explicit CsvTable(std::vector<std::string> headers);
  CsvTable& row();                        // start a new row
  CsvTable& add(double value);
  CsvTable& add(long long value);
  CsvTable& add(int value) { return add(static_cast<long long>(value)); }
  CsvTable& add(const std::string& text);
  std::string str() const;                // throws std::logic_error on a ragged row
  std::size_t rows() const { return rows_.size(); }

 private:
  std::vector<std::string> headers_;
  std::vector<std::vector<std::string>> rows_;
};

// "name [unit]", or "name" when unit is "" or "1".
std::string column(const std::string& name, const std::string& unit);
// Text of a double for CSV and tables (core/number_text.h).
using core::format_number;

}  // namespace framedyn::report
