// Every number framedyn writes carries its unit (issue 14, item 5): a shipped
// study run in its own units (in-lbf-s) and the same study converted to SI
// (every length, force, stiffness ... of the file multiplied by its factor to
// SI, units: m-N-s) must give the same numbers in every output after
// conversion by the units the outputs name: summary.json (each {value, unit};
// a bare number must be the same in both runs), events.csv (the blade's
// position in the text) and every CSV (each column by its "[unit]"). A number
// written in SI but labelled in inches (events.csv gave "x5 = 0.0004 m" for
// an inch study) or labelled "1" but holding kg m^2 (frame.parts.
// inertia_scale) makes the two runs disagree.
#include <gtest/gtest.h>

#include <yaml-cpp/yaml.h>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "core/units.h"
#include "tests/support/run_framedyn.h"
#include "tests/support/temp_dir.h"

namespace {

namespace fs = std::filesystem;
using framedyn::core::Quantity;
using framedyn::core::UnitSystem;
using framedyn::testing::framedyn;
using framedyn::testing::read_file;
using framedyn::testing::TempDir;

const fs::path kExamples = fs::path(FRAMEDYN_SOURCE_DIR) / "examples";

// ------------------------------------------------------------ the study in SI

// The quantity of a study key (its name, and its parent's for the swing
// spring, whose stiffness and damping are per radian); numbers under keys of
// kPlain are the same in every unit system. Any other number is an error of
// this table, so that no key is left unconverted unnoticed.
const std::set<std::string> kPlain = {"framedyn_study", "slope_deg", "steering_deg", "boom_angle_deg", "blade_angle_deg", "phase_deg", "frequency_hz",
                                      "duration", "output_interval", "rk4_step", "stiffness_reduction", "damping_reduction", "travel_angle_deg"};
Quantity quantity_of(const std::string& key, const std::string& parent) {
  static const std::set<std::string> lengths = {"front_end", "length", "radius_of_gyration", "radii_of_gyration", "position", "attachment", "contact",
                                                "cg", "upper_pivot", "lower_pivot", "upper_joint", "lower_joint", "blade_point", "point", "frame_point",
                                                "arm_point", "base", "points", "height", "top_fiber", "swing_pin", "pin", "leveling_cylinder",
                                                "boom_offset"};
  if (lengths.count(key)) return Quantity::length;
  if (key == "weight" || key == "force") return Quantity::force;
  if (key == "weight_per_length") return Quantity::force_per_length;
  if (key == "forward_speed") return Quantity::velocity;
  if (key == "area") return Quantity::area;
  if (key == "second_moment") return Quantity::second_moment_of_area;
  if (parent == "swing_spring" && (key == "stiffness" || key == "damping")) return Quantity::rotational_stiffness;  // per rad (times s)
  if (key == "stiffness") return Quantity::translational_stiffness;
  if (key == "damping") return Quantity::translational_damping;
  throw std::runtime_error("test_output_units: no quantity for the study key '" + parent + "." + key + "'");
}

std::string number_text(double v) { return fmt::format("{:.17g}", v); }

void convert(YAML::Node node, const std::string& key, const std::string& parent, const UnitSystem& from) {
  if (node.IsMap()) {
    for (auto kv : node) convert(kv.second, kv.first.Scalar(), key, from);
  } else if (node.IsSequence()) {
    for (std::size_t i = 0; i < node.size(); ++i) convert(node[i], key, parent, from);
  } else if (node.IsScalar()) {
    char* end = nullptr;
    const std::string s = node.Scalar();
    const double v = std::strtod(s.c_str(), &end);
    if (s.empty() || end != s.c_str() + s.size() || kPlain.count(key)) return;  // text, or the same in SI
    node = number_text(from.to_si(v, quantity_of(key, parent)));
  }
}

std::string study_in_si(const fs::path& study) {
  YAML::Node doc = YAML::LoadFile(study.string());
  const UnitSystem from = UnitSystem::from_name(doc["units"].Scalar());
  doc["units"] = "m-N-s";
  doc["name"] = doc["name"].Scalar() + " (SI)";
  for (auto kv : doc)
    if (kv.first.Scalar() != "units" && kv.first.Scalar() != "name") convert(kv.second, kv.first.Scalar(), "", from);
  YAML::Emitter out;
  out << doc;
  return std::string(out.c_str()) + "\n";
}

// ------------------------------------------------------------ comparing outputs

// Factor to SI of every unit label either system writes.
double to_si(const std::string& label) {
  static const std::map<std::string, double> factors = [] {
    std::map<std::string, double> f = {{"1", 1.0}, {"", 1.0}, {"rad", 1.0}, {"s", 1.0}, {"Hz", 1.0}, {"rad/s", 1.0}, {"rad/s^2", 1.0}};
    for (const char* name : {"in-lbf-s", "m-N-s"}) {
      const UnitSystem u = UnitSystem::from_name(name);
      for (int q = static_cast<int>(Quantity::dimensionless); q <= static_cast<int>(Quantity::time); ++q) {
        const auto [at, fresh] = f.emplace(u.label(static_cast<Quantity>(q)), u.to_si_factor(static_cast<Quantity>(q)));
        if (!fresh && std::abs(at->second - u.to_si_factor(static_cast<Quantity>(q))) > 1e-15 * at->second)
          throw std::runtime_error("two factors for the label " + at->first);
      }
    }
    return f;
  }();
  const auto at = factors.find(label);
  if (at == factors.end()) throw std::runtime_error("test_output_units: no factor for the unit '" + label + "'");
  return at->second;
}

// A unit label either of the system's own or one that is the same in every
// system: an inch study writes no metres, an SI study no inches.
bool label_of(const std::string& label, const std::string& system) {
  static const std::set<std::string> common = {"", "1", "s", "rad", "Hz", "rad/s", "rad/s^2"};
  if (common.count(label)) return true;
  const UnitSystem u = UnitSystem::from_name(system);
  for (int q = static_cast<int>(Quantity::dimensionless); q <= static_cast<int>(Quantity::time); ++q)
    if (u.label(static_cast<Quantity>(q)) == label) return true;
  return false;
}

// Two numbers, each in SI, agree to round-off and the integrator's tolerance
// (both runs compute in SI; only the inputs' last bits differ). `scale`: the
// size of the numbers they are compared among (a column, or the number).
::testing::AssertionResult agree(double a, double b, double scale, const std::string& where, double relative = 1e-6) {
  if (std::abs(a - b) <= relative * std::max({std::abs(a), std::abs(b)}) + 1e-6 * scale) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << where << ": " << a << " (own units, in SI) against " << b << " (SI run)";
}

void compare_json(const nlohmann::json& a, const nlohmann::json& b, const std::string& path, int& numbers) {
  ASSERT_EQ(a.type(), b.type()) << path;
  if (a.is_object()) {
    if (a.contains("value") && a.contains("unit") && a["value"].is_number()) {
      const std::string ua = a["unit"], ub = b["unit"];
      EXPECT_TRUE(label_of(ua, "in-lbf-s")) << path << ": '" << ua << "' in an inch study";
      EXPECT_TRUE(label_of(ub, "m-N-s")) << path << ": '" << ub << "' in an SI study";
      const double va = a["value"].get<double>() * to_si(ua), vb = b["value"].get<double>() * to_si(ub);
      EXPECT_TRUE(agree(va, vb, std::abs(va), path + " [" + ua + " / " + ub + "]"));
      ++numbers;
    }
    const auto numbers_only = [](const nlohmann::json& v) {
      return v.is_array() && std::all_of(v.begin(), v.end(), [](const nlohmann::json& e) { return e.is_number(); });
    };
    if (a.contains("value") && a.contains("unit") && numbers_only(a["value"])) {  // {value: [v0, v1, ...], unit}
      const std::string ua = a["unit"], ub = b["unit"];
      EXPECT_TRUE(label_of(ua, "in-lbf-s")) << path << ": '" << ua << "' in an inch study";
      EXPECT_TRUE(label_of(ub, "m-N-s")) << path << ": '" << ub << "' in an SI study";
      ASSERT_EQ(a["value"].size(), b["value"].size()) << path;
      double scale = 0.0;
      for (const auto& v : a["value"]) scale = std::max(scale, std::abs(v.get<double>() * to_si(ua)));
      for (std::size_t i = 0; i < a["value"].size(); ++i) {
        const double va = a["value"][i].get<double>() * to_si(ua), vb = b["value"][i].get<double>() * to_si(ub);
        EXPECT_TRUE(agree(va, vb, scale, path + "[" + std::to_string(i) + "] [" + ua + " / " + ub + "]"));
        ++numbers;
      }
    }
    // The calibration's parameters: {name, unit, initial, fitted, ratio}, the
    // numbers other than the ratio in the object's unit.
    const bool unit_for_all = a.contains("unit") && a["unit"].is_string() && !a.contains("value");
    for (auto it = a.begin(); it != a.end(); ++it) {
      if (it.key() == "value" && a.contains("unit")) continue;
      if (unit_for_all && it.value().is_number() && it.key() != "ratio") {
        const std::string ua = a["unit"], ub = b["unit"];
        const double va = it.value().get<double>() * to_si(ua), vb = b[it.key()].get<double>() * to_si(ub);
        EXPECT_TRUE(agree(va, vb, std::abs(va), path + "." + it.key() + " [" + ua + " / " + ub + "]"));
        ++numbers;
        continue;
      }
      ASSERT_TRUE(b.contains(it.key())) << path << "." << it.key();
      compare_json(it.value(), b[it.key()], path + "." + it.key(), numbers);
    }
  } else if (a.is_array()) {
    ASSERT_EQ(a.size(), b.size()) << path;
    for (std::size_t i = 0; i < a.size(); ++i) compare_json(a[i], b[i], path + "[" + std::to_string(i) + "]", numbers);
  } else if (a.is_number()) {
    // A bare number has no unit: it must be the same in both runs.
    EXPECT_TRUE(agree(a.get<double>(), b.get<double>(), std::abs(a.get<double>()), path + " (no unit)"));
    ++numbers;
  }
}

std::vector<std::vector<std::string>> csv_rows(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> cells;
    std::string cell;
    bool quoted = false;
    for (char c : line) {
      if (c == '"') quoted = !quoted;
      else if (c == ',' && !quoted) {
        cells.push_back(cell);
        cell.clear();
      } else cell += c;
    }
    cells.push_back(cell);
    rows.push_back(cells);
  }
  return rows;
}

