// `framedyn run STUDY.yaml` for model: rigid_3d (thesis CMW3D, Chapter III):
// modes with dominant coordinates, a forced response, and the frame loads as
// a load-history file (frame_loads.csv): the eight load points 24-31 and the
// attachment's loads at point 19 (plow swing pin, or chain pin and boom
// soil), every load on the frame, all of which load the frame model.
// With --figures, every run draws its own Chapter V load-point figures: the
// front axle pin's forces (thesis Figure 22 for the chain) and the rear axle
// pin's and leveling cylinder's forces (Figure 23 chain, Figure 24 plow), each
// PNG with a CSV of exactly the plotted series beside it.
#include "apps/run_3d.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <utility>
#include <vector>
#include <nlohmann/json.hpp>

#include "report/calibration_output.h"
#include "report/rigid_modes_output.h"
#include "apps/run_outputs.h"
#include "report/csv_writer.h"
#include "report/event_log.h"
#include "report/json_quantity.h"
#include "report/mode_shape_figure.h"
#include "core/results_folder.h"
#include "report/response_figures.h"
#include "report/plot.h"
#include "coupling/frame_loads_3d.h"
#include "coupling/frame_study.h"
#include "report/fatigue_outputs.h"
#include "report/frame_outputs.h"
#include "coupling/load_history.h"
#include "coupling/rigid_study_3d.h"
#include "coupling/validity_warnings.h"

