// Key paths into YAML documents; see key_path.h.
#include "batch/key_path.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>

namespace framedyn::batch {

namespace {

std::string shown(const std::vector<KeyPathStep>& steps, std::size_t n) {
  std::string s;
  for (std::size_t i = 0; i < n; ++i) {
    const KeyPathStep& k = steps[i];
    if (!k.is_item) s += (s.empty() ? "" : ".") + k.key;
    else s += k.by_name ? "[" + k.name + "]" : fmt::format("[{}]", k.index);
  }
  return s;
}

// A short account of a node for messages: "a number (300)", "a map", ...
std::string what_is(const YAML::Node& n) {
  if (n.IsMap()) return "a map";
  if (n.IsSequence()) return fmt::format("a list of {} items", n.size());
  if (n.IsScalar()) return "'" + n.Scalar() + "'";
  return "nothing";
}

std::string keys_of(const YAML::Node& map) {
  std::string s;
  for (const auto& kv : map) s += (s.empty() ? "" : ", ") + kv.first.Scalar();
  return s;
}

bool parse_double(const std::string& text, double& v) {
  if (text.empty()) return false;
  char* end = nullptr;
  v = std::strtod(text.c_str(), &end);
  return end == text.c_str() + text.size() && std::isfinite(v);
}

}  // namespace

std::vector<KeyPathStep> parse_key_path(const std::string& path) {
  std::vector<KeyPathStep> steps;
  std::size_t i = 0;
  const auto bad = [&](const std::string& why) { return KeyPathError(fmt::format("'{}' is not a key path ({})", path, why)); };
  if (path.empty()) throw bad("it is empty");
  while (i < path.size()) {
    if (path[i] == '[') {
      const std::size_t close = path.find(']', i);
      if (close == std::string::npos) throw bad("a '[' without its ']'");
      const std::string inside = path.substr(i + 1, close - i - 1);
      if (inside.empty()) throw bad("an empty []");
      KeyPathStep s;
      s.is_item = true;
      if (inside.find_first_not_of("0123456789") == std::string::npos && inside.size() < 10) {
        s.index = std::stoul(inside);
      } else {
        s.by_name = true;
        s.name = inside;
      }
      steps.push_back(s);
      i = close + 1;
      if (i < path.size() && path[i] == '.') {
        ++i;
        if (i == path.size()) throw bad("it ends with '.'");
      }
      continue;
    }
    const std::size_t end = path.find_first_of(".[]", i);
    const std::string key = path.substr(i, end == std::string::npos ? std::string::npos : end - i);
    if (key.empty()) throw bad("an empty key");
    if (end != std::string::npos && path[end] == ']') throw bad("a ']' without its '['");
    steps.push_back({key, false, false, 0, {}});
    i = end == std::string::npos ? path.size() : end;
    if (i < path.size() && path[i] == '.') {
      ++i;
      if (i == path.size()) throw bad("it ends with '.'");
    }
  }
  return steps;
}

YAML::Node find_key(const YAML::Node& doc, const std::string& path, const std::string& what) {
  const std::vector<KeyPathStep> steps = parse_key_path(path);
  YAML::Node n = doc;
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const KeyPathStep& k = steps[i];
    const std::string here = i == 0 ? what : what + "'s " + shown(steps, i);
    if (!k.is_item) {
      if (!n.IsMap()) throw KeyPathError(fmt::format("{} is {}, not a map with the key '{}'", here, what_is(n), k.key));
      YAML::Node next = n[k.key];
      if (!next.IsDefined()) throw KeyPathError(fmt::format("{} has no key '{}' (it has {})", here, k.key, keys_of(n)));
      n.reset(next);
      continue;
    }
    if (!n.IsSequence()) throw KeyPathError(fmt::format("{} is {}, not a list", here, what_is(n)));
    if (!k.by_name) {
      if (k.index >= n.size()) throw KeyPathError(fmt::format("{} has {} items (positions 0 to {}), not [{}]", here, n.size(), n.size() - 1, k.index));
      YAML::Node next = n[k.index];
      n.reset(next);
      continue;
    }
    std::string names;
    YAML::Node found;
    bool have = false;
    for (std::size_t j = 0; j < n.size(); ++j) {
      const YAML::Node item = n[j];
      if (!item.IsMap() || !item["name"] || !item["name"].IsScalar()) continue;
      names += (names.empty() ? "" : ", ") + item["name"].Scalar();
      if (item["name"].Scalar() == k.name && !have) {
        found.reset(item);
        have = true;
      }
    }
    if (!have)
      throw KeyPathError(fmt::format("{} has no item named '{}' ({})", here, k.name, names.empty() ? "its items have no names" : "it has " + names));
    n.reset(found);
  }
  return n;
}

double get_number(const YAML::Node& doc, const std::string& path, const std::string& what) {
  const YAML::Node n = find_key(doc, path, what);
  double v = 0.0;
  if (!n.IsScalar() || !parse_double(n.Scalar(), v))
    throw KeyPathError(fmt::format("{}'s {} is {}, not a number", what, path, what_is(n)));
  return v;
}

void set_number(YAML::Node& doc, const std::string& path, double value, const std::string& what) {
  get_number(doc, path, what);  // a number there, or the error
  YAML::Node n = find_key(doc, path, what);
  n = fmt::format("{}", value);  // shortest text that reads back as `value`
}

}  // namespace framedyn::batch
