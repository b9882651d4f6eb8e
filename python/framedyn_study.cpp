// The Python module's studies (issue 20; docs/user-guide.md, "Python"):
// bindings only. load_study parses a study file (coupling::load_yaml_file),
// Study.set edits one number by key path (coupling::set_study_number),
// Study.run runs the document in memory (report::run_study_document, the call
// behind `framedyn run`) and hands over summary.json's content as a dict and
// the series of report::study_series as numpy arrays; batch runs a list of
// parameter sets and tabulates report::summary_numbers, or with outputs= the
// design file's `outputs` (batch::summary_value, runs.csv's columns). Runs release the GIL:
// each works on its own copy of the document.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <string>

#include "core/error.h"
#include "batch/engine.h"
#include "coupling/frame_model_cache.h"
#include "coupling/study_key_path.h"
#include "coupling/yaml_input.h"
#include "report/csv_writer.h"
#include "report/study_run.h"
#include "report/study_series.h"
#include "python/framedyn_errors.h"

namespace py = pybind11;
namespace report = framedyn::report;
namespace coupling = framedyn::coupling;

namespace {

struct Study {
  YAML::Node doc;
  std::string file;
};

py::array_t<double> array(const std::vector<double>& v) { return py::array_t<double>(static_cast<py::ssize_t>(v.size()), v.data()); }

py::object summary_dict(const nlohmann::ordered_json& summary) {
  return py::module_::import("json").attr("loads")(summary.dump());
}

py::dict named(const std::vector<report::NamedSeries>& series, py::dict& units) {
  py::dict d;
  for (const report::NamedSeries& s : series) d[py::str(s.name)] = array(s.values), units[py::str(s.name)] = s.unit;
  return d;
}

struct Results {
  py::object summary;
  py::array_t<double> time, frame_time;
  py::dict coordinates, recovered, frame_loads, rail_stress, rail_series, rail_envelopes, units;
  py::list hot_spots;
};

Results results_of(const report::StudyRun& run) {
  const report::StudySeries s = report::study_series(run);
  Results r;
  r.summary = summary_dict(run.summary);
  r.units["system"] = s.units;
  r.units["time"] = "s", r.units["frame_time"] = "s";
  r.time = array(s.time), r.frame_time = array(s.frame_time);
  r.coordinates = named(s.coordinates, r.units);
  r.recovered = named(s.recovered, r.units);
  r.frame_loads = named(s.frame_loads, r.units);
  r.rail_stress = named(s.rail_stress, r.units);
  r.rail_series = named(s.rail_series, r.units);
  for (const report::RailEnvelope& e : s.rail_envelopes) {
    py::dict d;
    d["x"] = array(e.x), d["y"] = array(e.y), d["z"] = array(e.z);
    d["bending_moment"] = array(e.bending_moment), d["normal_stress"] = array(e.normal_stress);
    r.rail_envelopes[py::str(e.rail)] = d;
    py::dict u;
    u["x"] = e.length_unit, u["y"] = e.length_unit, u["z"] = e.length_unit, u["bending_moment"] = e.moment_unit, u["normal_stress"] = e.stress_unit;
    r.units["rail_envelopes"] = u;
  }
  for (const report::HotSpotHistory& h : s.hot_spots) {
    py::dict d;
    d["name"] = h.name, d["x"] = h.x, d["von_mises"] = array(h.von_mises), d["normal_stress"] = array(h.normal_stress);
    r.hot_spots.append(d);
    py::dict u;
    u["x"] = h.length_unit, u["von_mises"] = h.stress_unit, u["normal_stress"] = h.stress_unit;
    r.units["hot_spots"] = u;
  }
  return r;
}

// The document with the sample's values set, then run: the work of one row, without the GIL.
// With `outputs`, the run computes only what those summary paths read (as `framedyn batch`'s).
report::StudyRun run_sample(const Study& s, const std::vector<std::pair<std::string, double>>& sample, coupling::FrameModelCache* models,
                            const std::optional<std::vector<std::string>>& outputs) {
  YAML::Node doc = YAML::Clone(s.doc);
  for (const auto& [key, value] : sample) coupling::set_study_number(doc, key, value, s.file);
  report::StudyRunOptions o;
  o.frame_cache = models;
  o.summary_outputs = outputs;
  return report::run_study_document(doc, s.file, o);
}

// outputs= as a design file's `outputs:` (BATCH-08 there): a non-empty list of key paths
// into a run's summary (PY-08), each once (PY-09).
void check_outputs(const std::vector<std::string>& outputs) {
  using framedyn::python::ArgumentError;
  if (outputs.empty())
    throw ArgumentError("outputs", "expected a list of key paths into a run's summary (e.g. rigid.response.peak_cutting_force), found an empty list");
  std::set<std::string> seen;
  for (const std::string& o : outputs) {
    if (!coupling::parse_key_path(o)) throw ArgumentError("outputs", std::string("expected ") + coupling::kKeyPathForm + " into a run's summary, found '" + o + "'");
    if (!seen.insert(o).second) throw ArgumentError("outputs", "expected each output once, found '" + o + "' again");
  }
}

py::object batch(const Study& study, const std::vector<std::map<std::string, double>>& samples, int threads,
                 const std::optional<std::vector<std::string>>& outputs) {
  if (threads < 1) throw py::value_error("threads: expected at least 1, found " + std::to_string(threads));
  if (outputs) check_outputs(*outputs);
  // Keys in the order of the first sample that names them (std::map: sorted within a sample).
  std::vector<std::string> keys;
  for (const auto& sample : samples)
    for (const auto& [k, v] : sample)
      if (std::find(keys.begin(), keys.end(), k) == keys.end()) keys.push_back(k);
  std::vector<std::vector<report::SummaryNumber>> numbers(samples.size());
  std::vector<std::string> errors(samples.size());
  const Study copy{YAML::Clone(study.doc), study.file};
  {
    // On the batch engine's threads (batch/engine.h), each with its own frame models, without the GIL;
    // each run fills its own row, so the table is the serial one whatever the thread count.
    py::gil_scoped_release release;
    framedyn::batch::run_on_threads(samples.size(), threads, true, [&](std::size_t i, coupling::FrameModelCache* models) {
      try {
        const report::StudyRun run = run_sample(copy, {samples[i].begin(), samples[i].end()}, models, outputs);
        if (!outputs) {
          numbers[i] = report::summary_numbers(run.summary);
          return;
        }
        for (const std::string& path : *outputs) {  // runs.csv's cells: absent from this run's summary, none (NaN)
          report::SummaryNumber n;
          std::string why;
          n.path = path;
          if (framedyn::batch::summary_value(run.summary, path, n.value, n.unit, why)) numbers[i].push_back(n);
        }
      } catch (const std::exception& e) {  // a failed run is a row with its message; the batch goes on
        errors[i] = e.what();
      }
    });
  }
  // Columns: the parameters, then every summary number any run has ("path [unit]"), NaN where a run has none;
  // with outputs, those in their order, named as runs.csv names them (report::column: the unit of the
  // lowest-index run that gives the number, none for a bare number).
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<std::string> columns;
  std::map<std::string, std::vector<double>> table;
  for (const std::string& k : keys) {
    columns.push_back(k);
    std::vector<double>& col = table[k];
    for (const auto& sample : samples) col.push_back(sample.count(k) ? sample.at(k) : nan);
  }
  if (outputs) {
    for (const std::string& path : *outputs) {
      std::vector<double> col(samples.size(), nan);
      std::string unit;
      for (std::size_t i = 0; i < samples.size(); ++i)
        for (const report::SummaryNumber& n : numbers[i])
          if (n.path == path) {
            col[i] = n.value;
            if (unit.empty()) unit = n.unit;
          }
      const std::string name = report::column(path, unit);
      columns.push_back(name);
      table[name] = std::move(col);
    }
  }
  for (std::size_t i = 0; i < samples.size() && !outputs; ++i)
    for (const report::SummaryNumber& n : numbers[i]) {
      const std::string name = n.unit.empty() ? n.path : n.path + " [" + n.unit + "]";
      auto [it, added] = table.try_emplace(name, std::vector<double>(samples.size(), nan));
      if (added) columns.push_back(name);
      it->second[i] = n.value;
    }
  py::dict d;
  for (const std::string& c : columns) d[py::str(c)] = array(table[c]);
  d["error"] = py::cast(errors);
  try {
    py::module_ pandas = py::module_::import("pandas");
    return pandas.attr("DataFrame")(d);
  } catch (const py::error_already_set&) {  // no pandas: the dict of arrays
    return std::move(d);
  }
}

}  // namespace

