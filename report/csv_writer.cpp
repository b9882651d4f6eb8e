// CSV writing with units in the headers; see csv_writer.h.
#include "report/csv_writer.h"

#include <fmt/format.h>

#include <stdexcept>

namespace framedyn::report {

std::string column(const std::string& name, const std::string& unit) {
  if (unit.empty() || unit == "1") return name;
  return name + " [" + unit + "]";
}

CsvTable::CsvTable(std::vector<std::string> headers) : headers_(std::move(headers)) {}

CsvTable& CsvTable::row() {
  rows_.emplace_back();
  rows_.back().reserve(headers_.size());
  return *this;
}

CsvTable& CsvTable::add(double value) {
  if (rows_.empty()) row();
  rows_.back().push_back(core::format_number(value));
  return *this;
}

CsvTable& CsvTable::add(long long value) {
  if (rows_.empty()) row();
  rows_.back().push_back(fmt::format("{}", value));
  return *this;
}

CsvTable& CsvTable::add(const std::string& text) {
  if (rows_.empty()) row();
  const bool quote = text.find_first_of(",\"\n") != std::string::npos;
  if (!quote) {
    rows_.back().push_back(text);
  } else {
    std::string q = "\"";
    for (char c : text) q += (c == '"') ? std::string("\"\"") : std::string(1, c);
    rows_.back().push_back(q + "\"");
  }
  return *this;
}

std::string CsvTable::str() const {
  std::string out;
  for (std::size_t i = 0; i < headers_.size(); ++i) out += (i ? "," : "") + headers_[i];
  out += "\n";
  for (std::size_t r = 0; r < rows_.size(); ++r) {
    if (rows_[r].size() != headers_.size())
      throw std::logic_error(fmt::format("CSV row {} has {} fields for {} columns", r + 1, rows_[r].size(), headers_.size()));
    for (std::size_t i = 0; i < rows_[r].size(); ++i) out += (i ? "," : "") + rows_[r][i];
    out += "\n";
  }
  return out;
}

}  // namespace framedyn::report
