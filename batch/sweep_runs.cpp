// `framedyn sweep` as a design study over one parameter; see sweep_runs.h.
#include "batch/sweep_runs.h"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <exception>
#include <fstream>
#include <mutex>
#include <sstream>

#include "batch/engine.h"
#include "core/error.h"
#include "coupling/parameter_sweep.h"
#include "coupling/rigid_study.h"
#include "coupling/study_key_path.h"
#include "coupling/yaml_input.h"
#include "report/study_run.h"
#include "report/study_run_details.h"

namespace framedyn::batch {

namespace {

std::string read_text(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The study's calibration parameters (a calibrated key would be overwritten by the fit).
bool calibrates(const YAML::Node& doc, const std::string& key) {
  const YAML::Node cal = doc["calibration"];
  if (!cal || !cal.IsMap() || !cal["parameters"] || !cal["parameters"].IsSequence()) return false;
  for (const YAML::Node& p : cal["parameters"])
    if (p.IsScalar() && p.Scalar() == key) return true;
  return false;
}

}  // namespace

OneParameterSweepResult run_one_parameter_sweep(const OneParameterSweep& q) {
  const core::InputLocation where_parameter{q.study_file, 0, "--parameter"}, where_values{q.study_file, 0, "--values"};
  const YAML::Node doc = coupling::load_yaml_file(q.study_file);  // bad YAML or a duplicated key: the reader's own error
  const std::string text = read_text(q.study_file);
  const YAML::Node model = doc["model"];
  const std::string model_name = model && model.IsScalar() ? model.Scalar() : std::string();
  if (model_name != "rigid_2d" && model_name != "rigid_3d")
    throw core::InputError({q.study_file, model ? model.Mark().line + 1 : 0, "model"},
                           "a vehicle study (rigid_2d or rigid_3d: framedyn sweep collects the blade's motion and forces of its forced response)",
                           model ? "'" + model_name + "'" : std::string("none"));
  // A key the study does not have, or one that holds no number: the key-path walker's own error
  // (coupling/study_key_path.h), naming the study's line, as Study.set and design files give it.
  const double study_value = coupling::study_number(doc, q.key, q.study_file);
  if (calibrates(doc, q.key))
    throw core::InputError(where_parameter, "a parameter the study does not calibrate (calibration would overwrite each value)", "'" + q.key + "'");
  if (!doc["analysis"] || !doc["analysis"]["response"])
    throw core::InputError({q.study_file, 0, "analysis.response"}, "a forced response to sweep (the sweep collects its amplitude and forces)", "none");
  if (q.values.empty()) throw core::InputError(where_values, "at least one value", "none");

  // The runs: the requested values, then the study's own value if it is not among them.
  std::vector<double> run_values = q.values;
  const auto it = std::find(q.values.begin(), q.values.end(), study_value);
  const int reference_index = it == q.values.end() ? -1 : static_cast<int>(it - q.values.begin());
  if (reference_index < 0) run_values.push_back(study_value);

  const std::size_t n = run_values.size();
  std::vector<report::StudyRun> runs(n);
  std::vector<std::exception_ptr> errors(n);
  // On the batch engine's workers, each with its frame model reused across its runs (batch/engine.h);
  // a failed run is kept in its slot, so the error reported is the first in the order of the values.
  std::mutex progress_mutex;
  run_on_threads(n, q.threads, true, [&](std::size_t i, coupling::FrameModelCache* frame_cache) {
    try {
      if (q.progress) {
        const std::lock_guard<std::mutex> lock(progress_mutex);
        q.progress(fmt::format("run {} of {}: {} = {}", i + 1, n, q.key, run_values[i]));
      }
      YAML::Node copy = YAML::Load(text);  // with its marks: a refused value's error names the study's line
      coupling::set_study_number(copy, q.key, run_values[i], q.study_file);
      report::StudyRunOptions options;
      options.frame_cache = frame_cache;
      options.summary_outputs = std::vector<std::string>{"rigid"};  // a sweep's point reads the vehicle's results only: no frame run
      runs[i] = report::run_study_document(copy, q.study_file, options);
    } catch (...) {
      errors[i] = std::current_exception();
    }
  });
  for (const std::exception_ptr& e : errors)
    if (e) std::rethrow_exception(e);  // the first failed run, in the order of the values

  // The parameter's quantity, where the model's parameter tables know the key
  // (the calibratable names that are key paths, soil.damping; a 3-D key
  // missing from the 3-D table is looked up in the 2-D one); otherwise its
  // values stay in the study's units, labelled with the unit system's name, as runs.csv does.
  OneParameterSweepResult out;
  const report::StudyRunDetails& first = *runs.front().details;
  out.units = first.study->units;
  out.study_name = first.study->name;
  core::Quantity quantity = core::Quantity::dimensionless;
  bool known = true;
  try {
    quantity = coupling::parameter_quantity(first.study->machine, q.key);
  } catch (const std::invalid_argument&) {
    try {  // keys both models share (soil.damping): the 2-D table
      quantity = coupling::parameter_quantity(coupling::MachineParameters{rigid::Machine2DParameters{}}, q.key);
    } catch (const std::invalid_argument&) {
      known = false;
    }
  }
  out.parameter_unit = known ? out.units.label(quantity) : out.units.name();
  coupling::SweepResult& s = out.result;
  s.parameter = q.key;
  s.quantity = quantity;
  std::vector<coupling::SweepPoint> points;
  for (std::size_t i = 0; i < n; ++i) {
    const report::StudyRunDetails& d = *runs[i].details;
    const double value = known ? out.units.to_si(run_values[i], quantity) : run_values[i];
    points.push_back(coupling::sweep_point(*d.results, value));
  }
  s.reference_index = reference_index;
  s.reference = reference_index >= 0 ? points[static_cast<std::size_t>(reference_index)] : points.back();
  points.resize(q.values.size());
  s.points = std::move(points);
  return out;
}

}  // namespace framedyn::batch
