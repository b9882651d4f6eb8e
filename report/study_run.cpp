// Runs any study document in memory and returns its summary (see study_run.h).
// The summary and the results folder are assembled here exactly as `framedyn run`
// wrote them before this library call existed (moved from apps/run_command.cpp,
// apps/run_3d.cpp and apps/duty_cycle_command.cpp): 2-D (rigid_2d), 3-D (rigid_3d)
// with the frame pipeline, and duty cycles. Without a results folder the large
// tables (response, events, frame loads, the frame's series) are not formatted.
#include "report/study_run.h"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>
#include <utility>

#include "core/results_folder.h"
#include "coupling/frame_loads_3d.h"
#include "coupling/load_history.h"
#include "coupling/road_delays.h"
#include "coupling/study_key_path.h"
#include "coupling/validity_warnings.h"
#include "coupling/yaml_input.h"
#include "report/calibration_output.h"
#include "report/csv_writer.h"
#include "report/duty_cycle_outputs.h"
#include "report/event_log.h"
#include "report/fatigue_outputs.h"
#include "report/frame_outputs.h"
#include "report/json_quantity.h"
#include "report/mode_shape_figure.h"
#include "report/plot.h"
#include "report/response_figures.h"
#include "report/rigid_modes_output.h"
#include "report/run_outputs.h"
#include "report/study_run_details.h"