bool as_number(const std::string& s, double& v) {
  char* end = nullptr;
  v = std::strtod(s.c_str(), &end);
  return !s.empty() && end == s.c_str() + s.size();
}

// "name [unit]" -> unit ("" without brackets).
std::string unit_of(const std::string& header) {
  const std::size_t open = header.rfind('['), close = header.rfind(']');
  return open == std::string::npos || close == std::string::npos || close < open ? std::string() : header.substr(open + 1, close - open - 1);
}

void compare_csv(const fs::path& a_file, const fs::path& b_file, int& numbers) {
  const auto a = csv_rows(read_file(a_file)), b = csv_rows(read_file(b_file));
  const std::string name = a_file.filename().string();
  ASSERT_EQ(a.size(), b.size()) << name;
  ASSERT_FALSE(a.empty()) << name;
  const std::vector<std::string>& ha = a[0];
  const std::vector<std::string>& hb = b[0];
  ASSERT_EQ(ha.size(), hb.size()) << name;
  for (std::size_t c = 0; c < ha.size(); ++c) {
    EXPECT_TRUE(label_of(unit_of(ha[c]), "in-lbf-s")) << name << " column '" << ha[c] << "' in an inch study";
    EXPECT_TRUE(label_of(unit_of(hb[c]), "m-N-s")) << name << " column '" << hb[c] << "' in an SI study";
  }
  // A table whose rows are different quantities (calibration.csv: one row a
  // parameter) gives each row's unit in a column `unit`: the numbers of that
  // row without a unit in their header are in it.
  const auto unit_column = std::find(ha.begin(), ha.end(), "unit");
  const std::ptrdiff_t uc = unit_column == ha.end() ? -1 : unit_column - ha.begin();
  auto unit_in = [&](const std::vector<std::vector<std::string>>& t, const std::vector<std::string>& h, std::size_t r, std::size_t c) {
    const std::string u = unit_of(h[c]);
    return u.empty() && uc >= 0 && static_cast<std::size_t>(uc) < t[r].size() ? t[r][static_cast<std::size_t>(uc)] : u;
  };
  std::vector<double> scale(ha.size(), 0.0);
  for (std::size_t r = 1; r < a.size(); ++r)
    for (std::size_t c = 0; c < a[r].size() && c < ha.size(); ++c)
      if (double v = 0; as_number(a[r][c], v)) scale[c] = std::max(scale[c], std::abs(v) * to_si(unit_in(a, ha, r, c)));
  if (uc >= 0)  // rows of different quantities: compare each number with the scale of its own row
    std::fill(scale.begin(), scale.end(), 0.0);
  const std::regex located(R"(^(.*) at (\w+) = (\S+) (\S+)$)");
  for (std::size_t r = 1; r < a.size(); ++r) {
    ASSERT_EQ(a[r].size(), b[r].size()) << name << " row " << r;
    for (std::size_t c = 0; c < a[r].size(); ++c) {
      const std::string where = fmt::format("{} row {} column '{}'", name, r, ha[c]);
      double va = 0, vb = 0;
      if (static_cast<std::ptrdiff_t>(c) == uc) {
        EXPECT_TRUE(label_of(a[r][c], "in-lbf-s")) << where << ": '" << a[r][c] << "' in an inch study";
        EXPECT_TRUE(label_of(b[r][c], "m-N-s")) << where << ": '" << b[r][c] << "' in an SI study";
      } else if (as_number(a[r][c], va)) {
        ASSERT_TRUE(as_number(b[r][c], vb)) << where;
        EXPECT_TRUE(agree(va * to_si(unit_in(a, ha, r, c)), vb * to_si(unit_in(b, hb, r, c)), scale[c], where));
        ++numbers;
      } else if (std::smatch ma, mb; std::regex_match(a[r][c], ma, located)) {  // "blade backs off at x5 = 0.0157 in"
        ASSERT_TRUE(std::regex_match(b[r][c], mb, located)) << where << ": " << b[r][c];
        EXPECT_EQ(ma[1], mb[1]) << where;
        EXPECT_EQ(ma[2], mb[2]) << where;
        ASSERT_TRUE(as_number(ma[3], va) && as_number(mb[3], vb)) << where;
        EXPECT_TRUE(label_of(ma[4], "in-lbf-s")) << where << ": " << a[r][c];
        EXPECT_TRUE(label_of(mb[4], "m-N-s")) << where << ": " << b[r][c];
        const double sa = va * to_si(ma[4]), sb = vb * to_si(mb[4]);
        // The text gives 6 significant digits: each run rounds by up to 5e-6 of the value.
        EXPECT_TRUE(agree(sa, sb, 0.0, where + ": '" + a[r][c] + "' / '" + b[r][c] + "'", 1.1e-5));
        ++numbers;
      } else {
        EXPECT_EQ(a[r][c], b[r][c]) << where;
      }
    }
  }
}

