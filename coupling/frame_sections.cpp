// Frame section dimensions as study keys; see frame_sections.h.
#include "coupling/frame_sections.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <map>
#include <optional>
#include <sstream>

#include "coupling/yaml_input.h"

namespace framedyn::coupling {

namespace {

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

std::string trim(const std::string& s) {
  const std::size_t b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t") - b + 1);
}

std::vector<std::string> split_commas(const std::string& s) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = s.find(',', start);
    parts.push_back(s.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return parts;
}

bool is_comment(const std::string& t) { return t.size() >= 2 && t[0] == '*' && t[1] == '*'; }
bool is_keyword(const std::string& t) { return !t.empty() && t[0] == '*' && !is_comment(t); }

// A *BEAM SECTION (or CalculiX's *BEAM GENERAL SECTION, SECTION=BOX|PIPE) in the text.
struct SectionLine {
  std::string element_set;   // upper case
  std::string shape;         // upper case; RECTANGULAR read as RECT; GENERAL for A, I11, ... given directly
  std::size_t data_line = 0;  // index into the lines; 0 with `has_data` false: none
  bool has_data = false;
  std::vector<std::string> tokens;  // the data line's values as written (trimmed)
  std::vector<double> values;       // the same read as numbers (empty when one is not a number)
};

std::optional<double> parse_value(const std::string& token) {
  if (token.empty()) return std::nullopt;
  errno = 0;
  char* end = nullptr;
  const double v = std::strtod(token.c_str(), &end);
  if (end != token.c_str() + token.size() || errno == ERANGE) return std::nullopt;
  return v;
}

// The mesh's own unit system ("** units: NAME"), if it names one framedyn knows.
std::optional<core::UnitSystem> mesh_units(const std::vector<std::string>& lines) {
  for (const std::string& raw : lines) {
    const std::string t = trim(raw);
    if (!is_comment(t)) continue;
    const std::string body = trim(t.substr(2));
    std::string lower = body;
    for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (lower.rfind("units:", 0) != 0) continue;
    try {
      return core::UnitSystem::from_name(trim(body.substr(6)));
    } catch (const std::invalid_argument&) {
      return std::nullopt;  // the reader refuses it, naming the line
    }
  }
  return std::nullopt;
}

std::vector<SectionLine> find_sections(const std::vector<std::string>& lines) {
  std::vector<SectionLine> found;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const std::string t = trim(lines[i]);
    if (!is_keyword(t)) continue;
    const std::vector<std::string> parts = split_commas(t);
    std::string keyword;
    for (char c : upper(trim(parts[0])))
      if (c != ' ' && c != '\t') keyword += c;
    if (keyword != "*BEAMSECTION" && keyword != "*BEAMGENERALSECTION") continue;
    SectionLine s;
    for (std::size_t p = 1; p < parts.size(); ++p) {
      const std::size_t eq = parts[p].find('=');
      if (eq == std::string::npos) continue;
      const std::string key = upper(trim(parts[p].substr(0, eq))), value = upper(trim(parts[p].substr(eq + 1)));
      if (key == "ELSET") s.element_set = value;
      if (key == "SECTION") s.shape = value == "RECTANGULAR" ? "RECT" : value;
    }
    if (s.element_set.empty()) continue;  // the reader refuses it
    if (keyword == "*BEAMGENERALSECTION" && s.shape != "BOX" && s.shape != "PIPE") s.shape = "GENERAL";
    for (std::size_t j = i + 1; j < lines.size(); ++j) {
      std::string d = lines[j];
      if (!d.empty() && d.back() == '\r') d.pop_back();
      d = trim(d);
      if (d.empty() || is_comment(d)) continue;
      if (is_keyword(d)) break;
      s.has_data = true;
      s.data_line = j;
      for (std::string token : split_commas(d)) s.tokens.push_back(trim(token));
      if (s.tokens.size() > 1 && s.tokens.back().empty()) s.tokens.pop_back();  // a trailing comma
      for (const std::string& token : s.tokens) {
        const std::optional<double> v = parse_value(token);
        if (!v) {
          s.values.clear();
          break;
        }
        s.values.push_back(*v);
      }
      break;
    }
    found.push_back(s);
  }
  return found;
}

std::string join(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

// STUDY-153: the walls the changed dimensions leave must fit the section.
void check_walls(const SectionLine& s, const std::vector<double>& d, const SectionOverride& o, const std::string& length_label) {
  const std::vector<std::string> names = section_dimension_names(s.shape, d.size());
  const auto index = [&](const std::string& n) { return static_cast<std::size_t>(std::find(names.begin(), names.end(), n) - names.begin()); };
  // The first overridden dimension among `involved`, or none (the mesh's own values are the reader's to check).
  const auto changed = [&](std::initializer_list<const char*> involved) -> const SectionDimension* {
    for (const SectionDimension& dim : o.dimensions)
      for (const char* n : involved)
        if (dim.name == n) return &dim;
    return nullptr;
  };
  const auto v = [&](const char* n) { return d[index(n)]; };
  const auto fail = [&](const SectionDimension* at, const std::string& expected, const std::string& found) {
    throw core::InputError(at->where, expected, found);
  };
  const std::string L = length_label;
  if (s.shape == "BOX") {
    if (const auto* at = changed({"t1", "t3", "a"}); at && !(v("t1") + v("t3") < v("a")))
      fail(at, fmt::format("walls t1 + t3 thinner than the outer width a ({:g} {}) of ELSET {}'s BOX section (each wall less than half of it when equal)", v("a"), L, s.element_set),
           fmt::format("t1 + t3 = {:g} {}", v("t1") + v("t3"), L));
    if (const auto* at = changed({"t2", "t4", "b"}); at && !(v("t2") + v("t4") < v("b")))
      fail(at, fmt::format("walls t2 + t4 thinner than the outer width b ({:g} {}) of ELSET {}'s BOX section (each wall less than half of it when equal)", v("b"), L, s.element_set),
           fmt::format("t2 + t4 = {:g} {}", v("t2") + v("t4"), L));
  } else if (s.shape == "PIPE") {
    if (const auto* at = changed({"t", "r"}); at && v("t") > v("r"))
      fail(at, fmt::format("a wall t at most the outer radius r ({:g} {}) of ELSET {}'s PIPE section (half its diameter)", v("r"), L, s.element_set),
           fmt::format("t = {:g} {}", v("t"), L));
  } else if (s.shape == "I") {
    if (const auto* at = changed({"t1", "t2", "h"}); at && !(v("t1") + v("t2") < v("h")))
      fail(at, fmt::format("flanges t1 + t2 thinner than the height h ({:g} {}) of ELSET {}'s I section", v("h"), L, s.element_set),
           fmt::format("t1 + t2 = {:g} {}", v("t1") + v("t2"), L));
    if (const auto* at = changed({"t3", "b1", "b2"}); at && v("t3") > std::min(v("b1"), v("b2")))
      fail(at, fmt::format("a web t3 at most the narrower flange ({:g} {}) of ELSET {}'s I section", std::min(v("b1"), v("b2")), L, s.element_set),
           fmt::format("t3 = {:g} {}", v("t3"), L));
  } else if (s.shape == "CHANNEL") {
    if (const auto* at = changed({"tf", "h"}); at && !(2.0 * v("tf") < v("h")))
      fail(at, fmt::format("flanges tf thinner than half the height h ({:g} {}) of ELSET {}'s CHANNEL section", v("h"), L, s.element_set),
           fmt::format("tf = {:g} {}", v("tf"), L));
    if (const auto* at = changed({"tw", "b"}); at && !(v("tw") < v("b")))
      fail(at, fmt::format("a web tw thinner than the flange width b ({:g} {}) of ELSET {}'s CHANNEL section", v("b"), L, s.element_set),
           fmt::format("tw = {:g} {}", v("tw"), L));
  }
}

}  // namespace

std::vector<std::string> section_dimension_names(const std::string& shape, std::size_t values) {
  if (shape == "RECT") return {"a", "b"};
  if (shape == "BOX") return {"a", "b", "t1", "t2", "t3", "t4"};
  if (shape == "PIPE") return {"r", "t"};
  if (shape == "CIRC") return values > 1 ? std::vector<std::string>{"a", "b"} : std::vector<std::string>{"r"};
  if (shape == "I") return {"l", "h", "b1", "b2", "t1", "t2", "t3"};
  if (shape == "CHANNEL") return {"h", "b", "tf", "tw"};
  return {};
}

std::vector<SectionOverride> read_section_overrides(const YamlMap& sections) {
  std::vector<SectionOverride> out;
  std::map<std::string, std::string> seen;  // upper-case name -> as first written
  for (const auto& kv : sections.node()) {
    const std::string set = kv.first.Scalar();
    const YamlMap dims = sections.map(set);
    SectionOverride o;
    o.element_set = set;
    o.where = sections.location(set);
    o.where.key = sections.path() + "." + set;
    if (const auto first = seen.find(upper(set)); first != seen.end())  // STUDY-154
      throw sections.error(set, "each element set once (the mesh's set names are read without regard to case)",
                           fmt::format("'{}' after '{}'", set, first->second));
    seen[upper(set)] = set;
    for (const auto& d : dims.node()) {
      const std::string name = d.first.Scalar();
      double v = 0.0;
      // STUDY-152: a length, positive (an I section's unused offset l may be 0).
      const bool number = parse_number(d.second, v);
      if (!number || !(v > 0.0 || (name == "l" && v == 0.0)) || std::abs(v) > 1e300)
        throw dims.error(name, fmt::format("a section dimension: a positive number ({})", sections.units().label(core::Quantity::length)),
                         describe(d.second));
      core::InputLocation at = dims.location(name);
      at.key = dims.path() + "." + name;
      o.dimensions.push_back({name, v, at});
    }
    out.push_back(std::move(o));
  }
  return out;
}

std::string apply_section_overrides(const std::string& text, const std::string& mesh_name, const std::vector<SectionOverride>& overrides,
                                    const core::UnitSystem& study_units) {
  if (overrides.empty()) return text;
  // Lines with their ends kept, so every byte not rewritten stays.
  std::vector<std::string> lines;
  std::vector<std::string> ends;
  for (std::size_t start = 0; start < text.size();) {
    const std::size_t nl = text.find('\n', start);
    std::string line = text.substr(start, nl == std::string::npos ? std::string::npos : nl - start);
    std::string end = nl == std::string::npos ? "" : "\n";
    if (!line.empty() && line.back() == '\r') line.pop_back(), end = "\r" + end;
    lines.push_back(line);
    ends.push_back(end);
    start = nl == std::string::npos ? text.size() : nl + 1;
  }
  const std::vector<SectionLine> sections = find_sections(lines);
  const core::UnitSystem mesh = mesh_units(lines).value_or(study_units);
  const std::string L = mesh.label(core::Quantity::length);
  for (const SectionOverride& o : overrides) {
    std::vector<const SectionLine*> matches;
    for (const SectionLine& s : sections)
      if (s.element_set == upper(o.element_set)) matches.push_back(&s);
    if (matches.empty()) {  // STUDY-150
      std::vector<std::string> names;
      for (const SectionLine& s : sections)
        if (std::find(names.begin(), names.end(), s.element_set) == names.end()) names.push_back(s.element_set);
      throw core::InputError(o.where,
                             fmt::format("an element set with a *BEAM SECTION in the mesh {} (its sections: {}; sections in *INCLUDE files cannot be changed)",
                                         mesh_name, names.empty() ? "none" : join(names)),
                             "'" + o.element_set + "'");
    }
    for (const SectionLine* s : matches) {
      if (!s->has_data || s->values.empty()) continue;  // the reader refuses the line, naming it
      const std::vector<std::string> names = section_dimension_names(s->shape, s->values.size());
      std::vector<double> d = s->values;
      std::vector<std::string> tokens = s->tokens;
      // RECT with one value is a square: both values written once one changes.
      if (s->shape == "RECT" && d.size() == 1) d.push_back(d[0]), tokens.push_back(tokens[0]);
      for (const SectionDimension& dim : o.dimensions) {
        const auto it = std::find(names.begin(), names.end(), dim.name);
        if (it == names.end() || static_cast<std::size_t>(it - names.begin()) >= d.size())  // STUDY-151
          throw core::InputError(dim.where,
                                 names.empty() ? fmt::format("no dimension: ELSET {}'s section is SECTION={} (A, I11, I12, I22, J given directly), not one of "
                                                             "RECT, BOX, PIPE, CIRC, I, CHANNEL",
                                                             s->element_set, s->shape)
                                               : fmt::format("a dimension of ELSET {}'s {} section ({})", s->element_set, s->shape, join(names)),
                                 "'" + dim.name + "'");
        const std::size_t k = static_cast<std::size_t>(it - names.begin());
        // The study's number as written when the mesh is in the study's units (the reader then reads exactly it).
        const double v = mesh.name() == study_units.name() ? dim.value
                                                             : mesh.from_si(study_units.to_si(dim.value, core::Quantity::length), core::Quantity::length);
        d[k] = v;
        tokens[k] = fmt::format("{}", v);
      }
      check_walls(*s, d, o, L);
      // The data line rewritten: its indent, the values joined as the mesh writes them.
      const std::string& old = lines[s->data_line];
      const std::string indent = old.substr(0, old.find_first_not_of(" \t") == std::string::npos ? 0 : old.find_first_not_of(" \t"));
      std::string line = indent;
      for (std::size_t k = 0; k < tokens.size(); ++k) line += (k ? ", " : "") + tokens[k];
      lines[s->data_line] = line;
    }
  }
  std::string out;
  out.reserve(text.size() + 64);
  for (std::size_t i = 0; i < lines.size(); ++i) out += lines[i] + ends[i];
  return out;
}

std::string section_overrides_key(const std::vector<SectionOverride>& overrides) {
  std::string key;
  for (const SectionOverride& o : overrides) {
    key += "\n-- section " + upper(o.element_set);
    for (const SectionDimension& d : o.dimensions) key += fmt::format(" {} {}", d.name, d.value);
  }
  return key;
}

}  // namespace framedyn::coupling
