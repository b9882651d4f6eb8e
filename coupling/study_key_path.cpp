// A study document's number by key path; see study_key_path.h.
#include "coupling/study_key_path.h"

#include <yaml-cpp/yaml.h>

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>

#include "coupling/yaml_input.h"

namespace framedyn::coupling {

namespace {

struct Segment {
  std::string key;
  bool has_item = false;
  std::string item;  // index or name inside [...]
};

bool parse_path(const std::string& path, std::vector<Segment>& out) {
  std::size_t i = 0;
  while (i < path.size()) {
    Segment s;
    while (i < path.size() && path[i] != '.' && path[i] != '[') s.key += path[i++];
    if (s.key.empty()) return false;
    if (i < path.size() && path[i] == '[') {
      const std::size_t close = path.find(']', i);
      if (close == std::string::npos || close == i + 1) return false;
      s.has_item = true;
      s.item = path.substr(i + 1, close - i - 1);
      i = close + 1;
    }
    out.push_back(s);
    if (i < path.size()) {
      if (path[i] != '.' || i + 1 == path.size()) return false;
      ++i;
    }
  }
  return !out.empty();
}

std::string keys_of(const YAML::Node& map) {
  std::string keys;
  for (const auto& kv : map) keys += (keys.empty() ? "" : ", ") + kv.first.as<std::string>();
  return keys.empty() ? "no keys" : keys;
}

int line_of(const YAML::Node& n) { return n.Mark().line + 1; }

}  // namespace

void set_study_number(YAML::Node& doc, const std::string& key_path, double value, const std::string& file) {
  std::vector<Segment> path;
  if (!parse_path(key_path, path))
    throw core::InputError({file, 0, key_path}, "a key path: keys joined by '.', a list item as key[index] or key[name]", "'" + key_path + "'");
  // yaml-cpp: `a = b` on a Node writes b's value into what a refers to; reset() moves a reference.
  YAML::Node node;
  node.reset(doc);
  std::string so_far;
  for (const Segment& s : path) {
    const std::string here = so_far.empty() ? s.key : so_far + "." + s.key;
    if (!node.IsMap() || !node[s.key])
      throw core::InputError({file, line_of(node), key_path}, fmt::format("a key of the study ({} has {})", so_far.empty() ? "the top level" : so_far,
                                                                          node.IsMap() ? keys_of(node) : describe(node)),
                             "no key '" + s.key + "'");
    node.reset(node[s.key]);
    so_far = here;
    if (s.has_item) {
      if (!node.IsSequence()) throw core::InputError({file, line_of(node), key_path}, "a list at " + so_far, describe(node));
      YAML::Node found;
      bool have = false;
      char* end = nullptr;
      const long index = std::strtol(s.item.c_str(), &end, 10);
      if (*end == '\0') {
        if (index >= 0 && static_cast<std::size_t>(index) < node.size()) found.reset(node[static_cast<std::size_t>(index)]), have = true;
      } else {
        for (std::size_t k = 0; k < node.size(); ++k)
          if (node[k].IsMap() && node[k]["name"] && node[k]["name"].IsScalar() && node[k]["name"].Scalar() == s.item && !have)
            found.reset(node[k]), have = true;
      }
      if (!have)
        throw core::InputError({file, line_of(node), key_path},
                               fmt::format("an item of {} (index 0 to {}, or the name of an item)", so_far, node.size() == 0 ? 0 : node.size() - 1),
                               "no item '" + s.item + "'");
      node.reset(found);
      so_far += "[" + s.item + "]";
    }
  }
  double old = 0.0;
  if (!node.IsScalar() || !parse_number(node, old))
    throw core::InputError({file, line_of(node), key_path}, "a number there (a key path sets numbers only)", describe(node));
  if (!std::isfinite(value)) throw core::InputError({file, line_of(node), key_path}, "a finite number", fmt::format("{}", value));
  node = fmt::format("{}", value);  // shortest text that reads back to the same double
}

}  // namespace framedyn::coupling