void bind_studies(py::module_& m) {
  py::class_<Study>(m, "Study", "A study document (framedyn run's YAML) in memory")
      .def_readonly("path", &Study::file)
      .def("set", [](Study& s, const std::string& key, double value) { coupling::set_study_number(s.doc, key, value, s.file); }, py::arg("key_path"),
           py::arg("value"), "Sets one number by key path (soil.damping, frame.parts[engine].weight, ...), in the study's units")
      .def("yaml", [](const Study& s) { return YAML::Dump(s.doc); }, "The document as YAML text")
      .def(
          "run",
          [](const Study& s) {
            const YAML::Node doc = YAML::Clone(s.doc);
            report::StudyRun run;
            {
              py::gil_scoped_release release;
              run = report::run_study_document(doc, s.file);
            }
            return results_of(run);
          },
          "Runs the study in memory (no file is written): a Results");

  py::class_<Results>(m, "Results", "A study run: summary (summary.json's content) and its series as numpy arrays")
      .def_readonly("summary", &Results::summary)
      .def_readonly("time", &Results::time)
      .def_readonly("coordinates", &Results::coordinates)
      .def_readonly("recovered", &Results::recovered)
      .def_readonly("frame_loads", &Results::frame_loads)
      .def_readonly("rail_stress", &Results::rail_stress)
      .def_readonly("frame_time", &Results::frame_time)
      .def_readonly("rail_series", &Results::rail_series)
      .def_readonly("rail_envelopes", &Results::rail_envelopes)
      .def_readonly("hot_spots", &Results::hot_spots)
      .def_readonly("units", &Results::units);

  m.def(
      "load_study",
      [](const std::string& path) {
        Study s;
        s.file = path;
        py::gil_scoped_release release;
        s.doc = coupling::load_yaml_file(path);
        return s;
      },
      py::arg("path"), "Reads a study file (framedyn run's YAML)");
  m.def("batch", &batch, py::arg("study"), py::arg("samples"), py::arg("threads") = 1, py::arg("outputs") = py::none(),
        "Runs the study once per sample ({key path: value}) on `threads` threads of the batch engine (the same table whatever the count); a pandas DataFrame (a dict of arrays without pandas): the parameters, "
        "every number of each run's summary ('path [unit]') or, with outputs=[key path, ...], those numbers only (a design file's `outputs:`, "
        "named as runs.csv names them), and 'error' (empty, or why the run failed)");
}
