// Abaqus/CalculiX .inp reader for beam models; see inp_reader.h.
// Two passes: the text is split into keyword blocks (with *INCLUDE spliced
// in and continuation lines joined), then each block is parsed into raw
// records; the model is built at the end, when every set, material and node
// is known, and every reference is checked.
#include "fem/inp_reader.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <deque>
#include <map>
#include <unordered_map>
#include <set>
#include <sstream>

#include "core/error.h"
#include "fem/beam_element.h"
#include "fem/quadratic_beam_element.h"
#include "fem/member_releases.h"
#include "fem/rigid_links.h"

namespace framedyn::fem {

namespace {

namespace fs = std::filesystem;
using core::InputError;
using core::InputLocation;
using core::Quantity;

// ---------------------------------------------------------------- text level

struct Line {
  const std::string* file = nullptr;  // into TextSource::files (stable)
  int number = 0;
  std::string text;
};

// A place in the input that is cheap to keep for every node and element: it
// becomes an InputLocation (with its strings) only when an error is raised.
struct Where {
  const std::string* file = nullptr;
  int line = 0;
  const std::string* key = nullptr;
  operator InputLocation() const { return {file ? *file : std::string(), line, key ? *key : std::string()}; }
};

std::string trim(const std::string& s) {
  std::size_t a = 0, b = s.size();
  while (a < b && std::isspace(static_cast<unsigned char>(s[a]))) ++a;
  while (b > a && std::isspace(static_cast<unsigned char>(s[b - 1]))) --b;
  return s.substr(a, b - a);
}

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

std::vector<std::string> split_fields(const std::string& s) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : s) {
    if (c == ',') {
      out.push_back(trim(cur));
      cur.clear();
    } else {
      cur += c;
    }
  }
  out.push_back(trim(cur));
  // A trailing comma leaves one empty field: drop it.
  if (out.size() > 1 && out.back().empty()) out.pop_back();
  return out;
}

bool is_comment(const std::string& t) { return t.size() >= 2 && t[0] == '*' && t[1] == '*'; }
bool is_keyword(const std::string& t) { return !t.empty() && t[0] == '*' && !is_comment(t); }

struct Keyword {
  std::string name;                          // upper case, single spaces: "*BEAM SECTION"
  std::map<std::string, std::string> params; // upper-case key -> value as written
  std::vector<std::string> param_order;
  InputLocation where;
};

struct Block {
  Keyword keyword;
  std::vector<Line> data;
};

Keyword parse_keyword_line(const std::string& text, const InputLocation& where) {
  Keyword k;
  k.where = where;
  std::vector<std::string> fields = split_fields(text);
  std::string name;
  for (char c : fields[0]) {
    if (std::isspace(static_cast<unsigned char>(c))) {
      if (!name.empty() && name.back() != ' ') name += ' ';
    } else {
      name += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    }
  }
  k.name = trim(name);
  k.where.key = k.name;
  for (std::size_t i = 1; i < fields.size(); ++i) {
    if (fields[i].empty()) continue;
    const std::size_t eq = fields[i].find('=');
    std::string key = upper(trim(fields[i].substr(0, eq)));
    std::string value = eq == std::string::npos ? "" : trim(fields[i].substr(eq + 1));
    if (key.empty()) throw InputError(k.where, "a parameter NAME or NAME=VALUE", "'" + fields[i] + "'");
    if (k.params.count(key)) throw InputError(k.where, "each parameter once", "parameter " + key + " twice");
    k.params[key] = value;
    k.param_order.push_back(key);
  }
  return k;
}

struct TextSource {
  std::string name;  // the top-level file, for messages that have no line
  std::deque<std::string> files;  // every file read; Line::file points here
  std::vector<Line> lines;
  std::optional<std::string> units_comment;
  InputLocation units_where;
};

void load_lines(const std::string& text, const std::string& name, const fs::path& base_dir, TextSource& out,
                std::vector<std::string>& include_stack);

void load_file(const fs::path& path, const InputLocation& from, TextSource& out, std::vector<std::string>& include_stack) {
  const std::string key = fs::weakly_canonical(path).string();
  if (std::find(include_stack.begin(), include_stack.end(), key) != include_stack.end())
    throw InputError(from, "the file " + path.string() + " includes itself (directly or through other *INCLUDE files)");
  if (include_stack.size() > 16) throw InputError(from, "*INCLUDE nested more than 16 deep");
  if (fs::is_directory(path)) throw InputError(from, "cannot open " + path.string() + " (a directory, not a mesh file)");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(from, "cannot open " + path.string() + (fs::exists(path) ? " (permission?)" : " (no such file)"));
  std::stringstream ss;
  ss << in.rdbuf();
  include_stack.push_back(key);
  load_lines(ss.str(), path.string(), path.parent_path(), out, include_stack);
  include_stack.pop_back();
}

void load_lines(const std::string& text, const std::string& name, const fs::path& base_dir, TextSource& out,
                std::vector<std::string>& include_stack) {
  out.files.push_back(name);
  const std::string* file = &out.files.back();
  std::istringstream in(text);
  std::string raw;
  int number = 0;
  while (std::getline(in, raw)) {
    ++number;
    if (!raw.empty() && raw.back() == '\r') raw.pop_back();
    if (raw.find('\0') != std::string::npos)
      throw InputError({name, number, ""}, "text", "a NUL byte (is this a binary file?)");
    const std::string t = trim(raw);
    if (t.empty()) continue;
    if (is_comment(t)) {
      // "** units: in-lbf-s" names the unit system (a framedyn convention).
      std::string body = trim(t.substr(2));
      std::string lower_body = body;
      for (char& c : lower_body) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      if (lower_body.rfind("units:", 0) == 0) {
        const std::string value = trim(body.substr(6));
        // "SI" and "m-N-s" name one system: compare canonical names where known.
        auto canonical = [](const std::string& n) {
          try {
            return core::UnitSystem::from_name(n).name();
          } catch (const std::invalid_argument&) {
            return n;
          }
        };
        if (out.units_comment && canonical(*out.units_comment) != canonical(value))
          throw InputError({name, number, "** units:"}, "the same unit system as " + core::format_location(out.units_where) + " (" + *out.units_comment + ")", value);
        out.units_comment = value;
        out.units_where = {name, number, "** units:"};
      }
      continue;
    }
    if (is_keyword(t) && upper(t).rfind("*INCLUDE", 0) == 0) {
      const Keyword k = parse_keyword_line(t, {name, number, ""});
      if (k.name != "*INCLUDE") throw InputError(k.where, "a known keyword", k.name);
      auto it = k.params.find("INPUT");
      if (it == k.params.end() || it->second.empty()) throw InputError(k.where, "INPUT=file name", "no INPUT parameter");
      for (const auto& p : k.param_order)
        if (p != "INPUT") throw InputError(k.where, "only the parameter INPUT", p);
      std::string file = it->second;
      if (file.size() >= 2 && file.front() == '"' && file.back() == '"') file = file.substr(1, file.size() - 2);
      fs::path p(file);
      if (p.is_relative()) p = base_dir / p;
      load_file(p, k.where, out, include_stack);
      continue;
    }
    out.lines.push_back({file, number, t});
  }
}

// Keyword lines ending in a comma continue on the next line; so do data
// lines of *ELEMENT (elements with many nodes).
std::vector<Block> make_blocks(std::vector<Line>& lines) {
  std::vector<Block> blocks;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    Line& l = lines[i];
    if (is_keyword(l.text)) {
      std::string text = l.text;
      while (!text.empty() && text.back() == ',' && i + 1 < lines.size() && !is_keyword(lines[i + 1].text)) {
        text += lines[++i].text;
      }
      blocks.push_back({parse_keyword_line(text, {*l.file, l.number, ""}), {}});
    } else {
      if (blocks.empty()) throw InputError({*l.file, l.number, ""}, "a keyword line (starting with *) first", "'" + l.text + "'");
      Block& b = blocks.back();
      if (b.keyword.name == "*ELEMENT" && !b.data.empty() && !b.data.back().text.empty() && b.data.back().text.back() == ',')
        b.data.back().text += l.text;
      else
        b.data.push_back(std::move(l));
    }
  }
  return blocks;
}

// ---------------------------------------------------------------- values

Where at(const Line& l, const Keyword& k) { return {l.file, l.number, &k.name}; }

template <class Location>
double parse_double(const std::string& field, const Location& where, const std::string& what) {
  std::string s = field;
  for (char& c : s)
    if (c == 'd' || c == 'D') c = 'e';  // Fortran exponents: 1.0D3
  if (s.empty()) throw InputError(where, what + " (a number)", "an empty field");
  errno = 0;
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  // ERANGE with a finite result is underflow (1e-310 is a number, returned as a subnormal).
  if (end != s.c_str() + s.size() || !std::isfinite(v))
    throw InputError(where, what + " (a finite number)", "'" + field + "'");
  return v;
}

template <class Location>
long parse_int(const std::string& field, const Location& where, const std::string& what) {
  if (field.empty()) throw InputError(where, what + " (an integer)", "an empty field");
  errno = 0;
  char* end = nullptr;
  const long v = std::strtol(field.c_str(), &end, 10);
  if (end != field.c_str() + field.size() || errno == ERANGE || v > 2000000000L || v < -2000000000L)
    throw InputError(where, what + " (an integer)", "'" + field + "'");
  return v;
}

// The largest magnitude of an SI value or matrix entry the model may hold:
// beyond it, assembly's sums of a few entries could overflow to inf.
constexpr double kLargestSi = 1e300;
// CalculiX: a positive OFFSET1 puts the axis on the negative 1-side of the
// nodes (OFFSET1=0.5: the nodes on the section's positive face). Read from the
// expanded C3D20R mesh ccx 2.20 writes for a RECT section with OFFSET1=0.5.
constexpr double kOffsetSign = -1.0;

template <class Matrix>
bool within_range(const Matrix& m) {
  return m.allFinite() && m.cwiseAbs().maxCoeff() <= kLargestSi;
}

bool is_integer(const std::string& s) {
  if (s.empty()) return false;
  std::size_t i = (s[0] == '-' || s[0] == '+') ? 1 : 0;
  if (i == s.size()) return false;
  for (; i < s.size(); ++i)
    if (!std::isdigit(static_cast<unsigned char>(s[i]))) return false;
  return true;
}

