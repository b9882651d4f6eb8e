// Key paths into a YAML document: how a design study names the number it
// varies (`soil.damping`, `plow.shaker.frequency_hz`) and the output it
// collects from a run's summary (`frame.peak_normal_stress`).
//   key.key      a key of a map;
//   key[3]       an item of a list by its position, counted from 0;
//   key[engine]  the item of a list of maps whose `name:` is engine
//                (`frame.parts[engine].weight`, `cab.mounts[FL].z.stiffness`).
// docs/user-guide.md, "framedyn batch".
#pragma once

#include <yaml-cpp/yaml.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace framedyn::batch {

struct KeyPathStep {
  std::string key;  // a map key; empty for a list item
  bool is_item = false;
  bool by_name = false;
  std::size_t index = 0;
  std::string name;
};

// A key path that names nothing in the document, or that is malformed:
// what() says what the document has there ("the study's soil has no key 'dampin'
// (it has stiffness, damping, ...)").
class KeyPathError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Throws KeyPathError on a malformed path ("soil..damping", "parts[", "").
std::vector<KeyPathStep> parse_key_path(const std::string& path);

// The node at `path` (a handle into `doc`: assigning to it changes `doc`).
// Throws KeyPathError naming the first step the document does not have;
// `what` names the document in messages ("the study", "the summary").
YAML::Node find_key(const YAML::Node& doc, const std::string& path, const std::string& what);

// Sets the number at `path` (a key the document has, holding a number) to
// `value`, written with the fewest digits that read back as exactly `value`.
// Throws KeyPathError if the key is absent or does not hold a number.
void set_number(YAML::Node& doc, const std::string& path, double value, const std::string& what = "the study");
// The number at `path`; throws KeyPathError as set_number does.
double get_number(const YAML::Node& doc, const std::string& path, const std::string& what = "the study");

}  // namespace framedyn::batch
