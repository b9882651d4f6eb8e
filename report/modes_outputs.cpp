// The outputs of `framedyn modes`; see modes_outputs.h.
#include "report/modes_outputs.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

#include "report/csv_writer.h"
#include "report/json_quantity.h"
#include "report/summary_warnings.h"
#include "report/vtu_writer.h"
#include "report/xdmf_writer.h"

namespace framedyn::report {

namespace {
const char* kDirections[6] = {"x", "y", "z", "rx", "ry", "rz"};
}  // namespace

void write_modes_results(const fem::FrameModel& model, const fem::ModalResult& r, const ModesRun& run, const core::ResultsFolder& folder) {
  using core::Quantity;
  const core::UnitSystem& u = model.units;
  const double mass_f = 1.0 / u.to_si_factor(Quantity::mass);
  const double rot_f = 1.0 / u.to_si_factor(Quantity::rotary_inertia);
  auto eff_in_units = [&](const fem::Vector6d& v, int d) { return v(d) * (d < 3 ? mass_f : rot_f); };
  // A six-direction mass-like vector as {translation: {value [x, y, z], unit}, rotation: {value [rx, ry, rz], unit}}:
  // the two halves carry different units (Eqs. 7.4, 7.5).
  auto by_direction = [&](const fem::Vector6d& v, double translation_factor, double rotation_factor, Quantity tq, Quantity rq) {
    return nlohmann::ordered_json{
        {"translation", quantity(std::vector<double>{v(0) * translation_factor, v(1) * translation_factor, v(2) * translation_factor}, u.label(tq))},
        {"rotation", quantity(std::vector<double>{v(3) * rotation_factor, v(4) * rotation_factor, v(5) * rotation_factor}, u.label(rq))}};
  };
  const std::string hz = u.label(Quantity::frequency);
  // Effective masses as fractions of the model's total mass (Eq. 7.5).
  auto fraction = [&](const fem::Vector6d& v, int d) { return r.total_mass(d) > 0 ? v(d) / r.total_mass(d) : 0.0; };

  // summary.json
  nlohmann::ordered_json j;
  j["framedyn"] = {{"version", FRAMEDYN_VERSION}, {"command", "modes"}};
  j["input"] = {{"mesh", run.mesh_path}, {"units", u.name()}};
  nlohmann::ordered_json frame;
  frame["nodes"] = model.nodes.size();
  frame["beam_elements"] = model.beams.size();
  frame["dofs"] = model.dof_count();
  frame["free_dofs"] = r.free_dofs;
  frame["mass_formulation"] = run.lumped ? "lumped" : "consistent";
  // Masses (docs/theory/fem.md Eqs. 7.4, 7.5): the whole model's, supported
  // DOFs included; the part the free DOFs carry, per direction.
  frame["total_mass"] = {{"value", r.total_mass(0) * mass_f}, {"unit", u.label(Quantity::mass)}};
  frame["total_rotary_inertia"] = quantity(std::vector<double>{r.total_mass(3) * rot_f, r.total_mass(4) * rot_f, r.total_mass(5) * rot_f},
                                           u.label(Quantity::rotary_inertia));
  frame["total_rotary_inertia"]["about"] = "reference_point";
  frame["free_dof_mass"] = by_direction(r.free_mass, mass_f, rot_f, Quantity::mass, Quantity::rotary_inertia);
  frame["reference_point"] = quantity(std::vector<double>{0.0, 0.0, 0.0}, u.label(Quantity::length));
  frame["rigid_body_modes_expected"] = r.rigid_body_modes_expected;
  frame["parts"] = r.parts;
  frame["sturm_check"] = {{"certified", r.certified}, {"eigenvalues_below", r.sturm_count}, {"below", quantity(r.sturm_shift_hz, hz)},
                          {"lanczos_runs", r.lanczos_runs}};
  nlohmann::ordered_json modes = nlohmann::ordered_json::array();
  fem::Vector6d sum = fem::Vector6d::Zero();
  for (std::size_t i = 0; i < r.modes.size(); ++i) {
    const fem::Mode& m = r.modes[i];
    nlohmann::ordered_json jm;
    jm["mode"] = i + 1;
    jm["frequency"] = quantity(m.frequency_hz, hz);
    jm["rigid_body"] = m.rigid_body;
    nlohmann::ordered_json frac;
    for (int d = 0; d < 6; ++d) frac[kDirections[d]] = fraction(m.effective_mass, d);
    sum += m.effective_mass;
    jm["participation_factor"] = by_direction(m.participation, std::sqrt(mass_f), std::sqrt(rot_f), Quantity::participation_translation,
                                              Quantity::participation_rotation);
    jm["effective_mass"] = by_direction(m.effective_mass, mass_f, rot_f, Quantity::mass, Quantity::rotary_inertia);
    jm["effective_mass_fraction"] = frac;
    modes.push_back(jm);
  }
  frame["modes"] = modes;
  nlohmann::ordered_json cumulative;
  for (int d = 0; d < 6; ++d) cumulative[kDirections[d]] = fraction(sum, d);
  frame["effective_mass_fraction_sum"] = cumulative;
  frame["solver"] = {{"method", "shift-invert Lanczos (Spectra) on CHOLMOD, Sturm-count certified"}, {"shift", quantity(-run.shift_hz, hz)},
                     {"restarts", r.iterations}, {"operator_solves", r.operator_solves}};
  j["frame"] = frame;
  add_warnings(j, model.reader_warnings);
  folder.write_text("summary.json", j.dump(2) + "\n");

  // modes.csv
  std::vector<std::string> headers = {"mode", report::column("frequency", u.label(Quantity::frequency)), "rigid_body"};
  for (int d = 0; d < 6; ++d)
    headers.push_back(report::column(std::string("effective_mass_") + kDirections[d], d < 3 ? u.label(Quantity::mass) : u.label(Quantity::rotary_inertia)));
  for (int d = 0; d < 6; ++d) headers.push_back(std::string("effective_mass_fraction_") + kDirections[d]);
  report::CsvTable table(headers);
  for (std::size_t i = 0; i < r.modes.size(); ++i) {
    const fem::Mode& m = r.modes[i];
    table.row().add(static_cast<int>(i + 1)).add(m.frequency_hz).add(std::string(m.rigid_body ? "yes" : "no"));
    for (int d = 0; d < 6; ++d) table.add(eff_in_units(m.effective_mass, d));
    for (int d = 0; d < 6; ++d) table.add(fraction(m.effective_mass, d));
  }
  folder.write_text("modes.csv", table.str());

  // mode_shapes.csv: mass-normalised, in the input's units.
  const double sqrt_m = std::sqrt(u.to_si_factor(Quantity::mass));
  const double tr_f = sqrt_m / u.to_si_factor(Quantity::length);
  const std::string tr_unit = u.label(Quantity::mass_normalised_translation);
  const std::string rot_unit = u.label(Quantity::mass_normalised_rotation);
  if (run.mode_shapes_csv) {
    report::CsvTable shapes({"mode", "node", report::column("ux", tr_unit), report::column("uy", tr_unit), report::column("uz", tr_unit),
                             report::column("rx", rot_unit), report::column("ry", rot_unit), report::column("rz", rot_unit)});
    for (Eigen::Index i = 0; i < r.shapes.cols(); ++i)
      for (std::size_t n = 0; n < model.nodes.size(); ++n) {
        const auto s = r.shapes.col(i).segment<6>(static_cast<Eigen::Index>(6 * n));
        shapes.row().add(static_cast<int>(i + 1)).add(model.nodes[n].id);
        for (int d = 0; d < 6; ++d) shapes.add(s(d) * (d < 3 ? tr_f : sqrt_m));
      }
    folder.write_text("mode_shapes.csv", shapes.str());
  }
  if (run.paraview == ParaviewOutput::none) return;
  // ParaView: the translations scaled to a largest nodal translation of 1 (a
  // shape to look at; mode_shapes.csv has the mass-normalised values).
  const double length_scale = 1.0 / u.to_si_factor(Quantity::length);
  const auto shape_field = [&](Eigen::Index i, const std::string& name) {
    double max_translation = 0.0;
    for (std::size_t n = 0; n < model.nodes.size(); ++n)
      max_translation = std::max(max_translation, r.shapes.col(i).segment<3>(static_cast<Eigen::Index>(6 * n)).norm());
    report::VtuField f{name, 3, {}};
    f.values.reserve(3 * model.nodes.size());
    for (std::size_t n = 0; n < model.nodes.size(); ++n)
      for (int d = 0; d < 3; ++d) f.values.push_back(max_translation > 0 ? r.shapes(static_cast<Eigen::Index>(6 * n) + d, i) / max_translation : 0.0);
    return f;
  };
  if (run.paraview == ParaviewOutput::xdmf) {
    // Each mode a time step (its number): one field name, so one Warp By
    // Vector and one colour map serve every mode while the time controls
    // step through them; the frequency is in modes.csv under the same number.
    XdmfSeries series(folder, "modes", model, length_scale, static_cast<int>(r.shapes.cols()));
    for (Eigen::Index i = 0; i < r.shapes.cols(); ++i) series.add(static_cast<double>(i + 1), {shape_field(i, "mode_shape")}, {});
    series.finish();
    return;
  }
  std::vector<report::VtuField> fields;
  for (Eigen::Index i = 0; i < r.shapes.cols(); ++i)
    fields.push_back(shape_field(i, fmt::format("mode_{:02d}_{:.4g}Hz", i + 1, r.modes[static_cast<std::size_t>(i)].frequency_hz)));
  folder.write_text("modes.vtu", report::vtu_document(model, length_scale, fields, {}));
}

}  // namespace framedyn::report
