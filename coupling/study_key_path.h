// Key paths into a study document: how the Python module's Study.set and a
// design study (`framedyn batch`: the numbers it varies, the summary outputs it
// collects) name one number of a study (docs/user-guide.md, "Python" and
// "framedyn batch"):
//   key.key      a key of a map (`soil.damping`, `plow.shaker.frequency_hz`);
//   key[3]       an item of a list by its position, counted from 0;
//   key[engine]  the item of a list of maps whose `name:` is engine
//                (`frame.parts[engine].weight`, `cab.mounts[FL].z.stiffness`).
// The key must exist and hold a number: a path may change a value, never add a
// key or replace a map, a list or a text, so a typo cannot pass silently. The
// value is written in the study's own units (what the YAML file would say),
// with the fewest digits that read back to the same double.
// One walker, one error set (docs/errors.md, PY-01 to PY-05).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace YAML {
class Node;
}

namespace framedyn::coupling {

struct KeyPathStep {
  std::string key;  // a map key; empty for a list item
  bool is_item = false;
  bool by_name = false;  // [name] rather than [index]
  std::size_t index = 0;
  std::string name;
};

// What a key path looks like, for messages that refuse one.
extern const char* const kKeyPathForm;

// The steps of `path`; none if it is not key[.key...] with [index] or [name] items.
std::optional<std::vector<KeyPathStep>> parse_key_path(const std::string& path);
// `path`'s first `n` steps as text ("frame.parts[engine]").
std::string key_path_text(const std::vector<KeyPathStep>& steps, std::size_t n);

// The node at `path` (a handle into `doc`: assigning to it changes `doc`).
// Throws core::InputError naming `file`, the line of the deepest key found and
// the key path: not a key path (PY-04), an unknown key (PY-01), a list item
// that is not there (PY-02).
YAML::Node find_study_key(const YAML::Node& doc, const std::string& key_path, const std::string& file);
// The number at `path`; throws as find_study_key does, and if the key holds no number (PY-03).
double study_number(const YAML::Node& doc, const std::string& key_path, const std::string& file);
// Sets the number at `path` to `value`; throws as study_number does, and on a value that is not finite (PY-05).
void set_study_number(YAML::Node& doc, const std::string& key_path, double value, const std::string& file);

}  // namespace framedyn::coupling
