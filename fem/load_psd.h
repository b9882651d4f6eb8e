// The power spectral density of a random load: a table of (frequency, PSD)
// read from CSV, interpolated log-log between its rows (a straight line on
// a log-log plot: S = S_k (f / f_k)^b between rows k and k+1, so a power law
// is reproduced exactly). The PSD is one-sided in Hz: the mean square of the
// load factor a(t) is the integral of S(f) df over f >= 0 (docs/theory/fem.md,
// "Random response", Eq. S.1). framedyn applies it to the mesh's load pattern
// F as the load F a(t), so S has the unit 1/Hz.
//
// File format (docs/user-guide.md, "framedyn random"):
//   # comment lines and blank lines anywhere
//   frequency [Hz],psd [1/Hz]
//   5,0.001
//   200,0.001
// at least two rows, frequencies positive and strictly increasing, PSD positive.
#pragma once

#include <string>
#include <vector>

namespace framedyn::fem {

struct LoadPsd {
  std::vector<double> frequency_hz;  // strictly increasing, > 0
  std::vector<double> psd;           // > 0, 1/Hz
  double lowest() const { return frequency_hz.front(); }
  double highest() const { return frequency_hz.back(); }
  // S(f), log-log between the rows; f must lie in [lowest(), highest()].
  double at(double frequency_hz) const;
};

// Throws core::InputError naming the file and line for a file that cannot be
// read, a wrong header, a line that is not two numbers, a frequency or PSD
// that is not positive, frequencies that do not increase, or fewer than two rows.
LoadPsd read_load_psd(const std::string& path);

// Checks a table built in code (same rules; the messages name `source`).
void check_load_psd(const LoadPsd& psd, const std::string& source);

}  // namespace framedyn::fem
