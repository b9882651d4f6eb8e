// Setting one number of a study document by its key path (issue 20; the Python
// module's Study.set, docs/user-guide.md "Python"): `soil.damping`,
// `shaker.frequency`, a list item by index or by its `name`:
// `frame.parts[engine].weight`, `frame.parts[1].weight`. The key must exist
// and hold a number: a path may change a value, never add a key or replace a
// map, a list or a text, so a typo cannot pass silently. The value is written
// in the study's own units (what the YAML file would say), with the digits
// that read back to the same double.
#pragma once

#include <string>

namespace YAML {
class Node;
}

namespace framedyn::coupling {

// Throws core::InputError naming `file`, the line of the deepest key found and
// the key path: an unknown key (PY-01), a list item that is not there (PY-02),
// a target that is not a number (PY-03), a path that is not key[.key...] (PY-04).
void set_study_number(YAML::Node& doc, const std::string& key_path, double value, const std::string& file);

}  // namespace framedyn::coupling
