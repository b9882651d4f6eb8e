// Parameter sweeps over rigid-body studies; see parameter_sweep.h.
#include "coupling/parameter_sweep.h"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <mutex>
#include <thread>

#include "core/error.h"

namespace framedyn::coupling {

SweepPoint sweep_point(const VehicleResults& r, double value) {
  SweepPoint p;
  p.value = value;
  p.plow_vertical_pp = r.plow_vertical_peak_to_peak;
  p.peak_cutting_force = r.peak_cutting_force;
  p.peak_backing_force = r.peak_backing_force;
  p.average_peak_cutting_force = r.average_peak_cutting_force;
  p.average_peak_backing_force = r.average_peak_backing_force;
  for (const rigid::RigidMode& m : r.modes) {
    p.frequencies_hz.push_back(m.frequency_hz);
    p.dominant.push_back(m.dominant);
  }
  return p;
}

std::vector<std::string> sweepable_parameters() {
  std::vector<std::string> names = calibratable_parameters();
  names.push_back("soil.damping");
  return names;
}

std::optional<double> relative_change(const std::optional<double>& value, const std::optional<double>& reference) {
  if (!value || !reference || *reference == 0.0) return std::nullopt;
  return (*value - *reference) / *reference;
}

SweepResult run_parameter_sweep(const RigidStudy& study, const std::string& parameter, const std::vector<double>& values, int threads,
                                const std::function<void(const std::string&)>& progress) {
  const core::InputLocation where_parameter{study.file, 0, "--parameter"}, where_values{study.file, 0, "--values"};
  SweepResult result;
  result.parameter = parameter;
  double study_value = 0.0;
  try {
    result.quantity = parameter_quantity(study.machine, parameter);
    study_value = get_parameter(study.machine, parameter);
  } catch (const std::invalid_argument&) {
    std::string known;
    for (const std::string& k : sweepable_parameters()) known += (known.empty() ? "" : ", ") + k;
    throw core::InputError(where_parameter, "one of " + known, "'" + parameter + "'");
  }
  if (study.calibration && std::find(study.calibration->parameters.begin(), study.calibration->parameters.end(), parameter) !=
                               study.calibration->parameters.end())
    throw core::InputError(where_parameter, "a parameter the study does not calibrate (calibration would overwrite each value)", "'" + parameter + "'");
  if (!study.response)
    throw core::InputError({study.file, 0, "analysis.response"}, "a forced response to sweep (the sweep collects its amplitude and forces)", "none");
  if (values.empty()) throw core::InputError(where_values, "at least one value", "none");
  // A mass must be positive, as in the study file (a body of no mass leaves
  // its coordinates without inertia); the others may be 0.
  const bool inertial = result.quantity == core::Quantity::mass;
  for (double v : values)
    if (!std::isfinite(v) || v < 0 || (inertial && v == 0))
      throw core::InputError(where_values, inertial ? "finite positive values (a mass)" : "finite non-negative values",
                             fmt::format("{:g} {}", study.units.from_si(v, result.quantity), study.units.label(result.quantity)));

  // The runs: the requested values, then the study's own value if it is not among them.
  std::vector<double> run_values = values;
  const auto it = std::find(values.begin(), values.end(), study_value);
  result.reference_index = it == values.end() ? -1 : static_cast<int>(it - values.begin());
  if (result.reference_index < 0) run_values.push_back(study_value);

  const std::size_t n = run_values.size();
  std::vector<SweepPoint> points(n);
  std::vector<std::exception_ptr> errors(n);
  std::atomic<std::size_t> next{0};
  std::mutex progress_mutex;
  const auto worker = [&]() {
    for (std::size_t i = next++; i < n; i = next++) {
      try {
        if (progress) {
          const std::lock_guard<std::mutex> lock(progress_mutex);
          progress(fmt::format("run {} of {}: {} = {}", i + 1, n, parameter, study.units.from_si(run_values[i], result.quantity)));
        }
        RigidStudy s = study;
        set_parameter(s.machine, parameter, run_values[i]);
        points[i] = sweep_point(run_rigid_study(s), run_values[i]);
      } catch (...) {
        errors[i] = std::current_exception();
      }
    }
  };
  const std::size_t workers = std::min<std::size_t>(n, static_cast<std::size_t>(std::max(1, threads)));
  if (workers <= 1) {
    worker();
  } else {
    std::vector<std::thread> pool;
    for (std::size_t t = 0; t < workers; ++t) pool.emplace_back(worker);
    for (std::thread& t : pool) t.join();
  }
  for (const std::exception_ptr& e : errors)
    if (e) std::rethrow_exception(e);  // the first failed run, in the order of the values

  result.reference = result.reference_index >= 0 ? points[static_cast<std::size_t>(result.reference_index)] : points.back();
  points.resize(values.size());
  result.points = std::move(points);
  return result;
}

}  // namespace framedyn::coupling