// Runs `study` as shipped and converted to SI; compares every output.
void expect_same_results_in_si(const std::string& study, const std::set<std::string>& must_have) {
  TempDir dir("framedyn_test_output_units");
  const fs::path own = dir.write("own.yaml", read_file(kExamples / study));
  dir.write("si.yaml", study_in_si(own));
  const auto r1 = framedyn(dir, "run own.yaml --out own -q");
  ASSERT_EQ(r1.status, 0) << r1.err;
  const auto r2 = framedyn(dir, "run si.yaml --out si -q");
  ASSERT_EQ(r2.status, 0) << r2.err;
  for (const std::string& f : must_have) ASSERT_TRUE(fs::exists(dir / "own" / f)) << f;
  int numbers = 0;
  {
    SCOPED_TRACE("summary.json");
    compare_json(nlohmann::json::parse(read_file(dir / "own" / "summary.json")), nlohmann::json::parse(read_file(dir / "si" / "summary.json")), "", numbers);
  }
  for (const auto& e : fs::directory_iterator(dir / "own"))
    if (e.path().extension() == ".csv") {
      SCOPED_TRACE(e.path().filename().string());
      compare_csv(e.path(), dir / "si" / e.path().filename(), numbers);
    }
  std::printf("[ units ] %s: %d numbers agree in SI\n", study.c_str(), numbers);
  EXPECT_GT(numbers, 100);
}