void check_params(const Keyword& k, std::initializer_list<const char*> allowed) {
  for (const std::string& p : k.param_order) {
    bool ok = false;
    for (const char* a : allowed) ok = ok || p == a;
    if (!ok) {
      std::string list;
      for (const char* a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
      throw InputError(k.where, list.empty() ? "no parameters" : "one of the parameters " + list, "parameter " + p);
    }
  }
}

std::string required_param(const Keyword& k, const char* name) {
  auto it = k.params.find(name);
  if (it == k.params.end() || it->second.empty()) throw InputError(k.where, std::string(name) + "=...", std::string("no ") + name + " parameter");
  return it->second;
}

std::vector<double> numbers(const Line& l, const Keyword& k, std::size_t min_count, std::size_t max_count, const std::string& what) {
  std::vector<std::string> f = split_fields(l.text);
  if (f.size() == 1 && f[0].empty()) f.clear();
  if (f.size() < min_count || f.size() > max_count)
    throw InputError(at(l, k), fmt::format("{} ({}{} values)", what, min_count, max_count == min_count ? "" : fmt::format(" to {}", max_count)),
                     fmt::format("{} values in '{}'", f.size(), l.text));
  std::vector<double> v;
  for (const std::string& s : f) v.push_back(s.empty() ? 0.0 : parse_double(s, at(l, k), what));
  return v;
}

// ---------------------------------------------------------------- raw records

struct RawElement {
  int id;
  std::string type;  // B31, B32, B32R, B33, MASS, ROTARYI, SPRING1, SPRING2
  std::vector<int> node_ids;
  Where where;
};

struct RawSection {
  std::string elset, material, shape;
  std::vector<double> dims;
  Eigen::Vector3d n1{0, 0, -1};
  bool general = false;
  double general_density = 0.0, general_e = 0.0, general_g = 0.0;
  InputLocation where;
  bool rayleigh = false;                       // RAYLEIGH: bending rotary inertia for B33
  std::optional<Eigen::Vector2d> shear_stiffness;  // *TRANSVERSE SHEAR STIFFNESS (K13 along 1, K23 along 2)
  InputLocation shear_where;
  double offset1 = 0.0, offset2 = 0.0;         // OFFSET1, OFFSET2: the axis off the nodes, in section heights (Eq. 3.5)
};

struct RawMaterial {
  Material m;
  bool has_elastic = false, has_density = false;
  InputLocation where;
};

// `step`: 0 for model data (before the first *STEP), k inside the k-th step.
struct RawBoundary {
  std::string target;
  int first_dof, last_dof;
  double value;
  InputLocation where;
  int step = 0;
};

struct RawLoad {
  std::string target;
  int dof;
  double value;
  InputLocation where;
  int step = 0;
  std::string amplitude;  // AMPLITUDE=, upper case; empty: constant in the step
};

// One *STEP ... *END STEP (docs/theory/fem.md section 18).
struct RawStep {
  std::string procedure;            // STATIC, FREQUENCY; empty until the step names one
  std::optional<int> modes;         // *FREQUENCY's number of eigenvalues
  bool new_cloads = false, new_dloads = false;  // *CLOAD / *DLOAD with OP=NEW in this step
  bool new_boundaries = false;      // its first *BOUNDARY has OP=NEW: the earlier supports are removed
  std::optional<TransientSettings> transient;  // *MODAL DYNAMIC, *DYNAMIC
  InputLocation where;
};

struct RawRigidLink {  // *RIGID BODY (one per node set) or one *MPC BEAM line
  std::string reference, slaves;  // node number or node set name
  bool slave_rotations = true;    // false for PIN NSET
  InputLocation where;
};

struct RawCoupling {  // *DISTRIBUTING COUPLING, ELSET= (of DCOUP3D elements on the reference node)
  std::string elset;
  std::vector<std::pair<std::string, double>> mounts;  // node number or node set name, weight
  InputLocation where;
};

struct RawElementProperty {  // *MASS, *ROTARY INERTIA, *SPRING
  std::string keyword, elset;
  std::vector<double> values;
  std::vector<int> dofs;
  InputLocation where;
};

// ------------------------------------------- three-node beams, CalculiX decks
// (issue 13): B32/B32R elements, *BEAM GENERAL SECTION with SECTION=BOX or
// PIPE as CalculiX writes it, and the step parameters framedyn cannot honour.

// A B32 (3-point rule) or B32R (2-point rule) element; the mesh gives its
// nodes as end, midside, end.
BeamElement quadratic_beam(const RawElement& e, const std::vector<int>& node_indices) {
  BeamElement b;
  b.id = e.id;
  b.node_a = node_indices[0];
  b.node_m = node_indices[1];
  b.node_b = node_indices[2];
  b.theory = BeamTheory::timoshenko;
  b.reduced_integration = e.type == "B32R";
  return b;
}

// The geometry (the mapping must not fold, n1 not along the axis) and the
// range of the element matrices of a three-node element.
void check_quadratic_beam(const FrameModel& model, const BeamElement& b, const Where& where) {
  const SectionGeometry section = section_geometry(model, b.section, BeamTheory::timoshenko);
  try {
    check_quadratic_beam_geometry(model, b, section);
  } catch (const std::invalid_argument& e) {
    throw InputError(where, "a valid three-node beam (end, midside, end)",
                     fmt::format("element {} on nodes {}, {}, {}: {}", b.id, model.nodes[static_cast<std::size_t>(b.node_a)].id,
                                 model.nodes[static_cast<std::size_t>(b.node_m)].id, model.nodes[static_cast<std::size_t>(b.node_b)].id, e.what()));
  }
  if (!within_range(quadratic_beam_stiffness(model, b, section)) || !within_range(quadratic_beam_mass(model, b, section, MassFormulation::consistent)))
    throw InputError(where, "element stiffness and mass within the range of floating point (entries of at most 1e300 in SI units)",
                     fmt::format("element {}: length {:g} m, E {:g} Pa, G {:g} Pa, density {:g} kg/m^3, A {:g} m^2, I11 {:g} m^4, "
                                 "I22 {:g} m^4, J {:g} m^4 (section of ELSET {})",
                                 b.id, quadratic_beam_length(model, b), section.data.youngs_modulus, section.data.shear_modulus,
                                 section.data.density, section.data.section.area, section.data.section.i11, section.data.section.i22,
                                 section.data.section.torsion_constant, model.sections[static_cast<std::size_t>(b.section)].element_set));
}

// framedyn solves linear problems: a step asking for geometric nonlinearity
// (Abaqus/CalculiX *STEP, NLGEOM or NLGEOM=YES) is refused rather than
// answered linearly.
void refuse_nonlinear_step(const Keyword& k) {
  auto it = k.params.find("NLGEOM");
  if (it == k.params.end() || upper(it->second) == "NO") return;
  throw InputError(k.where,
                   "a linear step (framedyn is a linear, small-displacement code: remove NLGEOM, or run the deck in a "
                   "nonlinear code such as CalculiX)",
                   it->second.empty() ? std::string("NLGEOM") : "NLGEOM=" + it->second);
}

// Beam offsets (CalculiX OFFSET1, OFFSET2): the beam's axis lies off its
// nodes by that many section heights along the section's 1- and 2-directions
// (docs/theory/fem.md, Eq. 3.5 and section 21); offset_heights says what a
// section height is for each shape.
double offset_parameter(const Keyword& k, const char* name) {
  auto it = k.params.find(name);
  if (it == k.params.end()) return 0.0;
  const double v = parse_double(it->second, k.where, name);
  if (!std::isfinite(v)) throw InputError(k.where, std::string("a finite ") + name, std::string(name) + "=" + it->second);
  return v;
}
struct RawDistributedLoad {  // *DLOAD
  std::string target;        // element number or ELSET; empty: every element (GRAV only)
  std::string type;          // GRAV, P1, P2, PX, PY, PZ
  double magnitude = 0.0;    // force per length, or an acceleration for GRAV
  Eigen::Vector3d direction = Eigen::Vector3d::Zero();  // GRAV, unit length
  InputLocation where;
  int step = 0;              // as RawLoad::step
};

struct RawRelease {  // *RELEASE
  std::string target;
  ReleaseMask mask = 0;
  InputLocation where;
};

class Parser {
 public:
  explicit Parser(TextSource& src) : src_(src) {}

  FrameModel run(const InpReadOptions& options);
  InpReadOptions options_;

 private:
  TextSource& src_;
  std::vector<std::pair<int, Eigen::Vector3d>> nodes_;
  std::unordered_map<int, Where> node_where_;
  std::vector<RawElement> elements_;
  std::unordered_map<int, std::size_t> element_index_;
  std::map<std::string, std::vector<int>> nsets_, elsets_;
  std::map<std::string, std::vector<Where>> nset_where_, elset_where_;  // parallel to nsets_, elsets_
  std::vector<RawSection> sections_;
  std::map<std::string, RawMaterial> materials_;
  std::string current_material_;
  std::vector<RawBoundary> boundaries_;
  std::vector<RawLoad> loads_;
  std::vector<RawElementProperty> properties_;
  std::vector<RawRigidLink> rigid_links_;
  std::vector<RawCoupling> couplings_;
  std::optional<int> frequency_count_;
  bool in_step_ = false;
  int steps_ = 0;
  InputLocation step_where_;
  std::vector<RawStep> raw_steps_;
  // The step a load or support belongs to (0: model data), after checking
  // that it is not between two steps; whether OP=NEW was given.
  int data_step(const Keyword& k);
  bool replaces_earlier(const Keyword& k);
  std::map<int, int> boundary_cards_;  // step (0: model data) -> *BOUNDARY cards read so far

  void node(const Block& b);
  void element(const Block& b);
  void set(const Block& b, bool nodes);
  void beam_section(const Block& b);
  void general_beam_section(const Block& b);
  bool calculix_shape_section(const Block& b);
  void material(const Block& b);
  void elastic(const Block& b);
  void density(const Block& b);
  void boundary(const Block& b);
  void cload(const Block& b);
  void element_property(const Block& b);
  void step_keyword(const Block& b);
  void amplitude(const Block& b);
  void transient_procedure(const Block& b);
  void modal_damping(const Block& b);
  std::map<std::string, Amplitude> amplitudes_;
  void set_procedure(const Keyword& k, const char* procedure);
  // Distributed loads, end releases, section extras (issue 13); see their definitions.
  std::vector<RawDistributedLoad> dloads_;
  std::vector<RawRelease> releases_;
  void dload(const Block& b);
  void release(const Block& b);
  void transverse_shear_stiffness(const Block& b, const Block* previous);
  std::vector<int> element_targets(const std::string& target, const InputLocation& where) const;
  void apply_section_extras(FrameModel& model, const core::UnitSystem& units) const;
  void apply_releases(FrameModel& model) const;
  void apply_distributed_loads(const FrameModel& model, const core::UnitSystem& units, const std::vector<RawDistributedLoad>& dloads,
                               FrameModel& out) const;
  void apply_offsets(FrameModel& model);
  void rigid_body(const Block& b);
  void mpc(const Block& b);
  void distributing_coupling(const Block& b);
  void build_rigid_links(FrameModel& model) const;
  FrameModel build(const core::UnitSystem& units);
  std::vector<int> set_members(const std::string& name, bool nodes, const InputLocation& where) const;
};

void Parser::node(const Block& b) {
  check_params(b.keyword, {"NSET"});
  std::vector<int>* set = nullptr;
  std::vector<Where>* set_where = nullptr;
  if (b.keyword.params.count("NSET")) {
    const std::string name = upper(required_param(b.keyword, "NSET"));
    set = &nsets_[name];
    set_where = &nset_where_[name];
  }
  for (const Line& l : b.data) {
    std::vector<std::string> f = split_fields(l.text);
    if (f.size() < 2 || f.size() > 4) throw InputError(at(l, b.keyword), "node number, x[, y[, z]]", "'" + l.text + "'");
    const int id = static_cast<int>(parse_int(f[0], at(l, b.keyword), "node number"));
    if (id <= 0) throw InputError(at(l, b.keyword), "a positive node number", std::to_string(id));
    Eigen::Vector3d x = Eigen::Vector3d::Zero();
    for (std::size_t i = 1; i < f.size(); ++i) x(static_cast<int>(i) - 1) = f[i].empty() ? 0.0 : parse_double(f[i], at(l, b.keyword), "a coordinate");
    auto [it, inserted] = node_where_.emplace(id, at(l, b.keyword));
    if (!inserted) throw InputError(at(l, b.keyword), "a new node number", fmt::format("node {} again (first at {})", id, core::format_location(it->second)));
    nodes_.emplace_back(id, x);
    if (set) {
      set->push_back(id);
      set_where->push_back(at(l, b.keyword));
    }
  }
}

void Parser::element(const Block& b) {
  check_params(b.keyword, {"TYPE", "ELSET"});
  const std::string type = upper(required_param(b.keyword, "TYPE"));
  std::size_t node_count = 0;
  if (type == "B31" || type == "B33" || type == "SPRING2") node_count = 2;
  else if (type == "B32" || type == "B32R") node_count = 3;  // end, midside, end
  else if (type == "MASS" || type == "ROTARYI" || type == "SPRING1" || type == "DCOUP3D") node_count = 1;
  else
    throw InputError(b.keyword.where, "TYPE=B31, B32, B32R, B33, MASS, ROTARYI, SPRING1, SPRING2 or DCOUP3D (framedyn reads beam models)",
                     "TYPE=" + type);
  std::vector<int>* set = nullptr;
  std::vector<Where>* set_where = nullptr;
  if (b.keyword.params.count("ELSET")) {
    const std::string name = upper(required_param(b.keyword, "ELSET"));
    set = &elsets_[name];
    set_where = &elset_where_[name];
  }
  for (const Line& l : b.data) {
    std::vector<std::string> f = split_fields(l.text);
    if ((type == "B31" || type == "B33") && f.size() == 4)
      throw InputError(at(l, b.keyword), "element number and 2 nodes (give the orientation on the *BEAM SECTION line)",
                       "a third, orientation node in '" + l.text + "'");
    if (f.size() != node_count + 1)
      throw InputError(at(l, b.keyword), fmt::format("element number and {} node number(s) for {}", node_count, type), "'" + l.text + "'");
    RawElement e;
    e.id = static_cast<int>(parse_int(f[0], at(l, b.keyword), "element number"));
    if (e.id <= 0) throw InputError(at(l, b.keyword), "a positive element number", std::to_string(e.id));
    e.type = type;
    e.where = at(l, b.keyword);
    for (std::size_t i = 1; i < f.size(); ++i) e.node_ids.push_back(static_cast<int>(parse_int(f[i], at(l, b.keyword), "node number")));
    if (node_count == 2 && e.node_ids[0] == e.node_ids[1])
      throw InputError(at(l, b.keyword), "two different nodes", fmt::format("element {} from node {} to itself", e.id, e.node_ids[0]));
    if (node_count == 3 && (e.node_ids[0] == e.node_ids[1] || e.node_ids[1] == e.node_ids[2] || e.node_ids[0] == e.node_ids[2]))
      throw InputError(at(l, b.keyword), "three different nodes (end, midside, end)",
                       fmt::format("element {} on nodes {}, {}, {}", e.id, e.node_ids[0], e.node_ids[1], e.node_ids[2]));
    if (element_index_.count(e.id))
      throw InputError(at(l, b.keyword), "a new element number",
                       fmt::format("element {} again (first at {})", e.id, core::format_location(elements_[element_index_[e.id]].where)));
    element_index_[e.id] = elements_.size();
    elements_.push_back(e);
    if (set) {
      set->push_back(e.id);
      set_where->push_back(e.where);
    }
  }
}

std::vector<int> Parser::set_members(const std::string& name, bool nodes, const InputLocation& where) const {
  const auto& sets = nodes ? nsets_ : elsets_;
  auto it = sets.find(upper(name));
  if (it == sets.end()) throw InputError(where, std::string(nodes ? "a node number or a defined *NSET" : "a defined *ELSET"), "'" + name + "'");
  return it->second;
}

// The most members a node or element set may have: far beyond any beam model
// (a 1e6-DOF frame has fewer than 2e5 nodes), small enough to read in seconds.
constexpr long kMaxSetMembers = 10000000;

void Parser::set(const Block& b, bool nodes) {
  const char* pname = nodes ? "NSET" : "ELSET";
  check_params(b.keyword, {pname, "GENERATE"});
  const std::string name = upper(required_param(b.keyword, pname));
  const bool generate = b.keyword.params.count("GENERATE") > 0;
  std::vector<int> members;
  std::vector<Where> members_where;
  for (const Line& l : b.data) {
    std::vector<std::string> f = split_fields(l.text);
    if (generate) {
      if (f.size() < 2 || f.size() > 3) throw InputError(at(l, b.keyword), "first, last[, increment] with GENERATE", "'" + l.text + "'");
      const long first = parse_int(f[0], at(l, b.keyword), "first number");
      const long last = parse_int(f[1], at(l, b.keyword), "last number");
      const long inc = f.size() == 3 ? parse_int(f[2], at(l, b.keyword), "increment") : 1;
      if (inc <= 0 || last < first) throw InputError(at(l, b.keyword), "first <= last and a positive increment", "'" + l.text + "'");
      if ((last - first) / inc >= kMaxSetMembers) throw InputError(at(l, b.keyword), "a range of at most 1e7 members", "'" + l.text + "'");
      for (long v = first; v <= last; v += inc) {
        members.push_back(static_cast<int>(v));
        members_where.push_back(at(l, b.keyword));
      }
    } else {
      for (const std::string& s : f) {
        if (s.empty()) continue;
        if (is_integer(s)) {
          members.push_back(static_cast<int>(parse_int(s, at(l, b.keyword), "a number")));
          members_where.push_back(at(l, b.keyword));
        } else {
          const std::vector<int> sub = set_members(s, nodes, at(l, b.keyword));
          members.insert(members.end(), sub.begin(), sub.end());
          const std::vector<Where>& sub_where = (nodes ? nset_where_ : elset_where_).at(upper(s));
          members_where.insert(members_where.end(), sub_where.begin(), sub_where.end());
        }
      }
    }
    // Sets that name sets can double with every line (found by fuzz_inp_reader: a 4e7-member
    // range named twice per line took minutes); a 1e6-DOF frame has fewer than 2e5 nodes.
    const auto& sets = nodes ? nsets_ : elsets_;
    const auto earlier = sets.find(name);  // find, not []: an empty entry would let the set name itself
    const std::size_t count = members.size() + (earlier == sets.end() ? 0 : earlier->second.size());
    if (count > static_cast<std::size_t>(kMaxSetMembers))
      throw InputError(at(l, b.keyword), fmt::format("a set of at most 1e7 members ({} *{} {})", nodes ? "node" : "element", pname, name),
                       fmt::format("{} members by this line", count));
  }
  std::vector<int>& target = (nodes ? nsets_ : elsets_)[name];
  target.insert(target.end(), members.begin(), members.end());
  std::vector<Where>& target_where = (nodes ? nset_where_ : elset_where_)[name];
  target_where.insert(target_where.end(), members_where.begin(), members_where.end());
}

Eigen::Vector3d orientation_line(const Line& l, const Keyword& k) {
  const std::vector<double> v = numbers(l, k, 3, 3, "the local 1-direction n1 (three components)");
  const Eigen::Vector3d n(v[0], v[1], v[2]);
  if (!(n.norm() > 0.0)) throw InputError(at(l, k), "a nonzero local 1-direction", "0, 0, 0");
  return n;
}

// RAYLEIGH (a framedyn extension, no value): Euler-Bernoulli elements of the
// section get the rotary inertia of bending (see docs/user-guide.md).
bool rayleigh_parameter(const Keyword& k) {
  auto it = k.params.find("RAYLEIGH");
  if (it == k.params.end()) return false;
  if (!it->second.empty()) throw InputError(k.where, "RAYLEIGH without a value", "RAYLEIGH=" + it->second);
  return true;
}

void Parser::beam_section(const Block& b) {
  check_params(b.keyword, {"ELSET", "MATERIAL", "SECTION", "OFFSET1", "OFFSET2", "RAYLEIGH"});
  RawSection s;
  s.rayleigh = rayleigh_parameter(b.keyword);
  s.elset = upper(required_param(b.keyword, "ELSET"));
  s.material = upper(required_param(b.keyword, "MATERIAL"));
  s.shape = upper(required_param(b.keyword, "SECTION"));
  if (s.shape == "RECTANGULAR") s.shape = "RECT";  // CalculiX reads the first four letters
  s.offset1 = offset_parameter(b.keyword, "OFFSET1");
  s.offset2 = offset_parameter(b.keyword, "OFFSET2");
  s.where = b.keyword.where;
  std::size_t count = 0, fewest = 0;
  if (s.shape == "RECT") count = 2, fewest = 1;  // CalculiX: one thickness is a square
  else if (s.shape == "BOX") count = 6;
  else if (s.shape == "PIPE") count = 2;
  else if (s.shape == "CIRC") count = 2, fewest = 1;  // two values: CalculiX's ellipse (section 23)
  else if (s.shape == "I") count = 7;
  else if (s.shape == "CHANNEL") count = 4;
  else throw InputError(b.keyword.where, "SECTION=RECT, BOX, PIPE, CIRC, I or CHANNEL", "SECTION=" + s.shape);
  if (b.data.empty()) throw InputError(b.keyword.where, fmt::format("a data line with the {} dimensions of {}", count, s.shape), "none");
  if (b.data.size() > 2) throw InputError(at(b.data[2], b.keyword), "at most two data lines (dimensions, orientation)", "'" + b.data[2].text + "'");
  if (fewest == 0) fewest = count;
  s.dims = numbers(b.data[0], b.keyword, fewest, count,
                   fewest == count ? fmt::format("the {} dimensions of a {} section", count, s.shape)
                                   : fmt::format("the {} or {} dimensions of a {} section", fewest, count, s.shape));
  if (s.dims.size() < count && s.shape != "CIRC") s.dims.resize(count, s.dims[0]);  // CIRC: one value a circle, two an ellipse
  for (std::size_t i = 0; i < s.dims.size(); ++i)
    if (!(s.dims[i] > 0.0) && !(s.shape == "I" && i == 0))  // I: the offset l is not used and may be 0
      throw InputError(at(b.data[0], b.keyword), "positive section dimensions", "'" + b.data[0].text + "'");
  if (b.data.size() == 2) s.n1 = orientation_line(b.data[1], b.keyword);
  sections_.push_back(s);
}

void Parser::general_beam_section(const Block& b) {
  if (calculix_shape_section(b)) return;
  check_params(b.keyword, {"ELSET", "SECTION", "DENSITY", "RAYLEIGH"});
  RawSection s;
  s.rayleigh = rayleigh_parameter(b.keyword);
  s.general = true;
  s.shape = "GENERAL";
  s.elset = upper(required_param(b.keyword, "ELSET"));
  s.where = b.keyword.where;
  const std::string kind = upper(required_param(b.keyword, "SECTION"));
  if (kind != "GENERAL") throw InputError(b.keyword.where, "SECTION=GENERAL", "SECTION=" + kind);
  if (b.keyword.params.count("DENSITY")) {
    s.general_density = parse_double(b.keyword.params.at("DENSITY"), b.keyword.where, "DENSITY");
    if (s.general_density < 0) throw InputError(b.keyword.where, "a density >= 0", b.keyword.params.at("DENSITY"));
  }
  if (b.data.size() != 3)
    throw InputError(b.keyword.where, "three data lines (A, I11, I12, I22, J; the local 1-direction; E, G)", fmt::format("{} data lines", b.data.size()));
  s.dims = numbers(b.data[0], b.keyword, 5, 5, "A, I11, I12, I22, J");
  s.n1 = orientation_line(b.data[1], b.keyword);
  const std::vector<double> eg = numbers(b.data[2], b.keyword, 2, 3, "E, G[, thermal expansion]");
  s.general_e = eg[0];
  s.general_g = eg[1];
  if (!(s.general_e > 0) || !(s.general_g > 0)) throw InputError(at(b.data[2], b.keyword), "E > 0 and G > 0", "'" + b.data[2].text + "'");
  sections_.push_back(s);
}

// CalculiX reads *BEAM GENERAL SECTION, SECTION=BOX or PIPE (with MATERIAL=,
// a data line a, b, t1, t2, t3, t4 or r, t, and an optional 1-direction line)
// exactly as *BEAM SECTION with that shape: so does framedyn.
bool Parser::calculix_shape_section(const Block& b) {
  auto it = b.keyword.params.find("SECTION");
  if (it == b.keyword.params.end()) return false;
  const std::string kind = upper(it->second);
  if (kind != "BOX" && kind != "PIPE") return false;
  beam_section(b);
  return true;
}

void Parser::material(const Block& b) {
  check_params(b.keyword, {"NAME"});
  current_material_ = upper(required_param(b.keyword, "NAME"));
  if (materials_.count(current_material_)) throw InputError(b.keyword.where, "a new material name", current_material_ + " again");
  if (!b.data.empty()) throw InputError(at(b.data[0], b.keyword), "no data lines", "'" + b.data[0].text + "'");
  RawMaterial m;
  m.m.name = current_material_;
  m.where = b.keyword.where;
  materials_[current_material_] = m;
}

void Parser::elastic(const Block& b) {
  check_params(b.keyword, {"TYPE"});
  if (b.keyword.params.count("TYPE")) {
    const std::string t = upper(b.keyword.params.at("TYPE"));
    if (t != "ISO" && t != "ISOTROPIC") throw InputError(b.keyword.where, "TYPE=ISOTROPIC", "TYPE=" + t);
  }
  if (current_material_.empty()) throw InputError(b.keyword.where, "a *MATERIAL before *ELASTIC", "none");
  if (b.data.size() != 1) throw InputError(b.keyword.where, "one data line: E, nu", fmt::format("{} data lines", b.data.size()));
  const std::vector<double> v = numbers(b.data[0], b.keyword, 2, 3, "E, nu[, temperature]");
  if (!(v[0] > 0)) throw InputError(at(b.data[0], b.keyword), "Young's modulus E > 0", fmt::format("{}", v[0]));
  if (!(v[1] > -1.0 && v[1] < 0.5)) throw InputError(at(b.data[0], b.keyword), "Poisson's ratio between -1 and 0.5", fmt::format("{}", v[1]));
  RawMaterial& m = materials_[current_material_];
  // A second *ELASTIC would silently replace the first: which one was meant?
  if (m.has_elastic) throw InputError(b.keyword.where, "one *ELASTIC per *MATERIAL", "a second *ELASTIC for " + current_material_);
  m.m.youngs_modulus = v[0];
  m.m.poisson_ratio = v[1];
  m.has_elastic = true;
}

void Parser::density(const Block& b) {
  check_params(b.keyword, {});
  if (current_material_.empty()) throw InputError(b.keyword.where, "a *MATERIAL before *DENSITY", "none");
  if (b.data.size() != 1) throw InputError(b.keyword.where, "one data line: density", fmt::format("{} data lines", b.data.size()));
  const std::vector<double> v = numbers(b.data[0], b.keyword, 1, 2, "density[, temperature]");
  if (v[0] < 0) throw InputError(at(b.data[0], b.keyword), "a density >= 0", fmt::format("{}", v[0]));
  RawMaterial& m = materials_[current_material_];
  if (m.has_density) throw InputError(b.keyword.where, "one *DENSITY per *MATERIAL", "a second *DENSITY for " + current_material_);
  m.m.density = v[0];
  m.has_density = true;
}

template <class Location>
int dof_number(const std::string& s, const Location& where) {
  const long d = parse_int(s, where, "a degree of freedom 1-6");
  if (d < 1 || d > 6) throw InputError(where, "a degree of freedom 1-6", s);
  return static_cast<int>(d);
}

// Loads and supports before the first *STEP are model data (step 0) and hold
// in every step; after it they belong to a step.
int Parser::data_step(const Keyword& k) {
  if (!in_step_ && steps_ > 0)
    throw InputError(k.where, k.name + " inside a *STEP (after the first step, loads and supports belong to a step)", "it between two steps");
  return in_step_ ? steps_ : 0;
}

// OP=MOD (the default) keeps what earlier steps defined; OP=NEW removes it
// first (docs/theory/fem.md sections 18 and 21).
bool Parser::replaces_earlier(const Keyword& k) {
  auto it = k.params.find("OP");
  if (it == k.params.end()) return false;
  const std::string op = upper(it->second);
  if (op == "MOD") return false;
  if (op == "NEW") return true;
  throw InputError(k.where, "OP=MOD or OP=NEW", "OP=" + it->second);
}

void Parser::boundary(const Block& b) {
  check_params(b.keyword, {"OP"});
  const int step = data_step(b.keyword);
  // CalculiX: OP=NEW removes every support prescribed before the step, the
  // model data's included, and "takes effect for the first *BOUNDARY card
  // only" of the step. framedyn refuses it on a later card rather than guess
  // whether the cards before it survive (docs/theory/fem.md section 21).
  const int card = ++boundary_cards_[step];
  if (replaces_earlier(b.keyword)) {
    if (card > 1)
      throw InputError(b.keyword.where,
                       "OP=NEW on the first *BOUNDARY of its step only (it removes the supports prescribed before the step; CalculiX "
                       "applies it to the first *BOUNDARY card of a step)",
                       step > 0 ? fmt::format("OP=NEW on *BOUNDARY card {} of step {}", card, step)
                                : fmt::format("OP=NEW on *BOUNDARY card {} of the model data", card));
    if (step > 0) raw_steps_.back().new_boundaries = true;
  }
  for (const Line& l : b.data) {
    std::vector<std::string> f = split_fields(l.text);
    RawBoundary r;
    r.step = step;
    r.where = at(l, b.keyword);
    if (f.size() < 2 || f.size() > 4) throw InputError(r.where, "node or set, first DOF[, last DOF[, value]]", "'" + l.text + "'");
    r.target = f[0];
    const std::string kind = upper(f[1]);
    r.value = 0.0;
    if (kind == "ENCASTRE" || kind == "PINNED") {
      if (f.size() != 2) throw InputError(r.where, "node or set, " + kind, "'" + l.text + "'");
      r.first_dof = 1;
      r.last_dof = kind == "ENCASTRE" ? 6 : 3;
    } else if (!is_integer(f[1])) {
      throw InputError(r.where, "a DOF number or ENCASTRE or PINNED", "'" + f[1] + "'");
    } else {
      r.first_dof = dof_number(f[1], r.where);
      r.last_dof = (f.size() >= 3 && !f[2].empty()) ? dof_number(f[2], r.where) : r.first_dof;
      if (r.last_dof < r.first_dof) throw InputError(r.where, "last DOF >= first DOF", "'" + l.text + "'");
      if (f.size() == 4 && !f[3].empty()) r.value = parse_double(f[3], r.where, "a prescribed displacement");
    }
    boundaries_.push_back(r);
  }
}

void Parser::cload(const Block& b) {
  check_params(b.keyword, {"OP", "AMPLITUDE"});
  std::string amplitude;
  if (b.keyword.params.count("AMPLITUDE")) amplitude = upper(required_param(b.keyword, "AMPLITUDE"));
  const int step = data_step(b.keyword);
  if (replaces_earlier(b.keyword) && step > 0) raw_steps_.back().new_cloads = true;
  for (const Line& l : b.data) {
    std::vector<std::string> f = split_fields(l.text);
    RawLoad r;
    r.step = step;
    r.where = at(l, b.keyword);
    if (f.size() != 3) throw InputError(r.where, "node or set, DOF, magnitude", "'" + l.text + "'");
    r.target = f[0];
    r.dof = dof_number(f[1], r.where);
    r.value = parse_double(f[2], r.where, "a load magnitude");
    r.amplitude = amplitude;
    loads_.push_back(r);
  }
}

void Parser::element_property(const Block& b) {
  check_params(b.keyword, {"ELSET"});
  RawElementProperty p;
  p.keyword = b.keyword.name;
  p.elset = upper(required_param(b.keyword, "ELSET"));
  p.where = b.keyword.where;
  if (p.keyword == "*MASS") {
    if (b.data.size() != 1) throw InputError(b.keyword.where, "one data line: mass", fmt::format("{} data lines", b.data.size()));
    p.values = numbers(b.data[0], b.keyword, 1, 1, "the mass");
    if (!(p.values[0] > 0)) throw InputError(at(b.data[0], b.keyword), "a positive mass", b.data[0].text);
  } else if (p.keyword == "*ROTARY INERTIA") {
    if (b.data.size() != 1) throw InputError(b.keyword.where, "one data line: I11, I22, I33[, I12, I13, I23]", fmt::format("{} data lines", b.data.size()));
    p.values = numbers(b.data[0], b.keyword, 3, 6, "I11, I22, I33[, I12, I13, I23]");
    p.values.resize(6, 0.0);
  } else {  // *SPRING
    if (b.data.size() != 2) throw InputError(b.keyword.where, "two data lines: the DOF(s), then the stiffness", fmt::format("{} data lines", b.data.size()));
    for (const std::string& s : split_fields(b.data[0].text))
      if (!s.empty()) p.dofs.push_back(dof_number(s, at(b.data[0], b.keyword)));
    if (p.dofs.empty() || p.dofs.size() > 2) throw InputError(at(b.data[0], b.keyword), "one DOF (SPRING1) or two (SPRING2)", "'" + b.data[0].text + "'");
    p.values = numbers(b.data[1], b.keyword, 1, 1, "the spring stiffness");
    if (!(p.values[0] > 0)) throw InputError(at(b.data[1], b.keyword), "a positive stiffness", b.data[1].text);
  }
  properties_.push_back(p);
}

// ------------------------------------------------------------ rigid links
// *RIGID BODY, NSET=..., REF NODE=... (CalculiX; Abaqus's TIE NSET and PIN
// NSET too) and *MPC with BEAM lines ("BEAM, slave, master", as Abaqus
// defines it): the nodes follow the reference node rigidly (fem/rigid_links.h).

void Parser::rigid_body(const Block& b) {
  check_params(b.keyword, {"NSET", "TIE NSET", "PIN NSET", "REF NODE", "ROT NODE", "ELSET", "POSITION"});
  const Keyword& k = b.keyword;
  if (k.params.count("ROT NODE"))
    throw InputError(k.where, "no ROT NODE (framedyn's nodes have rotations: the REF NODE's DOFs 4-6 are the body's rotations; put the "
                              "*BOUNDARY and *CLOAD of the rotation node's DOFs 1-3 on DOFs 4-6 of the REF NODE)",
                     "ROT NODE=" + k.params.at("ROT NODE"));
  if (k.params.count("ELSET"))
    throw InputError(k.where, "the tied nodes as NSET=, TIE NSET= or PIN NSET= (framedyn has no rigid elements)", "ELSET=" + k.params.at("ELSET"));
  if (k.params.count("POSITION"))
    throw InputError(k.where, "the reference node where it is defined (no POSITION parameter)", "POSITION=" + k.params.at("POSITION"));
  if (!b.data.empty()) throw InputError(at(b.data[0], k), "no data lines after *RIGID BODY", "'" + b.data[0].text + "'");
  RawRigidLink r;
  r.where = k.where;
  r.reference = required_param(k, "REF NODE");
  bool any = false;
  for (const char* name : {"NSET", "TIE NSET", "PIN NSET"}) {
    if (!k.params.count(name)) continue;
    r.slaves = required_param(k, name);
    r.slave_rotations = std::string(name) != "PIN NSET";
    rigid_links_.push_back(r);
    any = true;
  }
  if (!any) throw InputError(k.where, "NSET=, TIE NSET= or PIN NSET= naming the nodes the reference node carries", "none");
}

void Parser::mpc(const Block& b) {
  check_params(b.keyword, {});
  if (b.data.empty()) throw InputError(b.keyword.where, "data lines 'BEAM, slave node, master node'", "none");
  for (const Line& l : b.data) {
    const std::vector<std::string> f = split_fields(l.text);
    const std::string type = upper(f[0]);
    if (type != "BEAM")
      throw InputError(at(l, b.keyword), "an MPC of type BEAM (a rigid link; framedyn reads no other MPC type)", "'" + f[0] + "'");
    if (f.size() != 3 || f[1].empty() || f[2].empty())
      throw InputError(at(l, b.keyword), "BEAM, slave node, master node", "'" + l.text + "'");
    RawRigidLink r;
    r.where = at(l, b.keyword);
    r.slaves = f[1];
    r.reference = f[2];
    rigid_links_.push_back(r);
  }
}

// *DISTRIBUTING COUPLING, ELSET= (Abaqus, CalculiX): the DCOUP3D element(s) of the
// set sit on the reference node; data lines "node or node set, weight" (weight
// 1 when left out) are the mounts (fem/rigid_links.h, Eqs. R.6-R.8).
void Parser::distributing_coupling(const Block& b) {
  check_params(b.keyword, {"ELSET"});
  RawCoupling c;
  c.where = b.keyword.where;
  c.elset = upper(required_param(b.keyword, "ELSET"));
  if (b.data.empty()) throw InputError(b.keyword.where, "data lines 'mount node or node set, weight'", "none");
  for (const Line& l : b.data) {
    const std::vector<std::string> f = split_fields(l.text);
    if (f.empty() || f.size() > 2 || f[0].empty()) throw InputError(at(l, b.keyword), "mount node or node set, weight", "'" + l.text + "'");
    const double w = f.size() == 2 && !f[1].empty() ? parse_double(f[1], at(l, b.keyword), "a weight") : 1.0;
    if (!(w > 0.0)) throw InputError(at(l, b.keyword), "a positive weight", f[1]);
    c.mounts.emplace_back(f[0], w);
  }
  couplings_.push_back(c);
}

// Resolves node numbers and sets, then checks the links against each other
// and the supports (rigid_link_constraints), each error at its line.
void Parser::build_rigid_links(FrameModel& model) const {
  auto nodes_of = [&](const std::string& t, const InputLocation& where, const char* role) {
    if (is_integer(t)) {
      const int id = static_cast<int>(parse_int(t, where, "node"));
      const int i = model.node_index(id);
      if (i < 0) throw InputError(where, fmt::format("a {} defined by *NODE", role), fmt::format("node {}", id));
      return std::vector<int>{i};
    }
    auto it = model.node_sets.find(upper(t));
    if (it == model.node_sets.end()) throw InputError(where, fmt::format("a {} given by its number or a defined *NSET", role), "'" + t + "'");
    return it->second;
  };
  for (const RawRigidLink& raw : rigid_links_) {
    const std::vector<int> ref = nodes_of(raw.reference, raw.where, "reference node");
    if (ref.size() != 1)
      throw InputError(raw.where, "one reference node", fmt::format("set {} of {} nodes", upper(raw.reference), ref.size()));
    RigidLink link;
    link.reference_node = ref[0];
    link.slave_nodes = nodes_of(raw.slaves, raw.where, "tied node");
    link.slave_rotations = raw.slave_rotations;
    link.source = core::format_location(raw.where);
    model.rigid_links.push_back(std::move(link));
  }
  std::vector<InputLocation> coupling_where;
  for (const RawCoupling& raw : couplings_)
    for (int id : model.element_sets.at(raw.elset)) {
      DistributingCoupling c;
      c.reference_node = model.node_index(elements_[element_index_.at(id)].node_ids[0]);
      for (const auto& [target, weight] : raw.mounts)
        for (int n : nodes_of(target, raw.where, "mount node")) {
          c.mount_nodes.push_back(n);
          c.weights.push_back(weight);
        }
      c.source = core::format_location(raw.where);
      model.distributing_couplings.push_back(std::move(c));
      coupling_where.push_back(raw.where);
    }
  try {
    (void)rigid_link_constraints(model);
  } catch (const RigidLinkError& e) {
    throw InputError(rigid_links_[static_cast<std::size_t>(e.link())].where, e.expected(), e.found());
  } catch (const DistributingCouplingError& e) {
    throw InputError(coupling_where[static_cast<std::size_t>(e.coupling())], e.expected(), e.found());
  }
  if (model.rigid_links.empty()) return;
  // T^T K T multiplies what acts on a tied node by up to (1 + |d|)^2 (Eq. R.2):
  // each element is within range (checked above), the reduced one must be too.
  std::vector<double> largest(model.nodes.size(), 0.0);
  std::vector<char> tied(model.nodes.size(), 0);
  for (const RigidLink& link : model.rigid_links)
    for (int n : link.slave_nodes) tied[static_cast<std::size_t>(n)] = 1;
  auto note = [&](int node, double value) {
    if (tied[static_cast<std::size_t>(node)]) largest[static_cast<std::size_t>(node)] = std::max(largest[static_cast<std::size_t>(node)], std::abs(value));
  };
  for (const BeamElement& b : model.beams) {
    if (!tied[static_cast<std::size_t>(b.node_a)] && !tied[static_cast<std::size_t>(b.node_b)]) continue;
    const BeamGeometry g = beam_geometry(model, b);
    const double entry = std::max({beam_local_stiffness(g.data).cwiseAbs().maxCoeff(),
                                   beam_local_mass(g.data, MassFormulation::consistent).cwiseAbs().maxCoeff(),
                                   beam_local_mass(g.data, MassFormulation::lumped).cwiseAbs().maxCoeff()});
    note(b.node_a, 3.0 * entry);  // a rotation of 3x3 blocks to global axes: at most 3 times the largest entry
    note(b.node_b, 3.0 * entry);
  }
  for (const PointMass& pm : model.point_masses) note(pm.node, std::max(pm.mass, pm.rotary_inertia.cwiseAbs().maxCoeff()));
  for (const Spring& sp : model.springs) {
    note(sp.node_a, sp.stiffness);
    if (sp.node_b >= 0) note(sp.node_b, sp.stiffness);
  }
  for (const NodalLoad& l : model.loads) note(l.node, l.value);
  for (std::size_t li = 0; li < model.rigid_links.size(); ++li) {
    const RigidLink& link = model.rigid_links[li];
    const Eigen::Vector3d& xr = model.nodes[static_cast<std::size_t>(link.reference_node)].position;
    for (int n : link.slave_nodes) {
      const double d = (model.nodes[static_cast<std::size_t>(n)].position - xr).norm();
      // Up to 4 x 4 terms of T's row (R.1) per entry: 16 (1 + d)^2 times the largest.
      const double reduced = 16.0 * largest[static_cast<std::size_t>(n)] * (1.0 + d) * (1.0 + d);
      if (largest[static_cast<std::size_t>(n)] > 0.0 && !(reduced <= kLargestSi))
        throw InputError(rigid_links_[li].where,
                         "a lever arm that keeps the tied node's stiffness, mass and loads within floating point once carried to the "
                         "reference node (at most 1e300 in SI units)",
                         fmt::format("node {} at d = {:g} m from reference node {}, with entries up to {:g}", model.nodes[static_cast<std::size_t>(n)].id,
                                     d, model.nodes[static_cast<std::size_t>(link.reference_node)].id, largest[static_cast<std::size_t>(n)]));
    }
  }
}

// One procedure per step (CalculiX and Abaqus read one).
void Parser::set_procedure(const Keyword& k, const char* procedure) {
  RawStep& step = raw_steps_.back();
  if (!step.procedure.empty())
    throw InputError(k.where, "one procedure (*STATIC, *FREQUENCY, *MODAL DYNAMIC or *DYNAMIC) per *STEP", "*" + step.procedure + " and " + k.name + fmt::format(" in step {}", steps_));
  step.procedure = procedure;
}

void Parser::step_keyword(const Block& b) {
  const std::string& k = b.keyword.name;
  if (k == "*STEP") {
    refuse_nonlinear_step(b.keyword);
    // INC (the most increments the step may take) is ignored: framedyn's linear steps
    // take one increment, its transient steps period / increment.
    check_params(b.keyword, {"NAME", "PERTURBATION", "NLGEOM", "INC"});  // NLGEOM=NO only, see refuse_nonlinear_step
    if (in_step_) throw InputError(b.keyword.where, "*END STEP before the next *STEP", "*STEP");
    ++steps_;
    in_step_ = true;
    step_where_ = b.keyword.where;
    raw_steps_.push_back({});
    raw_steps_.back().where = b.keyword.where;
  } else if (k == "*END STEP") {
    check_params(b.keyword, {});
    if (!in_step_) throw InputError(b.keyword.where, "a *STEP before *END STEP", "*END STEP");
    in_step_ = false;
  } else if (k == "*FREQUENCY") {
    check_params(b.keyword, {"SOLVER", "STORAGE"});
    if (!in_step_) throw InputError(b.keyword.where, "*FREQUENCY inside a *STEP", "it outside");
    set_procedure(b.keyword, "FREQUENCY");
    if (!b.data.empty()) {
      const std::vector<std::string> f = split_fields(b.data[0].text);
      const long n = parse_int(f[0], at(b.data[0], b.keyword), "the number of eigenvalues");
      if (n < 1) throw InputError(at(b.data[0], b.keyword), "at least 1 eigenvalue", f[0]);
      raw_steps_.back().modes = static_cast<int>(n);
      if (!frequency_count_) frequency_count_ = static_cast<int>(n);  // the first *FREQUENCY step's
    }
  } else if (k == "*STATIC") {
    check_params(b.keyword, {"SOLVER"});
    if (!in_step_) throw InputError(b.keyword.where, "*STATIC inside a *STEP", "it outside");
    set_procedure(b.keyword, "STATIC");
  }
  // Output requests (*NODE PRINT, *EL PRINT, ...) are CalculiX's business: skipped.
}

// ---------------------------------------------------------------- transient steps (issue 13)
// *AMPLITUDE (tabular, step time), *MODAL DYNAMIC, *DYNAMIC, *MODAL DAMPING;
// docs/theory/fem.md section 22.

// *AMPLITUDE, NAME=...: time, value pairs, four to a line as CalculiX writes
// them (any number per line is read). Only what CalculiX's default reading
// gives is accepted: TIME=STEP TIME, VALUE=RELATIVE, DEFINITION=TABULAR.
void Parser::amplitude(const Block& b) {
  const Keyword& k = b.keyword;
  check_params(k, {"NAME", "TIME", "VALUE", "DEFINITION"});
  const std::string name = upper(required_param(k, "NAME"));
  auto option = [&](const char* key, const char* supported) {  // INP-68
    auto it = k.params.find(key);
    if (it != k.params.end() && upper(it->second) != supported)
      throw InputError(k.where,
                       fmt::format("{}={} (framedyn reads tabular amplitudes in step time with relative values: TIME=STEP TIME, "
                                   "VALUE=RELATIVE, DEFINITION=TABULAR)", key, supported),
                       fmt::format("{}={} on *AMPLITUDE, NAME={}", key, it->second, name));
  };
  option("TIME", "STEP TIME");
  option("VALUE", "RELATIVE");
  option("DEFINITION", "TABULAR");
  if (amplitudes_.count(name)) throw InputError(k.where, "one *AMPLITUDE of each name", "a second *AMPLITUDE, NAME=" + name);
  std::vector<double> v;
  for (const Line& l : b.data)
    for (const std::string& f : split_fields(l.text))
      if (!f.empty()) v.push_back(parse_double(f, at(l, k), "an amplitude time or value"));
  Amplitude a;
  for (std::size_t i = 0; i + 1 < v.size(); i += 2) a.times.push_back(v[i]), a.values.push_back(v[i + 1]);
  // INP-70: pairs, at least one, times not decreasing.
  bool ordered = true;
  for (std::size_t i = 1; i < a.times.size(); ++i) ordered = ordered && a.times[i] >= a.times[i - 1];
  if (v.empty() || v.size() % 2 != 0 || !ordered)
    throw InputError(b.data.empty() ? k.where : InputLocation(at(b.data.front(), k)),
                     "time, value pairs with times that do not decrease",
                     v.empty() ? std::string("no data line")
                               : v.size() % 2 != 0 ? fmt::format("{} numbers (an odd count)", v.size())
                                                   : fmt::format("*AMPLITUDE, NAME={} going back in time", name));
  amplitudes_[name] = std::move(a);
}

// *MODAL DYNAMIC and *DYNAMIC: the data line is the time increment and the
// step's time period (s). framedyn integrates with that fixed increment;
// CalculiX's automatic-increment and explicit options are refused rather
// than approximated.
void Parser::transient_procedure(const Block& b) {
  const Keyword& k = b.keyword;
  const bool modal = k.name == "*MODAL DYNAMIC";
  if (modal) check_params(k, {"SOLVER", "DIRECT", "DELTMX", "STEADY STATE"});
  else check_params(k, {"SOLVER", "DIRECT", "ALPHA", "EXPLICIT"});
  if (!in_step_) throw InputError(k.where, k.name + " inside a *STEP", "it outside");
  // INP-75: the options framedyn's integrators cannot honour.
  if (k.params.count("STEADY STATE") || k.params.count("EXPLICIT"))
    throw InputError(k.where,
                     fmt::format("{} with a fixed time increment and period (framedyn has no {})", k.name,
                                 k.params.count("EXPLICIT") ? "explicit integration" : "run-to-steady-state option"),
                     k.params.count("EXPLICIT") ? "EXPLICIT" : "STEADY STATE");
  if (k.params.count("ALPHA")) {
    const double alpha = parse_double(k.params.at("ALPHA"), k.where, "ALPHA");
    if (alpha != 0.0)
      throw InputError(k.where,
                       "ALPHA=0 or no ALPHA (framedyn's *DYNAMIC is Newmark's average-acceleration rule, the alpha-method with "
                       "alpha = 0: no numerical damping)",
                       "ALPHA=" + k.params.at("ALPHA"));
  }
  set_procedure(k, modal ? "MODAL DYNAMIC" : "DYNAMIC");
  // INP-72: time increment and period, 0 < increment <= period.
  TransientSettings t;
  std::vector<double> v;
  if (!b.data.empty()) v = numbers(b.data.front(), k, 1, 8, "a time increment or period");
  if (v.size() < 2 || !(v[0] > 0.0) || !(v[1] >= v[0]) || v[1] / v[0] > 1e7)
    throw InputError(b.data.empty() ? k.where : InputLocation(at(b.data.front(), k)),
                     "a data line: time increment, time period (s), 0 < increment <= period, at most 1e7 increments",
                     b.data.empty() ? std::string("none") : "'" + b.data.front().text + "'");
  t.time_increment = v[0];
  t.time_period = v[1];
  raw_steps_.back().transient = t;
}

// *MODAL DAMPING (CalculiX): lines "first mode, last mode, ratio" (ratios of
// critical damping; modes in no range are undamped), or with RAYLEIGH one
// line ", , alpha, beta" (C = alpha M + beta K). In the *MODAL DYNAMIC step,
// after its procedure line.
void Parser::modal_damping(const Block& b) {
  const Keyword& k = b.keyword;
  check_params(k, {"RAYLEIGH", "MODAL", "OP"});
  RawStep* step = in_step_ ? &raw_steps_.back() : nullptr;
  if (!step || step->procedure != "MODAL DYNAMIC" || !step->transient)  // INP-74
    throw InputError(k.where, "*MODAL DAMPING in a *MODAL DYNAMIC step, after the *MODAL DYNAMIC line",
                     step ? fmt::format("it in step {} ({})", steps_, step->procedure.empty() ? std::string("no procedure yet") : "*" + step->procedure)
                          : std::string("it outside a step"));
  TransientSettings& t = *step->transient;
  const bool rayleigh = k.params.count("RAYLEIGH") > 0;
  if (b.data.empty()) throw InputError(k.where, rayleigh ? "a data line: , , alpha, beta" : "data lines: first mode, last mode, damping ratio", "none");
  for (const Line& l : b.data) {
    const std::vector<std::string> f = split_fields(l.text);
    const Where where = at(l, k);
    if (rayleigh) {
      if (f.size() != 4 || b.data.size() != 1)
        throw InputError(where, "one data line: , , alpha, beta (C = alpha M + beta K)", "'" + l.text + "'");
      t.rayleigh = true;
      t.rayleigh_alpha = f[2].empty() ? 0.0 : parse_double(f[2], where, "alpha");
      t.rayleigh_beta = f[3].empty() ? 0.0 : parse_double(f[3], where, "beta");
      if (t.rayleigh_alpha < 0.0 || t.rayleigh_beta < 0.0) throw InputError(where, "alpha >= 0 and beta >= 0", "'" + l.text + "'");
      continue;
    }
    if (f.size() != 3) throw InputError(where, "first mode, last mode, damping ratio", "'" + l.text + "'");
    ModalDampingRange r;
    r.first_mode = static_cast<int>(parse_int(f[0], where, "the first mode"));
    r.last_mode = static_cast<int>(parse_int(f[1], where, "the last mode"));
    r.ratio = parse_double(f[2], where, "a damping ratio");
    if (r.first_mode < 1 || r.last_mode < r.first_mode || !(r.ratio >= 0.0) || !(r.ratio < 1.0))
      throw InputError(where, "1 <= first mode <= last mode and a damping ratio 0 <= zeta < 1", "'" + l.text + "'");
    t.damping_ranges.push_back(r);
  }
}

// ---------------------------------------------------------------- *DLOAD, *RELEASE, *TRANSVERSE SHEAR STIFFNESS

// *DLOAD data lines (Abaqus): element or ELSET, load type, magnitude; for GRAV
// also the direction (three components, normalised here). Uniform loads on
// beams only: GRAV (acceleration, the mass from density and area, or the
// *MASS of MASS elements), P1 and P2 (force per length along the section's
// local 1 and 2 directions), PX, PY, PZ (force per length along global X, Y, Z).
void Parser::dload(const Block& b) {
  if (b.keyword.params.count("AMPLITUDE"))  // INP-76
    throw InputError(b.keyword.where,
                     "a *DLOAD constant in its step (framedyn reads AMPLITUDE= on *CLOAD only; give the line load's time history "
                     "as nodal loads with *CLOAD, AMPLITUDE=)",
                     "AMPLITUDE=" + b.keyword.params.at("AMPLITUDE"));
  check_params(b.keyword, {"OP"});
  const int step = data_step(b.keyword);
  if (replaces_earlier(b.keyword) && step > 0) raw_steps_.back().new_dloads = true;
  if (b.data.empty()) throw InputError(b.keyword.where, "data lines: element or ELSET, load type, magnitude", "none");
  for (const Line& l : b.data) {
    const std::vector<std::string> f = split_fields(l.text);
    RawDistributedLoad r;
    r.step = step;
    r.where = at(l, b.keyword);
    if (f.size() < 2) throw InputError(r.where, "element or ELSET, load type, magnitude", "'" + l.text + "'");
    r.target = f[0];
    r.type = upper(f[1]);
    if (r.type == "GRAV") {
      if (f.size() != 6) throw InputError(r.where, "element or ELSET (empty: all elements), GRAV, acceleration, direction x, y, z", "'" + l.text + "'");
      r.magnitude = parse_double(f[2], r.where, "the acceleration of gravity");
      for (int i = 0; i < 3; ++i) r.direction(i) = f[3 + static_cast<std::size_t>(i)].empty() ? 0.0 : parse_double(f[3 + static_cast<std::size_t>(i)], r.where, "a direction component");
      const double norm = r.direction.norm();
      if (!(norm > 0.0) || !std::isfinite(norm)) throw InputError(r.where, "a nonzero, finite gravity direction", "'" + l.text + "'");
      r.direction /= norm;
    } else if (r.type == "P1" || r.type == "P2" || r.type == "PX" || r.type == "PY" || r.type == "PZ") {
      if (f.size() != 3) throw InputError(r.where, "element or ELSET, " + r.type + ", force per length", "'" + l.text + "'");
      if (r.target.empty()) throw InputError(r.where, "an element or ELSET for " + r.type + " (only GRAV applies to all elements)", "an empty field");
      r.magnitude = parse_double(f[2], r.where, "a force per length");
    } else {
      throw InputError(r.where, "a load type framedyn reads on beams: GRAV, P1, P2, PX, PY or PZ (uniform)", "'" + f[1] + "'");
    }
    dloads_.push_back(r);
  }
}

// *RELEASE data lines (Abaqus): element or ELSET, end S1 (first node) or S2,
// release combination M1, M2, T, ALLM or moments joined by '-' (M1-M2, M1-T, M2-T).
void Parser::release(const Block& b) {
  check_params(b.keyword, {});
  if (b.data.empty()) throw InputError(b.keyword.where, "data lines: element or ELSET, S1 or S2, release combination", "none");
  for (const Line& l : b.data) {
    const std::vector<std::string> f = split_fields(l.text);
    RawRelease r;
    r.where = at(l, b.keyword);
    if (f.size() != 3 || f[0].empty()) throw InputError(r.where, "element or ELSET, S1 or S2, release combination", "'" + l.text + "'");
    r.target = f[0];
    const std::string end = upper(f[1]);
    if (end != "S1" && end != "S2") throw InputError(r.where, "the element end S1 (first node) or S2 (second node)", "'" + f[1] + "'");
    const int e = end == "S1" ? 0 : 1;
    const std::string combination = upper(f[2]);
    std::size_t start = 0;
    while (start <= combination.size()) {
      const std::size_t dash = combination.find('-', start);
      const std::string token = combination.substr(start, dash == std::string::npos ? std::string::npos : dash - start);
      if (token == "M1") r.mask |= release_bit(e, kReleaseM1);
      else if (token == "M2") r.mask |= release_bit(e, kReleaseM2);
      else if (token == "T") r.mask |= release_bit(e, kReleaseTorsion);
      else if (token == "ALLM") r.mask |= release_bit(e, kReleaseM1) | release_bit(e, kReleaseM2) | release_bit(e, kReleaseTorsion);
      else throw InputError(r.where, "a release combination of M1, M2, T (joined by '-') or ALLM", "'" + f[2] + "'");
      if (dash == std::string::npos) break;
      start = dash + 1;
    }
    releases_.push_back(r);
  }
}

// *TRANSVERSE SHEAR STIFFNESS after a beam section (Abaqus, beams): K23 (shear
// along local 2), K13 (shear along local 1)[, slenderness compensation factor].
// framedyn takes K = G A_s as given (no slenderness compensation: the factor
// must be blank or 0); Timoshenko elements (B31) use it, B33 has no shear strain.
void Parser::transverse_shear_stiffness(const Block& b, const Block* previous) {
  check_params(b.keyword, {});
  if (!previous || (previous->keyword.name != "*BEAM SECTION" && previous->keyword.name != "*BEAM GENERAL SECTION") || sections_.empty())
    throw InputError(b.keyword.where, "*TRANSVERSE SHEAR STIFFNESS directly after the *BEAM SECTION or *BEAM GENERAL SECTION it belongs to",
                     previous ? "it after " + previous->keyword.name : "it first");
  if (b.data.size() != 1) throw InputError(b.keyword.where, "one data line: K23, K13[, slenderness compensation]", fmt::format("{} data lines", b.data.size()));
  const std::vector<double> v = numbers(b.data[0], b.keyword, 2, 3, "K23, K13[, slenderness compensation]");
  if (!(v[0] > 0.0) || !(v[1] > 0.0)) throw InputError(at(b.data[0], b.keyword), "positive shear stiffnesses K23 and K13", "'" + b.data[0].text + "'");
  if (v.size() == 3 && v[2] != 0.0)
    throw InputError(at(b.data[0], b.keyword), "a slenderness compensation factor of 0 or blank (framedyn uses K as given)", "'" + b.data[0].text + "'");
  RawSection& s = sections_.back();
  if (s.shear_stiffness) throw InputError(b.keyword.where, "one *TRANSVERSE SHEAR STIFFNESS per section", "a second one");
  s.shear_stiffness = Eigen::Vector2d(v[1], v[0]);  // (along 1, along 2)
  s.shear_where = b.keyword.where;
}

std::vector<int> Parser::element_targets(const std::string& target, const InputLocation& where) const {
  if (is_integer(target)) {
    const int id = static_cast<int>(parse_int(target, where, "element number"));
    if (!element_index_.count(id)) throw InputError(where, "an element defined by *ELEMENT or a defined *ELSET", fmt::format("element {}", id));
    return {id};
  }
  auto it = elsets_.find(upper(target));
  if (it == elsets_.end()) throw InputError(where, "an element number or a defined *ELSET", "'" + target + "'");
  std::vector<int> ids = it->second;
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  return ids;
}

// RAYLEIGH and *TRANSVERSE SHEAR STIFFNESS onto the sections (model.sections
// was built from sections_ in order, one for one).
void Parser::apply_section_extras(FrameModel& model, const core::UnitSystem& units) const {
  for (std::size_t i = 0; i < sections_.size() && i < model.sections.size(); ++i) {
    const RawSection& raw = sections_[i];
    SectionAssignment& sa = model.sections[i];
    sa.bending_rotary_inertia = raw.rayleigh;
    if (!raw.shear_stiffness) continue;
    const double g = sa.material.shear_modulus;
    const double k1 = units.to_si((*raw.shear_stiffness)(0), Quantity::force), k2 = units.to_si((*raw.shear_stiffness)(1), Quantity::force);
    if (!(k1 <= kLargestSi) || !(k2 <= kLargestSi) || !(g > 0.0))
      throw InputError(raw.shear_where, "shear stiffnesses of magnitude at most 1e300 in SI units and a section with G > 0", "larger values");
    sa.properties.shear_area_1 = k1 / g;  // the element uses G A_s
    sa.properties.shear_area_2 = k2 / g;
  }
}

// The section heights (along 1, along 2; input units) that OFFSET1 and
// OFFSET2 count in, as CalculiX 2.20 places the expanded section (measured on
// the C3D20R mesh it writes, docs/theory/fem.md section 21): the outer widths
// of RECT and BOX, the outer diameter 2r of PIPE, the value written on the
// line of CIRC (CalculiX's thickness of a CIRC section). I and CHANNEL,
// which CalculiX has no offsets for, count in their outline: the wider
// flange along 1 and the height along 2.
Eigen::Vector2d offset_heights(const RawSection& s) {
  const std::vector<double>& d = s.dims;
  if (s.shape == "RECT" || s.shape == "BOX") return {d[0], d[1]};
  if (s.shape == "PIPE") return {2.0 * d[0], 2.0 * d[0]};
  if (s.shape == "CIRC") return {d[0], d.size() > 1 ? d[1] : d[0]};
  if (s.shape == "I") return {std::max(d[2], d[3]), d[1]};
  if (s.shape == "CHANNEL") return {d[1], d[0]};
  return {0.0, 0.0};  // GENERAL: no OFFSET parameters (check_params)
}

// Offsets (Eq. 3.5) as rigid eccentricities: each end of an offset element
// gets a node of its own on the element's axis, x + e, tied rigidly to the
// mesh node (a rigid link, section R), and the element is moved onto them.
// The new nodes are numbered after the mesh's highest node number, in the
// order of the elements; e is along the chord's local axes, the same at every
// node of the element (a three-node element keeps its midside node's place
// relative to its ends).
void Parser::apply_offsets(FrameModel& model) {
  int next_id = 0;
  for (const Node& n : model.nodes) next_id = std::max(next_id, n.id);
  bool added = false;
  for (BeamElement& beam : model.beams) {
    const RawSection& raw = sections_[static_cast<std::size_t>(beam.section)];
    if (raw.offset1 == 0.0 && raw.offset2 == 0.0) continue;
    const double l = model.units.to_si_factor(Quantity::length);
    const Eigen::Matrix3d axes = beam_local_axes(model.nodes[static_cast<std::size_t>(beam.node_a)].position,
                                                 model.nodes[static_cast<std::size_t>(beam.node_b)].position,
                                                 model.sections[static_cast<std::size_t>(beam.section)].n1_direction);
    const Eigen::Vector2d h = offset_heights(raw) * l;
    const Eigen::Vector3d e = kOffsetSign * (raw.offset1 * h(0) * axes.row(1).transpose() + raw.offset2 * h(1) * axes.row(2).transpose());
    for (int* end : {&beam.node_a, &beam.node_m, &beam.node_b}) {
      if (*end < 0) continue;
      const Node& mesh_node = model.nodes[static_cast<std::size_t>(*end)];
      const int mesh_id = mesh_node.id;
      const Eigen::Vector3d x = mesh_node.position + e;
      model.nodes.push_back({++next_id, x});
      *end = static_cast<int>(model.nodes.size()) - 1;
      RawRigidLink link;
      link.reference = std::to_string(mesh_id);
      link.slaves = std::to_string(next_id);
      link.where = raw.where;
      rigid_links_.push_back(link);
      added = true;
    }
  }
  if (added) model.index();
}

void Parser::apply_releases(FrameModel& model) const {
  for (const RawRelease& r : releases_) {
    for (int id : element_targets(r.target, r.where)) {
      const int bi = model.beam_index(id);
      if (bi < 0)
        throw InputError(r.where, "beam elements (B31, B32, B32R, B33) to release", fmt::format("element {} of type {}", id, elements_[element_index_.at(id)].type));
      BeamElement& beam = model.beams[static_cast<std::size_t>(bi)];
      beam.released |= r.mask;
      // On a section with a product of inertia the element works in principal
      // axes: a single bending release (M1 or M2 alone) would not be the
      // moment about the section's 1 or 2 axis.
      if (model.sections[static_cast<std::size_t>(beam.section)].properties.i12 != 0.0)
        for (int end = 0; end < 2; ++end)
          if (((beam.released & release_bit(end, kReleaseM1)) != 0) != ((beam.released & release_bit(end, kReleaseM2)) != 0))
            throw InputError(r.where, "M1 and M2 released together on a section with I12 != 0 (its elements bend about principal axes)",
                             fmt::format("element {}: {}", id, describe_releases(beam.released)));
      try {
        if (beam.is_quadratic())
          quadratic_beam_release_transformation(model, beam, section_geometry(model, beam.section, BeamTheory::timoshenko));
        else
          beam_release_transformation(beam_geometry(model, beam).data);
      } catch (const std::invalid_argument& e) {
        throw InputError(r.where, "releases that leave the element stiff against every motion of its nodes", fmt::format("element {}: {}", id, e.what()));
      }
    }
  }
}

// The loads of `dloads` on `model`'s elements, added to out.loads (GRAV on
// MASS elements) and out.element_loads.
void Parser::apply_distributed_loads(const FrameModel& model, const core::UnitSystem& units, const std::vector<RawDistributedLoad>& dloads,
                                     FrameModel& out) const {
  if (dloads.empty()) return;
  // The mass of each MASS element (several may share a node; model.point_masses merges them).
  std::unordered_map<int, double> element_mass;
  for (const RawElementProperty& p : properties_)
    if (p.keyword == "*MASS")
      for (int id : model.element_sets.at(p.elset)) element_mass[id] = units.to_si(p.values[0], Quantity::mass);
  // Accelerations: length per second squared, and time is in seconds in every system.
  const double acceleration_factor = units.to_si_factor(Quantity::length);
  for (const RawDistributedLoad& d : dloads) {
    std::vector<int> ids;
    if (d.target.empty()) {
      for (const RawElement& e : elements_) ids.push_back(e.id);
    } else {
      ids = element_targets(d.target, d.where);
    }
    double mass_found = 0.0;
    for (int id : ids) {
      const int bi = model.beam_index(id);
      const RawElement& raw = elements_[element_index_.at(id)];
      if (d.type == "GRAV") {
        const double g = d.magnitude * acceleration_factor;
        if (bi >= 0) {
          const SectionAssignment& sa = model.sections[static_cast<std::size_t>(model.beams[static_cast<std::size_t>(bi)].section)];
          const double mass_per_length = sa.material.density * sa.properties.area;
          mass_found += mass_per_length;
          if (!(std::abs(mass_per_length * g) <= kLargestSi))
            throw InputError(d.where, "a weight per length of magnitude at most 1e300 in SI units", fmt::format("element {}: {:g} N/m", id, mass_per_length * g));
          if (mass_per_length > 0.0) out.element_loads.push_back({bi, mass_per_length * g * d.direction});
        } else if (raw.type == "MASS") {
          const double m = element_mass.at(id);
          mass_found += m;
          if (!(std::abs(m * g) <= kLargestSi))
            throw InputError(d.where, "a weight of magnitude at most 1e300 in SI units", fmt::format("element {}: {:g} N", id, m * g));
          const int node = model.node_index(raw.node_ids[0]);
          for (int k = 0; k < 3; ++k)
            if (d.direction(k) != 0.0) out.loads.push_back({node, k, m * g * d.direction(k)});
        }
        // ROTARYI and SPRING elements have no translational mass: no weight.
        continue;
      }
      if (bi < 0)
        throw InputError(d.where, "beam elements (B31, B32, B32R, B33) for a " + d.type + " line load", fmt::format("element {} of type {}", id, raw.type));
      const BeamElement& beam = model.beams[static_cast<std::size_t>(bi)];
      const double q = units.to_si(d.magnitude, Quantity::force_per_length);
      Eigen::Vector3d direction = Eigen::Vector3d::Zero();
      if (d.type == "PX") direction = Eigen::Vector3d::UnitX();
      else if (d.type == "PY") direction = Eigen::Vector3d::UnitY();
      else if (d.type == "PZ") direction = Eigen::Vector3d::UnitZ();
      else if (beam.is_quadratic()) {
        // P1, P2 follow the section's axes as written, which turn along a curved element.
        if (!(std::abs(q) <= kLargestSi)) throw InputError(d.where, "a force per length of magnitude at most 1e300 in SI units", fmt::format("{:g}", d.magnitude));
        ElementLoad load{bi, Eigen::Vector3d::Zero(), Eigen::Vector2d::Zero()};
        load.section_force_per_length(d.type == "P1" ? 0 : 1) = q;
        out.element_loads.push_back(load);
        continue;
      } else {
        // The section's local axes as written (n1, n2 = t x n1), not the principal axes the element may use.
        const Eigen::Matrix3d axes = beam_local_axes(model.nodes[static_cast<std::size_t>(beam.node_a)].position,
                                                     model.nodes[static_cast<std::size_t>(beam.node_b)].position,
                                                     model.sections[static_cast<std::size_t>(beam.section)].n1_direction);
        direction = axes.row(d.type == "P1" ? 1 : 2).transpose();
      }
      if (!(std::abs(q) <= kLargestSi)) throw InputError(d.where, "a force per length of magnitude at most 1e300 in SI units", fmt::format("{:g}", d.magnitude));
      out.element_loads.push_back({bi, q * direction});
    }
    if (d.type == "GRAV" && !(mass_found > 0.0))
      throw InputError(d.where, "elements with mass for GRAV (beams whose material has a *DENSITY, or MASS elements)",
                       d.target.empty() ? std::string("no mass in the model") : "no mass in '" + d.target + "'");
  }
}

FrameModel Parser::run(const InpReadOptions& options) {
  options_ = options;
  const std::vector<Block> blocks = make_blocks(src_.lines);
  for (const Block& b : blocks) {
    const std::string& k = b.keyword.name;
    if (k == "*HEADING") continue;
    if (k == "*NODE") node(b);
    else if (k == "*ELEMENT") element(b);
    else if (k == "*NSET") set(b, true);
    else if (k == "*ELSET") set(b, false);
    else if (k == "*BEAM SECTION") beam_section(b);
    else if (k == "*BEAM GENERAL SECTION") general_beam_section(b);
    else if (k == "*MATERIAL") material(b);
    else if (k == "*ELASTIC") elastic(b);
    else if (k == "*DENSITY") density(b);
    else if (k == "*BOUNDARY") boundary(b);
    else if (k == "*CLOAD") cload(b);
    else if (k == "*DLOAD") dload(b);
    else if (k == "*RELEASE") release(b);
    else if (k == "*TRANSVERSE SHEAR STIFFNESS") transverse_shear_stiffness(b, &b == &blocks.front() ? nullptr : &b - 1);
    else if (k == "*MASS" || k == "*ROTARY INERTIA" || k == "*SPRING") element_property(b);
    else if (k == "*RIGID BODY") rigid_body(b);
    else if (k == "*MPC") mpc(b);
    else if (k == "*DISTRIBUTING COUPLING") distributing_coupling(b);
    else if (k == "*STEP" || k == "*END STEP" || k == "*FREQUENCY" || k == "*STATIC") step_keyword(b);
    else if (k == "*AMPLITUDE") amplitude(b);
    else if (k == "*MODAL DYNAMIC" || k == "*DYNAMIC") transient_procedure(b);
    else if (k == "*MODAL DAMPING") modal_damping(b);
    else if (k == "*NODE PRINT" || k == "*EL PRINT" || k == "*NODE FILE" || k == "*EL FILE" || k == "*NODE OUTPUT" ||
             k == "*ELEMENT OUTPUT" || k == "*OUTPUT") continue;
    // Time-dependent loads and the other procedures: named as such, not as
    // unknown keywords, since a CalculiX user's deck has them for a reason.
    else if (in_step_ && (k == "*STEADY STATE DYNAMICS" || k == "*BUCKLE" || k == "*HEAT TRANSFER"))
      throw InputError(b.keyword.where,
                       "*STATIC, *FREQUENCY, *MODAL DYNAMIC or *DYNAMIC as the step's procedure (framedyn's linear steps; a "
                       "harmonic sweep runs in framedyn harmonic)",
                       fmt::format("{} in step {}", k, steps_));
    else
      throw InputError(b.keyword.where,
                       "a keyword framedyn reads (*NODE, *ELEMENT, *NSET, *ELSET, *BEAM SECTION, *BEAM GENERAL SECTION, "
                       "*MATERIAL, *ELASTIC, *DENSITY, *BOUNDARY, *CLOAD, *DLOAD, *RELEASE, *TRANSVERSE SHEAR STIFFNESS, *MASS, *ROTARY INERTIA, *SPRING, *RIGID BODY, *MPC, *DISTRIBUTING COUPLING, *INCLUDE, "
                       "*HEADING, *STEP, *FREQUENCY, *STATIC, *MODAL DYNAMIC, *DYNAMIC, *MODAL DAMPING, *AMPLITUDE, *END STEP, output requests)",
                       k);
    if (k != "*ELASTIC" && k != "*DENSITY" && k != "*MATERIAL") current_material_.clear();
  }
  if (in_step_) throw InputError(step_where_, "*END STEP at the end of the step", "end of file");

  // Unit system: the caller's, or the file's "** units:" comment.
  auto system = [](const std::string& name, const InputLocation& where) {
    try {
      return core::UnitSystem::from_name(name);
    } catch (const std::invalid_argument&) {
      throw InputError(where, "in-lbf-s, m-N-s (or SI) or mm-N-s", "'" + name + "'");
    }
  };
  std::optional<core::UnitSystem> from_option, from_comment;
  if (options.units) from_option = system(*options.units, {src_.name, 0, "--units"});
  if (src_.units_comment) from_comment = system(*src_.units_comment, src_.units_where);
  if (from_option && from_comment && from_option->name() != from_comment->name())
    throw InputError(src_.units_where, "the unit system given on the command line (" + *options.units + ")", *src_.units_comment);
  if (!from_option && !from_comment)
    throw InputError({src_.name, 0, "units"},
                     "a unit system: --units in-lbf-s|m-N-s|mm-N-s, or a line '** units: NAME' in the mesh (the .inp format has no units)",
                     "neither");
  return build(from_option ? *from_option : *from_comment);
}

FrameModel Parser::build(const core::UnitSystem& units) {
  FrameModel model;
  model.units = units;
  model.requested_modes = frequency_count_;
  const double L = units.to_si_factor(Quantity::length);
  // A value in range in the file's units may not be in SI: 1e308 lbf*s^2/in is 1.75e310 kg.
  auto si = [&](double value, Quantity q, const InputLocation& where, const std::string& what) {
    const double x = units.to_si(value, q);
    if (!(std::abs(x) <= kLargestSi))
      throw InputError(where, what + " of magnitude at most 1e300 in SI units", fmt::format("{:g} ({:g} in SI units)", value, x));
    return x;
  };
  model.nodes.reserve(nodes_.size());
  for (const auto& [id, x] : nodes_) model.nodes.push_back({id, x * L});
  model.index();
  auto node_of = [&](int id, const auto& where) {
    const int i = model.node_index(id);
    if (i < 0) throw InputError(where, "a node defined by *NODE", fmt::format("node {}", id));
    return i;
  };

  // Sets: keep names; check that members exist.
  for (const auto& [name, ids] : nsets_) {
    std::vector<int> idx;
    idx.reserve(ids.size());
    const std::vector<Where>& where = nset_where_.at(name);
    for (std::size_t i = 0; i < ids.size(); ++i) idx.push_back(node_of(ids[i], where[i]));
    std::sort(idx.begin(), idx.end());
    idx.erase(std::unique(idx.begin(), idx.end()), idx.end());
    model.node_sets[name] = idx;
  }
  for (const auto& [name, ids] : elsets_) {
    const std::vector<Where>& where = elset_where_.at(name);
    for (std::size_t i = 0; i < ids.size(); ++i)
      if (!element_index_.count(ids[i]))
        throw InputError(where[i], "elements defined by *ELEMENT (in ELSET " + name + ")", fmt::format("element {}", ids[i]));
    std::vector<int> sorted = ids;
    std::sort(sorted.begin(), sorted.end());
    sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
    model.element_sets[name] = sorted;
  }

  // Elements.
  std::unordered_map<int, std::size_t> beam_of_element;
  for (const RawElement& e : elements_) {
    std::vector<int> idx;
    for (int id : e.node_ids) idx.push_back(node_of(id, e.where));
    if (e.type == "B31" || e.type == "B33") {
      BeamElement b;
      b.id = e.id;
      b.node_a = idx[0];
      b.node_b = idx[1];
      b.theory = e.type == "B31" ? BeamTheory::timoshenko : BeamTheory::euler_bernoulli;
      if ((model.nodes[static_cast<std::size_t>(idx[0])].position - model.nodes[static_cast<std::size_t>(idx[1])].position).norm() == 0.0)
        throw InputError(e.where, "an element of nonzero length", fmt::format("element {}: nodes {} and {} at the same point", e.id, e.node_ids[0], e.node_ids[1]));
      beam_of_element[e.id] = model.beams.size();
      model.beams.push_back(b);
    } else if (e.type == "B32" || e.type == "B32R") {
      beam_of_element[e.id] = model.beams.size();
      model.beams.push_back(quadratic_beam(e, idx));
    }
  }
  model.index();

  // Sections.
  for (const RawSection& s : sections_) {
    auto set_it = elsets_.find(s.elset);
    if (set_it == elsets_.end()) throw InputError(s.where, "ELSET naming a defined element set", s.elset);
    SectionAssignment sa;
    sa.element_set = s.elset;
    sa.n1_direction = s.n1;
    if (s.general) {
      sa.material.name = "(general section)";
      sa.material.youngs_modulus = units.to_si(s.general_e, Quantity::stress);
      sa.material.shear_modulus = units.to_si(s.general_g, Quantity::stress);
      sa.material.density = units.to_si(s.general_density, Quantity::density);
    } else {
      auto m = materials_.find(s.material);
      if (m == materials_.end()) throw InputError(s.where, "MATERIAL naming a defined *MATERIAL", s.material);
      if (!m->second.has_elastic) throw InputError(m->second.where, "an *ELASTIC definition for material " + s.material, "none");
      sa.material = m->second.m;
      sa.material.youngs_modulus = units.to_si(sa.material.youngs_modulus, Quantity::stress);
      sa.material.shear_modulus = sa.material.youngs_modulus / (2.0 * (1.0 + sa.material.poisson_ratio));
      sa.material.density = units.to_si(sa.material.density, Quantity::density);
    }
    // CIRC: Abaqus reads radii, CalculiX 2.20 diameters (section 23; measured
    // with ccx 2.20 on a B32 cantilever: its tip deflection is that of the
    // circle whose diameter is the value). Without a dialect, Abaqus's reading
    // and a warning with both.
    const double circ_scale = options_.dialect == InpDialect::calculix ? 0.5 : 1.0;
    if (s.shape == "CIRC" && !options_.dialect) {
      const std::string L_unit = units.label(Quantity::length);
      const std::string values = s.dims.size() > 1 ? fmt::format("{:g}, {:g}", s.dims[0], s.dims[1]) : fmt::format("{:g}", s.dims[0]);
      core::add_warning(model.reader_warnings, "circ_radius_or_diameter",
                        fmt::format("{}: SECTION=CIRC of ELSET {} read as Abaqus reads it, {} {} {}; CalculiX 2.20 reads the same line as "
                                    "{} (a section 1/16 as stiff in bending): give {} abaqus or calculix to say which the deck means",
                                    s.where.file + ":" + std::to_string(s.where.line), s.elset, s.dims.size() > 1 ? "semi-axes" : "radius", values,
                                    L_unit, s.dims.size() > 1 ? "the axes (semi-axes half as long)" : "the diameter (radius half as long)",
                                    options_.dialect_key),
                        {{"radius_read", s.dims[0], L_unit}, {"radius_calculix", 0.5 * s.dims[0], L_unit}});
    }
    try {
      const double l = L, l2 = L * L, l4 = l2 * l2;
      const std::vector<double>& d = s.dims;
      const double nu = sa.material.poisson_ratio;
      if (s.shape == "RECT") sa.properties = rectangle_section(d[0] * l, d[1] * l, nu);
      else if (s.shape == "BOX") sa.properties = box_section(d[0] * l, d[1] * l, d[2] * l, d[3] * l, d[4] * l, d[5] * l);
      else if (s.shape == "PIPE") sa.properties = pipe_section(d[0] * l, d[1] * l, nu);
      else if (s.shape == "CIRC" && d.size() > 1) sa.properties = ellipse_section(circ_scale * d[0] * l, circ_scale * d[1] * l, nu);
      else if (s.shape == "CIRC") sa.properties = circle_section(circ_scale * d[0] * l, nu);
      else if (s.shape == "I") sa.properties = i_section(d[1] * l, d[2] * l, d[3] * l, d[4] * l, d[5] * l, d[6] * l);
      else if (s.shape == "CHANNEL") sa.properties = channel_section(d[0] * l, d[1] * l, d[2] * l, d[3] * l);
      else sa.properties = fem::general_section(d[0] * l2, d[1] * l4, d[2] * l4, d[3] * l4, d[4] * l4);
    } catch (const std::invalid_argument& e) {
      throw InputError(s.where, "a valid " + s.shape + " section", e.what());
    }
    const int index = static_cast<int>(model.sections.size());
    model.sections.push_back(sa);
    for (int id : set_it->second) {
      auto b = beam_of_element.find(id);
      if (b == beam_of_element.end())
        throw InputError(s.where, "beam elements (B31, B32, B32R, B33) in ELSET " + s.elset, fmt::format("element {} of type {}", id, elements_[element_index_[id]].type));
      BeamElement& beam = model.beams[b->second];
      if (beam.section >= 0 && beam.section != index)
        throw InputError(s.where, fmt::format("one section per element"), fmt::format("element {} already has the section of ELSET {}", id, model.sections[static_cast<std::size_t>(beam.section)].element_set));
      beam.section = index;
    }
  }
  for (const BeamElement& b : model.beams) {
    if (b.section < 0)
      throw InputError(elements_[element_index_[b.id]].where, "a *BEAM SECTION for every beam element", fmt::format("element {} has none", b.id));
    if (b.is_quadratic()) {
      check_quadratic_beam(model, b, elements_[element_index_[b.id]].where);
      continue;
    }
    try {
      beam_local_axes(model.nodes[static_cast<std::size_t>(b.node_a)].position, model.nodes[static_cast<std::size_t>(b.node_b)].position,
                      model.sections[static_cast<std::size_t>(b.section)].n1_direction);
    } catch (const std::invalid_argument& e) {
      throw InputError(elements_[element_index_[b.id]].where, "a valid beam orientation", fmt::format("element {}: {}", b.id, e.what()));
    }
    // Each value may be finite and its products not: E = 1e300, a section 1e200 wide, an element 1e-200 long.
    const BeamGeometry g = beam_geometry(model, b);
    if (!within_range(g.axes) || !within_range(beam_local_stiffness(g.data)) ||
        !within_range(beam_local_mass(g.data, MassFormulation::consistent)) || !within_range(beam_local_mass(g.data, MassFormulation::lumped)))
      throw InputError(elements_[element_index_[b.id]].where,
                       "element stiffness and mass within the range of floating point (entries of at most 1e300 in SI units)",
                       fmt::format("element {}: length {:g} m, E {:g} Pa, G {:g} Pa, density {:g} kg/m^3, A {:g} m^2, I11 {:g} m^4, "
                                   "I22 {:g} m^4, J {:g} m^4 (section of ELSET {})",
                                   b.id, g.data.length, g.data.youngs_modulus, g.data.shear_modulus, g.data.density, g.data.section.area,
                                   g.data.section.i11, g.data.section.i22, g.data.section.torsion_constant,
                                   model.sections[static_cast<std::size_t>(b.section)].element_set));
  }

  // Point masses, rotary inertia, springs.
  std::map<int, std::size_t> point_mass_of_node;
  auto point_mass_at = [&](int node, int element_id) -> PointMass& {
    auto it = point_mass_of_node.find(node);
    if (it != point_mass_of_node.end()) return model.point_masses[it->second];
    PointMass pm;
    pm.node = node;
    pm.element_id = element_id;
    point_mass_of_node[node] = model.point_masses.size();
    model.point_masses.push_back(pm);
    return model.point_masses.back();
  };
  std::set<int> has_property;
  for (const RawElementProperty& p : properties_) {
    auto set_it = model.element_sets.find(p.elset);  // sorted, each element once
    if (set_it == model.element_sets.end()) throw InputError(p.where, "ELSET naming a defined element set", p.elset);
    const std::string want = p.keyword == "*MASS" ? "MASS" : p.keyword == "*ROTARY INERTIA" ? "ROTARYI" : "SPRING";
    for (int id : set_it->second) {
      const RawElement& e = elements_[element_index_[id]];
      if (e.type.rfind(want, 0) != 0)
        throw InputError(p.where, want + " elements in ELSET " + p.elset, fmt::format("element {} of type {}", id, e.type));
      if (!has_property.insert(id).second) throw InputError(p.where, "one property per element", fmt::format("element {} twice", id));
      const int n0 = model.node_index(e.node_ids[0]);
      if (p.keyword == "*MASS") {
        point_mass_at(n0, id).mass += si(p.values[0], Quantity::mass, p.where, "a mass");
      } else if (p.keyword == "*ROTARY INERTIA") {
        const double f = units.to_si_factor(Quantity::rotary_inertia);
        Eigen::Matrix3d j;
        j << p.values[0], p.values[3], p.values[4], p.values[3], p.values[1], p.values[5], p.values[4], p.values[5], p.values[2];
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(j);
        if (es.eigenvalues().minCoeff() < 0) throw InputError(p.where, "a positive semi-definite rotary inertia", "a negative principal value");
        if (!within_range(Eigen::Matrix3d(j * f)))
          throw InputError(p.where, "a rotary inertia of magnitude at most 1e300 in SI units", fmt::format("element {}: a larger entry", id));
        point_mass_at(n0, id).rotary_inertia += j * f;
      } else {
        Spring s;
        s.element_id = id;
        s.node_a = n0;
        s.dof_a = p.dofs[0] - 1;
        if (e.type == "SPRING2") {
          if (p.dofs.size() != 2) throw InputError(p.where, "two DOFs for SPRING2 elements", fmt::format("{}", p.dofs.size()));
          s.node_b = model.node_index(e.node_ids[1]);
          s.dof_b = p.dofs[1] - 1;
          if ((s.dof_a < 3) != (s.dof_b < 3)) throw InputError(p.where, "two translations or two rotations", "a translation and a rotation");
        } else if (p.dofs.size() != 1) {
          throw InputError(p.where, "one DOF for SPRING1 elements", fmt::format("{}", p.dofs.size()));
        }
        s.stiffness = si(p.values[0], s.dof_a < 3 ? Quantity::translational_stiffness : Quantity::rotational_stiffness, p.where, "a spring stiffness");
        model.springs.push_back(s);
      }
    }
  }
  // A DCOUP3D element's property is its *DISTRIBUTING COUPLING (build_rigid_links).
  for (const RawCoupling& c : couplings_) {
    auto set_it = model.element_sets.find(c.elset);
    if (set_it == model.element_sets.end()) throw InputError(c.where, "ELSET naming a defined element set of DCOUP3D elements", c.elset);
    for (int id : set_it->second) {
      const RawElement& e = elements_[element_index_[id]];
      if (e.type != "DCOUP3D") throw InputError(c.where, "DCOUP3D elements in ELSET " + c.elset, fmt::format("element {} of type {}", id, e.type));
      if (!has_property.insert(id).second) throw InputError(c.where, "one coupling per DCOUP3D element", fmt::format("element {} twice", id));
    }
  }
  for (const RawElement& e : elements_)
    if (e.type != "B31" && e.type != "B33" && e.type != "B32" && e.type != "B32R" && !has_property.count(e.id))
      throw InputError(e.where, (e.type == "DCOUP3D" ? "a *DISTRIBUTING COUPLING for element " : "a *MASS, *ROTARY INERTIA or *SPRING for element ") +
                                  std::to_string(e.id) + " of type " + e.type, "none");

  apply_section_extras(model, units);
  apply_releases(model);
  apply_offsets(model);

  // Supports and loads: the model data's, then what each step adds or
  // replaces (docs/theory/fem.md section 18). Without *STEP the model data
  // is all there is.
  auto targets = [&](const std::string& t, const InputLocation& where) {
    if (is_integer(t)) return std::vector<int>{node_of(static_cast<int>(parse_int(t, where, "node")), where)};
    auto it = model.node_sets.find(upper(t));
    if (it == model.node_sets.end()) throw InputError(where, "a node number or a defined *NSET", "'" + t + "'");
    return it->second;
  };
  std::vector<Constraint> constraints;
  std::map<std::pair<int, int>, std::size_t> constraint_of;  // (node, dof) -> index into constraints
  std::vector<NodalLoad> loads;
  std::vector<std::string> load_amplitudes;  // parallel to loads
  std::vector<RawDistributedLoad> dloads;
  for (const RawLoad& l : loads_)  // INP-71: an AMPLITUDE= no *AMPLITUDE defines
    if (!l.amplitude.empty() && !amplitudes_.count(l.amplitude)) {
      std::string known;
      for (const auto& [name, a] : amplitudes_) known += (known.empty() ? "" : ", ") + name;
      throw InputError(l.where, fmt::format("AMPLITUDE= naming an *AMPLITUDE of the deck ({})", known.empty() ? std::string("it defines none") : known),
                       "AMPLITUDE=" + l.amplitude);
    }
  model.amplitudes = amplitudes_;
  const int step_count = static_cast<int>(raw_steps_.size());
  for (int step = 0; step <= step_count; ++step) {
    // Supports: OP=NEW drops the earlier ones; a DOF defined again takes the new value (OP=MOD).
    if (step > 0 && raw_steps_[static_cast<std::size_t>(step - 1)].new_boundaries) constraints.clear(), constraint_of.clear();
    for (const RawBoundary& b : boundaries_) {
      if (b.step != step) continue;
      for (int n : targets(b.target, b.where))
        for (int d = b.first_dof; d <= b.last_dof; ++d) {
          const double v = si(b.value, d <= 3 ? Quantity::length : Quantity::angle, b.where, "a prescribed displacement");
          auto [it, fresh] = constraint_of.emplace(std::make_pair(n, d - 1), constraints.size());
          if (fresh) constraints.push_back({n, d - 1, v});
          else constraints[it->second].value = v;
        }
    }
    // Nodal loads: OP=NEW drops the earlier ones; a node and DOF loaded in
    // this step drops the earlier steps' loads there; lines of one step add up.
    const bool new_cloads = step > 0 && raw_steps_[static_cast<std::size_t>(step - 1)].new_cloads;
    const bool new_dloads = step > 0 && raw_steps_[static_cast<std::size_t>(step - 1)].new_dloads;
    if (new_cloads) loads.clear(), load_amplitudes.clear();
    std::vector<NodalLoad> added;
    std::vector<std::string> added_amplitudes;
    for (const RawLoad& l : loads_) {
      if (l.step != step) continue;
      for (int n : targets(l.target, l.where)) {
        added.push_back({n, l.dof - 1, si(l.value, l.dof <= 3 ? Quantity::force : Quantity::moment, l.where, "a load")});
        added_amplitudes.push_back(l.amplitude);
      }
    }
    std::set<std::pair<int, int>> redefined;
    for (const NodalLoad& a : added) redefined.insert({a.node, a.dof});
    std::size_t kept = 0;
    for (std::size_t i = 0; i < loads.size(); ++i)
      if (!redefined.count({loads[i].node, loads[i].dof})) loads[kept] = loads[i], load_amplitudes[kept++] = load_amplitudes[i];
    loads.resize(kept), load_amplitudes.resize(kept);
    loads.insert(loads.end(), added.begin(), added.end());
    load_amplitudes.insert(load_amplitudes.end(), added_amplitudes.begin(), added_amplitudes.end());
    // Distributed loads: a line with the same element or ELSET and load type replaces the earlier steps' line.
    if (new_dloads) dloads.clear();
    std::vector<RawDistributedLoad> added_d;
    for (const RawDistributedLoad& d : dloads_)
      if (d.step == step) added_d.push_back(d);
    dloads.erase(std::remove_if(dloads.begin(), dloads.end(),
                                [&](const RawDistributedLoad& x) {
                                  return std::any_of(added_d.begin(), added_d.end(),
                                                     [&](const RawDistributedLoad& a) { return upper(a.target) == upper(x.target) && a.type == x.type; });
                                }),
                 dloads.end());
    dloads.insert(dloads.end(), added_d.begin(), added_d.end());
    if (step == 0 && step_count > 0) continue;  // model data alone is no step
    FrameModel state;  // this step's loads: the nodal loads, GRAV on point masses and the beams' line loads
    state.loads = loads;
    apply_distributed_loads(model, units, dloads, state);
    AnalysisStep a;
    a.number = step;
    const RawStep* raw = step > 0 ? &raw_steps_[static_cast<std::size_t>(step - 1)] : nullptr;
    a.procedure = raw && !raw->procedure.empty() ? raw->procedure : "STATIC";
    if (raw) a.requested_modes = raw->modes;
    a.constraints = constraints;
    a.loads = std::move(state.loads);
    a.load_amplitudes = load_amplitudes;
    a.load_amplitudes.resize(a.loads.size());  // GRAV on point masses: constant
    if (raw) a.transient = raw->transient;
    // INP-77: framedyn's static and modal steps have constant loads; a load
    // history in one would be read as its constant magnitude, silently.
    for (std::size_t i = 0; i < a.load_amplitudes.size() && !a.transient; ++i)
      if (!a.load_amplitudes[i].empty())
        throw InputError(raw ? raw->where : InputLocation{src_.name, 0, "*CLOAD"},
                         "AMPLITUDE= on loads of *MODAL DYNAMIC and *DYNAMIC steps only (framedyn's *STATIC and *FREQUENCY steps "
                         "take loads as constant)",
                         fmt::format("AMPLITUDE={} on a load of {} (*{})", a.load_amplitudes[i], step > 0 ? fmt::format("step {}", step) : std::string("the model data"), a.procedure));
    a.element_loads = std::move(state.element_loads);
    if (step <= 1) {
      model.constraints = a.constraints;
      model.loads = a.loads;
      model.element_loads = a.element_loads;
    }
    if (step > 0) model.steps.push_back(std::move(a));
  }
  build_rigid_links(model);
  if (model.beams.empty() && model.nodes.empty())
    throw InputError({src_.name, 0, "*NODE"}, "a mesh with nodes and beam elements", "none");
  return model;
}

}  // namespace

FrameModel read_inp_text(const std::string& text, const std::string& name, const fs::path& base_dir, const InpReadOptions& options) {
  TextSource src;
  src.name = name;
  std::vector<std::string> stack;
  load_lines(text, name, base_dir, src, stack);
  return Parser(src).run(options);
}

FrameModel read_inp(const fs::path& path, const InpReadOptions& options) {
  TextSource src;
  src.name = path.string();
  std::vector<std::string> stack;
  load_file(path, {path.string(), 0, ""}, src, stack);
  return Parser(src).run(options);
}

}  // namespace framedyn::fem
