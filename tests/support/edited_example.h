// A shipped study (a file under examples/) read as text, with edits applied:
// for tests that run a shipped machine with one key changed.
#pragma once

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace framedyn::testing {

// The text of examples/<example> (FRAMEDYN_SOURCE_DIR, set for every test target).
inline std::string example_text(const std::string& example) {
  std::ifstream in(std::string(FRAMEDYN_SOURCE_DIR) + "/examples/" + example);
  if (!in) throw std::runtime_error("test example: cannot read examples/" + example);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// The text of examples/<example> with each (from, to) edit applied in order, to
// the first occurrence of `from`; a `from` that is not there throws, naming it.
inline std::string edited_example_text(const std::string& example,
                                       const std::vector<std::pair<std::string, std::string>>& edits) {
  std::string s = example_text(example);
  for (const auto& [from, to] : edits) {
    const std::size_t at = s.find(from);
    if (at == std::string::npos) throw std::runtime_error("test edit: '" + from + "' not in " + example);
    s.replace(at, from.size(), to);
  }
  return s;
}

}  // namespace framedyn::testing
