// Strict YAML access with key paths and units; see yaml_input.h.
#include "coupling/yaml_input.h"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>

namespace framedyn::coupling {

using core::InputError;
using core::InputLocation;
using core::Quantity;

std::string describe(const YAML::Node& node) {
  if (!node.IsDefined() || node.IsNull()) return "nothing";
  if (node.IsSequence()) return fmt::format("a list of {} item(s)", node.size());
  if (node.IsMap()) return "a map of keys";
  return "'" + node.Scalar() + "'";
}

namespace {
// yaml-cpp keeps both entries of a key given twice in one map, and lookups
// find the first: the second value would be silently ignored. Walks every
// map of the document and refuses a key given twice, naming both lines.
void require_unique_keys(const YAML::Node& node, const std::string& path, const std::string& file) {
  if (node.IsSequence()) {
    for (std::size_t i = 0; i < node.size(); ++i) require_unique_keys(node[i], fmt::format("{}[{}]", path, i), file);
    return;
  }
  if (!node.IsMap()) return;
  std::map<std::string, YAML::Mark> first;
  for (const auto& kv : node) {
    if (!kv.first.IsScalar()) continue;  // YamlMap::allow_only names it
    const std::string key = kv.first.Scalar();
    const std::string key_path = path.empty() ? key : path + "." + key;
    const YAML::Mark mark = kv.first.Mark();
    const auto [at, fresh] = first.emplace(key, mark);
    if (!fresh) {
      const YAML::Mark was = at->second;
      const std::string where = was.line == mark.line ? fmt::format("line {}, column {}", was.line + 1, was.column + 1) : fmt::format("line {}", was.line + 1);
      throw InputError({file, mark.line + 1, key_path}, "each key once in a map", fmt::format("'{}' a second time (first on {})", key, where));
    }
    require_unique_keys(kv.second, key_path, file);
  }
}
}  // namespace

YAML::Node load_yaml_file(const std::string& file) {
  if (std::filesystem::is_directory(file)) throw InputError({file, 0, ""}, "cannot read " + file + " (a directory)");
  std::ifstream in(file);
  if (!in) throw InputError({file, 0, ""}, "cannot open " + file + (std::filesystem::exists(file) ? "" : " (no such file)"));
  YAML::Node doc;
  try {
    doc = YAML::LoadFile(file);
  } catch (const YAML::Exception& e) {
    throw InputError({file, e.mark.line + 1, ""}, "valid YAML", e.msg);
  }
  require_unique_keys(doc, "", file);
  return doc;
}

YamlMap::YamlMap(YAML::Node node, std::string path, std::string file, const core::UnitSystem* units)
    : node_(std::move(node)), path_(std::move(path)), file_(std::move(file)), units_(units) {
  if (!node_.IsMap()) throw InputError({file_, node_.Mark().line + 1, path_.empty() ? "(top level)" : path_}, "a map of keys", describe(node_));
}

std::string YamlMap::child_path(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }

InputLocation YamlMap::location(const std::string& key) const {
  // No key: the map itself (a default YAML::Node is defined but has no mark).
  const YAML::Node n = key.empty() ? node_ : node_[key];
  const int line = (n.IsDefined() ? n.Mark().line : node_.Mark().line) + 1;
  return {file_, line > 0 ? line : 0, key.empty() ? path_ : child_path(key)};
}

InputError YamlMap::error(const std::string& key, const std::string& expected, const std::string& found) const {
  return InputError(location(key), expected, found);
}

void YamlMap::allow_only(std::initializer_list<const char*> allowed) const {
  for (const auto& kv : node_) {
    if (!kv.first.IsScalar())
      throw InputError({file_, kv.first.Mark().line + 1, path_}, "keys that are plain words", "a key that is " + describe(kv.first));
    const std::string key = kv.first.as<std::string>();
    bool ok = false;
    for (const char* a : allowed) ok = ok || key == a;
    if (!ok) {
      std::string list;
      for (const char* a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
      throw InputError({file_, kv.first.Mark().line + 1, child_path(key)}, "one of the keys " + list, "unknown key '" + key + "'");
    }
  }
}

bool YamlMap::has(const std::string& key) const { return node_[key].IsDefined() && !node_[key].IsNull(); }

YAML::Node YamlMap::required(const std::string& key) const {
  if (!has(key)) throw InputError({file_, node_.Mark().line + 1, child_path(key)}, "a value for this required key", "none");
  return node_[key];
}

YamlMap YamlMap::map(const std::string& key) const {
  const YAML::Node n = required(key);
  if (!n.IsMap()) throw error(key, "a map of keys", describe(n));
  return YamlMap(n, child_path(key), file_, units_);
}

std::optional<YamlMap> YamlMap::optional_map(const std::string& key) const {
  if (!has(key)) return std::nullopt;
  return map(key);
}

std::vector<YamlMap> YamlMap::list_of_maps(const std::string& key) const {
  std::vector<YamlMap> out;
  if (!has(key)) return out;
  const YAML::Node n = node_[key];
  if (!n.IsSequence()) throw error(key, "a list", describe(n));
  for (std::size_t i = 0; i < n.size(); ++i) {
    if (!n[i].IsMap()) throw InputError({file_, n[i].Mark().line + 1, fmt::format("{}[{}]", child_path(key), i)}, "a map of keys", describe(n[i]));
    out.emplace_back(n[i], fmt::format("{}[{}]", child_path(key), i), file_, units_);
  }
  return out;
}

bool parse_number(const YAML::Node& n, double& v) {
  if (!n.IsScalar()) return false;
  const std::string s = n.Scalar();
  char* end = nullptr;
  v = std::strtod(s.c_str(), &end);
  return !s.empty() && end == s.c_str() + s.size() && std::isfinite(v);
}

namespace {

// The largest magnitude of a value in SI units: 1e308 lbf/in is finite in the
// file and inf in N/m, and beyond 1e300 the machine's matrices (sums of
// products of these) could overflow.
constexpr double kLargestSi = 1e300;
bool in_range(double si) { return std::abs(si) <= kLargestSi; }
}  // namespace

double YamlMap::number(const std::string& key, Quantity q) const {
  const YAML::Node n = required(key);
  double v = 0;
  if (!parse_number(n, v)) throw error(key, fmt::format("a finite number ({})", units_->label(q)), describe(n));
  const double si = units_->to_si(v, q);
  if (!in_range(si)) throw error(key, fmt::format("a number ({}) of magnitude at most 1e300 in SI units", units_->label(q)), describe(n));
  return si;
}

double YamlMap::number_or(const std::string& key, Quantity q, double fallback) const { return has(key) ? number(key, q) : fallback; }

double YamlMap::positive(const std::string& key, Quantity q) const {
  const double v = number(key, q);
  if (!(v > 0)) throw error(key, fmt::format("a positive number ({})", units_->label(q)), describe(node_[key]));
  return v;
}

double YamlMap::non_negative(const std::string& key, Quantity q) const {
  const double v = number(key, q);
  if (v < 0) throw error(key, fmt::format("a number >= 0 ({})", units_->label(q)), describe(node_[key]));
  return v;
}

double YamlMap::non_negative_or(const std::string& key, Quantity q, double fallback) const {
  return has(key) ? non_negative(key, q) : fallback;
}

double YamlMap::fraction(const std::string& key, double fallback) const {
  if (!has(key)) return fallback;
  const double v = number(key, Quantity::dimensionless);
  if (v < 0 || v > 1) throw error(key, "a reduction factor between 0 and 1", describe(node_[key]));
  return v;
}

Eigen::Vector2d YamlMap::point(const std::string& key) const {
  const YAML::Node n = required(key);
  double x = 0, z = 0;
  if (!n.IsSequence() || n.size() != 2 || !parse_number(n[0], x) || !parse_number(n[1], z))
    throw error(key, fmt::format("a point [X, Z] of two numbers ({})", units_->label(Quantity::length)), describe(n));
  const Eigen::Vector2d p(units_->to_si(x, Quantity::length), units_->to_si(z, Quantity::length));
  if (!in_range(p.x()) || !in_range(p.y()))
    throw error(key, fmt::format("a point [X, Z] of two numbers ({}) of magnitude at most 1e300 in SI units", units_->label(Quantity::length)),
                fmt::format("[{}, {}]", n[0].Scalar(), n[1].Scalar()));
  return p;
}

std::string YamlMap::text(const std::string& key) const {
  const YAML::Node n = required(key);
  if (!n.IsScalar()) throw error(key, "a text value", describe(n));
  return n.Scalar();
}

void require_distinct_names(const std::vector<YamlMap>& items, const std::string& what, const std::vector<std::string>& reserved) {
  std::vector<std::string> names;
  for (std::size_t i = 0; i < items.size(); ++i) {
    const std::string name = items[i].text("name");
    for (const std::string& r : reserved)
      if (name == r) {
        std::string list;
        for (const std::string& n : reserved) list += (list.empty() ? "" : ", ") + n;
        throw items[i].error("name", "a name other than those of the machine's own frame loads (" + list + ")", "'" + name + "'");
      }
    for (std::size_t k = 0; k < i; ++k)
      if (names[k] == name)
        throw items[i].error("name", "a name no other " + what + " has", fmt::format("'{}', also the name of {} (line {})", name, items[k].path(),
                                                                                      items[k].location("name").line));
    names.push_back(name);
  }
}

std::string YamlMap::text_or(const std::string& key, const std::string& fallback) const { return has(key) ? text(key) : fallback; }

int YamlMap::integer(const std::string& key) const {
  const YAML::Node n = required(key);
  double v = 0;
  if (!parse_number(n, v) || v != std::floor(v) || std::abs(v) > 1e9) throw error(key, "an integer", describe(n));
  return static_cast<int>(v);
}

bool YamlMap::boolean_or(const std::string& key, bool fallback) const {
  if (!has(key)) return fallback;
  const YAML::Node n = node_[key];
  const std::string s = n.IsScalar() ? n.Scalar() : "";
  if (s == "true" || s == "yes") return true;
  if (s == "false" || s == "no") return false;
  throw error(key, "true or false", describe(n));
}

std::vector<std::string> YamlMap::strings(const std::string& key) const {
  std::vector<std::string> out;
  if (!has(key)) return out;
  const YAML::Node n = node_[key];
  if (!n.IsSequence()) throw error(key, "a list of names", describe(n));
  for (const auto& item : n) {
    if (!item.IsScalar()) throw error(key, "a list of names", describe(n));
    out.push_back(item.Scalar());
  }
  return out;
}

std::vector<double> YamlMap::numbers(const std::string& key, Quantity q) const {
  std::vector<double> out;
  if (!has(key)) return out;
  const YAML::Node n = node_[key];
  if (!n.IsSequence()) throw error(key, "a list of numbers", describe(n));
  for (const auto& item : n) {
    double v = 0;
    if (!parse_number(item, v)) throw error(key, "a list of numbers", describe(item));
    const double si = units_->to_si(v, q);
    if (!in_range(si)) throw error(key, fmt::format("a list of numbers ({}) of magnitude at most 1e300 in SI units", units_->label(q)), describe(item));
    out.push_back(si);
  }
  return out;
}

double YamlMap::mass(double gravity) const {
  if (has("mass") == has("weight"))
    throw error("", "exactly one of 'mass' or 'weight'", has("mass") ? "both" : "neither");
  if (has("mass")) return positive("mass", Quantity::mass);
  return positive("weight", Quantity::force) / gravity;
}

}  // namespace framedyn::coupling
