// Load PSD table, log-log interpolation and CSV reader; see load_psd.h.
#include "fem/load_psd.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "core/cell_text.h"
#include "core/error.h"

namespace framedyn::fem {

using core::InputError;
using core::parse_number;
using core::trim;

double LoadPsd::at(double f) const {
  if (!(f >= lowest() && f <= highest()))
    throw std::invalid_argument(fmt::format("PSD asked at {} Hz, outside its band {} to {} Hz", f, lowest(), highest()));
  const auto it = std::upper_bound(frequency_hz.begin(), frequency_hz.end(), f);
  const std::size_t k = it == frequency_hz.end() ? frequency_hz.size() - 2 : static_cast<std::size_t>(it - frequency_hz.begin()) - 1;
  const double f0 = frequency_hz[k], f1 = frequency_hz[k + 1], s0 = psd[k], s1 = psd[k + 1];
  const double slope = std::log(s1 / s0) / std::log(f1 / f0);  // dB/decade / 10, the power of f
  return s0 * std::pow(f / f0, slope);
}

void check_load_psd(const LoadPsd& p, const std::string& source) {
  if (p.frequency_hz.size() != p.psd.size()) throw std::invalid_argument(source + ": as many PSD values as frequencies are needed");
  if (p.frequency_hz.size() < 2)
    throw InputError({source, 0, ""}, "at least two rows (the band's lowest and highest frequency)", fmt::format("{} row(s)", p.frequency_hz.size()));
  for (std::size_t k = 0; k < p.psd.size(); ++k) {
    if (!(p.frequency_hz[k] > 0.0) || !std::isfinite(p.frequency_hz[k]))
      throw InputError({source, 0, fmt::format("row {}", k + 1)}, "a positive frequency", fmt::format("{}", p.frequency_hz[k]));
    if (!(p.psd[k] > 0.0) || !std::isfinite(p.psd[k]))
      throw InputError({source, 0, fmt::format("row {}", k + 1)}, "a positive PSD (log-log interpolation)", fmt::format("{}", p.psd[k]));
    if (k > 0 && !(p.frequency_hz[k] > p.frequency_hz[k - 1]))
      throw InputError({source, 0, fmt::format("row {}", k + 1)}, "frequencies increasing row by row",
                       fmt::format("{} Hz after {} Hz", p.frequency_hz[k], p.frequency_hz[k - 1]));
  }
}

LoadPsd read_load_psd(const std::string& path) {
  std::ifstream in(path);
  std::error_code ec;
  if (!in || std::filesystem::is_directory(path, ec))
    throw InputError({path, 0, ""}, "cannot open " + path + (std::filesystem::exists(path, ec) ? " (not a readable file)" : " (no such file)"));
  LoadPsd p;
  std::string line;
  bool header = false;
  int header_line = 0;
  for (int n = 1; std::getline(in, line); ++n) {
    const std::string t = trim(line);
    if (t.empty() || t[0] == '#') continue;
    const std::size_t comma = t.find(',');
    if (!header) {
      const std::string a = comma == std::string::npos ? t : trim(t.substr(0, comma));
      const std::string b = comma == std::string::npos ? "" : trim(t.substr(comma + 1));
      if (a != "frequency [Hz]" || b != "psd [1/Hz]")
        throw InputError({path, n, "header"}, "the columns 'frequency [Hz],psd [1/Hz]'", "'" + t + "'");
      header = true;
      header_line = n;
      continue;
    }
    double f = 0.0, s = 0.0;
    if (comma == std::string::npos || t.find(',', comma + 1) != std::string::npos || !parse_number(t.substr(0, comma), f) ||
        !parse_number(t.substr(comma + 1), s))
      throw InputError({path, n, ""}, "two numbers 'frequency,psd' (Hz, 1/Hz)", "'" + t + "'");
    if (!(f > 0.0)) throw InputError({path, n, "frequency [Hz]"}, "a positive frequency", fmt::format("{}", f));
    if (!(s > 0.0)) throw InputError({path, n, "psd [1/Hz]"}, "a positive PSD (it is interpolated log-log)", fmt::format("{}", s));
    if (!p.frequency_hz.empty() && !(f > p.frequency_hz.back()))
      throw InputError({path, n, "frequency [Hz]"}, "frequencies increasing row by row", fmt::format("{} Hz after {} Hz", f, p.frequency_hz.back()));
    p.frequency_hz.push_back(f);
    p.psd.push_back(s);
  }
  if (!header) throw InputError({path, 0, "header"}, "the columns 'frequency [Hz],psd [1/Hz]'", "an empty file");
  if (p.frequency_hz.size() < 2)
    throw InputError({path, header_line, ""}, "at least two rows after the header (the band's lowest and highest frequency)",
                     fmt::format("{} row(s)", p.frequency_hz.size()));
  return p;
}

}  // namespace framedyn::fem
