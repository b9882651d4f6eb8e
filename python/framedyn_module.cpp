// The Python module framedyn's extension _framedyn (issue 20; docs/user-guide.md,
// "Python"): bindings only. Each function calls the library functions the
// framedyn program calls for the same command (read_inp, with_frequency_step +
// compute_modes, static_load_cases + solve_static_cases + recover_stations,
// count_history) and hands their results to Python as numpy arrays in the
// input's units, as the program's CSV files give them. The solves run with the
// GIL released (the model is a C++ copy Python cannot touch meanwhile).
// core::InputError and core::NumericalError become framedyn.Error with the
// library's message word for word (and file, line, key for an InputError).
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <string>
#include <variant>

#include "core/build_info.h"
#include "core/error.h"
#include "core/stress_unit.h"
#include "fatigue/counted_history.h"
#include "fem/inp_reader.h"
#include "fem/modal_analysis.h"
#include "fem/section_forces.h"
#include "fem/static_analysis.h"
#include "python/framedyn_errors.h"

namespace py = pybind11;
using framedyn::core::Quantity;
namespace core = framedyn::core;
namespace fem = framedyn::fem;
namespace fatigue = framedyn::fatigue;

namespace {

// A mesh as read: the model (SI inside, as the library keeps it), its file and
// the dialect it was read in (unset: Abaqus's reading, with a warning where the two differ).
struct Mesh {
  fem::FrameModel model;
  std::string path;
  std::optional<std::string> dialect;
};

using framedyn::python::ArgumentError;  // a refused keyword argument (python/framedyn_errors.h)

// dialect= as the command line's --inp-dialect (PY-06 for another value).
std::optional<fem::InpDialect> parse_dialect(const std::optional<std::string>& dialect) {
  if (!dialect) return std::nullopt;
  if (*dialect == "abaqus") return fem::InpDialect::abaqus;
  if (*dialect == "calculix") return fem::InpDialect::calculix;
  throw ArgumentError("dialect", "expected 'abaqus' (SECTION=CIRC values are radii) or 'calculix' (diameters), found '" + *dialect + "'");
}

// The reader's warnings as summary.json lists them: {code, message, figures: {name: {value, unit}}}.
py::list warning_list(const std::vector<core::Warning>& warnings) {
  py::list l;
  for (const core::Warning& w : warnings) {
    py::dict d, figures;
    d["code"] = w.code, d["message"] = w.message;
    for (const core::WarningFigure& f : w.figures) {
      py::dict v;
      v["value"] = f.value, v["unit"] = f.unit;
      figures[py::str(f.name)] = v;
    }
    d["figures"] = figures;
    l.append(d);
  }
  return l;
}

// Each reader warning once, as a Python UserWarning, when a mesh is read
// (the command line prints them on stderr once): with the GIL held.
void warn_python(const fem::FrameModel& model) {
  for (const core::Warning& w : model.reader_warnings) {
    const std::string text = "[" + w.code + "] " + w.message;
    if (PyErr_WarnEx(PyExc_UserWarning, text.c_str(), 1) != 0) throw py::error_already_set();  // warnings turned into errors
  }
}

struct ModesResult {
  Eigen::VectorXd frequencies_hz;
  Eigen::MatrixXd shapes;             // DOFs x modes, mass-normalised, input units
  Eigen::MatrixXd effective_masses;   // modes x 6, input units
  Eigen::MatrixXd effective_mass_fractions;
  std::vector<bool> rigid_body;
  Eigen::VectorXd total_mass;         // 6, input units
  bool certified = false;
  py::dict units;
  py::list warnings;  // the mesh reader's, as summary.json's
};

struct StaticResult {
  int step = 0;
  Eigen::VectorXi node_ids;
  Eigen::MatrixXd displacements;      // nodes x 6
  Eigen::VectorXi reaction_nodes;
  Eigen::MatrixXd reactions;          // supported nodes x 6
  py::dict section_forces;            // column name -> array, one row per station
  int free_rigid_motions = 0;
  py::dict units;
  py::list warnings;  // the mesh reader's, as summary.json's
};

struct RainflowResult {
  Eigen::VectorXd range, mean, count;
  double cycles = 0.0, max_range = 0.0;
  std::size_t samples = 0, turning_points = 0;
  std::optional<double> damage, equivalent_range;
  std::string unit;
};

// Read without the GIL; the caller warns (warn_python) once it holds it again.
fem::FrameModel load_model(const std::string& path, const std::optional<std::string>& units, std::optional<fem::InpDialect> dialect) {
  fem::InpReadOptions o;
  o.units = units;
  o.dialect = dialect;
  o.dialect_key = "dialect=";  // the warning names the keyword, not the command line's option
  return fem::read_inp(path, o);
}

// A Mesh, or a path read with `units` and `dialect` (a path's reader warnings raised as UserWarning).
fem::FrameModel model_of(const std::variant<Mesh, std::string>& mesh_or_path, const std::optional<std::string>& units,
                         const std::optional<std::string>& dialect, std::string& source) {
  const std::optional<fem::InpDialect> d = parse_dialect(dialect);
  if (const Mesh* m = std::get_if<Mesh>(&mesh_or_path)) {
    if (units && core::UnitSystem::from_name(*units).name() != m->model.units.name())
      throw std::invalid_argument("units='" + *units + "' for a mesh already read in " + m->model.units.name() +
                                  " (read_mesh(path, units=...) sets a mesh's units)");
    if (dialect && dialect != m->dialect)
      throw ArgumentError("dialect", "expected no dialect or the one the mesh was read in (read_mesh(path, dialect=...) sets how a mesh is read), found '" +
                                         *dialect + "' for a mesh read " + (m->dialect ? "as " + *m->dialect : std::string("without a dialect")));
    source = m->path;
    return m->model;
  }
  source = std::get<std::string>(mesh_or_path);
  fem::FrameModel model;
  {
    py::gil_scoped_release release;
    model = load_model(source, units, d);
  }
  warn_python(model);
  return model;
}

Eigen::MatrixXd node_positions(const fem::FrameModel& model) {
  const double lf = 1.0 / model.units.to_si_factor(Quantity::length);
  Eigen::MatrixXd x(static_cast<Eigen::Index>(model.nodes.size()), 3);
  for (std::size_t n = 0; n < model.nodes.size(); ++n) x.row(static_cast<Eigen::Index>(n)) = model.nodes[n].position.transpose() * lf;
  return x;
}

Eigen::MatrixXi element_nodes(const fem::FrameModel& model) {
  Eigen::MatrixXi e(static_cast<Eigen::Index>(model.beams.size()), 3);
  for (std::size_t i = 0; i < model.beams.size(); ++i) {
    const fem::BeamElement& b = model.beams[i];
    e.row(static_cast<Eigen::Index>(i)) << model.nodes[static_cast<std::size_t>(b.node_a)].id, model.nodes[static_cast<std::size_t>(b.node_b)].id,
        b.is_quadratic() ? model.nodes[static_cast<std::size_t>(b.node_m)].id : -1;
  }
  return e;
}

py::dict node_sets(const fem::FrameModel& model) {
  py::dict d;
  for (const auto& [name, indices] : model.node_sets) {
    std::vector<int> ids;
    for (int i : indices) ids.push_back(model.nodes[static_cast<std::size_t>(i)].id);
    d[py::str(name)] = py::array_t<int>(static_cast<py::ssize_t>(ids.size()), ids.data());
  }
  return d;
}

py::dict element_sets(const fem::FrameModel& model) {
  py::dict d;
  for (const auto& [name, ids] : model.element_sets) d[py::str(name)] = py::array_t<int>(static_cast<py::ssize_t>(ids.size()), ids.data());
  return d;
}

Eigen::VectorXi node_ids(const fem::FrameModel& model) {
  Eigen::VectorXi ids(static_cast<Eigen::Index>(model.nodes.size()));
  for (std::size_t n = 0; n < model.nodes.size(); ++n) ids(static_cast<Eigen::Index>(n)) = model.nodes[n].id;
  return ids;
}

py::list six_units(const core::UnitSystem& u, Quantity translation, Quantity rotation) {
  py::list l;
  for (int d = 0; d < 6; ++d) l.append(u.label(d < 3 ? translation : rotation));
  return l;
}

ModesResult compute_modes(const std::variant<Mesh, std::string>& mesh_or_path, std::optional<int> n, const std::optional<std::string>& units,
                          bool lumped, double shift_hz, const std::optional<std::string>& dialect) {
  std::string source;
  const fem::FrameModel model = fem::with_frequency_step(model_of(mesh_or_path, units, dialect, source));
  fem::ModalOptions mo;  // as `framedyn modes`
  mo.mode_count = n ? *n : model.requested_modes.value_or(10);
  mo.mass = lumped ? fem::MassFormulation::lumped : fem::MassFormulation::consistent;
  mo.shift_hz = shift_hz;
  if (mo.mode_count < 1 || mo.mode_count > 100000) throw std::invalid_argument("n: expected a number of modes from 1 to 100000, found " + std::to_string(mo.mode_count));
  if (!(shift_hz > 0)) throw std::invalid_argument("shift_hz: expected a positive shift in Hz");
  fem::ModalResult r;
  {
    py::gil_scoped_release release;
    r = fem::compute_modes(model, mo);
  }
  const core::UnitSystem& u = model.units;
  const double mass_f = 1.0 / u.to_si_factor(Quantity::mass), rot_f = 1.0 / u.to_si_factor(Quantity::rotary_inertia);
  const double sqrt_m = std::sqrt(u.to_si_factor(Quantity::mass)), tr_f = sqrt_m / u.to_si_factor(Quantity::length);
  ModesResult out;
  const Eigen::Index modes = static_cast<Eigen::Index>(r.modes.size());
  out.frequencies_hz.resize(modes);
  out.effective_masses.resize(modes, 6);
  out.effective_mass_fractions.resize(modes, 6);
  for (Eigen::Index i = 0; i < modes; ++i) {
    const fem::Mode& m = r.modes[static_cast<std::size_t>(i)];
    out.frequencies_hz(i) = m.frequency_hz;
    out.rigid_body.push_back(m.rigid_body);
    for (int d = 0; d < 6; ++d) {
      out.effective_masses(i, d) = m.effective_mass(d) * (d < 3 ? mass_f : rot_f);
      out.effective_mass_fractions(i, d) = r.total_mass(d) > 0 ? m.effective_mass(d) / r.total_mass(d) : 0.0;
    }
  }
  out.shapes = r.shapes;
  for (Eigen::Index row = 0; row < out.shapes.rows(); ++row) out.shapes.row(row) *= (row % 6 < 3 ? tr_f : sqrt_m);
  out.total_mass.resize(6);
  for (int d = 0; d < 6; ++d) out.total_mass(d) = r.total_mass(d) * (d < 3 ? mass_f : rot_f);
  out.certified = r.certified;
  out.units["frequencies_hz"] = "Hz";
  out.units["shapes"] = six_units(u, Quantity::mass_normalised_translation, Quantity::mass_normalised_rotation);
  out.units["effective_masses"] = six_units(u, Quantity::mass, Quantity::rotary_inertia);
  out.units["total_mass"] = six_units(u, Quantity::mass, Quantity::rotary_inertia);
  out.units["system"] = u.name();
  out.warnings = warning_list(model.reader_warnings);
  return out;
}

py::object solve_static(const std::variant<Mesh, std::string>& mesh_or_path, const std::optional<std::string>& units, int stations,
                        bool inertia_relief, const std::optional<std::string>& dialect) {
  if (stations < 2 || stations > 101) throw std::invalid_argument("stations: expected 2 to 101 stations (the element's ends and points between), found " + std::to_string(stations));
  std::string source;
  const fem::FrameModel model = model_of(mesh_or_path, units, dialect, source);
  std::vector<fem::StaticLoadCase> cases = fem::static_load_cases(model, source);
  std::vector<fem::FrameModel> models;
  for (const fem::StaticLoadCase& c : cases) models.push_back(c.model);
  std::vector<fem::StaticResult> results;
  std::vector<std::vector<fem::StationResult>> recovered;
  {
    py::gil_scoped_release release;
    fem::StaticOptions so;
    so.inertia_relief = inertia_relief;
    results = fem::solve_static_cases(models, {}, so);
    for (std::size_t c = 0; c < models.size(); ++c) recovered.push_back(fem::recover_stations(models[c], results[c].displacement, stations));
  }
  const core::UnitSystem& u = model.units;
  const double lf = 1.0 / u.to_si_factor(Quantity::length), ff = 1.0 / u.to_si_factor(Quantity::force);
  const double mf = 1.0 / u.to_si_factor(Quantity::moment), sf = 1.0 / u.to_si_factor(Quantity::stress);
  py::list list;
  for (std::size_t c = 0; c < models.size(); ++c) {
    const fem::FrameModel& m = models[c];
    const fem::StaticResult& r = results[c];
    StaticResult out;
    out.step = cases[c].step;
    out.node_ids = node_ids(m);
    const Eigen::Index nn = static_cast<Eigen::Index>(m.nodes.size());
    out.displacements.resize(nn, 6);
    std::vector<char> supported(m.nodes.size(), 0);
    for (const fem::Constraint& k : m.constraints) supported[static_cast<std::size_t>(k.node)] = 1;
    std::vector<int> rnodes;
    for (Eigen::Index n = 0; n < nn; ++n) {
      for (int k = 0; k < 6; ++k) out.displacements(n, k) = r.displacement(6 * n + k) * (k < 3 ? lf : 1.0);
      if (supported[static_cast<std::size_t>(n)]) rnodes.push_back(static_cast<int>(n));
    }
    out.reaction_nodes.resize(static_cast<Eigen::Index>(rnodes.size()));
    out.reactions.resize(static_cast<Eigen::Index>(rnodes.size()), 6);
    for (std::size_t i = 0; i < rnodes.size(); ++i) {
      const Eigen::Index row = static_cast<Eigen::Index>(i);
      out.reaction_nodes(row) = m.nodes[static_cast<std::size_t>(rnodes[i])].id;
      for (int k = 0; k < 6; ++k) out.reactions(row, k) = r.reaction(6 * rnodes[i] + k) * (k < 3 ? ff : mf);
    }
    const std::vector<fem::StationResult>& st = recovered[c];
    const Eigen::Index ns = static_cast<Eigen::Index>(st.size());
    Eigen::VectorXi element(ns), station(ns);
    Eigen::MatrixXd v(ns, 11);  // x, N, Vy, Vz, T, My, Mz, X, Y, Z, and the fiber extremes below
    Eigen::VectorXd smax(ns), smin(ns);
    for (Eigen::Index i = 0; i < ns; ++i) {
      const fem::StationResult& s = st[static_cast<std::size_t>(i)];
      element(i) = s.element_id;
      station(i) = s.station;
      v.row(i) << s.x * lf, s.forces.n * ff, s.forces.vy * ff, s.forces.vz * ff, s.forces.t * mf, s.forces.my * mf, s.forces.mz * mf,
          s.point.x() * lf, s.point.y() * lf, s.point.z() * lf, 0.0;
      double hi = 0.0, lo = 0.0;  // 0 for a GENERAL section (no stress points), as section_forces.csv
      if (!s.fiber_stress.empty()) hi = *std::max_element(s.fiber_stress.begin(), s.fiber_stress.end()), lo = *std::min_element(s.fiber_stress.begin(), s.fiber_stress.end());
      smax(i) = hi * sf, smin(i) = lo * sf;
    }
    const char* names[10] = {"x", "N", "Vy", "Vz", "T", "My", "Mz", "X", "Y", "Z"};
    out.section_forces["element"] = element;
    out.section_forces["station"] = station;
    for (int k = 0; k < 10; ++k) out.section_forces[names[k]] = Eigen::VectorXd(v.col(k));
    out.section_forces["fiber_stress_max"] = smax;
    out.section_forces["fiber_stress_min"] = smin;
    out.free_rigid_motions = r.free_rigid_motions;
    const std::string L = u.label(Quantity::length), F = u.label(Quantity::force), M = u.label(Quantity::moment), S = u.label(Quantity::stress);
    out.units["displacements"] = py::make_tuple(L, L, L, "rad", "rad", "rad");
    out.units["reactions"] = py::make_tuple(F, F, F, M, M, M);
    py::dict sec;
    for (const char* k : {"x", "X", "Y", "Z"}) sec[k] = L;
    for (const char* k : {"N", "Vy", "Vz"}) sec[k] = F;
    for (const char* k : {"T", "My", "Mz"}) sec[k] = M;
    sec["fiber_stress_max"] = S, sec["fiber_stress_min"] = S;
    out.units["section_forces"] = sec;
    out.units["system"] = u.name();
    out.warnings = warning_list(model.reader_warnings);
    list.append(py::cast(std::move(out)));
  }
  if (list.size() == 1) return list[0];
  return std::move(list);
}

RainflowResult count(const py::array_t<double, py::array::c_style | py::array::forcecast>& history, const std::string& unit,
                     const std::optional<std::string>& sn, bool repeat) {
  if (history.ndim() != 1) throw std::invalid_argument("history: expected a one-dimensional array, found " + std::to_string(history.ndim()) + " dimensions");
  const double pa = core::pascals_per_stress_unit(unit);
  if (pa <= 0) throw std::invalid_argument("unit: expected Pa, kPa, MPa, GPa, N/mm^2, psi or ksi, found '" + unit + "'");
  std::optional<fatigue::SnCurve> curve;
  if (sn) {
    try {
      curve = fatigue::sn_curve_from_name(*sn);
    } catch (const std::invalid_argument&) {
      throw std::invalid_argument("sn: expected " + fatigue::sn_curve_names() + ", found '" + *sn + "'");
    }
  }
  std::vector<double> values(history.data(), history.data() + history.size());
  fatigue::CountedHistory c;
  {
    py::gil_scoped_release release;
    c = fatigue::count_history(values, repeat ? fatigue::Residue::repeated_block : fatigue::Residue::half_cycles, curve, pa);
  }
  RainflowResult out;
  const Eigen::Index n = static_cast<Eigen::Index>(c.cycles.size());
  out.range.resize(n), out.mean.resize(n), out.count.resize(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const fatigue::Cycle& k = c.cycles[static_cast<std::size_t>(i)];
    out.range(i) = k.range, out.mean(i) = k.mean, out.count(i) = k.count;
  }
  out.cycles = c.summary.cycles, out.max_range = c.summary.max_range;
  out.samples = c.summary.samples, out.turning_points = c.summary.turning_points;
  out.damage = c.damage, out.equivalent_range = c.equivalent_range;
  out.unit = unit;
  return out;
}

}  // namespace