TEST(OutputUnits, PlowStudy2DGivesTheSameNumbersInInchesAndInSI) {
  expect_same_results_in_si("r100_plow_2d.yaml", {"summary.json", "events.csv", "response.csv", "rigid_modes.csv"});
}

TEST(OutputUnits, PlowStudy3DGivesTheSameNumbersInInchesAndInSI) {
  expect_same_results_in_si("r100_plow_straight.yaml", {"summary.json", "events.csv", "response.csv", "rigid_modes.csv"});
}

// The 3-D calibration of the thesis's case 2 fits frame.parts.inertia_scale.*
// (the parts' total inertia, kg m^2 or lbf in s^2) among its parameters.
TEST(OutputUnits, Calibration3DGivesTheSameFittedParametersInInchesAndInSI) {
  expect_same_results_in_si("thesis/case2.yaml", {"summary.json", "rigid_modes.csv"});
}

// frame.parts.inertia_scale.xx starts at the parts' total inertia about X,
// sum W_i / g * kx_i^2 (each part about its own centre of mass), in the
// study's unit lbf*s^2/in*in^2 with g = 9.80665 m/s^2 = 386.0886 in/s^2; it
// was labelled "1" and given in kg m^2.
TEST(OutputUnits, FramePartsInertiaScaleIsTheTotalInertiaInTheStudysUnit) {
  TempDir dir("framedyn_test_output_units");
  // The shipped case 2 fits the tires only: fit the parts' inertia scales here.
  std::string text = read_file(kExamples / "thesis" / "case2.yaml");
  const std::string fitted = "  parameters: [tires.front.vertical.stiffness, tires.front.longitudinal.stiffness, tires.front.lateral.stiffness,\n"
                             "               tires.rear.vertical.stiffness, tires.rear.longitudinal.stiffness, tires.rear.lateral.stiffness]\n";
  const std::size_t at = text.find(fitted);
  ASSERT_NE(at, std::string::npos) << "case2.yaml's calibration parameters changed";
  text.replace(at, fitted.size(), "  parameters: [frame.parts.inertia_scale.xx, frame.parts.inertia_scale.yy]\n");
  dir.write("case2.yaml", text);
  const auto run = framedyn(dir, "run case2.yaml --out out -q");
  ASSERT_EQ(run.status, 0) << run.err;
  const YAML::Node study = YAML::LoadFile((dir / "case2.yaml").string());
  const double g = 9.80665 / 0.0254;
  double total = 0.0;
  for (const auto& part : study["frame"]["parts"]) {
    const double kx = part["radii_of_gyration"][0].as<double>();
    total += part["weight"].as<double>() / g * kx * kx;
  }
  const nlohmann::json j = nlohmann::json::parse(read_file(dir / "out" / "summary.json"));
  bool found = false;
  for (const auto& p : j["rigid"]["calibration"]["parameters"])
    if (p["name"] == "frame.parts.inertia_scale.xx") {
      found = true;
      EXPECT_EQ(p["unit"], "lbf*s^2/in*in^2");
      EXPECT_NEAR(p["initial"].get<double>(), total, 1e-12 * total);
    }
  EXPECT_TRUE(found);
}