namespace framedyn::apps {

namespace {
using core::Quantity;

// Thesis Figure 25: the envelope of the bending moment along the left and
// right rails over the run (largest resultant |M| at each station).
void write_rail_moment_figure(const coupling::FrameStudyResults& f, const core::UnitSystem& u, const core::ResultsFolder& folder) {
  report::LinePlot plot;
  plot.title = "Bending moment along the rails (envelope over the run; thesis Figure 25)";
  plot.x_label = "X along the frame";
  plot.x_unit = u.label(Quantity::length);
  plot.y_label = "peak bending moment";
  plot.y_unit = u.label(Quantity::moment);
  for (const coupling::RailRecovery& rail : f.rails) {
    report::PlotSeries series;
    series.name = rail.spec.name;
    for (std::size_t i = 0; i < rail.station_points.size(); ++i) {
      series.x.push_back(u.from_si(rail.station_points[i].x(), Quantity::length));
      series.y.push_back(u.from_si(rail.envelope_bending_moment(static_cast<Eigen::Index>(i)), Quantity::moment));
    }
    plot.series.push_back(series);
  }
  report::write_png(plot, folder.path_of("fig25_rail_bending_moment.png"));
}
// The bending-moment envelope along each rail under the run's support and
// the compared ones (frame_response.compare_supports), one line per rail and support.
void write_support_comparison_figure(const coupling::FrameStudyResults& f, const coupling::FrameStudyRequest& q,
                                     const std::vector<coupling::FrameStudyResults>& compared, const core::UnitSystem& u,
                                     const core::ResultsFolder& folder) {
  report::LinePlot plot;
  plot.title = "Bending moment along the rails under each support (envelope over the run)";
  plot.x_label = "X along the frame";
  plot.x_unit = u.label(Quantity::length);
  plot.y_label = "peak bending moment";
  plot.y_unit = u.label(Quantity::moment);
  std::vector<std::pair<const coupling::FrameStudyResults*, coupling::FrameSupports>> runs = {{&f, q.supports}};
  for (std::size_t k = 0; k < compared.size(); ++k) runs.push_back({&compared[k], q.compare_supports[k]});
  for (const auto& [run, supports] : runs)
    for (const coupling::RailRecovery& rail : run->rails) {
      report::PlotSeries series;
      series.name = rail.spec.name + ", " + coupling::supports_name(supports);
      for (std::size_t i = 0; i < rail.station_points.size(); ++i) {
        series.x.push_back(u.from_si(rail.station_points[i].x(), Quantity::length));
        series.y.push_back(u.from_si(rail.envelope_bending_moment(static_cast<Eigen::Index>(i)), Quantity::moment));
      }
      plot.series.push_back(series);
    }
  report::write_png(plot, folder.path_of("frame_supports_envelopes.png"));
}

// Thesis Figures 22-24: forces at load points over time, one figure per
// group. `file` names both the PNG and the CSV of the plotted values.
struct LoadPointFigure {
  std::string file, title;
  std::vector<std::pair<std::string, int>> series;  // (load point, component 0..2 = FX, FY, FZ)
};

std::vector<LoadPointFigure> load_point_figures(rigid::Attachment attachment) {
  const bool chain = attachment == rigid::Attachment::chain, plow = attachment == rigid::Attachment::plow;
  return {
      {"front_pin_forces", std::string(chain ? "Figure 22: " : "") + "front axle pin 25",
       {{"P25_FRONT_AXLE_PIN", 0}, {"P25_FRONT_AXLE_PIN", 1}, {"P25_FRONT_AXLE_PIN", 2}}},
      {"rear_pin_and_leveling_cylinder_forces", std::string(chain ? "Figure 23: " : plow ? "Figure 24: " : "") + "rear axle pin 26, leveling cylinder 27",
       {{"P26_REAR_AXLE_PIN", 0}, {"P26_REAR_AXLE_PIN", 1}, {"P26_REAR_AXLE_PIN", 2}, {"P27_LEVELING_CYLINDER", 2}}},
  };
}

// Draws the load-point figures of one run; returns the PNG file names.
std::vector<std::string> write_load_point_figures(const coupling::LoadHistory& h, rigid::Attachment attachment, const std::string& run_name,
                                                  const core::UnitSystem& u, const core::ResultsFolder& folder) {
  std::vector<std::string> written;
  std::vector<double> time(h.times.data(), h.times.data() + h.times.size());
  for (const LoadPointFigure& f : load_point_figures(attachment)) {
    report::LinePlot plot;
    plot.title = f.title + "; " + run_name;  // "Figure N" is the thesis's
    plot.width = 1200;
    plot.x_label = "time";
    plot.x_unit = u.label(Quantity::time);
    plot.y_label = "force on the frame";
    plot.y_unit = u.label(Quantity::force);
    std::vector<std::string> header = {report::column("time", u.label(Quantity::time))};
    for (const auto& [point, c] : f.series) {
      const std::string& name = point;  // C++17 lambdas cannot capture a structured binding (clang refuses it)
      const auto it = std::find_if(h.points.begin(), h.points.end(), [&](const coupling::LoadPointHistory& p) { return p.name == name; });
      if (it == h.points.end()) throw std::logic_error("the frame loads have no load point " + point);
      report::PlotSeries ps{point + " " + coupling::kLoadComponents[c], time, {}};
      for (Eigen::Index i = 0; i < it->values.rows(); ++i) ps.y.push_back(u.from_si(it->values(i, c), Quantity::force));
      header.push_back(report::column(point + "." + coupling::kLoadComponents[c], u.label(Quantity::force)));
      plot.series.push_back(std::move(ps));
    }
    report::CsvTable csv(header);
    for (std::size_t i = 0; i < time.size(); ++i) {
      csv.row().add(time[i]);
      for (const report::PlotSeries& ps : plot.series) csv.add(ps.y[i]);
    }
    folder.write_text(f.file + ".csv", csv.str());
    report::write_png(plot, folder.path_of(f.file + ".png"));
    written.push_back(f.file + ".png");
  }
  return written;
}

}  // namespace

int run_study_3d(const std::string& study_file, const std::string& out, bool figures, const ProgressFlags& flags) {
  Progress progress(flags);
  if (figures) report::require_gnuplot();
  const std::string out_dir = out.empty() ? std::filesystem::path(study_file).stem().string() + "_results" : out;
  core::check_results_target(out_dir, {study_file});  // before the run: a refusal costs no time
  progress.stage("reading " + study_file);
  const coupling::RigidStudy3D study = coupling::read_rigid_study_3d(study_file);
  const core::UnitSystem& u = study.units;
  progress.stage(study.response ? "rigid-body modes and forced response (3-D)" : "rigid-body modes (3-D)");
  const coupling::RigidResults3D r = coupling::run_rigid_study_3d(study);
  progress.stage("writing results");
  core::ResultsFolder folder(out_dir, {study_file});
  const double lf = 1.0 / u.to_si_factor(Quantity::length), ff = 1.0 / u.to_si_factor(Quantity::force), mf = 1.0 / u.to_si_factor(Quantity::moment);

  std::vector<std::string> figure_files;
  nlohmann::ordered_json j;
  j["framedyn"] = {{"version", FRAMEDYN_VERSION}, {"command", "run"}};
  j["input"] = {{"study", study_file}, {"name", study.name}, {"units", u.name()}};
  nlohmann::ordered_json rigid;
  rigid["model"] = "rigid_3d";
  rigid["dofs"] = r.coordinates.size();
  rigid["coordinates"] = r.coordinates;
  rigid["fixed_coordinates"] = study.fixed_coordinates;
  rigid["modes"] = report::write_rigid_modes(r.coordinates, r.modes, folder);
  rigid["modes_state"] = coupling::contact_state_name(rigid::ModalSoil::cutting);  // the contact state rigid.modes is in
  rigid["modes_by_state"] = modes_by_state_json(r.modes_by_state);
  rigid["static"] = static_json(r.static_contacts, u);

  if (r.calibration && study.calibration)
    rigid["calibration"] = report::write_calibration(*study.calibration, *r.calibration, u, coupling::parameter_quantity_3d, folder);

  if (study.response) {
    const rigid::Trajectory& tr = r.trajectory;
    nlohmann::ordered_json resp;
    resp["method"] = study.response->method == coupling::ResponseRequest::Method::event_located ? "event_located (CVODE)" : "rk4";
    resp["duration"] = {{"value", study.response->duration}, {"unit", u.label(Quantity::time)}};
    resp["events"] = tr.events.size();
    resp["steps"] = tr.steps;
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
    for (const coupling::Series& s : r.series) h.push_back(report::column(s.name, u.label(s.quantity)));
    report::CsvTable csv(h);
    for (std::size_t i = 0; i < tr.time.size(); ++i) {
      csv.row().add(tr.time[i]);
      for (std::size_t c = 0; c < r.coordinates.size(); ++c) csv.add(u.from_si(tr.q[i](static_cast<Eigen::Index>(c)), r.coordinate_quantities[c]));
      for (const coupling::Series& s : r.series) csv.add(u.from_si(s.values[i], s.quantity));
    }
    folder.write_text("response.csv", csv.str());
    report::CsvTable ev({report::column("time", u.label(Quantity::time)), "event"});
    for (const auto& e : tr.events) ev.row().add(e.time).add(report::event_text(e, u));
    folder.write_text("events.csv", ev.str());

    if (r.frame_loads) {
      folder.write_text("frame_loads.csv", coupling::format_load_history(coupling::all_frame_loads(*r.frame_loads), u));
      if (figures) {
        const std::vector<std::string> drawn = write_load_point_figures(r.frame_loads->points, study.machine.attachment, study.name, u, folder);
        figure_files.insert(figure_files.end(), drawn.begin(), drawn.end());
      }
      nlohmann::ordered_json loads;
      for (const coupling::LoadPointHistory& p : coupling::all_frame_loads(*r.frame_loads).points) {
        nlohmann::ordered_json jp;
        jp["location"] = {{"value", {p.location.x() * lf, p.location.y() * lf, p.location.z() * lf}}, {"unit", u.label(Quantity::length)}};
        for (int c = 0; c < 6; ++c) {
          double peak = 0.0;  // the value of largest magnitude, with its sign
          for (Eigen::Index i = 0; i < p.values.rows(); ++i)
            if (std::abs(p.values(i, c)) > std::abs(peak)) peak = p.values(i, c);
          jp[coupling::kLoadComponents[c]] = {{"peak", report::quantity(peak * (c < 3 ? ff : mf), u.label(c < 3 ? Quantity::force : Quantity::moment))}};
        }
        loads[p.name] = jp;
      }
      rigid["frame_loads"] = loads;
    }
  }
  j["rigid"] = rigid;
  add_warnings(j, r.warnings);

  // The pipeline: this run's frame loads into the beam model of the frame.
  std::optional<coupling::FrameStudyResults> frame;
  if (study.frame_response) {
    // Every load on the frame (points 24-31 and the attachment's at point 19).
    const coupling::LoadHistory loads = coupling::all_frame_loads(*r.frame_loads);
    progress.stage("frame transient (pipeline)");
    const coupling::LoadHistory static_loads = coupling::all_frame_loads(*r.static_frame_loads);  // at the static equilibrium
    frame = coupling::run_frame_study(*study.frame_response, &loads, &static_loads, r.steady.operation.reached_at);
    progress.stage("writing results (frame)");
    report::write_frame_outputs(*frame, *study.frame_response, folder, progress.step_callback());
    j["frame"] = report::frame_summary(*frame, *study.frame_response);
    j["frame"]["steady"] = frame_steady_json(*frame, r.steady.operation.reached_at, u);
    if (frame->life) j["fatigue"] = report::fatigue_summary(*frame, *study.frame_response);
    add_warnings(j, coupling::frame_warnings(*frame, *study.frame_response));
    // The same loads on the supports compared (frame_response.compare_supports), each run on its own (one
    // assembly and factorisation per support): their peaks in the summary, their envelopes in one figure.
    std::vector<coupling::FrameStudyResults> compared;
    for (const coupling::FrameSupports s : study.frame_response->compare_supports) {
      progress.stage(fmt::format("frame transient (pipeline, supports: {})", coupling::supports_name(s)));
      coupling::FrameStudyRequest cq = *study.frame_response;
      cq.supports = s;
      cq.compare_supports.clear();
      cq.paraview = coupling::ParaviewOutput::none;
      cq.fatigue.reset();  // the life map is the run's own support's
      cq.stress_histories = coupling::FrameStudyRequest::StressHistoryOutput::none;
      compared.push_back(coupling::run_frame_study(cq, &loads, &static_loads, r.steady.operation.reached_at));
      const nlohmann::ordered_json full = report::frame_summary(compared.back(), cq);
      nlohmann::ordered_json c = {{"support", full["support"]}, {"rails", full["rails"]}};
      for (const char* key : {"peak_bending_moment", "peak_von_mises", "static"})
        if (full.contains(key)) c[key] = full[key];
      j["frame"]["compared_supports"].push_back(c);
    }
    // The shaker near an elastic mode of the frame model (Eq. 8.3's band, on the beam model's modes).
    if (study.machine.attachment == rigid::Attachment::plow) {
      const std::vector<double> frame_hz(frame->frequencies_hz.data(), frame->frequencies_hz.data() + frame->frequencies_hz.size());
      add_warnings(j, coupling::frame_resonance_warnings(study.machine.plow.shaker_frequency, frame_hz,
                                                         study.frame_response->mesh.filename().string()));
    }
    if (figures) {
      write_rail_moment_figure(*frame, u, folder);
      figure_files.push_back("fig25_rail_bending_moment.png");
      if (!compared.empty()) {
        write_support_comparison_figure(*frame, *study.frame_response, compared, u, folder);
        figure_files.push_back("frame_supports_envelopes.png");
      }
      if (!frame->hot_spots.by_von_mises.empty()) {
        report::write_png(report::hot_spot_stress_figure(*frame, u), folder.path_of("frame_hot_spots.png"));
        figure_files.push_back("frame_hot_spots.png");
      }
      if (frame->life) {
        const report::LinePlot life = report::life_along_rails_figure(*frame, u);
        if (!life.series.empty()) {  // no station with damage: nothing to draw on a log axis
          report::write_png(life, folder.path_of("frame_life.png"));
          figure_files.push_back("frame_life.png");
        }
      }
      if (frame->mode_shapes.cols() > 0) {
        const std::vector<double> hz(frame->frequencies_hz.data(), frame->frequencies_hz.data() + std::min<Eigen::Index>(frame->frequencies_hz.size(), frame->mode_shapes.cols()));
        report::write_png(report::mode_shape_figure(frame->model, frame->mode_shapes, hz,
                                                    fmt::format("Frame model's lowest elastic modes ({}, supports: {})", study.frame_response->mesh.filename().string(),
                                                                coupling::supports_name(study.frame_response->supports))),
                          folder.path_of("frame_mode_shapes.png"));
        figure_files.push_back("frame_mode_shapes.png");
      }
    }
  }
  folder.write_text("summary.json", j.dump(2) + "\n");
  folder.commit();
  progress.done();
  if (progress.quiet()) {  // -q: errors only, and the results folder on stdout
    fmt::print("results in {}/\n", out_dir);
    return 0;
  }

  fmt::print("framedyn run: {} ({}, 3-D, {} coordinates, units {})\n", study_file, study.name, r.coordinates.size(), u.name());
  if (!r.modes.empty()) {
    fmt::print("\n mode  frequency [Hz]  dominant\n");
    for (std::size_t i = 0; i < r.modes.size(); ++i) fmt::print("{:5d}  {:14.4f}  {}\n", i + 1, r.modes[i].frequency_hz, r.modes[i].dominant);
  }
  if (r.calibration && study.calibration) report::print_calibration(*study.calibration, *r.calibration);
  if (frame) {
    const coupling::FrameStudyResults& f = *frame;
    fmt::print("\nframe ({}): {} nodes, {} beam elements, {} elastic modes used, lowest {:.2f} Hz; {} output times in {:.3f} s\n",
               study.frame_response->mesh.filename().string(), f.model.nodes.size(), f.model.beams.size(), f.frequencies_hz.size(),
               f.frequencies_hz.size() > 0 ? f.frequencies_hz(0) : 0.0, f.response.times.size(), f.wall_seconds);
    for (const coupling::RailRecovery& rail : f.rails)
      fmt::print("{}: peak bending moment {:.5g} {} at X = {:.4g} {}, t = {:.4f} s; peak normal stress {:.5g} {} ({:.0f} % from bending)\n",
                 rail.spec.name, u.from_si(rail.peak_bending_moment.value, Quantity::moment), u.label(Quantity::moment),
                 rail.peak_bending_moment.point.x() * lf, u.label(Quantity::length), rail.peak_bending_moment.time,
                 u.from_si(rail.peak_normal_stress.value, Quantity::stress), u.label(Quantity::stress), 100.0 * rail.bending_share);
    if (f.static_state) {
      const coupling::FrameStaticState& st = *f.static_state;
      fmt::print("static state (gravity and the static loads): peak normal stress {:.5g} {} on {} at X = {:.4g} {}; balance residual {:.1e} (force), "
                 "{:.1e} (moment)\n",
                 u.from_si(st.peak_normal_stress.value, Quantity::stress), u.label(Quantity::stress), st.peak_output,
                 st.peak_normal_stress.point.x() * lf, u.label(Quantity::length), st.force_residual, st.moment_residual);
      for (const coupling::RailRecovery& rail : f.rails)
        fmt::print("{}: peak total (static + dynamic) normal stress {:.5g} {} at X = {:.4g} {}, t = {:.4f} s\n", rail.spec.name,
                   u.from_si(rail.peak_total_normal_stress.value, Quantity::stress), u.label(Quantity::stress),
                   rail.peak_total_normal_stress.point.x() * lf, u.label(Quantity::length), rail.peak_total_normal_stress.time);
    }
    print_hot_spot_line(f, u);
    print_fatigue_line(f, *study.frame_response);
  }
  if (figures) {
    std::string list;
    for (const std::string& f : figure_files) list += (list.empty() ? "" : ", ") + f;
    fmt::print("\nfigures: {}\n", list.empty() ? std::string("none (the study has no response)") : list);
  }
  fmt::print("\nresults in {}/\n", out_dir);
  return 0;
}

}  // namespace framedyn::apps
