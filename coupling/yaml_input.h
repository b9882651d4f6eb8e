// Strict reading of YAML study files: every value is looked up by its key
// path, unknown keys are errors, and every error names the file, the line,
// the key path, what was expected and what was found. Quantities are
// converted from the study's unit system to SI on the way in.
#pragma once

#include <yaml-cpp/yaml.h>

#include <Eigen/Dense>

#include <initializer_list>
#include <optional>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/units.h"

namespace framedyn::coupling {

class YamlMap {
 public:
  YamlMap(YAML::Node node, std::string path, std::string file, const core::UnitSystem* units);

  // Fails on keys not in `allowed` (call once per map with every key it may have).
  void allow_only(std::initializer_list<const char*> allowed) const;
  bool has(const std::string& key) const;

  YamlMap map(const std::string& key) const;                  // required sub-map
  std::optional<YamlMap> optional_map(const std::string& key) const;
  std::vector<YamlMap> list_of_maps(const std::string& key) const;  // missing key: empty

  double number(const std::string& key, core::Quantity q) const;  // required, converted to SI
  double number_or(const std::string& key, core::Quantity q, double fallback_si) const;
  double positive(const std::string& key, core::Quantity q) const;
  double non_negative(const std::string& key, core::Quantity q) const;
  double non_negative_or(const std::string& key, core::Quantity q, double fallback_si) const;
  double fraction(const std::string& key, double fallback) const;  // in [0, 1]
  Eigen::Vector2d point(const std::string& key) const;            // [X, Z], lengths
  std::string text(const std::string& key) const;
  std::string text_or(const std::string& key, const std::string& fallback) const;
  int integer(const std::string& key) const;
  bool boolean_or(const std::string& key, bool fallback) const;
  std::vector<std::string> strings(const std::string& key) const;  // missing key: empty
  std::vector<double> numbers(const std::string& key, core::Quantity q) const;  // missing key: empty

  // A mass given as `mass` or `weight` (exactly one), in SI kg.
  double mass(double gravity_si) const;

  core::InputError error(const std::string& key, const std::string& expected, const std::string& found) const;
  core::InputLocation location(const std::string& key) const;
  const std::string& path() const { return path_; }
  const std::string& file() const { return file_; }
  const core::UnitSystem& units() const { return *units_; }
  YAML::Node node() const { return node_; }

 private:
  YAML::Node node_;
  std::string path_, file_;
  const core::UnitSystem* units_;
  std::string child_path(const std::string& key) const;
  YAML::Node required(const std::string& key) const;
};

// Checks the `name` of each map in `items` (a list such as frame.added_masses)
// to be distinct, and none of `reserved`: a name labels the item's
// frame load and sweep parameters, which a second item of the same name
// would silently share. `what` names one item in messages ("added mass").
void require_distinct_names(const std::vector<YamlMap>& items, const std::string& what, const std::vector<std::string>& reserved = {});

// Loads a YAML file; a syntax error becomes an InputError with its line.
YAML::Node load_yaml_file(const std::string& file);
// How a node looks, for messages: "a list", "the text 'abc'", ...
std::string describe(const YAML::Node& node);

// A scalar that is a finite number, read into `v` (no units).
bool parse_number(const YAML::Node& n, double& v);

}  // namespace framedyn::coupling