// ------------------------------------------------------------ a unit on every number

// One style for every dimensional number (issue 14, "one {value, unit} style
// everywhere"): a number is either inside an object that names its unit
// (the `value` of {value, unit}, or the calibration's {name, unit, initial,
// fitted, ...}),
// or it sits under a key that names something dimensionless. A unit carried
// in a key's name (`frequency_hz`) fails here.
const std::set<std::string> kDimensionlessKeys = {
    "mode", "dofs", "free_dofs", "nodes", "elements", "beam_elements", "output_times", "events", "steps", "step", "count", "grid_points",
    "mode_count", "rigid_body_modes", "free_rigid_motions", "rigid_body_modes_expected", "parts", "eigenvalues_below", "lanczos_runs",
    "restarts", "operator_solves", "iterations", "relative_residual", "target_count", "parameter_count", "information", "degrees_of_freedom", "independent_targets", "shape_components", "jobs", "node", "element",
    "station", "frame_node", "fiber", "mount_nodes", "startup_times", "steady_times",
    "stress_histories_in_memory_bytes", "samples", "cycles", "turning_points", "damage", "window_periods", "max_period_multiple", "period_multiple", "index",
    // ratios and fractions
    "damping_ratio", "tension_fraction", "lift_off_fraction", "bending_share", "ratio", "relative_error", "residual_max", "tolerance",
    "singular_values", "regularization_weight", "mac", "shape_weight", "load_factor_rms", "share",
    "relative_force", "relative_moment"};
