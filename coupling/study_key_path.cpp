// A study document's number by key path; see study_key_path.h.
#include "coupling/study_key_path.h"

#include <yaml-cpp/yaml.h>

#include <fmt/format.h>

#include <cmath>

#include "coupling/yaml_input.h"

namespace framedyn::coupling {

const char* const kKeyPathForm = "a key path: keys joined by '.', a list item as key[index] or key[name]";

namespace {

std::string keys_of(const YAML::Node& map) {
  std::string keys;
  for (const auto& kv : map) keys += (keys.empty() ? "" : ", ") + kv.first.as<std::string>();
  return keys.empty() ? "no keys" : keys;
}

int line_of(const YAML::Node& n) { return n.Mark().line + 1; }

}  // namespace

std::optional<std::vector<KeyPathStep>> parse_key_path(const std::string& path) {
  std::vector<KeyPathStep> steps;
  std::size_t i = 0;
  while (i < path.size()) {
    if (path[i] == '[') {
      const std::size_t close = path.find(']', i);
      if (close == std::string::npos || close == i + 1) return std::nullopt;
      const std::string inside = path.substr(i + 1, close - i - 1);
      if (inside.find_first_of("[.") != std::string::npos) return std::nullopt;
      KeyPathStep s;
      s.is_item = true;
      if (inside.find_first_not_of("0123456789") == std::string::npos && inside.size() < 10) s.index = std::stoul(inside);
      else s.by_name = true, s.name = inside;
      steps.push_back(s);
      i = close + 1;
    } else {
      const std::size_t end = path.find_first_of(".[]", i);
      const std::string key = path.substr(i, end == std::string::npos ? std::string::npos : end - i);
      if (key.empty() || (end != std::string::npos && path[end] == ']')) return std::nullopt;
      steps.push_back({key, false, false, 0, {}});
      i = end == std::string::npos ? path.size() : end;
    }
    if (i < path.size() && path[i] == '.') {
      ++i;
      if (i == path.size() || path[i] == '[') return std::nullopt;
    } else if (i < path.size() && path[i] != '[') {
      return std::nullopt;
    }
  }
  if (steps.empty()) return std::nullopt;
  return steps;
}

std::string key_path_text(const std::vector<KeyPathStep>& steps, std::size_t n) {
  std::string s;
  for (std::size_t i = 0; i < n && i < steps.size(); ++i) {
    const KeyPathStep& k = steps[i];
    if (!k.is_item) s += (s.empty() ? "" : ".") + k.key;
    else s += k.by_name ? "[" + k.name + "]" : fmt::format("[{}]", k.index);
  }
  return s;
}

YAML::Node find_study_key(const YAML::Node& doc, const std::string& key_path, const std::string& file) {
  const std::optional<std::vector<KeyPathStep>> steps = parse_key_path(key_path);
  if (!steps) throw core::InputError({file, 0, key_path}, kKeyPathForm, "'" + key_path + "'");
  // yaml-cpp: `a = b` on a Node writes b's value into what a refers to; reset() moves a reference.
  YAML::Node node;
  node.reset(doc);
  for (std::size_t i = 0; i < steps->size(); ++i) {
    const KeyPathStep& s = (*steps)[i];
    const std::string so_far = key_path_text(*steps, i);
    if (!s.is_item) {
      if (!node.IsMap() || !node[s.key])
        throw core::InputError({file, line_of(node), key_path},
                               fmt::format("a key of the study ({} has {})", so_far.empty() ? "the top level" : so_far, node.IsMap() ? keys_of(node) : describe(node)),
                               "no key '" + s.key + "'");
      node.reset(node[s.key]);
      continue;
    }
    const std::string list = so_far.empty() ? "the top level" : so_far;
    if (!node.IsSequence()) throw core::InputError({file, line_of(node), key_path}, "a list at " + list, describe(node));
    YAML::Node found;
    bool have = false;
    if (!s.by_name) {
      if (s.index < node.size()) found.reset(node[s.index]), have = true;
    } else {
      for (std::size_t k = 0; k < node.size() && !have; ++k)
        if (node[k].IsMap() && node[k]["name"] && node[k]["name"].IsScalar() && node[k]["name"].Scalar() == s.name) found.reset(node[k]), have = true;
    }
    if (!have)
      throw core::InputError({file, line_of(node), key_path},
                             fmt::format("an item of {} (index 0 to {}, or the name of an item)", list, node.size() == 0 ? 0 : node.size() - 1),
                             "no item '" + (s.by_name ? s.name : std::to_string(s.index)) + "'");
    node.reset(found);
  }
  return node;
}

double study_number(const YAML::Node& doc, const std::string& key_path, const std::string& file) {
  const YAML::Node node = find_study_key(doc, key_path, file);
  double v = 0.0;
  if (!node.IsScalar() || !parse_number(node, v))
    throw core::InputError({file, line_of(node), key_path}, "a number there (a key path sets numbers only)", describe(node));
  return v;
}

void set_study_number(YAML::Node& doc, const std::string& key_path, double value, const std::string& file) {
  study_number(doc, key_path, file);  // a number there, or the error
  YAML::Node node = find_study_key(doc, key_path, file);
  if (!std::isfinite(value)) throw core::InputError({file, line_of(node), key_path}, "a finite number", fmt::format("{}", value));
  node = fmt::format("{}", value);  // shortest text that reads back to the same double
}

}  // namespace framedyn::coupling