namespace framedyn::report {

namespace {

using core::Quantity;
using Stage = std::function<void(const std::string&)>;  // a run's progress: a stage begins

// The run's results folder, or one in memory without `out`.
std::unique_ptr<core::ResultsFolder> results_folder(const StudyRunOptions& options, std::vector<std::filesystem::path> inputs) {
  if (!options.out) return std::make_unique<core::ResultsFolder>(core::ResultsFolder::InMemory{});
  return std::make_unique<core::ResultsFolder>(*options.out, std::move(inputs));
}

// Thesis Figure 25: the envelope of the bending moment along the left and
// right rails over the run (largest resultant |M| at each station).
// A plot of bending-moment envelopes along X (the lines added by the caller).
report::LinePlot rail_envelope_plot(const std::string& title, const core::UnitSystem& u) {
  report::LinePlot plot;
  plot.title = title;
  plot.x_label = "X along the frame";
  plot.x_unit = u.label(Quantity::length);
  plot.y_label = "peak bending moment";
  plot.y_unit = u.label(Quantity::moment);
  return plot;
}
// One rail's envelope of the resultant |M| at each station, as a line named `name`.
report::PlotSeries rail_envelope_series(const coupling::RailRecovery& rail, const std::string& name, const core::UnitSystem& u) {
  report::PlotSeries series;
  series.name = name;
  for (std::size_t i = 0; i < rail.station_points.size(); ++i) {
    series.x.push_back(u.from_si(rail.station_points[i].x(), Quantity::length));
    series.y.push_back(u.from_si(rail.envelope_bending_moment(static_cast<Eigen::Index>(i)), Quantity::moment));
  }
  return series;
}
void write_rail_moment_figure(const coupling::FrameStudyResults& f, const core::UnitSystem& u, const core::ResultsFolder& folder) {
  report::LinePlot plot = rail_envelope_plot("Bending moment along the rails (envelope over the run; thesis Figure 25)", u);
  for (const coupling::RailRecovery& rail : f.rails) plot.series.push_back(rail_envelope_series(rail, rail.spec.name, u));
  report::write_png(plot, folder.path_of("fig25_rail_bending_moment.png"));
}
// The bending-moment envelope along each rail under the run's support and
// the compared ones (frame_response.compare_supports), one line per rail and support.
void write_support_comparison_figure(const coupling::FrameStudyResults& f, const coupling::FrameStudyRequest& q,
                                     const std::vector<coupling::FrameStudyResults>& compared, const core::UnitSystem& u,
                                     const core::ResultsFolder& folder) {
  report::LinePlot plot = rail_envelope_plot("Bending moment along the rails under each support (envelope over the run)", u);
  std::vector<std::pair<const coupling::FrameStudyResults*, coupling::FrameSupports>> runs = {{&f, q.supports}};
  for (std::size_t k = 0; k < compared.size(); ++k) runs.push_back({&compared[k], q.compare_supports[k]});
  for (const auto& [run, supports] : runs)
    for (const coupling::RailRecovery& rail : run->rails) plot.series.push_back(rail_envelope_series(rail, rail.spec.name + ", " + coupling::supports_name(supports), u));
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

// ---- The vehicle studies (rigid_2d, rigid_3d): one set of writers --------------------------------
// The summary parts, the files and the stages are written once from coupling::RigidStudy and
// coupling::RigidResults (docs/theory/coupling.md section 15); the frame is each model's own (2-D: the
// frame_output block's loads and resultants, the response figures; 3-D: the frame loads at the load
// points and the frame pipeline).

// The stage message of the run.
std::string running_stage(const coupling::RigidStudy& s) {
  if (s.dimensions() == 2) return s.response ? "modes and forced response" : "modes";
  return s.response ? "rigid-body modes and forced response (3-D)" : "rigid-body modes (3-D)";
}

// The model's keys after rigid.fixed_coordinates: the road inputs' delays behind the front axle
// (docs/theory/fatigue.md section 11), the same in 2-D and 3-D (coupling::road_delays).
void add_road_inputs(nlohmann::ordered_json& rigid, const coupling::RigidStudy& study) {
  const core::UnitSystem& u = study.units;
  const double lf = 1.0 / u.to_si_factor(Quantity::length);
  nlohmann::ordered_json road = nlohmann::ordered_json::array();
  for (const coupling::RoadDelay& d : std::visit([](const auto& m) { return coupling::road_delays(m); }, study.machine))
    road.push_back({{"tire", d.tire}, {"behind", report::quantity(d.behind * lf, u.label(Quantity::length))},
                    {"delay", report::quantity(d.delay, "s")}, {"source", d.given ? "behind (given)" : "derived from the tire positions"}});
  if (!road.empty()) rigid["road_inputs"] = road;
}

// The summary's rigid block up to the response: model, dofs, coordinates, fixed coordinates, the
// road inputs, modes (rigid_modes.csv), modes by contact state, the static contacts, the calibration.
nlohmann::ordered_json rigid_block(const coupling::RigidStudy& s, const coupling::RigidResults& r, const core::ResultsFolder& folder) {
  nlohmann::ordered_json rigid;
  rigid["model"] = s.model();
  rigid["dofs"] = r.coordinates.size();
  rigid["coordinates"] = r.coordinates;
  rigid["fixed_coordinates"] = s.fixed_coordinates;
  add_road_inputs(rigid, s);
  rigid["modes"] = report::write_rigid_modes(r.coordinates, r.modes, folder);
  rigid["modes_state"] = coupling::contact_state_name(s.modal_soil);
  rigid["modes_by_state"] = modes_by_state_json(r.modes_by_state);
  rigid["static"] = static_json(r.static_contacts, s.units);
  if (r.calibration && s.calibration)
    rigid["calibration"] = report::write_calibration(*s.calibration, *r.calibration, s.units,
                                                     [&s](const std::string& name) { return coupling::parameter_quantity(s.machine, name); }, folder);
  return rigid;
}

// With a response: rigid.response (method, steps, the blade's peaks), rigid.contacts, rigid.steady, and
// (to a folder) response.csv (time, coordinates, recovered series) and events.csv.
void add_response(const coupling::RigidStudy& s, const coupling::RigidResults& r, const core::ResultsFolder& folder, nlohmann::ordered_json& rigid) {
  const core::UnitSystem& u = s.units;
  const rigid::Trajectory& tr = r.trajectory;
  nlohmann::ordered_json resp;
  resp["method"] = s.response->method == coupling::ResponseRequest::Method::event_located ? "event_located (CVODE)" : "rk4";
  resp["duration"] = {{"value", s.response->duration}, {"unit", u.label(Quantity::time)}};
  resp["events"] = tr.events.size();
  resp["steps"] = tr.steps;
  const double lf = 1.0 / u.to_si_factor(Quantity::length), ff = 1.0 / u.to_si_factor(Quantity::force);
  const auto force = [&](const char* key, const std::optional<double>& v) {
    if (v) resp[key] = {{"value", *v * ff}, {"unit", u.label(Quantity::force)}};
  };
  if (r.plow_vertical_peak_to_peak) resp["plow_vertical_pp"] = {{"value", *r.plow_vertical_peak_to_peak * lf}, {"unit", u.label(Quantity::length)}};
  force("peak_cutting_force", r.peak_cutting_force);
  force("peak_backing_force", r.peak_backing_force);
  force("average_peak_cutting_force", r.average_peak_cutting_force);
  force("average_peak_backing_force", r.average_peak_backing_force);
  rigid["response"] = resp;
  rigid["contacts"] = contacts_json(r.contacts, u);
  rigid["steady"] = steady_json(r.steady, u);
  if (folder.in_memory()) return;  // the time histories are formatted only to be written

  std::vector<std::string> h = {report::column("time", u.label(Quantity::time))};
  for (std::size_t c = 0; c < r.coordinates.size(); ++c) h.push_back(report::column(r.coordinates[c], u.label(r.coordinate_quantities[c])));
  // A dimensionless series (the plow force's angle, in degrees) is named without a unit.
  for (const coupling::Series& series : r.series)
    h.push_back(series.quantity == Quantity::dimensionless ? series.name : report::column(series.name, u.label(series.quantity)));
  report::CsvTable csv(h);
  for (std::size_t i = 0; i < tr.time.size(); ++i) {
    csv.row().add(tr.time[i]);
    for (std::size_t c = 0; c < r.coordinates.size(); ++c) csv.add(u.from_si(tr.q[i](static_cast<Eigen::Index>(c)), r.coordinate_quantities[c]));
    for (const coupling::Series& series : r.series) csv.add(u.from_si(series.values[i], series.quantity));
  }
  folder.write_text("response.csv", csv.str());
  report::CsvTable ev({report::column("time", u.label(Quantity::time)), "event"});
  for (const auto& e : tr.events) ev.row().add(e.time).add(report::event_text(e, u));
  folder.write_text("events.csv", ev.str());
}

// The 2-D response's frame: with frame_output, the frame loads (frame_loads.csv) and the stress
// resultants of Eq. 2.47 with the rail's top-fiber stress (frame_resultants.csv, rigid.frame).
void add_frame_output_2d(const coupling::RigidStudy& study, const coupling::RigidResults& r, const core::ResultsFolder& folder, nlohmann::ordered_json& rigid) {
  if (!r.resultants) return;
  const core::UnitSystem& u = study.units;
  const rigid::Trajectory& tr = r.trajectory;
  const bool tables = !folder.in_memory();
  const std::string F = u.label(Quantity::force), M = u.label(Quantity::moment), L = u.label(Quantity::length);
  const double lf = 1.0 / u.to_si_factor(Quantity::length), ff = 1.0 / u.to_si_factor(Quantity::force);
  const double mf = 1.0 / u.to_si_factor(Quantity::moment), sf = 1.0 / u.to_si_factor(Quantity::stress);
  std::vector<std::string> lh = {report::column("time", u.label(Quantity::time))};
  for (const coupling::FrameLoad2D& l : r.frame_loads_2d)
    for (const char* c : {"_fx", "_fz", "_my"}) lh.push_back(report::column(l.name + c, std::string(c) == "_my" ? M : F));
  report::CsvTable lcsv(lh);
  for (std::size_t i = 0; tables && i < tr.time.size(); ++i) {
    lcsv.row().add(tr.time[i]);
    for (const coupling::FrameLoad2D& l : r.frame_loads_2d) lcsv.add(l.force[i].x() * ff).add(l.force[i].y() * ff).add(l.moment[i] * mf);
  }
  if (tables) folder.write_text("frame_loads.csv", lcsv.str());
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
  for (std::size_t i = 0; tables && i < tr.time.size(); ++i)
    for (std::size_t k = 0; k < sr.output_x.size(); ++k) {
      rcsv.row().add(tr.time[i]).add(sr.output_x[k] * lf).add(sr.srx[i][k] * ff).add(sr.srz[i][k] * ff).add(sr.srmy[i][k] * mf);
      if (stress) rcsv.add(r.rail_top_stress[i][k] * sf);
    }
  if (tables) folder.write_text("frame_resultants.csv", rcsv.str());
  rigid["frame"] = {{"units", {{"x", L}, {"force", F}, {"moment", M}, {"stress", u.label(Quantity::stress)}}},
                    {"loads", [&] {
                       std::vector<std::string> names;
                       for (const auto& l : r.frame_loads_2d) names.push_back(l.name);
                       return names;
                     }()},
                    {"output_points", points}};
}

// The 3-D response's frame loads at the load points 24-31 and the attachment's at point 19
// (frame_loads.csv, rigid.frame_loads' peaks) and, with figures, the load-point figures (Figures 22-24).
void add_load_points_3d(const coupling::RigidStudy& study, const coupling::RigidResults& r, const StudyRunOptions& options,
                        const core::ResultsFolder& folder, nlohmann::ordered_json& rigid, StudyRun& run) {
  if (!r.frame_loads_3d) return;
  const core::UnitSystem& u = study.units;
  const double lf = 1.0 / u.to_si_factor(Quantity::length), ff = 1.0 / u.to_si_factor(Quantity::force), mf = 1.0 / u.to_si_factor(Quantity::moment);
  if (!folder.in_memory()) folder.write_text("frame_loads.csv", coupling::format_load_history(coupling::all_frame_loads(*r.frame_loads_3d), u));
  if (options.figures) {
    const std::vector<std::string> drawn = write_load_point_figures(r.frame_loads_3d->points, study.attachment(), study.name, u, folder);
    run.figures.insert(run.figures.end(), drawn.begin(), drawn.end());
  }
  nlohmann::ordered_json loads;
  for (const coupling::LoadPointHistory* at : coupling::frame_load_points(*r.frame_loads_3d)) {
    const coupling::LoadPointHistory& p = *at;
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

// The frame block's keys that come from the frame's modes, loads and rails (report::frame_summary and
// frame.steady), none from its stress histories or hot spots.
bool frame_key_without_hot_spots(const std::string& key) {
  static const std::set<std::string> keys = {"model", "mesh", "supports", "method", "nodes", "elements", "output_times", "modes",
                                             "support", "load_points", "constant_loads", "free_rigid_motions", "parts", "total_mass",
                                             "structure", "peak_bending_moment", "peak_bending_moment_components", "peak_normal_stress",
                                             "rails", "static", "peak_total_normal_stress", "outputs", "steady"};
  return keys.count(key) > 0;
}

// Whether a summary read only at `paths` (StudyRunOptions::summary_outputs) needs the frame's hot spots:
// a path outside input, rigid and those frame keys does (frame.hot_spots, frame.peak_von_mises,
// frame.compared_supports, fatigue, warnings, and any path this does not recognise).
bool summary_needs_hot_spots(const std::vector<std::string>& paths) {
  for (const std::string& path : paths) {
    const std::optional<std::vector<coupling::KeyPathStep>> steps = coupling::parse_key_path(path);
    if (!steps || steps->size() < 2 || steps->front().is_item) return true;
    const std::string& top = steps->front().key;
    if (top == "input" || top == "rigid") continue;
    const coupling::KeyPathStep& second = (*steps)[1];  // frame.KEY, or frame[KEY] (a map's item by name)
    const std::string key = !second.is_item ? second.key : second.by_name ? second.name : std::string();
    if (top != "frame" || !frame_key_without_hot_spots(key)) return true;
  }
  return false;
}

// Whether a summary read only at `paths` needs the frame at all: a path outside `input` and `rigid` does
// (the frame and fatigue blocks, warnings, and any path this does not recognise).
bool summary_needs_frame(const std::vector<std::string>& paths) {
  for (const std::string& path : paths) {
    const std::optional<std::vector<coupling::KeyPathStep>> steps = coupling::parse_key_path(path);
    if (!steps || steps->empty() || steps->front().is_item) return true;
    if (steps->front().key != "input" && steps->front().key != "rigid") return true;
  }
  return false;
}

// After the rigid block and its warnings, 3-D: the pipeline, this run's frame loads into the beam model
// of the frame (summary frame and fatigue blocks, the frame's files and figures).
void run_pipeline(const coupling::RigidStudy& study, const coupling::RigidResults& r, const StudyRunOptions& options, const Stage& stage,
                  core::ResultsFolder& folder, nlohmann::ordered_json& j, StudyRun& run, StudyRunDetails& details) {
  if (!study.frame_response) return;
  // A summary read only in its input and rigid blocks, in memory (a design whose outputs are all the
  // vehicle's, a sweep): the frame is not run at all.
  if (!options.out && options.summary_outputs && !summary_needs_frame(*options.summary_outputs)) return;
  const core::UnitSystem& u = study.units;
  // Every load on the frame (points 24-31 and the attachment's at point 19).
  const coupling::LoadHistory loads = coupling::all_frame_loads(*r.frame_loads_3d);
  stage("frame transient (pipeline)");
  const coupling::LoadHistory static_loads = coupling::all_frame_loads(*r.static_frame_loads_3d);  // at the static equilibrium
  // A summary read only where no hot spot shows, in memory: the frame's stress histories are skipped.
  const bool hot_spots = options.out || !options.summary_outputs || summary_needs_hot_spots(*options.summary_outputs);
  std::optional<coupling::FrameStudyRequest> summary_only;
  if (!hot_spots) {
    summary_only = *study.frame_response;
    summary_only->hot_spots = false;
  }
  details.frame = coupling::run_frame_study(summary_only ? *summary_only : *study.frame_response, &loads, &static_loads, r.steady.operation.reached_at,
                                            options.frame_cache);
  const coupling::FrameStudyResults& frame = *details.frame;
  stage("writing results (frame)");
  if (!folder.in_memory()) report::write_frame_outputs(frame, *study.frame_response, folder, options.step);
  j["frame"] = report::frame_summary(frame, *study.frame_response);
  j["frame"]["steady"] = frame_steady_json(frame, r.steady.operation.reached_at, u);
  if (frame.life) j["fatigue"] = report::fatigue_summary(frame, *study.frame_response);
  add_warnings(j, coupling::frame_warnings(frame, *study.frame_response), options.warning);
  // The same loads on the supports compared (frame_response.compare_supports), each run on its own (one
  // assembly and factorisation per support): their peaks in the summary, their envelopes in one figure.
  std::vector<coupling::FrameStudyResults> compared;
  for (const coupling::FrameSupports s : study.frame_response->compare_supports) {
    stage(fmt::format("frame transient (pipeline, supports: {})", coupling::supports_name(s)));
    coupling::FrameStudyRequest cq = *study.frame_response;
    cq.supports = s;
    cq.compare_supports.clear();
    cq.paraview = coupling::ParaviewOutput::none;
    cq.fatigue.reset();  // the life map is the run's own support's
    cq.stress_histories = coupling::FrameStudyRequest::StressHistoryOutput::none;
    cq.hot_spots = hot_spots;
    compared.push_back(coupling::run_frame_study(cq, &loads, &static_loads, r.steady.operation.reached_at, options.frame_cache));
    const nlohmann::ordered_json full = report::frame_summary(compared.back(), cq);
    nlohmann::ordered_json c = {{"support", full["support"]}, {"rails", full["rails"]}};
    for (const char* key : {"peak_bending_moment", "peak_von_mises", "static"})
      if (full.contains(key)) c[key] = full[key];
    j["frame"]["compared_supports"].push_back(c);
  }
  // The shaker near an elastic mode of the frame model (Eq. 8.3's band, on the beam model's modes).
  if (study.attachment() == rigid::Attachment::plow) {
    const std::vector<double> frame_hz(frame.frequencies_hz.data(), frame.frequencies_hz.data() + frame.frequencies_hz.size());
    add_warnings(j, coupling::frame_resonance_warnings(study.shaker_frequency(), frame_hz, study.frame_response->mesh.filename().string()),
                 options.warning);
  }
  if (!options.figures) return;
  write_rail_moment_figure(frame, u, folder);
  run.figures.push_back("fig25_rail_bending_moment.png");
  if (!compared.empty()) {
    write_support_comparison_figure(frame, *study.frame_response, compared, u, folder);
    run.figures.push_back("frame_supports_envelopes.png");
  }
  if (!frame.hot_spots.by_von_mises.empty()) {
    report::write_png(report::hot_spot_stress_figure(frame, u), folder.path_of("frame_hot_spots.png"));
    run.figures.push_back("frame_hot_spots.png");
  }
  if (frame.life) {
    const report::LinePlot life = report::life_along_rails_figure(frame, u);
    if (!life.series.empty()) {  // no station with damage: nothing to draw on a log axis
      report::write_png(life, folder.path_of("frame_life.png"));
      run.figures.push_back("frame_life.png");
    }
  }
  if (frame.mode_shapes.cols() > 0) {
    const std::vector<double> hz(frame.frequencies_hz.data(), frame.frequencies_hz.data() + std::min<Eigen::Index>(frame.frequencies_hz.size(), frame.mode_shapes.cols()));
    report::write_png(report::mode_shape_figure(frame.model, frame.mode_shapes, hz,
                                                fmt::format("Frame model's lowest elastic modes ({}, supports: {})", study.frame_response->mesh.filename().string(),
                                                            coupling::supports_name(study.frame_response->supports))),
                      folder.path_of("frame_mode_shapes.png"));
    run.figures.push_back("frame_mode_shapes.png");
  }
}

// model: rigid_2d or rigid_3d, one reader, one runner and one set of writers for both: read, run
// (modes with their dominant coordinates, a forced response with recovered forces), then the summary,
// rigid_modes.csv, response.csv and events.csv, and the frame: 2-D the frame_output block's loads and
// resultants and the response figures; 3-D the frame loads at the load points and the pipeline.
StudyRun run_vehicle(const YAML::Node& doc, const std::filesystem::path& file, const StudyRunOptions& options, const Stage& stage) {
  const std::string file_s = file.string();
  stage("reading " + file_s);
  const coupling::RigidStudy study = coupling::read_rigid_study(doc, file_s);
  StudyRun run;
  run.model = study.model();
  stage(running_stage(study));
  const coupling::RigidResults r = coupling::run_rigid_study(study);
  stage("writing results");
  const std::unique_ptr<core::ResultsFolder> folder_owner = results_folder(options, {file});
  core::ResultsFolder& folder = *folder_owner;

  nlohmann::ordered_json j;
  j["framedyn"] = {{"version", FRAMEDYN_VERSION}, {"command", "run"}};
  j["input"] = {{"study", file_s}, {"name", study.name}, {"units", study.units.name()}};
  nlohmann::ordered_json rigid = rigid_block(study, r, folder);
  if (study.response) {
    add_response(study, r, folder, rigid);
    if (study.dimensions() == 2) add_frame_output_2d(study, r, folder, rigid);
    else add_load_points_3d(study, r, options, folder, rigid, run);
  }
  j["rigid"] = rigid;
  add_warnings(j, r.warnings, options.warning);
  auto details = std::make_shared<StudyRunDetails>();
  details->study = study;
  details->results = r;
  if (study.dimensions() == 3) run_pipeline(study, r, options, stage, folder, j, run, *details);
  else if (options.figures) {
    stage("figures");
    run.figures = report::write_response_figures(study, r, folder);
  }
  run.summary = std::move(j);
  if (!folder.in_memory()) folder.write_text("summary.json", run.summary.dump(2) + "\n");
  folder.commit();
  run.details = std::move(details);
  return run;
}

// model: duty_cycle: every scenario's pipeline and the life map (coupling/duty_cycle.h).
StudyRun run_duty_cycle(const YAML::Node& doc, const std::filesystem::path& file, const StudyRunOptions& options,
                        const std::function<void(const std::string&)>& stage) {
  const std::string file_s = file.string();
  StudyRun run;
  run.model = "duty_cycle";
  stage("reading " + file_s);
  coupling::DutyCycleRequest q = coupling::read_duty_cycle(doc, file_s);
  std::vector<std::filesystem::path> inputs = {file};
  for (const coupling::DutyCycleScenarioSpec& s : q.scenarios) inputs.push_back(s.study);
  if (options.out) core::check_results_target(*options.out, inputs);
  coupling::DutyCycleResults r = coupling::run_duty_cycle(q, stage, options.threads);
  stage("writing results");
  if (options.out) {
    core::ResultsFolder folder(*options.out, inputs);
    run.figures = write_duty_cycle_outputs(file_s, q, r, options.figures, folder);
    folder.commit();
  }
  run.summary = duty_cycle_summary(file_s, q, r);
  auto details = std::make_shared<StudyRunDetails>();
  details->duty_cycle = std::move(q);
  details->duty_cycle_results = std::move(r);
  run.details = std::move(details);
  return run;
}

}  // namespace

StudyRun run_study_document(const YAML::Node& doc, const std::filesystem::path& file, const StudyRunOptions& options) {
  if (options.figures && !options.out) throw std::invalid_argument("run_study_document: figures need a results folder (out)");
  if (options.figures) require_gnuplot();
  if (options.out) core::check_results_target(*options.out, {file});  // before the run: a refusal costs no time
  const std::function<void(const std::string&)> stage = options.stage ? options.stage : [](const std::string&) {};
  const std::string model = coupling::study_model(doc, file.string());
  if (model == "duty_cycle") return run_duty_cycle(doc, file, options, stage);  // issue 18
  // rigid_2d and rigid_3d; read_rigid_study refuses any other model
  return run_vehicle(doc, file, options, stage);
}

StudyRun run_study_file(const std::filesystem::path& file, const StudyRunOptions& options) {
  return run_study_document(coupling::load_yaml_file(file.string()), file, options);
}

}  // namespace framedyn::report
