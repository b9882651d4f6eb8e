// Reader and writer of load-history files; see load_history.h.
#include "coupling/load_history.h"

#include <fmt/format.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include "core/number_text.h"
#include "core/error.h"

namespace framedyn::coupling {

namespace {

constexpr const char* kFirstLine = "# framedyn load history, version 1";
constexpr const char* kFormatPrefix = "# framedyn load history, version ";
// The largest magnitude a coordinate, time or load may have: beyond it a value
// overflows when converted to SI (1 lbf = 4.45 N) or when written back at 10
// significant digits (1.7976931348e308 rounds up past the largest double).
constexpr double kLargest = 1e300;

core::Quantity component_quantity(int c) { return c < 3 ? core::Quantity::force : core::Quantity::moment; }

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

std::vector<std::string> split_commas(const std::string& line) {
  std::vector<std::string> out;
  std::string cell;
  std::istringstream in(line);
  while (std::getline(in, cell, ',')) out.push_back(trim(cell));
  if (!line.empty() && line.back() == ',') out.emplace_back();
  return out;
}

std::vector<std::string> split_blanks(const std::string& line) {
  std::vector<std::string> out;
  std::istringstream in(line);
  std::string w;
  while (in >> w) out.push_back(w);
  return out;
}

// A whole cell as a double, or false.
bool parse_double(const std::string& text, double& value) {
  if (text.empty()) return false;
  errno = 0;
  char* end = nullptr;
  value = std::strtod(text.c_str(), &end);
  // ERANGE is also underflow (a subnormal such as 1e-310, returned as it is):
  // a number, which the writer itself produces from a tiny load converted to SI
  // (found by fuzz_load_history_reader). Only an overflow is refused here.
  return end == text.c_str() + text.size() && !(errno == ERANGE && std::isinf(value));
}

std::string quoted(const std::string& s) { return "'" + s + "'"; }

class Reader {
 public:
  explicit Reader(std::string file) : file_(std::move(file)) {}

  [[noreturn]] void fail(int line, const std::string& key, const std::string& expected, const std::string& found) const {
    throw core::InputError({file_, line, key}, expected, found);
  }