void bind_studies(py::module_& m);  // framedyn_study.cpp

PYBIND11_MODULE(_framedyn, m) {
  // The extension and the libraries it links must have been compiled alike (core/build_info.h).
  if (std::strcmp(FRAMEDYN_BUILD_SIGNATURE, core::library_build_signature()) != 0)
    throw py::import_error(std::string("framedyn: the Python module was compiled as '") + FRAMEDYN_BUILD_SIGNATURE +
                           "' but the framedyn libraries it links as '" + core::library_build_signature() +
                           "'; rebuild both in one build tree (cmake --build build)");
  m.doc() = "framedyn's C++ libraries (see the package framedyn)";
  m.def("build_signature", [] { return std::string(core::library_build_signature()); },
        "Compiler, vector extensions and Eigen alignment the libraries were built with");

  static py::exception<core::InputError> error(m, "Error", PyExc_RuntimeError);
  error.doc() = "framedyn refused the input or the computation: str(e) is framedyn's message; file, line, key locate bad input";
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const core::InputError& e) {
      py::object exc = py::handle(error.ptr())(e.what());
      exc.attr("file") = e.where().file;
      exc.attr("line") = e.where().line;
      exc.attr("key") = e.where().key;
      PyErr_SetObject(error.ptr(), exc.ptr());
    } catch (const core::NumericalError& e) {
      py::object exc = py::handle(error.ptr())(e.what());
      exc.attr("file") = py::none(), exc.attr("line") = 0, exc.attr("key") = py::none();
      PyErr_SetObject(error.ptr(), exc.ptr());
    } catch (const ArgumentError& e) {
      py::object exc = py::handle(error.ptr())(e.what());
      exc.attr("file") = py::none(), exc.attr("line") = 0, exc.attr("key") = e.key;
      PyErr_SetObject(error.ptr(), exc.ptr());
    }
  });

  py::class_<Mesh>(m, "Mesh", "A frame mesh (.inp) as framedyn reads it; arrays in the mesh's units")
      .def_readonly("path", &Mesh::path)
      .def_property_readonly("units", [](const Mesh& s) {
        py::dict d;
        d["system"] = s.model.units.name(), d["nodes"] = s.model.units.label(Quantity::length);
        return d;
      })
      .def_property_readonly("node_ids", [](const Mesh& s) { return node_ids(s.model); })
      .def_property_readonly("nodes", [](const Mesh& s) { return node_positions(s.model); }, "nodes x 3 coordinates, rows in node_ids' order")
      .def_property_readonly("element_ids", [](const Mesh& s) {
        Eigen::VectorXi ids(static_cast<Eigen::Index>(s.model.beams.size()));
        for (std::size_t i = 0; i < s.model.beams.size(); ++i) ids(static_cast<Eigen::Index>(i)) = s.model.beams[i].id;
        return ids;
      })
      .def_property_readonly("elements", [](const Mesh& s) { return element_nodes(s.model); },
                             "beam elements x 3 node ids: end a, end b, midside (-1 for a two-node beam)")
      .def_property_readonly("node_sets", [](const Mesh& s) { return node_sets(s.model); })
      .def_property_readonly("element_sets", [](const Mesh& s) { return element_sets(s.model); })
      .def_property_readonly("dof_count", [](const Mesh& s) { return s.model.dof_count(); })
      .def_readonly("dialect", &Mesh::dialect, "the dialect= it was read in, or None (Abaqus's reading, with a warning where CalculiX reads otherwise)")
      .def_property_readonly("warnings", [](const Mesh& s) { return warning_list(s.model.reader_warnings); },
                             "what the reader noticed that may change the answer, as summary.json's warnings: {code, message, figures}")
      .def("__repr__", [](const Mesh& s) {
        return "<framedyn.Mesh " + s.path + ": " + std::to_string(s.model.nodes.size()) + " nodes, " + std::to_string(s.model.beams.size()) +
               " beam elements, units " + s.model.units.name() + ">";
      });

  py::class_<ModesResult>(m, "ModesResult", "Natural frequencies and mass-normalised mode shapes (as `framedyn modes`)")
      .def_readonly("frequencies_hz", &ModesResult::frequencies_hz)
      .def_readonly("shapes", &ModesResult::shapes, "DOFs x modes; DOF 6 i + d is node i's ux, uy, uz, rx, ry, rz")
      .def_readonly("effective_masses", &ModesResult::effective_masses, "modes x 6 (x, y, z, rx, ry, rz)")
      .def_readonly("effective_mass_fractions", &ModesResult::effective_mass_fractions)
      .def_readonly("rigid_body", &ModesResult::rigid_body)
      .def_readonly("total_mass", &ModesResult::total_mass)
      .def_readonly("certified", &ModesResult::certified)
      .def_readonly("units", &ModesResult::units)
      .def_readonly("warnings", &ModesResult::warnings, "the mesh reader's warnings, as summary.json's");

  py::class_<StaticResult>(m, "StaticResult", "Static displacements, reactions and section forces (as `framedyn static`)")
      .def_readonly("step", &StaticResult::step)
      .def_readonly("node_ids", &StaticResult::node_ids)
      .def_readonly("displacements", &StaticResult::displacements, "nodes x 6 (ux, uy, uz, rx, ry, rz), rows in node_ids' order")
      .def_readonly("reaction_nodes", &StaticResult::reaction_nodes)
      .def_readonly("reactions", &StaticResult::reactions, "supported nodes x 6 (fx, fy, fz, mx, my, mz), rows in reaction_nodes' order")
      .def_readonly("section_forces", &StaticResult::section_forces, "column -> array, one entry per station of every element")
      .def_readonly("free_rigid_motions", &StaticResult::free_rigid_motions)
      .def_readonly("units", &StaticResult::units)
      .def_readonly("warnings", &StaticResult::warnings, "the mesh reader's warnings, as summary.json's");

  py::class_<RainflowResult>(m, "RainflowResult", "Rainflow cycles (ASTM E1049-85) and Miner damage (as `framedyn rainflow`)")
      .def_readonly("range", &RainflowResult::range)
      .def_readonly("mean", &RainflowResult::mean)
      .def_readonly("count", &RainflowResult::count, "1 for a full cycle, 0.5 for a half cycle")
      .def_readonly("cycles", &RainflowResult::cycles)
      .def_readonly("max_range", &RainflowResult::max_range)
      .def_readonly("samples", &RainflowResult::samples)
      .def_readonly("turning_points", &RainflowResult::turning_points)
      .def_readonly("damage", &RainflowResult::damage, "Miner damage with an S-N curve, else None")
      .def_readonly("equivalent_range", &RainflowResult::equivalent_range, "range at 2e6 cycles of equal damage, in unit")
      .def_readonly("unit", &RainflowResult::unit);

  m.def(
      "read_mesh",
      [](const std::string& path, const std::optional<std::string>& units, const std::optional<std::string>& dialect) {
        const std::optional<fem::InpDialect> d = parse_dialect(dialect);
        Mesh mesh;
        mesh.path = path;
        mesh.dialect = dialect;
        {
          py::gil_scoped_release release;
          mesh.model = load_model(path, units, d);
        }
        warn_python(mesh.model);
        return mesh;
      },
      py::arg("path"), py::arg("units") = py::none(), py::arg("dialect") = py::none(),
      "Reads a frame mesh (.inp); units as --units (default: the mesh's '** units:' line), dialect as --inp-dialect ('abaqus' or 'calculix'; "
      "default Abaqus's reading, with a UserWarning where CalculiX reads the deck otherwise)");
  m.def("modes", &compute_modes, py::arg("mesh_or_path"), py::arg("n") = py::none(), py::arg("units") = py::none(), py::arg("lumped") = false,
        py::arg("shift_hz") = 1.0, py::arg("dialect") = py::none(),
        "Natural frequencies and mode shapes, as `framedyn modes` (n: default the *FREQUENCY count, else 10; dialect as read_mesh's)");
  m.def("static", &solve_static, py::arg("mesh_or_path"), py::arg("units") = py::none(), py::arg("stations") = 3, py::arg("inertia_relief") = false,
        py::arg("dialect") = py::none(),
        "Linear static response, as `framedyn static`: a StaticResult, or a list of them (one per step) for a deck with several static steps");
  m.def("rainflow", &count, py::arg("history"), py::arg("unit") = "MPa", py::arg("sn") = py::none(), py::arg("repeat") = false,
        "Rainflow counting of a stress history in `unit`; with an S-N curve (sn, as --sn: FAT90, EN71, ...) its Miner damage");
  bind_studies(m);
}
