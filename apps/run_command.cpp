// `framedyn run STUDY.yaml`: runs a study file. Today: rigid-body studies
// (model: rigid_2d) — natural frequencies with their dominant coordinates and
// a forced response with recovered forces. Writes DIR/summary.json,
// DIR/rigid_modes.csv and, with a response, DIR/response.csv and DIR/events.csv.
// With --figures, PNG time histories too (report/response_figures.cpp).
#include <fmt/format.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "apps/commands.h"
#include "apps/progress.h"
#include "report/response_figures.h"
#include "report/calibration_output.h"
#include "report/rigid_modes_output.h"
#include "apps/run_outputs.h"
#include "report/csv_writer.h"
#include "report/event_log.h"
#include "report/json_quantity.h"
#include "core/results_folder.h"
#include "coupling/rigid_study.h"
#include "coupling/rigid_study_3d.h"
#include "apps/duty_cycle_command.h"
#include "apps/run_3d.h"

namespace framedyn::apps {

namespace {

using core::Quantity;

struct RunOptions {
  std::string study;
  std::string out;
  bool figures = false;  // --figures: PNG time histories (report/response_figures.cpp)
  ProgressFlags progress;
};


int run_study(const RunOptions& opt) {
  if (coupling::study_model(opt.study) == "rigid_3d") return run_study_3d(opt.study, opt.out, opt.figures, opt.progress);  // issue 4
  if (coupling::study_model(opt.study) == "duty_cycle") return run_duty_cycle_study(opt.study, opt.out, opt.figures, opt.progress);  // issue 18
  Progress progress(opt.progress);
  if (opt.figures) report::require_gnuplot();
  const std::string out_dir = opt.out.empty() ? std::filesystem::path(opt.study).stem().string() + "_results" : opt.out;
  core::check_results_target(out_dir, {opt.study});  // before the run: a refusal costs no time
  progress.stage("reading " + opt.study);
  const coupling::RigidStudy study = coupling::read_rigid_study(opt.study);
  const core::UnitSystem& u = study.units;
  progress.stage(study.response ? "modes and forced response" : "modes");
  const coupling::RigidResults r = coupling::run_rigid_study(study);

  progress.stage("writing results");
  core::ResultsFolder folder(out_dir, {opt.study});

  nlohmann::ordered_json j;
  j["framedyn"] = {{"version", FRAMEDYN_VERSION}, {"command", "run"}};
  j["input"] = {{"study", opt.study}, {"name", study.name}, {"units", u.name()}};
  nlohmann::ordered_json rigid;
  rigid["model"] = "rigid_2d";
  rigid["dofs"] = r.coordinates.size();
  rigid["coordinates"] = r.coordinates;
  rigid["fixed_coordinates"] = study.fixed_coordinates;
  rigid["modes"] = report::write_rigid_modes(r.coordinates, r.modes, folder);
  rigid["modes_state"] = coupling::contact_state_name(study.modal_soil);  // the contact state rigid.modes is in
  rigid["modes_by_state"] = modes_by_state_json(r.modes_by_state);
  rigid["static"] = static_json(r.static_contacts, u);

  if (r.calibration && study.calibration)
    rigid["calibration"] = report::write_calibration(*study.calibration, *r.calibration, u,
                                             [&](const std::string& name) { return coupling::parameter_quantity(study.machine, name); }, folder);

  if (study.response) {
    const rigid::Trajectory& tr = r.trajectory;
    nlohmann::ordered_json resp;
    resp["method"] = study.response->method == coupling::ResponseRequest::Method::event_located ? "event_located (CVODE)" : "rk4";
    resp["duration"] = {{"value", study.response->duration}, {"unit", u.label(Quantity::time)}};
    resp["events"] = tr.events.size();
    resp["steps"] = tr.steps;
    const double lf = 1.0 / u.to_si_factor(Quantity::length), ff = 1.0 / u.to_si_factor(Quantity::force);
    if (r.plow_vertical_peak_to_peak) resp["plow_vertical_pp"] = {{"value", *r.plow_vertical_peak_to_peak * lf}, {"unit", u.label(Quantity::length)}};
    if (r.peak_cutting_force) resp["peak_cutting_force"] = {{"value", *r.peak_cutting_force * ff}, {"unit", u.label(Quantity::force)}};
    if (r.peak_backing_force) resp["peak_backing_force"] = {{"value", *r.peak_backing_force * ff}, {"unit", u.label(Quantity::force)}};
    if (r.average_peak_cutting_force)
      resp["average_peak_cutting_force"] = {{"value", *r.average_peak_cutting_force * ff}, {"unit", u.label(Quantity::force)}};
    if (r.average_peak_backing_force)
      resp["average_peak_backing_force"] = {{"value", *r.average_peak_backing_force * ff}, {"unit", u.label(Quantity::force)}};
    rigid["response"] = resp;
    rigid["contacts"] = contacts_json(r.contacts, u);
    rigid["steady"] = steady_json(r.steady, u);

    std::vector<std::string> h = {report::column("time", u.label(Quantity::time))};
    for (std::size_t c = 0; c < r.coordinates.size(); ++c) h.push_back(report::column(r.coordinates[c], u.label(r.coordinate_quantities[c])));
    for (const coupling::Series& s : r.series)
      h.push_back(s.quantity == Quantity::dimensionless ? s.name : report::column(s.name, u.label(s.quantity)));
    report::CsvTable csv(h);
    for (std::size_t i = 0; i < tr.time.size(); ++i) {
      csv.row().add(tr.time[i]);
      for (std::size_t c = 0; c < r.coordinates.size(); ++c)
        csv.add(u.from_si(tr.q[i](static_cast<Eigen::Index>(c)), r.coordinate_quantities[c]));
      for (const coupling::Series& s : r.series) csv.add(u.from_si(s.values[i], s.quantity));
    }
    folder.write_text("response.csv", csv.str());
    report::CsvTable ev({report::column("time", u.label(Quantity::time)), "event"});
    for (const auto& e : tr.events) ev.row().add(e.time).add(report::event_text(e, u));
    folder.write_text("events.csv", ev.str());

    if (r.resultants) {
      // Frame loads (forces on the frame) and the stress resultants of Eq. 2.47.
      const std::string F = u.label(Quantity::force), M = u.label(Quantity::moment), L = u.label(Quantity::length);
      const double mf = 1.0 / u.to_si_factor(Quantity::moment), sf = 1.0 / u.to_si_factor(Quantity::stress);
      std::vector<std::string> lh = {report::column("time", u.label(Quantity::time))};
      for (const coupling::FrameLoad2D& l : r.frame_loads)
        for (const char* c : {"_fx", "_fz", "_my"}) lh.push_back(report::column(l.name + c, std::string(c) == "_my" ? M : F));
      report::CsvTable lcsv(lh);
      for (std::size_t i = 0; i < tr.time.size(); ++i) {
        lcsv.row().add(tr.time[i]);
        for (const coupling::FrameLoad2D& l : r.frame_loads) lcsv.add(l.force[i].x() * ff).add(l.force[i].y() * ff).add(l.moment[i] * mf);
      }
      folder.write_text("frame_loads.csv", lcsv.str());
      const coupling::StressResultants& sr = *r.resultants;
      const bool stress = !r.rail_top_stress.empty();
      std::vector<std::string> rh = {report::column("time", u.label(Quantity::time)), report::column("X", L), report::column("SRX", F), report::column("SRZ", F), report::column("SRMY", M)};
      if (stress) rh.push_back(report::column("rail_top_stress", u.label(Quantity::stress)));
      report::CsvTable rcsv(rh);
      nlohmann::ordered_json points = nlohmann::ordered_json::array();
      for (std::size_t k = 0; k < sr.output_x.size(); ++k) {
        double px = 0, pz = 0, pm = 0, ps = 0, ps_time = 0;
        for (std::size_t i = 0; i < tr.time.size(); ++i) {
          px = std::max(px, std::abs(sr.srx[i][k]));
          pz = std::max(pz, std::abs(sr.srz[i][k]));
          pm = std::max(pm, std::abs(sr.srmy[i][k]));
          if (stress && std::abs(r.rail_top_stress[i][k]) > ps) {
            ps = std::abs(r.rail_top_stress[i][k]);
            ps_time = tr.time[i];
          }
        }
        // Each number with its unit ({value, unit}), as in the rest of the summary.
        const std::string S = u.label(Quantity::stress);
        nlohmann::ordered_json jp = {{"x", {{"value", sr.output_x[k] * lf}, {"unit", L}}},
                                     {"peak_srx", {{"value", px * ff}, {"unit", F}}},
                                     {"peak_srz", {{"value", pz * ff}, {"unit", F}}},
                                     {"peak_srmy", {{"value", pm * mf}, {"unit", M}}}};
        if (stress) jp["peak_rail_top_stress"] = {{"value", ps * sf}, {"unit", S}, {"time", report::quantity(ps_time, u.label(Quantity::time))}};
        points.push_back(jp);
      }
      for (std::size_t i = 0; i < tr.time.size(); ++i)
        for (std::size_t k = 0; k < sr.output_x.size(); ++k) {
          rcsv.row().add(tr.time[i]).add(sr.output_x[k] * lf).add(sr.srx[i][k] * ff).add(sr.srz[i][k] * ff).add(sr.srmy[i][k] * mf);
          if (stress) rcsv.add(r.rail_top_stress[i][k] * sf);
        }
      folder.write_text("frame_resultants.csv", rcsv.str());
      rigid["frame"] = {{"units", {{"x", L}, {"force", F}, {"moment", M}, {"stress", u.label(Quantity::stress)}}},
                        {"loads", [&] {
                           std::vector<std::string> names;
                           for (const auto& l : r.frame_loads) names.push_back(l.name);
                           return names;
                         }()},
                        {"output_points", points}};
    }
  }
  j["rigid"] = rigid;
  add_warnings(j, r.warnings);
  std::vector<std::string> figures;
  if (opt.figures) {
    progress.stage("figures");
    figures = report::write_response_figures(study, r, folder);
  }
  folder.write_text("summary.json", j.dump(2) + "\n");
  folder.commit();
  progress.done();
  if (progress.quiet()) {  // -q: errors only, and the results folder on stdout
    fmt::print("results in {}/\n", out_dir);
    return 0;
  }

  fmt::print("framedyn run: {} ({}, {} coordinates, units {})\n", opt.study, study.name, r.coordinates.size(), u.name());
  if (!r.modes.empty()) {
    fmt::print("\n mode  frequency [Hz]  dominant\n");
    for (std::size_t i = 0; i < r.modes.size(); ++i) fmt::print("{:5d}  {:14.4f}  {}\n", i + 1, r.modes[i].frequency_hz, r.modes[i].dominant);
  }
  if (r.calibration && study.calibration) report::print_calibration(*study.calibration, *r.calibration);
  if (r.plow_vertical_peak_to_peak) {
    const double lf = 1.0 / u.to_si_factor(Quantity::length), ff = 1.0 / u.to_si_factor(Quantity::force);
    fmt::print("\nblade vertical motion, average peak to peak: {:.4g} {}\n", *r.plow_vertical_peak_to_peak * lf, u.label(Quantity::length));
    fmt::print("peak cutting force {:.5g} {}, peak backing force {:.5g} {}\n", r.peak_cutting_force.value_or(0) * ff, u.label(Quantity::force),
               r.peak_backing_force.value_or(0) * ff, u.label(Quantity::force));
    fmt::print("average of the shaker cycles' peaks: cutting {:.5g} {}, backing {:.5g} {}\n", r.average_peak_cutting_force.value_or(0) * ff,
               u.label(Quantity::force), r.average_peak_backing_force.value_or(0) * ff, u.label(Quantity::force));
  }
  if (opt.figures) fmt::print("\nfigures: {}\n", figures.empty() ? std::string("none (the study has no response)") : fmt::format("{}", fmt::join(figures, ", ")));
  fmt::print("\nresults in {}/\n", out_dir);
  return 0;
}

}  // namespace

void add_run_command(CLI::App& app, std::function<int()>& run) {
  auto opt = std::make_shared<RunOptions>();
  CLI::App* cmd = app.add_subcommand("run", "Run a study file (rigid-body vehicle modes and forced response)");
  cmd->add_option("study", opt->study, "Study file (.yaml)")->required();
  cmd->add_option("--out,-o", opt->out, "Results folder (default: <study name>_results)");
  cmd->add_flag("--figures", opt->figures, "Also write PNG figures of the response (needs gnuplot)");
  opt->progress.add_to(*cmd);
  cmd->callback([opt, &run]() { run = [opt]() { return run_study(*opt); }; });
}

}  // namespace framedyn::apps
