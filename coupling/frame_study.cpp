// The frame transient study: read and run; see frame_study.h (report/frame_outputs writes it).
#include "coupling/frame_study.h"

#include <fmt/format.h>

#include <chrono>
#include <exception>
#include <fstream>
#include <sstream>
#include <thread>
#include <cctype>
#include <cmath>
#include <stdexcept>
#include <tuple>
#include <algorithm>
#include <limits>
#include <map>
#include <memory>

#include "core/error.h"
#include "coupling/frame_model_cache.h"
#include "fem/inp_reader.h"
#include "fem/modal_analysis.h"
#include "fem/quadratic_beam_element.h"
#include "fem/section_forces.h"
#include "fem/solver_counters.h"
#include "fem/static_analysis.h"

namespace framedyn::coupling {

namespace {

std::string quoted(const std::string& s) { return "'" + s + "'"; }

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

// " (its node sets: A, B, C)" for messages about a set the mesh lacks; the first 12.
std::string set_names(const std::map<std::string, std::vector<int>>& sets, const char* kind) {
  if (sets.empty()) return fmt::format(" (it has no {} sets)", kind);
  std::string names;
  int n = 0;
  for (const auto& kv : sets) {
    if (n == 12) {
      names += fmt::format(", ... ({} in all)", sets.size());
      break;
    }
    names += (n++ ? ", " : "") + kv.first;
  }
  return fmt::format(" (its {} sets: {})", kind, names);
}

}  // namespace

const char* supports_name(FrameSupports s) {
  switch (s) {
    case FrameSupports::fixed_rear_end: return "fixed_rear_end";
    case FrameSupports::clamped: return "clamped";
    case FrameSupports::mesh_boundary: return "mesh_boundary";
    case FrameSupports::free_free_inertia_relief: return "free_free_inertia_relief";
    case FrameSupports::axle_pins: return "axle_pins";
  }
  return "";
}
const char* method_name(FrameMethod m) {
  switch (m) {
    case FrameMethod::mode_displacement: return "mode_displacement";
    case FrameMethod::mode_acceleration: return "mode_acceleration";
    case FrameMethod::direct: return "direct";
  }
  return "";
}

namespace {

std::string json_number(double v) {
  if (!std::isfinite(v)) return "null";
  return v == 0.0 ? "0" : fmt::format("{:.10g}", v);
}


// A load point must lie on the frame: inside the mesh's extent, widened on
// every side by half its largest dimension (loads at the tire contacts, well
// below a flat frame, are on it). A point outside (a typo in a coordinate, a
// mesh in other units, the wrong mesh) would otherwise reach the frame
// through a spider of any length and move the load's moment arm.
void check_load_points_on_mesh(const fem::FrameModel& model, const LoadMapping& mapping, const LoadHistory& loads, const FrameStudyRequest& q,
                               const std::string& loads_file) {
  Eigen::Vector3d lo = model.nodes.front().position, hi = lo;
  for (const fem::Node& n : model.nodes) {
    lo = lo.cwiseMin(n.position);
    hi = hi.cwiseMax(n.position);
  }
  const double margin = 0.5 * (hi - lo).maxCoeff();
  const core::UnitSystem& u = q.units;
  const double lf = 1.0 / u.to_si_factor(core::Quantity::length);
  const std::string L = u.label(core::Quantity::length);
  for (std::size_t j = 0; j < mapping.points.size(); ++j) {
    const MappedLoadPoint& m = mapping.points[j];
    const Eigen::Vector3d x = m.location;
    if ((x.array() >= lo.array() - margin).all() && (x.array() <= hi.array() + margin).all()) continue;
    int nearest = 0;
    for (std::size_t n = 1; n < model.nodes.size(); ++n)
      if ((model.nodes[n].position - x).norm() < (model.nodes[static_cast<std::size_t>(nearest)].position - x).norm()) nearest = static_cast<int>(n);
    const fem::Node& near = model.nodes[static_cast<std::size_t>(nearest)];
    const int line = j < loads.points.size() ? loads.points[j].line : 0;
    throw core::InputError(
        {loads_file, line, "point " + m.name},
        fmt::format("a load point on the frame mesh {} (X {:g} to {:g}, Y {:g} to {:g}, Z {:g} to {:g} {}, give or take {:g} {})", q.mesh.string(),
                    lo.x() * lf, hi.x() * lf, lo.y() * lf, hi.y() * lf, lo.z() * lf, hi.z() * lf, L, margin * lf, L),
        fmt::format("{:g} {:g} {:g} {}, {:.4g} {} from the nearest node ({})", x.x() * lf, x.y() * lf, x.z() * lf, L, (near.position - x).norm() * lf, L,
                    near.id));
  }
}

}  // namespace

core::InputLocation FrameStudyRequest::where(const std::string& key) const {
  const auto at = key_locations.find(key);
  return at != key_locations.end() ? at->second : core::InputLocation{file, 0, "frame." + key};
}

FrameStudyRequest read_frame_block(const YamlMap& f, const std::filesystem::path& dir, FrameDefaults defaults) {
  const bool pipeline = defaults == FrameDefaults::pipeline;
  // dead_load in the pipeline only: the static loads come from the vehicle model.
  if (pipeline)
    f.allow_only({"mesh", "loads", "supports", "support_set", "modes", "method", "damping", "output_interval", "stations", "outputs", "paraview", "pvd",
                  "direct_substeps", "convert_units", "inp_dialect", "mesh_loads", "steady_from", "stress_histories", "yield_strength", "dead_load",
                  "compare_supports", "fatigue", "sections"});
  else
    f.allow_only({"mesh", "loads", "supports", "support_set", "modes", "method", "damping", "output_interval", "stations", "outputs", "paraview", "pvd",
                  "direct_substeps", "convert_units", "inp_dialect", "mesh_loads", "steady_from", "stress_histories", "yield_strength", "fatigue", "sections"});
  FrameStudyRequest r;
  r.file = f.file();
  r.units = f.units();
  const auto resolve = [&](const std::string& p) {
    const std::filesystem::path path(p);
    return path.is_absolute() ? path : dir / path;
  };
  r.mesh = resolve(f.text("mesh"));
  // Here, not in the mesh reader, so that the message names the study's key and line.
  if (std::error_code ec; !std::filesystem::is_regular_file(r.mesh, ec))
    throw f.error("mesh", "an .inp mesh file (a path relative to the study file)",
                  quoted(r.mesh.string()) + (std::filesystem::exists(r.mesh, ec) ? ", not a file" : ", no such file"));
  if (f.has("loads")) r.loads = resolve(f.text("loads"));
  // An operating study holds the frame as the machine does: free, its loads balanced by its inertia (the
  // vehicle model's frame acceleration; docs/user-guide.md, "Which support to believe"). The thesis's
  // clamped rear end (fixed_rear_end) is kept for parity with its SAPIV runs.
  const std::string supports = f.text_or("supports", pipeline ? "none" : "mesh_boundary");
  if (supports == "fixed_rear_end") r.supports = FrameSupports::fixed_rear_end;
  else if (supports == "clamped") r.supports = FrameSupports::clamped;
  else if (supports == "mesh_boundary") r.supports = FrameSupports::mesh_boundary;
  else if (supports == "free_free_inertia_relief" || supports == "none") r.supports = FrameSupports::free_free_inertia_relief;
  else if (supports == "axle_pins") r.supports = FrameSupports::axle_pins;
  else throw f.error("supports", "clamped, mesh_boundary, none (free_free_inertia_relief), axle_pins or fixed_rear_end", quoted(supports));
  // support_set: a node-set name or a list of them.
  if (f.has("support_set")) {
    const YAML::Node n = f.node()["support_set"];
    r.support_sets = n.IsSequence() ? f.strings("support_set") : std::vector<std::string>{f.text("support_set")};
    if (r.support_sets.empty()) throw f.error("support_set", "a node-set name or a list of them", "an empty list");
    if (r.supports == FrameSupports::mesh_boundary || r.supports == FrameSupports::free_free_inertia_relief || r.supports == FrameSupports::axle_pins)
      throw f.error("support_set", "support_set only with supports: clamped or fixed_rear_end (the node sets they clamp)",
                    "supports: " + supports);
  } else if (r.supports == FrameSupports::clamped) {
    throw f.error("supports", "supports: clamped with support_set naming the node set(s) to clamp", "no support_set");
  }
  // Supports compared in the same run (pipeline only: the key is refused elsewhere).
  if (f.has("compare_supports")) {
    const YAML::Node n = f.node()["compare_supports"];
    const std::vector<std::string> names = n.IsSequence() ? f.strings("compare_supports") : std::vector<std::string>{f.text("compare_supports")};
    for (const std::string& name : names) {
      FrameSupports c;
      if (name == "none" || name == "free_free_inertia_relief") c = FrameSupports::free_free_inertia_relief;
      else if (name == "axle_pins") c = FrameSupports::axle_pins;
      else if (name == "fixed_rear_end") c = FrameSupports::fixed_rear_end;
      else throw f.error("compare_supports", "a list of supports among none, axle_pins and fixed_rear_end", quoted(name));
      if (c == r.supports || std::find(r.compare_supports.begin(), r.compare_supports.end(), c) != r.compare_supports.end())
        throw f.error("compare_supports", "supports other than the run's own (supports: " + supports + ") and each once",
                      quoted(name) + (c == r.supports ? ", the run's own support" : " twice"));
      r.compare_supports.push_back(c);
    }
  }
  // Output sets. Without the key: the pipeline's two rails, or none.
  if (!pipeline) r.rails.clear();
  if (f.has("outputs")) {
    r.rails.clear();
    const YamlMap outputs = f.map("outputs");
    for (const auto& kv : outputs.node()) {
      const std::string name = kv.first.Scalar();
      bool plain = !name.empty();
      for (char c : name) plain = plain && (std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-');
      if (!plain) throw outputs.error(name, "an output name of letters, digits, '_' and '-' (it names files)", quoted(name));
      const YamlMap o = outputs.map(name);
      o.allow_only({"element_set", "node_set", "history"});
      if (o.has("element_set") == o.has("node_set"))
        throw outputs.error(name, "exactly one of element_set or node_set", o.has("node_set") ? "both" : "neither");
      const std::string which = o.has("element_set") ? "element_set" : "node_set";
      core::InputLocation at = o.location(which);
      at.key = o.path() + "." + which;
      r.key_locations["outputs." + name] = at;
      if (which == "element_set") {
        r.rails.push_back({name, o.text("element_set"), o.boolean_or("history", true)});
      } else {
        if (o.has("history")) throw o.error("history", "no history key for a node set (its history is always written)", "history");
        r.node_outputs.push_back({name, o.text("node_set")});
      }
    }
  } else {
    for (const RailSpec& rail : r.rails) {
      core::InputLocation at = f.location("");
      at.key = f.path() + ".outputs";
      r.key_locations["outputs." + rail.name] = at;
    }
  }
  r.convert_units = f.boolean_or("convert_units", false);
  if (f.has("inp_dialect")) {
    const std::string dialect = f.text("inp_dialect");
    if (dialect == "abaqus") r.inp_dialect = fem::InpDialect::abaqus;
    else if (dialect == "calculix") r.inp_dialect = fem::InpDialect::calculix;
    else  // STUDY-155
      throw f.error("inp_dialect", "abaqus (SECTION=CIRC values are radii) or calculix (diameters)", quoted(dialect));
  }
  if (f.has("sections")) r.sections = read_section_overrides(f.map("sections"));  // STUDY-152, 154; 150, 151, 153 once the mesh is read
  const std::string mesh_loads = f.text_or("mesh_loads", pipeline ? "none" : "constant");
  if (mesh_loads != "constant" && mesh_loads != "none")
    throw f.error("mesh_loads", "constant (the mesh's *CLOAD and *DLOAD act throughout, from their static equilibrium) or none", quoted(mesh_loads));
  r.mesh_loads = mesh_loads == "constant";
  r.dead_load = pipeline && f.boolean_or("dead_load", true);
  // The static state has gravity and the vehicle model's static loads: the mesh's own would count twice.
  if (r.dead_load && r.mesh_loads)
    throw f.error("mesh_loads", "mesh_loads: none with the dead load on (the static state already applies gravity and the static loads), or dead_load: false",
                  "mesh_loads: constant");
  for (const char* key : {"supports", "support_set", "modes", "loads", "mesh", "inp_dialect"}) {
    // A defaulted key: the block's line, still under the key's own path.
    core::InputLocation at = f.location(f.has(key) ? key : "");
    at.key = f.path() + "." + key;
    r.key_locations[key] = at;
  }
  if (f.has("modes")) {
    const YAML::Node n = f.node()["modes"];
    if (n.IsScalar() && n.Scalar() == "all") r.modes = -1;
    else {
      r.modes = f.integer("modes");
      if (r.modes < 1) throw f.error("modes", "a number of modes >= 1 or 'all'", describe(n));
    }
  }
  const std::string method = f.text_or("method", "mode_acceleration");
  if (method == "mode_displacement") r.method = FrameMethod::mode_displacement;
  else if (method == "mode_acceleration") r.method = FrameMethod::mode_acceleration;
  else if (method == "direct") r.method = FrameMethod::direct;
  else throw f.error("method", "mode_displacement, mode_acceleration or direct", quoted(method));
  if (f.has("damping")) {
    const YamlMap d = f.map("damping");
    d.allow_only({"modal_ratio", "rayleigh"});
    if (d.has("modal_ratio") == d.has("rayleigh"))
      throw f.error("damping", "exactly one of modal_ratio or rayleigh", d.has("rayleigh") ? "both" : "neither");
    if (d.has("modal_ratio")) {
      const YAML::Node n = d.node()["modal_ratio"];
      std::vector<double> ratios = n.IsSequence() ? d.numbers("modal_ratio", core::Quantity::dimensionless)
                                                  : std::vector<double>{d.number("modal_ratio", core::Quantity::dimensionless)};
      if (ratios.empty()) throw d.error("modal_ratio", "a ratio or a list of ratios", "an empty list");
      for (double z : ratios)
        if (!(z >= 0.0 && z < 1.0)) throw d.error("modal_ratio", "damping ratios in [0, 1)", json_number(z));
      r.damping = fem::ModalDamping{ratios, false, 0.0, 0.0};
    } else {
      const YamlMap ry = d.map("rayleigh");
      ry.allow_only({"alpha", "beta"});
      // alpha in 1/s and beta in s are the same in every unit system.
      r.damping = fem::ModalDamping::rayleigh_damping(ry.non_negative("alpha", core::Quantity::dimensionless),
                                                      ry.non_negative("beta", core::Quantity::dimensionless));
    }
  }
  if (r.method == FrameMethod::direct && !r.damping.rayleigh)
    throw f.error("damping", "rayleigh: {alpha, beta} for method direct (a full-system integrator needs C = alpha M + beta K)",
                  "modal_ratio");
  if (f.has("output_interval")) r.output_interval = f.positive("output_interval", core::Quantity::time);
  if (f.has("stations")) {
    r.stations = f.integer("stations");
    if (r.stations < 2) throw f.error("stations", "at least 2 stations per element (the ends)", std::to_string(r.stations));
  }
  // paraview: xdmf | vtu | none; the older pvd: true / false means vtu / none.
  if (f.has("pvd") && f.has("paraview"))
    throw f.error("pvd", "either paraview (xdmf, vtu or none) or the older pvd (true: vtu, false: none), not both", "both keys");
  if (f.has("pvd")) {
    r.paraview = f.boolean_or("pvd", false) ? ParaviewOutput::vtu : ParaviewOutput::none;
  } else {
    const std::string paraview = f.text_or("paraview", "xdmf");
    if (paraview == "xdmf") r.paraview = ParaviewOutput::xdmf;
    else if (paraview == "vtu") r.paraview = ParaviewOutput::vtu;
    else if (paraview == "none") r.paraview = ParaviewOutput::none;
    else
      throw f.error("paraview", "xdmf (one .xdmf + .h5 file per run), vtu (a .pvd + one .vtu per output time) or none for the ParaView time series",
                    quoted(paraview));
  }
  if (f.has("steady_from")) r.steady_from = f.non_negative("steady_from", core::Quantity::time);
  if (f.has("yield_strength")) r.yield_strength = f.positive("yield_strength", core::Quantity::stress);
  const std::string histories = f.text_or("stress_histories", "none");
  if (histories == "none") r.stress_histories = FrameStudyRequest::StressHistoryOutput::none;
  else if (histories == "hot_spots") r.stress_histories = FrameStudyRequest::StressHistoryOutput::hot_spots;
  else if (histories == "all") r.stress_histories = FrameStudyRequest::StressHistoryOutput::all;
  else
    throw f.error("stress_histories",
                  "none, hot_spots (the top stations' worst points) or all (every station and section point) for frame_stress_histories.csv",
                  quoted(histories));
  if (f.has("fatigue")) r.fatigue = read_fatigue_block(f.map("fatigue"));
  if (f.has("direct_substeps")) {
    r.direct_substeps = f.integer("direct_substeps");
    if (r.direct_substeps < 1) throw f.error("direct_substeps", "an integer >= 1", std::to_string(r.direct_substeps));
  }
  return r;
}

FrameStudyRequest read_frame_study(const std::string& file) {
  const YAML::Node doc = load_yaml_file(file);
  core::UnitSystem si = core::UnitSystem::si();
  YamlMap top(doc, "", file, &si);
  if (top.integer("framedyn_study") != 1) throw top.error("framedyn_study", "1 (the study format this framedyn reads)", top.text("framedyn_study"));
  // The model before the keys: a rigid-body study's keys are not unknown, they are another command's.
  if (const std::string model = top.text("model"); model != "frame_transient")
    throw top.error("model", "frame_transient (the study framedyn frame-response runs)",
                    quoted(model) + (model.rfind("rigid_", 0) == 0 ? " (a rigid-body study: run it with framedyn run)" : ""));
  top.allow_only({"framedyn_study", "name", "units", "model", "frame"});
  const std::string units = top.text("units");
  core::UnitSystem u = si;
  try {
    u = core::UnitSystem::from_name(units);
  } catch (const std::invalid_argument&) {
    throw top.error("units", "in-lbf-s, m-N-s (or SI) or mm-N-s", quoted(units));
  }
  YamlMap root(doc, "", file, &u);
  const std::string model = root.text("model");
  if (model != "frame_transient") throw root.error("model", "frame_transient", quoted(model));
  FrameStudyRequest r = read_frame_block(root.map("frame"), std::filesystem::path(file).parent_path(), FrameDefaults::standalone);
  r.name = root.text_or("name", file);
  r.units = u;
  r.file = file;
  return r;
}

fem::FrameModel read_frame_mesh(const FrameStudyRequest& q) {
  fem::InpReadOptions o;
  o.dialect = q.inp_dialect;
  o.dialect_key = q.where("inp_dialect").key;  // the warning names the study's key, not the command line's option
  fem::FrameModel model;
  if (q.sections.empty()) {
    model = fem::read_inp(q.mesh, o);
  } else {  // the mesh text with the study's section dimensions on its *BEAM SECTION lines
    std::ifstream in(q.mesh, std::ios::binary);
    if (!in) throw core::InputError(q.where("mesh"), "a readable .inp mesh file", quoted(q.mesh.string()));
    std::stringstream text;
    text << in.rdbuf();
    model = fem::read_inp_text(apply_section_overrides(text.str(), q.mesh.string(), q.sections, q.units), q.mesh.string(), q.mesh.parent_path(), o);
  }
  // A mesh in other units than the study is most often the wrong file (a
  // metric copy of an inch frame): converted only when the study says so.
  if (!q.convert_units && model.units.name() != q.units.name())
    throw core::InputError(q.where("mesh"),
                           fmt::format("a mesh in the study's units, {} (or frame.convert_units: true to convert it)", q.units.name()),
                           fmt::format("{} in {} (its '** units:' line)", q.mesh.string(), model.units.name()));
  return model;
}

namespace {

// supports: axle_pins (docs/theory/coupling.md, section 12): the six DOFs that
// hold the frame where the machine does, statically determinately (3-2-1): the
// rear axle pin's three translations (the rear axle is rigid with the frame),
// the front axle pin's lateral and vertical translation (the front axle rolls
// about its pin, so the pin takes no roll moment; with the rear pin they fix
// pitch and yaw), and the leveling cylinder's vertical translation (roll); a
// mesh without the cylinder's node set holds roll at the rear axle pin (RX).
// The pins are the mesh's load-point node sets (the vehicle model's points 25-27).
std::vector<int> axle_pin_supports(const fem::FrameModel& model, const FrameStudyRequest& q) {
  const auto node_of = [&](const char* set_name) {
    const auto set = model.node_sets.find(set_name);
    return set == model.node_sets.end() || set->second.empty() ? -1 : set->second.front();
  };
  const int rear = node_of("P26_REAR_AXLE_PIN"), front = node_of("P25_FRONT_AXLE_PIN"), cylinder = node_of("P27_LEVELING_CYLINDER");
  if (rear < 0 || front < 0)
    throw core::InputError(q.where("supports"),
                           "node sets P26_REAR_AXLE_PIN and P25_FRONT_AXLE_PIN in the mesh " + q.mesh.string() +
                               " (where supports: axle_pins holds the frame; supports: none needs no node set)",
                           fmt::format("no node set {}", rear < 0 ? "P26_REAR_AXLE_PIN" : "P25_FRONT_AXLE_PIN"));
  constexpr int k = fem::kDofsPerNode;
  return {k * rear + 0, k * rear + 1, k * rear + 2, k * front + 1, k * front + 2, cylinder >= 0 ? k * cylinder + 2 : k * rear + 3};
}

// The slowest decay rate of a free vibration among the basis's elastic modes (1/s), numbered as
// modal_transient numbers them for its damping: zeta omega for an underdamped mode, the slower root
// omega (zeta - sqrt(zeta^2 - 1)) for an overdamped one; 0 when a mode is undamped (nothing decays).
double slowest_modal_decay(const fem::ModalBasis& basis, const fem::ModalDamping& damping) {
  double slowest = std::numeric_limits<double>::infinity();
  int elastic = 0;
  for (Eigen::Index i = 0; i < basis.eigenvalues.size(); ++i) {
    if (basis.rigid_body[static_cast<std::size_t>(i)]) continue;
    const double omega = std::sqrt(std::max(basis.eigenvalues(i), 0.0));
    const double zeta = damping.ratio_of(elastic++, omega);
    const double rate = !(omega > 0.0) ? 0.0 : zeta < 1.0 ? zeta * omega : omega * (zeta - std::sqrt(zeta * zeta - 1.0));
    slowest = std::min(slowest, rate);
  }
  return std::isfinite(slowest) ? slowest : 0.0;
}

}  // namespace

FrameStudyResults run_frame_study(const FrameStudyRequest& q, const LoadHistory* given, const LoadHistory* static_loads,
                                  std::optional<double> rigid_steady_from, FrameModelCache* cache, core::WorkShare* share) {
  const auto start = std::chrono::steady_clock::now();
  FrameStudyResults out;
  const fem::SolverCounts counts_before = fem::solver_counts();
  // Built before by this worker for the same mesh, supports and parts (frame_model_cache.h): the same objects.
  const std::string build_key = cache ? frame_build_key(q) : std::string();
  const FrameBuild* const built = cache ? cache->find(build_key) : nullptr;
  const std::string mesh_name = q.mesh.string();
  fem::FrameModel& model = out.model;
  if (built) {
    model = built->supported;
  } else {
  out.model = read_frame_mesh(q);
  if (q.supports == FrameSupports::fixed_rear_end || q.supports == FrameSupports::clamped) {
    for (const std::string& name : q.support_sets) {
      const auto set = model.node_sets.find(upper(name));
      if (set == model.node_sets.end() || set->second.empty())
        throw core::InputError(q.where("support_set"), "a node set of the mesh " + mesh_name + set_names(model.node_sets, "node"), quoted(name));
      for (int node : set->second)
        for (int d = 0; d < fem::kDofsPerNode; ++d) model.constraints.push_back({node, d, 0.0});
    }
  } else if (q.supports == FrameSupports::mesh_boundary) {
    if (model.constraints.empty())
      throw core::InputError(q.where("supports"),
                             "supports for the mesh " + mesh_name +
                                 ": *BOUNDARY in the mesh (supports: mesh_boundary, the default), supports: clamped with support_set, or supports: none "
                                 "(free-free)",
                             "no *BOUNDARY in the mesh");
  } else if (!model.constraints.empty()) {
    throw core::InputError(q.where("supports"), fmt::format("a mesh without *BOUNDARY for {}", supports_name(q.supports)),
                           fmt::format("{} constrained DOFs in {}", model.constraints.size(), mesh_name));
  }
  }  // built
  // The output sets, before the solve: a misspelt name costs no run.
  for (const RailSpec& rail : q.rails) {
    const auto set = model.element_sets.find(upper(rail.element_set));
    bool beams = false;
    if (set != model.element_sets.end())
      for (int id : set->second) beams = beams || model.beam_index(id) >= 0;
    if (!beams)
      throw core::InputError(q.where("outputs." + rail.name), "an element set of the mesh " + mesh_name + " with beam elements" +
                                                                  set_names(model.element_sets, "element"),
                             quoted(rail.element_set) + (set == model.element_sets.end() ? "" : ", without beam elements"));
  }
  for (const NodeOutputSpec& o : q.node_outputs) {
    const auto set = model.node_sets.find(upper(o.node_set));
    if (set == model.node_sets.end() || set->second.empty())
      throw core::InputError(q.where("outputs." + o.name), "a node set of the mesh " + mesh_name + set_names(model.node_sets, "node"),
                             quoted(o.node_set) + (set == model.node_sets.end() ? "" : ", an empty set"));
  }
  if (given) out.loads = *given;
  else if (q.loads) {
    out.loads = read_load_history(*q.loads);
    if (!q.convert_units && out.loads.units.name() != q.units.name())
      throw core::InputError(q.where("loads"),
                             fmt::format("a load history in the study's units, {} (or frame.convert_units: true to convert it)", q.units.name()),
                             fmt::format("{} in {} (its '# units:' line)", q.loads->string(), out.loads.units.name()));
  }
  else throw core::InputError(q.where("loads"), "a load-history file", "no 'loads' key and no loads from a rigid-body run");
  // Where the loads came from, for messages: the load-history file, or this study's own run.
  const std::string loads_file = !given && q.loads ? q.loads->string() : q.file;
  if (out.loads.times.size() < 2)
    throw core::InputError({loads_file, 0, given ? "frame_response" : "rows"}, "a load history with at least two times (loads are linear between rows)",
                           fmt::format("one row, t = {} s", out.loads.times.size() == 1 ? out.loads.times(0) : 0.0));

  std::vector<LoadPointLocation> points;
  for (const LoadPointHistory& p : out.loads.points) points.push_back({p.name, p.location});
  out.mapping = map_load_points(model, points);
  check_load_points_on_mesh(model, out.mapping, out.loads, q, loads_file);
  // The frame assembly's parts, after the loads are mapped (a load point reaches frame nodes, never a part's c.g.
  // node): their nodes are numbered after the mesh's, so the distribution gains zero rows for them.
  std::unique_ptr<FrameBuild> building;  // with a cache and no build for this key: kept for the worker's next runs
  if (built) {
    model = built->mounted;
    out.parts = built->parts;
    out.mass = built->mass;
  } else {
    if (cache && !build_key.empty()) {
      building = std::make_unique<FrameBuild>();
      building->key = build_key;
      building->supported = model;
    }
    out.parts = mount_frame_parts(model, q.parts, mesh_name);
    out.mass = frame_rigid_body_mass(model);  // M alone over all DOFs (supports freed): the one mass-only assembly
  }
  out.mapping.distribution.conservativeResize(model.dof_count(), out.mapping.distribution.cols());

  // One assembly of K and M and one factorisation of the frame per run (issue 17):
  // the modes (dense, or the Lanczos on this K and M), the dynamic response
  // (mode acceleration's static correction) and the static state all use them.
  // Factorisations that remain are of other matrices: K - sigma M and M for
  // the shift-invert Lanczos of `modes: N` (and its Sturm counts), and the
  // Newmark matrix K + a0 M + a1 C of `method: direct`.
  if (built) out.pin_supports = built->pin_supports;
  else if (q.supports == FrameSupports::axle_pins) out.pin_supports = axle_pin_supports(model, q);
  // The dynamics keep a reference to their model: a kept build's own copy, else this run's.
  std::unique_ptr<const fem::FrameDynamics> assembled;
  if (!built) {
    const fem::FrameModel* on = &model;
    if (building) {
      building->mounted = model;
      on = &building->mounted;
    }
    assembled = out.pin_supports.empty() ? std::make_unique<const fem::FrameDynamics>(*on) : std::make_unique<const fem::FrameDynamics>(*on, out.pin_supports);
  }
  const fem::FrameDynamics& frame = built ? *built->dynamics : *assembled;
  const int rigid_count = frame.rigid_count();  // free-free 6, supported 0, partially supported between
  out.free_rigid_motions = rigid_count;
  fem::ModalBasis computed_basis;
  const fem::ModalBasis& basis = built ? built->basis : computed_basis;
  if (built) {
  } else if (q.method != FrameMethod::direct && q.modes < 0) {
    computed_basis = frame.all_modes();
  } else {
    fem::ModalOptions mo;
    const int wanted = q.method == FrameMethod::direct ? std::min(20, frame.dofs().free_count() - 7) : q.modes;
    mo.mode_count = wanted + rigid_count;
    if (mo.mode_count >= frame.dofs().free_count())
      throw core::InputError(q.where("modes"), fmt::format("fewer than {} modes (the free DOFs), or 'all'", frame.dofs().free_count() - rigid_count),
                             std::to_string(q.modes));
    computed_basis = fem::modal_basis(frame.dofs(), fem::compute_modes(model, frame.dofs(), frame.system(), mo));
  }
  if (building) {
    building->parts = out.parts;
    building->mass = out.mass;
    building->pin_supports = out.pin_supports;
    building->dynamics = std::move(assembled);
    building->basis = computed_basis;
    // `frame` refers to the kept dynamics (the pointer moved, not the object): valid while the cache holds it.
    cache->keep(std::move(building));
  }

  // The lowest elastic shapes on all DOFs (rigid-link slaves included), for the mode-shape figure.
  {
    std::vector<Eigen::Index> elastic;
    for (Eigen::Index i = 0; i < basis.eigenvalues.size() && elastic.size() < 4; ++i)
      if (!basis.rigid_body[static_cast<std::size_t>(i)]) elastic.push_back(i);
    out.mode_shapes.resize(model.dof_count(), static_cast<Eigen::Index>(elastic.size()));
    const Eigen::VectorXd none = Eigen::VectorXd::Zero(model.dof_count());
    for (std::size_t k = 0; k < elastic.size(); ++k)
      out.mode_shapes.col(static_cast<Eigen::Index>(k)) = fem::expand_free(frame.dofs(), basis.shapes.col(elastic[k]), none);
  }

  fem::TransientInput in;
  in.times = out.loads.times;
  in.distribution = out.mapping.distribution;
  in.components = out.loads.component_matrix();
  // The mesh's own loads (*CLOAD, *DLOAD with gravity): one more load
  // component, 1 at every time, so they act throughout; with the default
  // initial state the response starts from the static equilibrium under them
  // and the history's first row (no start-up shock; docs/theory/fem.md, Eq. 19.8).
  if (q.mesh_loads && (!model.loads.empty() || !model.element_loads.empty())) {
    out.constant_load = fem::applied_loads(model);
    out.constant_cloads = static_cast<int>(model.loads.size());
    std::vector<int> beams;
    for (const fem::ElementLoad& e : model.element_loads) beams.push_back(e.beam);
    std::sort(beams.begin(), beams.end());
    out.constant_dloads = static_cast<int>(std::unique(beams.begin(), beams.end()) - beams.begin());
    std::vector<Eigen::Triplet<double>> t;
    for (int col = 0; col < in.distribution.outerSize(); ++col)
      for (fem::SparseMatrix::InnerIterator it(in.distribution, col); it; ++it) t.emplace_back(static_cast<int>(it.row()), col, it.value());
    const int extra = static_cast<int>(in.distribution.cols());
    for (Eigen::Index g = 0; g < out.constant_load.size(); ++g)
      if (out.constant_load(g) != 0.0) t.emplace_back(static_cast<int>(g), extra, out.constant_load(g));
    fem::SparseMatrix d(in.distribution.rows(), extra + 1);
    d.setFromTriplets(t.begin(), t.end());
    in.distribution = d;
    in.components.conservativeResize(extra + 1, Eigen::NoChange);
    in.components.row(extra).setOnes();
  }
  int interval = 1;
  if (q.output_interval) {
    const double dt = (in.times(in.times.size() - 1) - in.times(0)) / static_cast<double>(in.times.size() - 1);
    interval = std::max(1, static_cast<int>(std::lround(*q.output_interval / dt)));
  }
  // The steady window on the output times (every interval-th input time from the first), known before the run.
  SteadyWindow window;
  {
    Eigen::VectorXd t((in.times.size() - 1) / interval + 1);
    for (Eigen::Index j = 0; j < t.size(); ++j) t(j) = in.times(j * interval);
    window = steady_window(rigid_steady_from, q.steady_from, t);
  }
  // Duty cycles (request.window_lead_in_decay): the transient from a lead-in before the steady window.
  if (q.window_lead_in_decay && q.method != FrameMethod::direct) {
    const double rate = slowest_modal_decay(basis, q.damping);
    if (rate > 0.0 && *q.window_lead_in_decay > 0.0 && *q.window_lead_in_decay < 1.0) {
      const double lead_in = std::log(1.0 / *q.window_lead_in_decay) / rate;
      // The latest input time on the output grid (every interval-th time from the first) at or before
      // t_s - L: the outputs kept are then the whole run's outputs at the same times.
      Eigen::Index first = 0;
      for (Eigen::Index k = 0; k < in.times.size(); k += interval)
        if (in.times(k) <= window.from - lead_in) first = k;
      if (first > 0) {
        const Eigen::Index n = in.times.size() - first;
        in.times = Eigen::VectorXd(in.times.tail(n));
        in.components = Eigen::MatrixXd(in.components.rightCols(n));
      }
      out.window_only = FrameStudyResults::WindowOnly{in.times(0), window.from, lead_in, rate};
    }
  }
  std::optional<ModalRates> rates;  // velocities and accelerations (modal methods, node-set outputs)
  if (q.method == FrameMethod::direct) {
    fem::NewmarkOptions no;
    no.rayleigh_alpha = q.damping.alpha;
    no.rayleigh_beta = q.damping.beta;
    no.substeps = q.direct_substeps;
    no.output_interval = interval;
    out.response = fem::direct_transient(frame, in, no);
    std::vector<double> f;
    for (Eigen::Index i = 0; i < basis.eigenvalues.size(); ++i)
      if (!basis.rigid_body[static_cast<std::size_t>(i)]) f.push_back(std::sqrt(std::max(basis.eigenvalues(i), 0.0)) / 6.283185307179586);
    out.frequencies_hz = Eigen::Map<Eigen::VectorXd>(f.data(), static_cast<Eigen::Index>(f.size()));
  } else {
    fem::ModalTransientOptions mo;
    mo.method = q.method == FrameMethod::mode_displacement ? fem::ResponseMethod::mode_displacement : fem::ResponseMethod::mode_acceleration;
    mo.damping = q.damping;
    mo.output_interval = interval;
    mo.share = share;
    // A duty cycle's lead-in is integrated through, not kept: the outputs from the window's start on
    // (a time within round-off of it counts as steady), when the window holds two of them at least.
    if (out.window_only) {
      const double from = out.window_only->outputs_from, edge = from - 1e-9 * std::max(1.0, std::abs(from));
      Eigen::Index kept = 0;
      for (Eigen::Index k = 0; k < in.times.size(); k += interval) kept += in.times(k) >= edge ? 1 : 0;
      if (kept >= 2) mo.outputs_from = edge;
    }
    out.response = fem::modal_transient(frame, basis, in, mo);
    out.frequencies_hz = out.response.frequencies_hz;
    if (!q.node_outputs.empty()) rates = modal_rates(frame, basis, in, mo);
  }
  // The window alone: the outputs from its start on, by the hot spots' and the life map's own test (a time
  // within round-off of the start counts as steady).
  if (out.window_only) {
    const double from = out.window_only->outputs_from, edge = from - 1e-9 * std::max(1.0, std::abs(from));
    Eigen::Index first = 0;
    while (first < out.response.times.size() && out.response.times(first) < edge) ++first;
    const Eigen::Index n = out.response.times.size() - first;
    if (n < 2) {
      out.window_only.reset();  // no window to speak of: the life map says so on the whole record
    } else if (first > 0) {
      fem::TransientResult& r = out.response;
      r.times = Eigen::VectorXd(r.times.tail(n));
      r.displacement = Eigen::MatrixXd(r.displacement.rightCols(n));
      if (r.modal_coordinates.cols() > 0) r.modal_coordinates = Eigen::MatrixXd(r.modal_coordinates.rightCols(n));
      if (r.rigid_coordinates.cols() > 0) r.rigid_coordinates = Eigen::MatrixXd(r.rigid_coordinates.rightCols(n));
      if (rates) {
        rates->velocity = Eigen::MatrixXd(rates->velocity.rightCols(n));
        rates->acceleration = Eigen::MatrixXd(rates->acceleration.rightCols(n));
        rates->modal_coordinates = Eigen::MatrixXd(rates->modal_coordinates.rightCols(n));
      }
    }
  }
  // Static plus dynamic (section 11): the static state on the same model, supports and load mapping.
  std::vector<std::vector<std::vector<double>>> static_stress;
  if (q.dead_load) {
    Eigen::VectorXd components;
    if (static_loads) {
      bool same = static_loads->points.size() == out.loads.points.size() && static_loads->times.size() >= 1;
      for (std::size_t p = 0; same && p < out.loads.points.size(); ++p) same = static_loads->points[p].name == out.loads.points[p].name;
      if (!same) throw std::logic_error("the static loads are not at the load history's points");
      components = static_loads->component_matrix().col(0);
    }
    out.static_state = frame_static_state(frame, out.mass, q.gravity, static_loads ? &out.mapping.distribution : nullptr, static_loads ? &components : nullptr,
                                          q.rails, q.stations);
    for (const StaticStations& st : out.static_state->outputs) static_stress.push_back(st.fiber_stress);
  }
  out.rails = recover_rails(model, out.response.times, out.response.displacement, q.rails, q.stations, q.dead_load ? &static_stress : nullptr);
  for (const NodeOutputSpec& o : q.node_outputs) out.nodal.push_back(nodal_history(model, o, out.response, rates ? &*rates : nullptr));
  // Without hot spots (request.hot_spots off: a summary that reads none of what follows), the run ends here.
  if (!q.hot_spots) {
    out.solver_counts = fem::solver_counts() - counts_before;
    out.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
  }
  for (const RailSpec& rail : q.rails)
    out.sections.push_back(rail.history ? section_history(model, out.response.displacement, rail.element_set, q.stations, share) : SectionHistory{});
  // Stress histories at every station and section point, and the hot spots (docs/theory/coupling.md section 10).
  {
    std::vector<SetHistory> sets;
    for (std::size_t k = 0; k < q.rails.size(); ++k) {
      const SectionHistory& h = out.sections[k];
      if (!h.element_ids.empty()) {
        sets.push_back({q.rails[k].name, h.element_ids, h.station_index, out.rails[k].station_points, &h.values, nullptr, {}, 0});
      } else {  // no history kept: the stresses' section forces straight from the displacements
        const SectionHistory at = section_stations(model, q.rails[k].element_set, q.stations);
        sets.push_back({q.rails[k].name, at.element_ids, at.station_index, out.rails[k].station_points, nullptr, &out.response.displacement,
                        q.rails[k].element_set, q.stations});
      }
    }
    out.stress = stress_histories(model, out.response.times, sets, share);
  }
  // The static section forces at every stress station (total = static + dynamic), matched by
  // (output, element, station); without a static state static_forces stays empty (zero).
  if (out.static_state) {
    std::map<std::tuple<std::string, int, int>, fem::SectionForces> by_station;
    for (const StaticStations& st : out.static_state->outputs)
      for (std::size_t i = 0; i < st.forces.size(); ++i) by_station[{st.output, st.element_ids[i], st.station[i]}] = st.forces[i];
    out.static_forces.reserve(out.stress.stations.size());
    for (const StressStation& st : out.stress.stations) {
      const auto at = by_station.find({st.set, st.element_id, st.station});
      if (at == by_station.end())
        throw std::logic_error(fmt::format("no static section forces at {} element {} station {}", st.set, st.element_id, st.station));
      out.static_forces.push_back(at->second);
    }
  }
  out.hot_spots = find_hot_spots(out.stress, window, 10, &out.static_forces, share);
  out.solver_counts = fem::solver_counts() - counts_before;
  if (q.fatigue) out.life = frame_life_map(out.model, out.stress, out.static_forces, out.hot_spots.window, *q.fatigue, share);
  out.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

std::vector<core::Warning> frame_warnings(const FrameStudyResults& r, const FrameStudyRequest& q) {
  std::vector<core::Warning> out = r.model.reader_warnings;
  // A von Mises stress above the yield strength the study declares (the total: static + dynamic).
  if (q.yield_strength && r.hot_spots.peak.von_mises_total > *q.yield_strength && r.hot_spots.peak.station < r.stress.stations.size()) {
    const core::UnitSystem& u = q.units;
    const HotSpot& p = r.hot_spots.peak;
    const StressStation& st = r.stress.stations[p.station];
    const std::string S = u.label(core::Quantity::stress);
    out.push_back({"stress_above_yield",
                   fmt::format("{}: the peak von Mises stress {:.5g} {} (element {}, station {}, {}, X = {:.4g} {}, t = {:.4g} s) exceeds the yield "
                               "strength {:.5g} {} (frame.yield_strength): the elastic frame model no longer holds there",
                               st.set, u.from_si(p.von_mises_total, core::Quantity::stress), S, st.element_id, st.station, p.point_name,
                               u.from_si(st.point.x(), core::Quantity::length), u.label(core::Quantity::length), p.time,
                               u.from_si(*q.yield_strength, core::Quantity::stress), S),
                   {{"peak_von_mises", u.from_si(p.von_mises_total, core::Quantity::stress), S},
                    {"yield_strength", u.from_si(*q.yield_strength, core::Quantity::stress), S}}});
  }
  // Only the study's clamp is artificial: free-free has no support, and the mesh's own *BOUNDARY is what
  // its author says holds the structure (a portal frame's feet).
  const bool clamp = q.supports == FrameSupports::fixed_rear_end || q.supports == FrameSupports::clamped;
  if (!clamp) return out;
  std::vector<bool> supported(r.model.nodes.size(), false);
  for (const std::string& name : q.support_sets) {
    const auto set = r.model.node_sets.find(upper(name));
    if (set != r.model.node_sets.end())
      for (int node : set->second) supported[static_cast<std::size_t>(node)] = true;
  }
  const core::UnitSystem& u = q.units;
  using core::Quantity;
  const double lf = 1.0 / u.to_si_factor(Quantity::length);
  std::string held;
  for (std::size_t k = 0; k < q.support_sets.size(); ++k) held += (k ? ", " : "") + q.support_sets[k];
  const std::string support = fmt::format("the clamp of {} ({})", held, supports_name(q.supports));
  for (const RailRecovery& rail : r.rails)
    for (const auto& [what, peak, qty] : {std::tuple<const char*, const RailPeak*, Quantity>{"normal stress", &rail.peak_normal_stress, Quantity::stress},
                                          {"bending moment", &rail.peak_bending_moment, Quantity::moment}}) {
      const int e = r.model.beam_index(peak->element_id);
      if (e < 0) continue;
      // One warning per rail and element: the moment's peak where the stress's is says nothing new.
      if (peak == &rail.peak_bending_moment && rail.peak_bending_moment.element_id == rail.peak_normal_stress.element_id && !out.empty() &&
          out.back().message.rfind(rail.spec.name + ":", 0) == 0)
        continue;
      const fem::BeamElement& b = r.model.beams[static_cast<std::size_t>(e)];
      int at = -1;
      if (supported[static_cast<std::size_t>(b.node_a)]) at = b.node_a;
      else if (supported[static_cast<std::size_t>(b.node_b)]) at = b.node_b;
      if (at < 0) continue;
      out.push_back({"peak_at_artificial_support",
                     fmt::format("{}: the peak {} {:.5g} {} at X = {:.4g} {} (element {}, t = {:.4g} s) lies at or next to {}, node {}: a support the "
                                 "moving machine does not have, whose reaction sets this stress; compare with supports: none "
                                 "(free_free_inertia_relief) before using it (docs/user-guide.md, \"Which support to believe\")",
                                 rail.spec.name, what, u.from_si(peak->value, qty), u.label(qty), peak->point.x() * lf, u.label(Quantity::length),
                                 peak->element_id, peak->time, support, r.model.nodes[static_cast<std::size_t>(at)].id),
                     {}});
    }
  return out;
}

}  // namespace framedyn::coupling