  LoadHistory parse(const std::string& text) {
    std::vector<std::string> lines;
    {
      std::istringstream in(text);
      std::string l;
      while (std::getline(in, l)) {
        if (!l.empty() && l.back() == '\r') l.pop_back();
        lines.push_back(l);
      }
    }
    // Line 1: format and version.
    if (lines.empty()) fail(1, "", quoted(kFirstLine), "an empty file");
    const std::string first = trim(lines[0]);
    if (first != kFirstLine) {
      if (first.rfind(kFormatPrefix, 0) == 0)
        fail(1, "version", "version 1 (the only version this framedyn reads)",
             "version " + quoted(first.substr(std::string(kFormatPrefix).size())));
      fail(1, "", quoted(kFirstLine) + " (a framedyn load-history file)", quoted(first));
    }
    // Line 2: units.
    if (lines.size() < 2) fail(2, "units", "'# units: NAME'", "the end of the file");
    const std::string second = trim(lines[1]);
    const std::string units_prefix = "# units:";
    if (second.rfind(units_prefix, 0) != 0) fail(2, "units", "'# units: NAME'", quoted(second));
    const std::string unit_name = trim(second.substr(units_prefix.size()));
    core::UnitSystem units = core::UnitSystem::si();
    try {
      units = core::UnitSystem::from_name(unit_name);
    } catch (const std::invalid_argument&) {
      fail(2, "units", "a unit system (in-lbf-s, m-N-s or SI, mm-N-s)", quoted(unit_name));
    }
    const double length = units.to_si_factor(core::Quantity::length);

    // Point lines.
    LoadHistory h;
    std::map<std::string, int> point_line;
    std::size_t i = 2;
    for (; i < lines.size(); ++i) {
      const std::string l = trim(lines[i]);
      if (l.empty()) continue;
      if (l.rfind("#", 0) != 0) break;
      const std::vector<std::string> w = split_blanks(l.substr(1));
      const int line_no = static_cast<int>(i + 1);
      if (w.empty() || w[0] != "point") fail(line_no, "", "'# point NAME x y z' or the CSV header", quoted(l));
      if (w.size() != 5)
        fail(line_no, "point", "'# point NAME x y z' (a name and three coordinates)",
             fmt::format("{} field(s) after '# point'", w.size() - 1));
      LoadPointHistory p;
      p.name = w[1];
      if (point_line.count(p.name))
        fail(line_no, "point " + p.name, "each point declared once",
             fmt::format("a second declaration (first on line {})", point_line[p.name]));
      for (int k = 0; k < 3; ++k) {
        double v = 0.0;
        if (!parse_double(w[2 + k], v) || !std::isfinite(v))
          fail(line_no, "point " + p.name, fmt::format("a finite number for coordinate {}", "xyz"[k]), quoted(w[2 + k]));
        if (!(std::abs(v) <= kLargest) || !(std::abs(v * length) <= kLargest))
          fail(line_no, "point " + p.name, fmt::format("a coordinate {} of magnitude at most 1e300, in the file's units and in SI", "xyz"[k]),
               quoted(w[2 + k]));
        p.location(k) = v * length;
      }
      point_line[p.name] = line_no;
      p.line = line_no;
      h.points.push_back(std::move(p));
    }
    if (h.points.empty())
      fail(static_cast<int>(std::min(i, lines.size()) + 1), "point", "at least one '# point NAME x y z' line",
           i < lines.size() ? quoted(trim(lines[i])) : "the end of the file");
    if (i >= lines.size()) fail(static_cast<int>(i + 1), "header", "the CSV header line 'time [s],...'", "the end of the file");

    // Header.
    const int header_line = static_cast<int>(i + 1);
    const std::vector<std::string> header = split_commas(lines[i]);
    const std::size_t columns = 1 + 6 * h.points.size();
    if (header.empty() || header[0] != "time [s]")
      fail(header_line, "column 1", "'time [s]'", header.empty() ? "an empty header" : quoted(header[0]));
    for (std::size_t p = 0; p < h.points.size(); ++p) {
      for (int c = 0; c < 6; ++c) {
        const std::size_t col = 1 + 6 * p + static_cast<std::size_t>(c);
        const std::string name = h.points[p].name + "." + kLoadComponents[c];
        const std::string want = name + " [" + units.label(component_quantity(c)) + "]";
        const std::string key = fmt::format("column {}", col + 1);
        if (col >= header.size()) fail(header_line, key, quoted(want) + " (missing component)", "the end of the header");
        const std::string& got = header[col];
        if (got == want) continue;
        // Say what is wrong: the unit, the component, or the point.
        const auto bracket = got.find(" [");
        const std::string got_name = bracket == std::string::npos ? got : got.substr(0, bracket);
        if (got_name == name)
          fail(header_line, key + " (" + name + ")",
               fmt::format("the unit label [{}] of the declared unit system {}", units.label(component_quantity(c)), units.name()),
               quoted(got));
        const auto dot = got_name.rfind('.');
        const std::string got_point = dot == std::string::npos ? got_name : got_name.substr(0, dot);
        if (got_point == h.points[p].name)
          fail(header_line, key, quoted(want) + " (components FX FY FZ MX MY MZ in this order; missing component)", quoted(got));
        if (!point_line.count(got_point))
          fail(header_line, key, quoted(want), quoted(got) + ", a column of a point with no '# point' line");
        fail(header_line, key, quoted(want) + " (points in the order of the '# point' lines, six components each)", quoted(got));
      }
    }
    if (header.size() > columns)
      fail(header_line, fmt::format("column {}", columns + 1),
           fmt::format("{} columns (time and six components of {} point(s))", columns, h.points.size()), quoted(header[columns]));

    // Rows.
    std::vector<double> times;
    std::vector<std::vector<double>> rows;
    for (++i; i < lines.size(); ++i) {
      const std::string l = trim(lines[i]);
      const int line_no = static_cast<int>(i + 1);
      if (l.empty()) continue;
      const std::vector<std::string> cells = split_commas(l);
      if (cells.size() != columns)
        fail(line_no, "", fmt::format("{} values (as the header)", columns), fmt::format("{} values", cells.size()));
      std::vector<double> row(columns);
      for (std::size_t c = 0; c < columns; ++c) {
        if (!parse_double(cells[c], row[c]))
          fail(line_no, fmt::format("column {} ({})", c + 1, header[c]), "a number", quoted(cells[c]));
        if (!std::isfinite(row[c]))
          fail(line_no, fmt::format("column {} ({})", c + 1, header[c]), "a finite number", quoted(cells[c]));
        if (!(std::abs(row[c]) <= kLargest))
          fail(line_no, fmt::format("column {} ({})", c + 1, header[c]), "a number of magnitude at most 1e300", quoted(cells[c]));
        // ... and in SI, the units framedyn computes and writes in: 8e299 lbf is 3.6e300 N, which the
        // same check would refuse when the history is written back in SI (found by fuzz_load_history_reader).
        if (c > 0) {
          const core::Quantity q = component_quantity(static_cast<int>((c - 1) % 6));
          if (const double si = row[c] * units.to_si_factor(q); !(std::abs(si) <= kLargest))
            fail(line_no, fmt::format("column {} ({})", c + 1, header[c]), "a number of magnitude at most 1e300 in SI units",
                 fmt::format("{} ({:g} {} in SI units)", quoted(cells[c]), si, core::UnitSystem::si().label(q)));
        }
      }
      if (!times.empty() && !(row[0] > times.back()))
        fail(line_no, "column 1 (time [s])", fmt::format("a time after {} s (times strictly increasing)", core::format_number(times.back())),
             quoted(cells[0]));
      // The file holds 10 significant digits: two times that agree in them would be one time when written back.
      if (!times.empty() && core::format_number(row[0]) == core::format_number(times.back()))
        fail(line_no, "column 1 (time [s])",
             fmt::format("a time that differs from the previous one, {} s, in the first 10 significant digits (the file's precision)",
                         core::format_number(times.back())),
             quoted(cells[0]));
      times.push_back(row[0]);
      rows.push_back(std::move(row));
    }
    if (rows.empty()) fail(static_cast<int>(lines.size() + 1), "", "at least one row of values", "the end of the file");

    const Eigen::Index n = static_cast<Eigen::Index>(rows.size());
    h.units = units;
    h.times = Eigen::Map<const Eigen::VectorXd>(times.data(), n);
    for (std::size_t p = 0; p < h.points.size(); ++p) {
      Eigen::MatrixXd& v = h.points[p].values;
      v.resize(n, 6);
      for (Eigen::Index k = 0; k < n; ++k)
        for (int c = 0; c < 6; ++c)
          v(k, c) = units.to_si(rows[static_cast<std::size_t>(k)][1 + 6 * p + static_cast<std::size_t>(c)], component_quantity(c));
    }
    return h;
  }

