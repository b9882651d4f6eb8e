// The frame transient study's outputs; see frame_outputs.h.
#include "report/frame_outputs.h"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <thread>
#include <tuple>

#include "core/number_text.h"
#include "fem/quadratic_beam_element.h"
#include "coupling/frame_parts.h"
#include "fem/section_forces.h"
#include "fem/section_stress.h"
#include "report/csv_writer.h"
#include "report/json_quantity.h"
#include "report/vtu_writer.h"
#include "report/fatigue_outputs.h"
#include "report/frame_parts_json.h"
#include "report/xdmf_writer.h"

namespace framedyn::report {

using coupling::FrameStudyRequest;
using coupling::FrameStudyResults;
using coupling::FrameSupports;
using coupling::NodalHistory;
using coupling::NodalPeak;
using coupling::MappedLoadPoint;
using coupling::RailPeak;
using coupling::RailRecovery;
using coupling::SectionHistory;

namespace {

// frame_stress_histories.csv (frame.stress_histories: hot_spots or all): per
// location (station and section point), one row per output time, of the
// total state (static + dynamic; docs/theory/coupling.md section 10).
void write_stress_histories(const FrameStudyResults& r, const FrameStudyRequest& q, const core::ResultsFolder& folder) {
  using Output = FrameStudyRequest::StressHistoryOutput;
  if (q.stress_histories == Output::none) return;
  const coupling::StressHistories& h = r.stress;
  std::vector<std::pair<std::size_t, int>> locations;  // (station, point)
  if (q.stress_histories == Output::all) {
    for (std::size_t s = 0; s < h.stations.size(); ++s)
      for (std::size_t p = 0; p < h.points[static_cast<std::size_t>(h.stations[s].section)].size(); ++p) locations.emplace_back(s, static_cast<int>(p));
  } else {
    for (const auto* list : {&r.hot_spots.by_von_mises, &r.hot_spots.by_normal_range})
      for (const coupling::HotSpot& x : *list)
        if (std::find(locations.begin(), locations.end(), std::pair{x.station, x.point}) == locations.end()) locations.emplace_back(x.station, x.point);
  }
  const core::UnitSystem& u = q.units;
  using core::Quantity;
  const double lf = 1.0 / u.to_si_factor(Quantity::length), sf = 1.0 / u.to_si_factor(Quantity::stress);
  const std::string L = u.label(Quantity::length), S = u.label(Quantity::stress);
  report::CsvTable t({report::column("time", u.label(Quantity::time)), "set", "element", "station", report::column("X", L), report::column("Y", L),
                      report::column("Z", L), "point", report::column("normal_stress", S), report::column("shear_stress", S),
                      report::column("von_mises", S)});
  for (const auto& [s, p] : locations) {
    const coupling::StressStation& st = h.stations[s];
    const std::size_t sec = static_cast<std::size_t>(st.section);
    const fem::SectionPoint& point = h.points[sec][static_cast<std::size_t>(p)];
    const std::vector<fem::PointStress> history = coupling::point_stress_history(h, s, p, &r.static_forces);
    for (Eigen::Index j = 0; j < h.times.size(); ++j) {
      const fem::PointStress& ps = history[static_cast<std::size_t>(j)];
      t.row().add(h.times(j)).add(st.set).add(st.element_id).add(st.station).add(st.point.x() * lf).add(st.point.y() * lf).add(st.point.z() * lf)
          .add(point.name).add(ps.normal * sf).add(ps.shear * sf).add(ps.von_mises * sf);
    }
  }
  folder.write_text("frame_stress_histories.csv", t.str());
}

}  // namespace

void write_frame_outputs(const FrameStudyResults& r, const FrameStudyRequest& q, const core::ResultsFolder& folder,
                         const std::function<void(int, int)>& written) {
  const core::UnitSystem& u = q.units;
  using core::Quantity;
  const double lf = 1.0 / u.to_si_factor(Quantity::length), mf = 1.0 / u.to_si_factor(Quantity::moment),
               sf = 1.0 / u.to_si_factor(Quantity::stress);
  const std::string T = report::column("time", u.label(Quantity::time));
  {
    report::CsvTable t({"mode", report::column("frequency", u.label(Quantity::frequency)), "damping_ratio"});
    for (Eigen::Index i = 0; i < r.frequencies_hz.size(); ++i) {
      t.row().add(static_cast<int>(i + 1)).add(r.frequencies_hz(i));
      if (i < r.response.damping_ratios.size()) t.add(r.response.damping_ratios(i));
      else t.add(q.damping.ratio_of(static_cast<int>(i), 6.283185307179586 * r.frequencies_hz(i)));
    }
    folder.write_text("frame_modes.csv", t.str());
  }
  // The parts the frame model carried, as an .inp fragment to include after the mesh (coupling/frame_parts.h).
  if (!r.parts.empty()) folder.write_text("frame_parts.inp", coupling::frame_parts_inp(r.model, r.parts));
  // With the dead load (static plus dynamic, coupling/frame_dead_load.h): static and total columns after the dynamic ones.
  const bool statics = !r.rails.empty() && r.rails.front().has_static();
  const std::string S = u.label(Quantity::stress);
  if (!r.rails.empty()) {
    std::vector<std::string> h = {"rail", "element", "station", report::column("X", u.label(Quantity::length)), report::column("Y", u.label(Quantity::length)),
                                  report::column("Z", u.label(Quantity::length)), report::column("max_bending_moment", u.label(Quantity::moment)),
                                  report::column("max_abs_Mz", u.label(Quantity::moment)), report::column("max_abs_My", u.label(Quantity::moment)),
                                  report::column("max_abs_normal_stress", S)};
    if (statics) {
      h.push_back(report::column("static_max_abs_normal_stress", S));
      h.push_back(report::column("total_max_abs_normal_stress", S));
    }
    report::CsvTable t(h);
    for (const RailRecovery& rail : r.rails)
      for (std::size_t k = 0; k < rail.station_points.size(); ++k) {
        const Eigen::Index i = static_cast<Eigen::Index>(k);
        t.row().add(rail.spec.name).add(rail.station_element_ids[k]).add(static_cast<int>(k % static_cast<std::size_t>(q.stations)))
            .add(rail.station_points[k].x() * lf).add(rail.station_points[k].y() * lf).add(rail.station_points[k].z() * lf)
            .add(rail.envelope_bending_moment(i) * mf).add(rail.envelope_mz(i) * mf).add(rail.envelope_my(i) * mf)
            .add(rail.envelope_normal_stress(i) * sf);
        if (statics) t.add(rail.static_normal_stress(i) * sf).add(rail.envelope_total_normal_stress(i) * sf);
      }
    folder.write_text("frame_rails_envelope.csv", t.str());
  }
  if (!r.rails.empty()) {
    std::vector<std::string> h = {T};
    for (const RailRecovery& rail : r.rails) {
      h.push_back(report::column(rail.spec.name + ".max_bending_moment", u.label(Quantity::moment)));
      h.push_back(report::column(rail.spec.name + ".max_abs_normal_stress", S));
    }
    if (statics)
      for (const RailRecovery& rail : r.rails) {
        h.push_back(report::column(rail.spec.name + ".static_max_abs_normal_stress", S));
        h.push_back(report::column(rail.spec.name + ".total_max_abs_normal_stress", S));
      }
    report::CsvTable t(h);
    for (Eigen::Index j = 0; j < r.response.times.size(); ++j) {
      t.row().add(r.response.times(j));
      for (const RailRecovery& rail : r.rails) t.add(rail.series_bending_moment(j) * mf).add(rail.series_normal_stress(j) * sf);
      if (statics)
        for (const RailRecovery& rail : r.rails) t.add(rail.static_normal_stress.maxCoeff() * sf).add(rail.series_total_normal_stress(j) * sf);
    }
    folder.write_text("frame_rails_series.csv", t.str());
  }
  // Section-force histories of the element sets that ask for them, one row per output time and station.
  const double ff = 1.0 / u.to_si_factor(Quantity::force);
  for (std::size_t k = 0; k < r.rails.size() && k < r.sections.size(); ++k) {
    const SectionHistory& h = r.sections[k];
    if (!q.rails[k].history) continue;
    const std::string F = u.label(Quantity::force), M = u.label(Quantity::moment);
    report::CsvTable t({T, "element", "station", report::column("x", u.label(Quantity::length)), report::column("N", F), report::column("Vy", F),
                      report::column("Vz", F), report::column("T", M), report::column("My", M), report::column("Mz", M),
                      report::column("max_abs_normal_stress", u.label(Quantity::stress))});
    const Eigen::Index ns = static_cast<Eigen::Index>(h.element_ids.size());
    for (Eigen::Index j = 0; j < r.response.times.size(); ++j)
      for (Eigen::Index s = 0; s < ns; ++s) {
        const auto v = h.values.row(j * ns + s);
        t.row().add(r.response.times(j)).add(h.element_ids[static_cast<std::size_t>(s)]).add(h.station_index[static_cast<std::size_t>(s)])
            .add(h.station_x[static_cast<std::size_t>(s)] * lf).add(v(0) * ff).add(v(1) * ff).add(v(2) * ff).add(v(3) * mf).add(v(4) * mf)
            .add(v(5) * mf).add(v(6) * sf);
      }
    folder.write_text("frame_sections_" + q.rails[k].name + ".csv", t.str());
  }
  // Nodal histories, one row per output time and node: displacement, velocity, acceleration per DOF.
  for (const NodalHistory& h : r.nodal) {
    const std::string L = u.label(Quantity::length);
    std::vector<std::string> head = {T, "node"};
    const char* names[6] = {"X", "Y", "Z", "RX", "RY", "RZ"};
    const bool rates = h.velocity.size() > 0;
    for (int d = 0; d < 6; ++d) head.push_back(report::column(std::string("U") + names[d], d < 3 ? L : u.label(Quantity::angle)));
    if (rates) {
      for (int d = 0; d < 6; ++d) head.push_back(report::column(std::string("V") + names[d], u.label(d < 3 ? Quantity::velocity : Quantity::angular_velocity)));
      for (int d = 0; d < 6; ++d) head.push_back(report::column(std::string("A") + names[d], u.label(d < 3 ? Quantity::acceleration : Quantity::angular_acceleration)));
    }
    report::CsvTable t(head);
    for (Eigen::Index j = 0; j < r.response.times.size(); ++j)
      for (std::size_t n = 0; n < h.nodes.size(); ++n) {
        t.row().add(r.response.times(j)).add(h.node_ids[n]);
        const Eigen::Index row = fem::kDofsPerNode * static_cast<Eigen::Index>(n);
        for (int d = 0; d < 6; ++d) t.add(h.displacement(row + d, j) * (d < 3 ? lf : 1.0));
        if (rates) {
          for (int d = 0; d < 6; ++d) t.add(h.velocity(row + d, j) * (d < 3 ? lf : 1.0));
          for (int d = 0; d < 6; ++d) t.add(h.acceleration(row + d, j) * (d < 3 ? lf : 1.0));
        }
      }
    folder.write_text("frame_nodes_" + h.spec.name + ".csv", t.str());
  }
  write_stress_histories(r, q, folder);
  write_life_map(r, q, folder);
  if (q.paraview == coupling::ParaviewOutput::none) return;
  // ParaView time series: the same fields per output time in either format.
  const fem::FrameModel& m = r.model;
  std::vector<fem::BeamGeometry> geometry;
  for (const fem::BeamElement& b : m.beams) geometry.push_back(fem::beam_geometry(m, b));
  // The life map (when the study asks for fatigue): constant cell fields on every step, so ParaView
  // shows the life beside the stresses (docs/user-guide.md "Fatigue").
  const std::vector<VtuField> life_fields = r.life && q.fatigue ? life_cell_fields(m, r.stress, r.life->damage_per_hour) : std::vector<VtuField>{};
  // Point fields (displacement, rotation) and cell fields (peak stress, moment, mid-length axial force; the life map) at output time j.
  const auto frame_fields = [&](Eigen::Index j) -> std::pair<std::vector<VtuField>, std::vector<VtuField>> {
    const Eigen::VectorXd uj = r.response.displacement.col(j);
    report::VtuField disp{fmt::format("displacement [{}]", u.label(Quantity::length)), 3, {}};
    report::VtuField rot{fmt::format("rotation [{}]", u.label(Quantity::angle)), 3, {}};
    for (std::size_t n = 0; n < m.nodes.size(); ++n)
      for (int d = 0; d < 3; ++d) {
        disp.values.push_back(uj(fem::kDofsPerNode * static_cast<Eigen::Index>(n) + d) * lf);
        rot.values.push_back(uj(fem::kDofsPerNode * static_cast<Eigen::Index>(n) + 3 + d));
      }
    report::VtuField stress{fmt::format("max_abs_normal_stress [{}]", u.label(Quantity::stress)), 1, {}};
    report::VtuField moment{fmt::format("max_bending_moment [{}]", u.label(Quantity::moment)), 1, {}};
    report::VtuField axial{fmt::format("axial_force_mid [{}]", u.label(Quantity::force)), 1, {}};
    for (std::size_t e = 0; e < m.beams.size(); ++e) {
      if (m.beams[e].is_quadratic()) {  // three-node beams (B32, B32R): stations by statics of their nodal forces
        double smax = 0.0, mmax = 0.0;
        for (const fem::StationResult& st : fem::quadratic_beam_stations(m, m.beams[e], uj, q.stations)) {
          mmax = std::max(mmax, std::hypot(st.forces.my, st.forces.mz));
          for (double v : st.fiber_stress) smax = std::max(smax, std::abs(v));
        }
        stress.values.push_back(smax * sf);
        moment.values.push_back(mmax * mf);
        axial.values.push_back(fem::quadratic_beam_stations(m, m.beams[e], uj, 3)[1].forces.n / u.to_si_factor(Quantity::force));
        continue;
      }
      const fem::Vector12d f = fem::element_end_forces(geometry[e], m.beams[e], uj);
      double smax = 0.0, mmax = 0.0;
      for (int s = 0; s < q.stations; ++s) {
        const fem::SectionForces sfc = fem::section_forces_at(f, geometry[e].data.length * s / (q.stations - 1));
        mmax = std::max(mmax, std::hypot(sfc.my, sfc.mz));
        for (double v : fem::fiber_stresses(geometry[e].data.section, sfc)) smax = std::max(smax, std::abs(v));
      }
      stress.values.push_back(smax * sf);
      moment.values.push_back(mmax * mf);
      axial.values.push_back(fem::section_forces_at(f, 0.5 * geometry[e].data.length).n / u.to_si_factor(Quantity::force));
    }
    std::vector<VtuField> cells = {stress, moment, axial};
    cells.insert(cells.end(), life_fields.begin(), life_fields.end());
    return {{disp, rot}, cells};
  };
  const Eigen::Index frames = r.response.times.size();
  if (q.paraview == coupling::ParaviewOutput::xdmf) {
    // frame_response.xdmf + frame_response.h5: the fields of the next output
    // time are computed on a second thread while this one writes (HDF5's
    // serial library takes one writer).
    XdmfSeries series(folder, "frame_response", m, lf, static_cast<int>(frames));
    std::pair<std::vector<VtuField>, std::vector<VtuField>> current;
    if (frames > 0) current = frame_fields(0);
    for (Eigen::Index j = 0; j < frames; ++j) {
      std::pair<std::vector<VtuField>, std::vector<VtuField>> next;
      std::exception_ptr failure;
      std::thread ahead;
      if (j + 1 < frames)
        ahead = std::thread([&] {
          try {
            next = frame_fields(j + 1);
          } catch (...) {
            failure = std::current_exception();
          }
        });
      try {
        series.add(r.response.times(j), current.first, current.second);
      } catch (...) {
        if (ahead.joinable()) ahead.join();
        throw;
      }
      if (ahead.joinable()) ahead.join();
      if (failure) std::rethrow_exception(failure);
      current = std::move(next);
      if (written) written(static_cast<int>(j + 1), static_cast<int>(frames));
    }
    series.finish();
    return;
  }
  // One VTU per output time, built and written on two threads (the files are
  // independent, so the bytes do not depend on the order), and a PVD
  // collection naming them.
  const auto write_frame = [&](Eigen::Index j) {
    const auto [points, cells] = frame_fields(j);
    folder.write_text(fmt::format("frame_response_{:05d}.vtu", j), report::vtu_document(m, lf, points, cells));
  };
  // Progress: the writing thread below counts, this one reports (the callback need not be thread-safe).
  std::atomic<int> done{0};
  const auto write_counted = [&](Eigen::Index j) {
    write_frame(j);
    ++done;
  };
  std::exception_ptr failure;
  std::thread second([&] {
    try {
      for (Eigen::Index j = 1; j < frames; j += 2) write_counted(j);
    } catch (...) {
      failure = std::current_exception();
    }
  });
  try {
    for (Eigen::Index j = 0; j < frames; j += 2) {
      write_counted(j);
      if (written) written(done.load(), static_cast<int>(frames));
    }
  } catch (...) {
    second.join();
    throw;
  }
  second.join();
  if (failure) std::rethrow_exception(failure);
  std::string pvd = "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n  <Collection>\n";
  for (Eigen::Index j = 0; j < frames; ++j)
    pvd += fmt::format("    <DataSet timestep=\"{}\" group=\"\" part=\"0\" file=\"frame_response_{:05d}.vtu\"/>\n",
                       core::format_number(r.response.times(j)), j);
  pvd += "  </Collection>\n</VTKFile>\n";
  folder.write_text("frame_response.pvd", pvd);
}

namespace {

// frame.hot_spots, frame.hot_spots_by_normal_stress_range, frame.peak_von_mises and
// frame.hot_spot_window (docs/theory/coupling.md section 10), in the study's units.
void add_hot_spots(nlohmann::ordered_json& j, const FrameStudyResults& r, const FrameStudyRequest& q) {
  using nlohmann::ordered_json;
  using core::Quantity;
  const core::UnitSystem& u = q.units;
  const coupling::HotSpotReport& h = r.hot_spots;
  const std::string S = u.label(Quantity::stress), L = u.label(Quantity::length), T = u.label(Quantity::time);
  const auto stress = [&](double v) { return u.from_si(v, Quantity::stress); };
  const auto where = [&](const coupling::HotSpot& x) {
    const coupling::StressStation& st = r.stress.stations[x.station];
    return ordered_json{{"set", st.set},
                        {"element", st.element_id},
                        {"station", st.station},
                        {"X", {{"value", u.from_si(st.point.x(), Quantity::length)}, {"unit", L}}},
                        {"Y", {{"value", u.from_si(st.point.y(), Quantity::length)}, {"unit", L}}},
                        {"Z", {{"value", u.from_si(st.point.z(), Quantity::length)}, {"unit", L}}},
                        {"point", x.point_name}};
  };
  const auto spot = [&](const coupling::HotSpot& x) {
    ordered_json o = where(x);
    o["von_mises"] = {{"static", stress(x.von_mises_static)}, {"dynamic", stress(x.von_mises_dynamic)}, {"total", stress(x.von_mises_total)}, {"unit", S}};
    o["normal_stress_range"] = {{"value", stress(x.normal_stress_range)}, {"unit", S}};
    o["time"] = {{"value", x.time}, {"unit", T}};
    o["startup_peak_von_mises"] = {{"value", stress(x.startup_peak_von_mises)}, {"unit", S}, {"time", {{"value", x.startup_time}, {"unit", T}}}};
    return o;
  };
  if (r.stress.stations.empty()) return;
  ordered_json by_vm = ordered_json::array(), by_range = ordered_json::array();
  for (const coupling::HotSpot& x : h.by_von_mises) by_vm.push_back(spot(x));
  for (const coupling::HotSpot& x : h.by_normal_range) by_range.push_back(spot(x));
  j["hot_spots"] = by_vm;
  j["hot_spots_by_normal_stress_range"] = by_range;
  if (h.peak.point_name.empty()) return;  // no section points (GENERAL sections only): no peak to name
  const bool in_startup = h.startup_times > 0 && h.peak.time < h.window.from;
  j["peak_von_mises"] = {{"value", stress(h.peak.von_mises_total)},
                         {"unit", S},
                         {"where", where(h.peak)},
                         {"when", {{"value", h.peak.time}, {"unit", T}}},
                         {"in", in_startup ? "start-up" : "steady operation"}};
  j["hot_spot_window"] = {
      {"steady_from", {{"value", h.window.from}, {"unit", T}}},
      {"source", h.window.source},
      {"startup_times", h.startup_times},
      {"steady_times", h.steady_times},
      {"startup_peak_von_mises", {{"value", stress(h.startup_peak.von_mises_total)}, {"unit", S}}},
      {"steady_peak_von_mises", {{"value", stress(h.steady_peak.von_mises_total)}, {"unit", S}}},
      {"static_state", r.static_forces.empty() ? "zero: no static state computed, total = dynamic" : "static section forces added: total = static + dynamic"},
      {"stress_histories_in_memory_bytes", h.memory_bytes},
      {"ranked_by", "each station's worst section point; ties within 1e-6 go to the lower station, point and time"}};
}

}  // namespace

LinePlot hot_spot_stress_figure(const FrameStudyResults& r, const core::UnitSystem& u, int count) {
  using core::Quantity;
  const coupling::HotSpotReport& h = r.hot_spots;
  LinePlot plot;
  plot.title = fmt::format("von Mises stress (static + dynamic) at the top hot spots; steady from t = {:.3g} s", h.window.from);
  plot.x_label = "time";
  plot.x_unit = u.label(Quantity::time);
  plot.y_label = "von Mises stress";
  plot.y_unit = u.label(Quantity::stress);
  const std::vector<double> times(r.stress.times.data(), r.stress.times.data() + r.stress.times.size());
  for (std::size_t k = 0; k < h.by_von_mises.size() && static_cast<int>(k) < count; ++k) {
    const coupling::HotSpot& x = h.by_von_mises[k];
    const coupling::StressStation& st = r.stress.stations[x.station];
    PlotSeries series;
    series.name = fmt::format("{}: {} X = {:.4g} {}, {}", k + 1, st.set, u.from_si(st.point.x(), Quantity::length), u.label(Quantity::length),
                              x.point_name);
    series.x = times;
    for (const fem::PointStress& ps : coupling::point_stress_history(r.stress, x.station, x.point, &r.static_forces))
      series.y.push_back(u.from_si(ps.von_mises, Quantity::stress));
    plot.series.push_back(series);
  }
  return plot;
}

nlohmann::ordered_json frame_summary(const FrameStudyResults& r, const FrameStudyRequest& q) {
  using nlohmann::ordered_json;
  const core::UnitSystem& u = q.units;
  using core::Quantity;
  const double lf = 1.0 / u.to_si_factor(Quantity::length);
  // Every number as {value, unit} (report/json_quantity.h); strings (paths, names) escaped by nlohmann.
  auto peak = [&](const RailPeak& p, double value, Quantity q_value, const std::string& rail) {
    ordered_json j = quantity(u.from_si(value, q_value), u.label(q_value));
    j["rail"] = rail;
    j["element"] = p.element_id;
    j["station"] = p.station;
    j["x"] = quantity(p.point.x() * lf, u.label(Quantity::length));
    j["time"] = quantity(p.time, u.label(Quantity::time));
    return j;
  };
  ordered_json j;
  j["model"] = "frame_transient";
  j["mesh"] = q.mesh.string();
  j["supports"] = coupling::supports_name(q.supports);
  j["method"] = coupling::method_name(q.method);
  // No wall time here: the same study must give byte-identical files (the console prints it).
  j["nodes"] = r.model.nodes.size();
  j["elements"] = r.model.beams.size();
  j["output_times"] = r.response.times.size();
  ordered_json modes = ordered_json::array();
  for (Eigen::Index i = 0; i < r.frequencies_hz.size(); ++i) {
    const double zeta = i < r.response.damping_ratios.size() ? r.response.damping_ratios(i)
                                                             : q.damping.ratio_of(static_cast<int>(i), 6.283185307179586 * r.frequencies_hz(i));
    modes.push_back({{"mode", i + 1}, {"frequency", quantity(r.frequencies_hz(i), u.label(Quantity::frequency))}, {"damping_ratio", zeta}});
  }
  j["modes"] = modes;
  // The support used, and whether the real machine has it (see frame_warnings).
  {
    const bool clamp = q.supports == FrameSupports::fixed_rear_end || q.supports == FrameSupports::clamped;
    std::vector<int> supported;
    for (const fem::Constraint& c : r.model.constraints) supported.push_back(r.model.nodes[static_cast<std::size_t>(c.node)].id);
    std::sort(supported.begin(), supported.end());
    supported.erase(std::unique(supported.begin(), supported.end()), supported.end());
    const char* meaning = q.supports == FrameSupports::free_free_inertia_relief
                              ? "no supports: the loads are balanced by the frame model's rigid-body inertia (inertia relief)"
                          : q.supports == FrameSupports::axle_pins
                              ? "held statically determinately at the axle pins and the leveling cylinder, the loads (the pins' forces "
                                "included) balanced by the frame model's rigid-body inertia: the pins take no further reaction and the "
                                "stresses are those of supports: none (docs/theory/coupling.md, section 12)"
                          : clamp ? "all six DOFs of the support nodes fixed: a support the moving machine does not have (thesis parity)"
                                  : "the mesh's own *BOUNDARY (the supports the mesh's author gave)";
    j["support"] = {{"kind", coupling::supports_name(q.supports)},
                    {"node_sets", clamp ? q.support_sets : std::vector<std::string>{}},
                    {"nodes", supported},
                    {"artificial", clamp},
                    {"meaning", meaning}};
    if (!r.pin_supports.empty()) {
      std::vector<std::string> held;
      for (int g : r.pin_supports) held.push_back(r.model.describe_dof(g));
      j["support"]["held_at"] = held;  // the auxiliary supports, each with no reaction (section 12)
    }
  }
  // Every load applied to the frame model: where it is, how it reaches the mesh, its largest force and moment.
  ordered_json points = ordered_json::array();
  const std::string L = u.label(Quantity::length);
  for (std::size_t p = 0; p < r.mapping.points.size(); ++p) {
    const MappedLoadPoint& mp = r.mapping.points[p];
    std::vector<int> ids;
    for (int n : mp.nodes) ids.push_back(r.model.nodes[static_cast<std::size_t>(n)].id);
    ordered_json jp = {{"name", mp.name},
                       {"position", {{"value", {mp.location.x() * lf, mp.location.y() * lf, mp.location.z() * lf}}, {"unit", L}}},
                       {"at_node", mp.at_node},
                       {"node_set", mp.from_node_set},
                       {"nodes", ids},
                       {"spider_length", quantity(mp.spider_length * lf, L)}};
    if (p < r.loads.points.size()) {
      // Largest resultant |F| and |M| over the history, with when.
      const Eigen::MatrixXd& v = r.loads.points[p].values;
      Eigen::Index kf = 0, km = 0;
      for (Eigen::Index k = 1; k < v.rows(); ++k) {
        if (v.row(k).head<3>().norm() > v.row(kf).head<3>().norm()) kf = k;
        if (v.row(k).tail<3>().norm() > v.row(km).tail<3>().norm()) km = k;
      }
      if (v.rows() > 0) {
        jp["peak_force"] = {{"value", u.from_si(v.row(kf).head<3>().norm(), Quantity::force)}, {"unit", u.label(Quantity::force)},
                            {"time", quantity(r.loads.times(kf), u.label(Quantity::time))}};
        jp["peak_moment"] = {{"value", u.from_si(v.row(km).tail<3>().norm(), Quantity::moment)}, {"unit", u.label(Quantity::moment)},
                             {"time", quantity(r.loads.times(km), u.label(Quantity::time))}};
      }
    }
    points.push_back(jp);
  }
  j["load_points"] = points;
  // The mesh's own loads, constant throughout (mesh_loads: constant).
  if (r.constant_load.size() > 0) {
    Eigen::Vector3d total = Eigen::Vector3d::Zero();
    for (Eigen::Index n = 0; n + 5 < r.constant_load.size(); n += 6) total += r.constant_load.segment<3>(n);
    const double ff = 1.0 / u.to_si_factor(Quantity::force);
    j["constant_loads"] = {{"source", q.mesh.filename().string()},
                           {"cload_entries", r.constant_cloads},
                           {"dload_beams", r.constant_dloads},
                           {"resultant_force", {{"value", {total.x() * ff + 0.0, total.y() * ff + 0.0, total.z() * ff + 0.0}}, {"unit", u.label(Quantity::force)}}},
                           {"meaning", "the mesh's *CLOAD and *DLOAD act at every time, added to the load history; the response starts from the "
                                       "static equilibrium under them and the history's first row"}};
  }  // absent: no constant load acted (a null would read as a broken-down number)
  if (r.free_rigid_motions > 0 && q.supports != coupling::FrameSupports::free_free_inertia_relief && q.supports != coupling::FrameSupports::axle_pins)
    j["free_rigid_motions"] = {{"count", r.free_rigid_motions},
                               {"meaning", "the supports leave these rigid motions free: the loads are relieved by their inertia and the "
                                           "displacements are the elastic part (as for supports: none)"}};
  // The parts on the frame model, its total mass and where the frame structure's mass came from (Eqs. 9.3, 9.4).
  {
    FramePartsSummary parts =
        frame_parts_summary(r.model, r.parts, r.mass, q.structure_part, q.structure_source, q.parts_carried_by_mesh, u);
    j["parts"] = std::move(parts.parts);
    j["total_mass"] = std::move(parts.total_mass);
    j["structure"] = std::move(parts.structure);
  }
  ordered_json moments = ordered_json::object(), components = ordered_json::object();
  const RailRecovery* worst = nullptr;
  for (const RailRecovery& rail : r.rails) {
    moments[rail.spec.name] = peak(rail.peak_bending_moment, rail.peak_bending_moment.value, Quantity::moment, rail.spec.name);
    components[rail.spec.name] = {{"mz", peak(rail.peak_mz, rail.peak_mz.value, Quantity::moment, rail.spec.name)},
                                  {"my", peak(rail.peak_my, rail.peak_my.value, Quantity::moment, rail.spec.name)}};
    if (!worst || std::abs(rail.peak_normal_stress.value) > std::abs(worst->peak_normal_stress.value)) worst = &rail;
  }
  j["peak_bending_moment"] = moments;
  j["peak_bending_moment_components"] = components;
  if (worst) {
    ordered_json stress = peak(worst->peak_normal_stress, worst->peak_normal_stress.value, Quantity::stress, worst->spec.name);
    stress["fiber"] = worst->peak_normal_stress.fiber;
    stress["bending_share"] = worst->bending_share;
    j["peak_normal_stress"] = stress;
    ordered_json rails = ordered_json::object();
    for (const RailRecovery& rail : r.rails)
      rails[rail.spec.name] = {{"peak_normal_stress", peak(rail.peak_normal_stress, rail.peak_normal_stress.value, Quantity::stress, rail.spec.name)},
                               {"bending_share", rail.bending_share}};
    j["rails"] = rails;
  }
  // Static plus dynamic (docs/theory/coupling.md, section 11).
  if (r.static_state) {
    const coupling::FrameStaticState& st = *r.static_state;
    ordered_json s;
    s["gravity"] = {{"value", {u.from_si(st.gravity.x(), Quantity::acceleration) + 0.0, u.from_si(st.gravity.y(), Quantity::acceleration) + 0.0,
                               u.from_si(st.gravity.z(), Quantity::acceleration) + 0.0}},
                    {"unit", u.label(Quantity::acceleration)}};
    s["weight"] = quantity(u.from_si(st.weight, Quantity::force), u.label(Quantity::force));
    ordered_json where = {{"rail", st.peak_output}, {"element", st.peak_normal_stress.element_id}, {"station", st.peak_normal_stress.station},
                          {"fiber", st.peak_normal_stress.fiber}, {"x", quantity(st.peak_normal_stress.point.x() * lf, L)}};
    s["peak_normal_stress"] = {{"value", u.from_si(st.peak_normal_stress.value, Quantity::stress)}, {"unit", u.label(Quantity::stress)}, {"where", where}};
    s["residual"] = {{"relative_force", st.force_residual},
                     {"relative_moment", st.moment_residual},
                     {"meaning", "|resultant force| / weight and |resultant moment about the c.g.| / (weight x the model's largest extent) of gravity "
                                 "plus the static loads (Eq. 11.3): round-off when the frame model carries the vehicle model's frame assembly"}};
    s["free_rigid_motions"] = st.free_rigid_motions;
    j["static"] = s;
    const RailRecovery* most = nullptr;  // the first rail whose total peak is within 1e-6 relative of the largest
    double largest = 0.0;
    for (const RailRecovery& rail : r.rails) largest = std::max(largest, std::abs(rail.peak_total_normal_stress.value));
    for (const RailRecovery& rail : r.rails)
      if (!most && std::abs(rail.peak_total_normal_stress.value) >= largest * (1.0 - 1e-6)) most = &rail;
    if (most) {
      ordered_json total = peak(most->peak_total_normal_stress, most->peak_total_normal_stress.value, Quantity::stress, most->spec.name);
      total["fiber"] = most->peak_total_normal_stress.fiber;
      total["meaning"] = "static + dynamic at every section point (Eq. 11.4); peak_normal_stress is the dynamic part alone";
      j["peak_total_normal_stress"] = total;
      for (const RailRecovery& rail : r.rails)
        j["rails"][rail.spec.name]["peak_total_normal_stress"] =
            peak(rail.peak_total_normal_stress, rail.peak_total_normal_stress.value, Quantity::stress, rail.spec.name);
    }
  }
  // Every output set by its name: where and when each quantity peaks.
  auto set_peak = [&](const RailPeak& p, Quantity qty) {
    return ordered_json{{"value", u.from_si(p.value, qty)}, {"unit", u.label(qty)}, {"element", p.element_id}, {"station", p.station},
                        {"time", quantity(p.time, u.label(Quantity::time))}};
  };
  auto nodal_peak = [&](const NodalPeak& p, double factor, const std::string& unit) {
    return ordered_json{{"value", p.value * factor}, {"unit", unit}, {"node", p.node_id}, {"dof", fem::dof_name(p.dof)}, {"time", quantity(p.time, u.label(Quantity::time))}};
  };
  ordered_json outputs = ordered_json::object();
  for (const RailRecovery& rail : r.rails) {
    const int stations = std::max(1, q.stations);
    outputs[rail.spec.name] = {{"kind", "element_set"},
                               {"set", rail.spec.element_set},
                               {"elements", rail.station_element_ids.size() / static_cast<std::size_t>(stations)},
                               {"peak_axial_force", set_peak(rail.peak_axial_force, Quantity::force)},
                               {"peak_shear_y", set_peak(rail.peak_shear_y, Quantity::force)},
                               {"peak_shear_z", set_peak(rail.peak_shear_z, Quantity::force)},
                               {"peak_torque", set_peak(rail.peak_torque, Quantity::moment)},
                               {"peak_my", set_peak(rail.peak_my, Quantity::moment)},
                               {"peak_mz", set_peak(rail.peak_mz, Quantity::moment)},
                               {"peak_bending_moment", set_peak(rail.peak_bending_moment, Quantity::moment)},
                               {"peak_normal_stress", set_peak(rail.peak_normal_stress, Quantity::stress)}};
  }
  for (const NodalHistory& h : r.nodal) {
    ordered_json o = {{"kind", "node_set"}, {"set", h.spec.node_set}, {"nodes", h.node_ids}};
    o["peak_displacement"] = nodal_peak(h.peak_displacement, lf, L);
    if (h.velocity.size() > 0) {
      o["peak_velocity"] = nodal_peak(h.peak_velocity, lf, u.label(Quantity::velocity));
      o["peak_acceleration"] = nodal_peak(h.peak_acceleration, lf, u.label(Quantity::acceleration));
    }
    outputs[h.spec.name] = o;
  }
  j["outputs"] = outputs;
  add_hot_spots(j, r, q);
  return j;
}

std::string frame_summary_json(const FrameStudyResults& r, const FrameStudyRequest& q) { return frame_summary(r, q).dump(2); }

}  // namespace framedyn::report
