// summary.json's rigid.calibration and calibration.csv; see calibration_output.h.
#include "report/json_quantity.h"
#include "report/calibration_output.h"

#include <fmt/format.h>

#include <cmath>

#include "report/csv_writer.h"

namespace framedyn::report {

namespace {

// JSON has no infinity, and the results folder refuses null: an unbounded side
// is written "none", the uncertainty of a parameter the targets do not
// determine "undetermined".
nlohmann::ordered_json finite_or(double v, const char* otherwise) { return std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json(otherwise); }

}  // namespace

std::string fit_status(const rigid::CalibrationResult& c) {
  if (c.iteration_limit_reached) return "not_converged";
  return c.max_relative_error <= kTargetsMetTolerance ? "targets_met" : "best_within_bounds";
}

nlohmann::ordered_json write_calibration(const coupling::CalibrationRequest& request, const rigid::CalibrationResult& c,
                                         const core::UnitSystem& u, const std::function<core::Quantity(const std::string&)>& quantity,
                                         const core::ResultsFolder& folder) {
  nlohmann::ordered_json cal;
  nlohmann::ordered_json params = nlohmann::ordered_json::array();
  report::CsvTable pcsv({"parameter", "unit", "initial", "fitted", "fitted/initial [1]", "lower", "upper", "at_bound", "uncertainty"});
  for (std::size_t i = 0; i < c.fitted.size(); ++i) {
    const std::string& name = request.parameters[i];
    const core::Quantity q = quantity(name);
    params.push_back({{"name", name},
                      {"unit", u.label(q)},
                      {"initial", u.from_si(c.initial[i], q)},
                      {"fitted", u.from_si(c.fitted[i], q)},
                      {"ratio", c.fitted[i] / c.initial[i]},
                      {"lower", u.from_si(c.lower[i], q)},
                      {"upper", finite_or(u.from_si(c.upper[i], q), "none")},
                      {"at_bound", static_cast<bool>(c.at_bound[i])},
                      {"uncertainty", finite_or(u.from_si(c.uncertainty[i], q), "undetermined")},
                      {"bounds_basis", request.bounds[i].basis}});
    pcsv.row()
        .add(name)
        .add(u.label(q))
        .add(u.from_si(c.initial[i], q))
        .add(u.from_si(c.fitted[i], q))
        .add(c.fitted[i] / c.initial[i])
        .add(u.from_si(c.lower[i], q))
        .add(std::isfinite(c.upper[i]) ? core::format_number(u.from_si(c.upper[i], q)) : std::string("none"))
        .add(c.at_bound[i] ? "yes" : "no")
        .add(std::isfinite(c.uncertainty[i]) ? core::format_number(u.from_si(c.uncertainty[i], q)) : std::string("undetermined"));
  }
  nlohmann::ordered_json targets = nlohmann::ordered_json::array(), labels = nlohmann::ordered_json::array();
  for (std::size_t t = 0; t < request.targets.size(); ++t) {
    const rigid::FrequencyTarget& tg = request.targets[t];
    const std::string hz = core::UnitSystem::si().label(core::Quantity::frequency);
    targets.push_back({{"frequency", report::quantity(tg.frequency_hz, hz)},
                       {"dominant", tg.dominant},
                       {"achieved", report::quantity(c.achieved_hz[t], hz)},
                       {"achieved_dominant", c.achieved_dominant[t]},
                       {"relative_error", (c.achieved_hz[t] - tg.frequency_hz) / tg.frequency_hz},
                       {"label_matches", static_cast<bool>(c.label_matches[t])}});
    if (t < request.shapes.size() && request.shapes[t]) {
      targets.back()["shape_components"] = request.shapes[t]->components.size();
      targets.back()["shape_weight"] = request.shapes[t]->weight;
      targets.back()["mac"] = c.mac[t];  // modal assurance of the measured and the fitted shape (9.6)
    }
    labels.push_back(static_cast<bool>(c.label_matches[t]));
  }
  nlohmann::ordered_json unresolved = nlohmann::ordered_json::array();
  for (const Eigen::VectorXd& v : c.unresolved) {
    nlohmann::ordered_json combo;
    for (std::size_t i = 0; i < request.parameters.size(); ++i)
      if (std::abs(v(static_cast<Eigen::Index>(i))) > 1e-3) combo[request.parameters[i]] = v(static_cast<Eigen::Index>(i));
    unresolved.push_back(combo);
  }
  std::vector<double> sv(c.singular_values.data(), c.singular_values.data() + c.singular_values.size());
  cal["parameters"] = params;
  cal["targets"] = targets;
  cal["target_count"] = request.targets.size();
  cal["parameter_count"] = c.fitted.size();
  cal["information"] = c.information;  // frequencies plus (m - 1) per measured shape of m components
  cal["degrees_of_freedom"] = c.degrees_of_freedom;  // information - parameters (Eq. 14.1)
  // With nothing to spare the fit meets its targets whenever it converges
  // inside its bounds: the agreement is a calibration, not evidence.
  cal["agreement"] = c.agreement_guaranteed ? "guaranteed_by_construction" : "tested_by_surplus_targets";
  cal["independent_targets"] = c.independent_targets;
  cal["singular_values"] = sv;
  cal["unresolved"] = unresolved;  // ln-parameter combinations the targets cannot tell apart
  cal["underdetermined"] = c.underdetermined;
  cal["regularization_weight"] = c.regularization;
  cal["residual_max"] = c.max_relative_error;
  cal["labels_match"] = labels;
  cal["labels_all_match"] = c.labels_match;
  cal["iterations"] = c.iterations;
  cal["iteration_limit_reached"] = c.iteration_limit_reached;
  cal["fit_status"] = fit_status(c);
  folder.write_text("calibration.csv", pcsv.str());
  return cal;
}

void print_calibration(const coupling::CalibrationRequest& request, const rigid::CalibrationResult& c) {
  const std::string status = fit_status(c);
  fmt::print("\ncalibration ({} iterations, {}): {} targets, {} independent, {} parameters, {} degrees of freedom ({}){}; largest frequency error {:.3g} %; "
             "dominant coordinates (predicted) {}\n",
             c.iterations,
             status == "not_converged" ? "NOT CONVERGED" : status == "targets_met" ? "converged, targets met" : "converged to the best within its bounds, targets missed",
             request.targets.size(), c.independent_targets, c.fitted.size(), c.degrees_of_freedom,
             c.agreement_guaranteed ? (status == "targets_met" ? "agreement guaranteed by construction"
                                                               : "no surplus targets: met targets would have been guaranteed by construction")
                                    : "agreement tested by the surplus targets",
             c.underdetermined ? fmt::format(", UNDERDETERMINED (regularization weight {:g})", c.regularization) : "", 100 * c.max_relative_error,
             c.labels_match ? "as the targets say" : "NOT all as the targets say");
  for (std::size_t t = 0; t < request.targets.size(); ++t)
    if (c.mac[t] >= 0) fmt::print("  target {} ({:g} Hz): measured shape MAC {:.4f}\n", t + 1, request.targets[t].frequency_hz, c.mac[t]);
  if (c.iteration_limit_reached)
    fmt::print("  the fit stopped at its iteration limit with the residual still falling: the values are not a converged fit\n");
  for (std::size_t i = 0; i < c.fitted.size(); ++i)
    fmt::print("  {:32s} x {:.4f}  (bounds x {:.4g} .. x {:.4g}){}\n", request.parameters[i], c.fitted[i] / c.initial[i], c.lower[i] / c.initial[i],
               c.upper[i] / c.initial[i], c.at_bound[i] ? "  AT BOUND" : "");
}

}  // namespace framedyn::report