 private:
  std::string file_;
};

}  // namespace

Eigen::VectorXd LoadHistory::components_at(int k) const {
  Eigen::VectorXd v(6 * static_cast<Eigen::Index>(points.size()));
  for (std::size_t p = 0; p < points.size(); ++p) v.segment<6>(6 * static_cast<Eigen::Index>(p)) = points[p].values.row(k).transpose();
  return v;
}

Eigen::MatrixXd LoadHistory::component_matrix() const {
  Eigen::MatrixXd m(6 * static_cast<Eigen::Index>(points.size()), times.size());
  for (std::size_t p = 0; p < points.size(); ++p) m.middleRows<6>(6 * static_cast<Eigen::Index>(p)) = points[p].values.transpose();
  return m;
}

LoadHistory parse_load_history(const std::string& text, const std::string& name) { return Reader(name).parse(text); }

LoadHistory read_load_history(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    std::error_code ec;
    throw core::InputError({path.string(), 0, ""}, std::string("cannot open the load-history file") +
                                                       (std::filesystem::exists(path, ec) ? " (permission?)" : " (no such file)"));
  }
  std::ostringstream s;
  s << in.rdbuf();
  return parse_load_history(s.str(), path.string());
}

std::string format_load_history(const LoadHistory& h, const core::UnitSystem& units) {
  for (const LoadPointHistory& p : h.points)
    if (p.values.rows() != h.times.size() || p.values.cols() != 6)
      throw std::invalid_argument(fmt::format("load point {}: {} x {} values for {} times (expected n_times x 6)", p.name,
                                              p.values.rows(), p.values.cols(), h.times.size()));
  std::string out = std::string(kFirstLine) + "\n# units: " + units.name() + "\n";
  const double length = units.to_si_factor(core::Quantity::length);
  for (const LoadPointHistory& p : h.points)
    out += fmt::format("# point {} {} {} {}\n", p.name, core::format_number(p.location.x() / length),
                       core::format_number(p.location.y() / length), core::format_number(p.location.z() / length));
  out += "time [" + units.label(core::Quantity::time) + "]";
  for (const LoadPointHistory& p : h.points)
    for (int c = 0; c < 6; ++c) out += "," + p.name + "." + kLoadComponents[c] + " [" + units.label(component_quantity(c)) + "]";
  out += "\n";
  for (Eigen::Index k = 0; k < h.times.size(); ++k) {
    out += core::format_number(h.times(k));
    for (const LoadPointHistory& p : h.points)
      for (int c = 0; c < 6; ++c) out += "," + core::format_number(units.from_si(p.values(k, c), component_quantity(c)));
    out += "\n";
  }
  return out;
}

void write_load_history(const std::filesystem::path& path, const LoadHistory& h, const core::UnitSystem& units) {
  const std::string text = format_load_history(h, units);
  std::ofstream out(path, std::ios::binary);
  if (!out) throw std::runtime_error("cannot write " + path.string());
  out << text;
  if (!out) throw std::runtime_error("error writing " + path.string());
}

}  // namespace framedyn::coupling
