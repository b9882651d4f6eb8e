// Errors shared by every module. Two channels, as in Spectra and Drake:
// InputError for input that breaks a stated constraint (names the file, the
// line or key, what was expected and what was found); NumericalError for a
// numerical outcome the user must hear about (a mechanism, a non-converged
// eigensolver). Library code throws; only apps/ prints and chooses exit codes.
#pragma once

#include <stdexcept>
#include <string>

namespace framedyn::core {

// Where in an input a problem was found. line == 0 means "no line" (a key
// path or a command-line option is given in `key` instead).
struct InputLocation {
  std::string file;
  int line = 0;
  std::string key;
};

class InputError : public std::runtime_error {
 public:
  InputError(InputLocation where, const std::string& expected, const std::string& found);
  // For errors that are not "expected X, found Y" (a missing file, a cycle of includes).
  InputError(InputLocation where, const std::string& message);

  const InputLocation& where() const { return where_; }

 private:
  InputLocation where_;
};

class NumericalError : public std::runtime_error {
 public:
  explicit NumericalError(const std::string& explanation) : std::runtime_error(explanation) {}
};

std::string format_location(const InputLocation& where);

}  // namespace framedyn::core