// Objects whose every member is a dimensionless number (shares and fractions by coordinate or direction).
const std::set<std::string> kDimensionlessMaps = {"energy_share", "effective_mass_fraction", "effective_mass_fraction_sum", "relative_change",
                                                  "relative_spread", "unresolved"};

void find_bare_numbers(const nlohmann::json& j, const std::string& path, const std::string& key, bool in_unit_object,
                       std::vector<std::string>& bare) {
  if (j.is_object()) {
    if (kDimensionlessMaps.count(key)) return;
    // In {value, unit, ...} the unit is the value's only; in the calibration's
    // {name, unit, initial, fitted, ...} (no `value`) it is every number's.
    const bool has_unit = j.contains("unit") && j["unit"].is_string();
    for (auto it = j.begin(); it != j.end(); ++it)
      find_bare_numbers(it.value(), path + "." + it.key(), it.key(), has_unit && (it.key() == "value" || !j.contains("value")), bare);
  } else if (j.is_array()) {
    for (std::size_t i = 0; i < j.size(); ++i) find_bare_numbers(j[i], path + "[" + std::to_string(i) + "]", key, in_unit_object, bare);
  } else if (j.is_number() && !in_unit_object && !kDimensionlessKeys.count(key)) {
    bare.push_back(path);
  }
}

TEST(OutputUnits, EveryDimensionalNumberOfEverySummaryIsAValueWithItsUnit) {
  TempDir dir("framedyn_test_output_units");
  std::string mesh = read_file(fs::path(FRAMEDYN_SOURCE_DIR) / "meshes" / "portal_frame.inp");
  mesh += "*BOUNDARY\nFEET, 1, 6\n*STEP\n*STATIC\n*CLOAD\n7, 1, 1000.\n*END STEP\n";
  dir.write("frame.inp", mesh);
  dir.write("psd.csv", "frequency [Hz],psd [1/Hz]\n1,1\n50,1\n");
  dir.write("series.csv", "time [s],stress [MPa]\n0,0\n1,80\n2,-40\n3,120\n4,-60\n5,30\n6,0\n");
  const std::vector<std::pair<std::string, std::string>> runs = {
      {"plow_2d", "run '" + (kExamples / "r100_plow_2d.yaml").string() + "' -q --out plow_2d"},
      {"pipeline", "run '" + (kExamples / "offset_plowing.yaml").string() + "' -q --out pipeline"},
      {"calibration", "run '" + (kExamples / "thesis" / "case1.yaml").string() + "' -q --out calibration"},
      {"sweep", "sweep '" + (kExamples / "r100_plow_2d.yaml").string() + "' -p soil.damping --values 200,300 --no-figures -q --out sweep"},
      {"frame_response", "frame-response '" + (kExamples / "portal_frame_sway.yaml").string() + "' -q --out frame_response"},
      {"modes", "modes frame.inp --modes 8 -q --out modes"},
      {"static", "static frame.inp -q --out static"},
      {"harmonic", "harmonic frame.inp -f 1:50:20 -z 0.02 --no-figures -q --out harmonic"},
      {"random", "random frame.inp --psd psd.csv -z 0.02 --no-figures -q --out random"},
      {"rainflow", "rainflow series.csv --sn FAT90 -q --out rainflow"}};
  for (const auto& [name, command] : runs) {
    const auto r = framedyn(dir, command);
    ASSERT_EQ(r.status, 0) << command << "\n" << r.err;
    std::vector<std::string> bare;
    find_bare_numbers(nlohmann::json::parse(read_file(dir / name / "summary.json")), "", "", false, bare);
    std::string list;
    for (const std::string& b : bare) list += "\n  " + b;
    EXPECT_TRUE(bare.empty()) << name << "/summary.json: numbers with neither a unit nor a dimensionless key:" << list;
  }
}

}  // namespace
