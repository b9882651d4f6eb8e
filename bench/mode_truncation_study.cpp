// Mode-truncation study (issue 5, "Studies"): how many modes the modal
// transient response of the R-100-like frame needs, with the mode-displacement
// and the mode-acceleration method, against direct integration of the full
// frame (Newmark, average acceleration, converged by halving the step).
//
// For each support case (the thesis's fixed rear end; free-free with inertia
// relief) and each mode count (5, 10, 20, 40, all) it reports the relative
// error of the peak bending moment and of the peak normal stress at the
// critical points of each rail: the station where the converged Newmark
// response has its peak, the same station for every case. It also splits the
// bending moment and the corner stress at the critical point and time into
// the contributions of the individual modes (all modes, mode displacement:
// the decomposition is exact because recovery is linear in the displacement).
//
//   mode_truncation_study --loads FRAME_LOADS.csv [--mesh meshes/r100_frame.inp]
//                         [--out DIR] [--png FILE] [--substeps 1,2,4,8,16,32]
//                         [--alpha 1/s] [--beta s]
//
// Prints markdown tables; writes DIR/mode_truncation.csv,
// DIR/mode_truncation_newmark.csv, DIR/mode_truncation_participation.csv and
// the figure (default DIR/mode_truncation.png). docs/validation.md, "Mode
// truncation (issue 5)", shows a run of it.
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

#include "report/csv_writer.h"
#include "report/plot.h"
#include "coupling/load_history.h"
#include "coupling/load_mapping.h"
#include "coupling/rail_stress.h"
#include "fem/direct_integration.h"
#include "fem/inp_reader.h"
#include "fem/modal_transient.h"
#include "fem/section_forces.h"

namespace fs = std::filesystem;
using namespace framedyn;

namespace {

constexpr double kTwoPi = 6.283185307179586;
constexpr int kStations = 5;
const std::vector<coupling::RailSpec> kRails = {{"left_rail", "LEFT_RAIL"}, {"right_rail", "RIGHT_RAIL"}};

std::vector<int> parse_ints(const std::string& s) {
  std::vector<int> v;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, ',')) v.push_back(std::stoi(item));
  return v;
}

// Index into a RailRecovery's station arrays of (element, station).
int station_index(const coupling::RailRecovery& rail, int element_id, int station) {
  for (std::size_t k = 0; k < rail.station_element_ids.size(); ++k)
    if (rail.station_element_ids[k] == element_id) return static_cast<int>(k) + station;
  throw std::runtime_error(fmt::format("element {} is not on rail {}", element_id, rail.spec.name));
}

struct CriticalPoint {
  int bending_station = 0;   // index into the rail's stations
  int stress_station = 0;
  int bending_element = 0, bending_local = 0, stress_element = 0, stress_local = 0, stress_fiber = 0;
  double bending_time = 0.0, stress_time = 0.0;
  Eigen::Vector3d bending_point, stress_point;
  double bending_reference = 0.0, stress_reference = 0.0;  // peak |M| (N m), peak |sigma| (Pa)
};

struct SupportCase {
  std::string name;
  fem::FrameModel model;
};

struct Row {
  std::string supports, method;
  int modes = 0;
  std::string rail;
  double moment = 0.0, moment_error = 0.0, stress = 0.0, stress_error = 0.0;
};

}  // namespace

int main(int argc, char** argv) {
  std::string loads_path, mesh_path = std::string(FRAMEDYN_SOURCE_DIR) + "/meshes/r100_frame.inp", out_dir = "mode_truncation_out",
                          png_path;
  std::vector<int> substeps = {1, 2, 4, 8, 16, 32};
  // Rayleigh damping, the same in the modal and the direct solutions: 2 % at 25 Hz and at 250 Hz (see docs/validation.md).
  double alpha = 2.0 * 0.02 * (kTwoPi * 25) * (kTwoPi * 250) / (kTwoPi * 275);
  double beta = 2.0 * 0.02 / (kTwoPi * 275);
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto next = [&]() -> std::string {
      if (i + 1 >= argc) throw std::invalid_argument("missing value after " + a);
      return argv[++i];
    };
    if (a == "--loads") loads_path = next();
    else if (a == "--mesh") mesh_path = next();
    else if (a == "--out") out_dir = next();
    else if (a == "--png") png_path = next();
    else if (a == "--substeps") substeps = parse_ints(next());
    else if (a == "--alpha") alpha = std::stod(next());
    else if (a == "--beta") beta = std::stod(next());
    else {
      std::cerr << "usage: mode_truncation_study --loads FRAME_LOADS.csv [--mesh INP] [--out DIR] [--png FILE] [--substeps 1,2,4]"
                   " [--alpha 1/s] [--beta s]\n";
      return 2;
    }
  }
  if (loads_path.empty()) {
    std::cerr << "mode_truncation_study: --loads FRAME_LOADS.csv is required (e.g. from `framedyn run examples/r100_plow_offset.yaml`)\n";
    return 2;
  }
  fs::create_directories(out_dir);
  if (png_path.empty()) png_path = (fs::path(out_dir) / "mode_truncation.png").string();

  const coupling::LoadHistory loads = coupling::read_load_history(loads_path);
  std::vector<coupling::LoadPointLocation> points;
  for (const auto& p : loads.points) points.push_back({p.name, p.location});

  std::vector<SupportCase> cases;
  {
    SupportCase fixed{"fixed_rear_end", fem::read_inp(mesh_path)};
    for (int node : fixed.model.node_sets.at("REAR_END"))
      for (int d = 0; d < fem::kDofsPerNode; ++d) fixed.model.constraints.push_back({node, d, 0.0});
    cases.push_back(std::move(fixed));
    cases.push_back({"free_free_inertia_relief", fem::read_inp(mesh_path)});
  }
  const std::vector<int> counts = {5, 10, 20, 40, -1};
  const double dt = (loads.times(loads.times.size() - 1) - loads.times(0)) / static_cast<double>(loads.times.size() - 1);

  fmt::print("# Mode truncation study\n\nloads: {} ({} times, {:.4g} s to {:.4g} s, step {:.4g} s), mesh: {}\n", loads_path,
             loads.times.size(), loads.times(0), loads.times(loads.times.size() - 1), dt, mesh_path);
  fmt::print("Rayleigh damping alpha = {:.6g} 1/s, beta = {:.6g} s (modal and direct)\n\n", alpha, beta);

  std::vector<Row> rows;
  report::CsvTable newmark_csv({"supports", "substeps", "step [s]", "rail", "peak_bending_moment [N*m]", "peak_normal_stress [Pa]",
                              "wall [s]"});
  report::CsvTable part_csv({"supports", "rail", "quantity", "mode", "frequency [Hz]", "contribution", "share"});
  std::vector<report::PlotSeries> series;

  for (SupportCase& sc : cases) {
    const coupling::LoadMapping mapping = coupling::map_load_points(sc.model, points);
    fem::FrameDynamics frame(sc.model);
    fem::TransientInput in;
    in.times = loads.times;
    in.distribution = mapping.distribution;
    in.components = loads.component_matrix();

    // Direct integration with the step halved until the peaks settle.
    fmt::print("## {}: Newmark (average acceleration) on the full frame, {} free DOFs\n\n", sc.name, frame.dofs().free_count());
    fmt::print("| substeps | step (s) | rail | peak bending moment (N m) | change | peak normal stress (MPa) | change |\n");
    fmt::print("|---:|---:|---|---:|---:|---:|---:|\n");
    std::vector<coupling::RailRecovery> reference;
    fem::TransientResult reference_response;
    std::vector<double> last_m(2, 0.0), last_s(2, 0.0);
    for (int s : substeps) {
      fem::NewmarkOptions no;
      no.rayleigh_alpha = alpha;
      no.rayleigh_beta = beta;
      no.substeps = s;
      const auto t0 = std::chrono::steady_clock::now();
      fem::TransientResult r = fem::direct_transient(frame, in, no);
      const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      auto rails = coupling::recover_rails(sc.model, r.times, r.displacement, kRails, kStations);
      for (std::size_t k = 0; k < rails.size(); ++k) {
        const double m = rails[k].peak_bending_moment.value, st = std::abs(rails[k].peak_normal_stress.value);
        const std::string cm = last_m[k] > 0 ? fmt::format("{:.2e}", std::abs(m - last_m[k]) / m) : "";
        const std::string cs = last_s[k] > 0 ? fmt::format("{:.2e}", std::abs(st - last_s[k]) / st) : "";
        fmt::print("| {} | {:.3e} | {} | {:.6g} | {} | {:.6g} | {} |\n", s, dt / s, rails[k].spec.name, m, cm, st / 1e6, cs);
        newmark_csv.row().add(sc.name).add(s).add(dt / s).add(rails[k].spec.name).add(m).add(st).add(wall);
        last_m[k] = m;
        last_s[k] = st;
      }
      reference = std::move(rails);
      reference_response = std::move(r);
    }
    fmt::print("\n(change: relative to the row above; the last row is the reference)\n\n");

    // Critical points: where the reference has its peaks.
    std::vector<CriticalPoint> critical;
    for (const auto& rail : reference) {
      CriticalPoint c;
      c.bending_element = rail.peak_bending_moment.element_id;
      c.bending_local = rail.peak_bending_moment.station;
      c.bending_station = station_index(rail, c.bending_element, c.bending_local);
      c.bending_time = rail.peak_bending_moment.time;
      c.bending_point = rail.peak_bending_moment.point;
      c.bending_reference = rail.envelope_bending_moment(c.bending_station);
      c.stress_element = rail.peak_normal_stress.element_id;
      c.stress_local = rail.peak_normal_stress.station;
      c.stress_station = station_index(rail, c.stress_element, c.stress_local);
      c.stress_fiber = rail.peak_normal_stress.fiber;
      c.stress_time = rail.peak_normal_stress.time;
      c.stress_point = rail.peak_normal_stress.point;
      c.stress_reference = rail.envelope_normal_stress(c.stress_station);
      critical.push_back(c);
      fmt::print("critical points, {}: peak bending moment {:.6g} N m at X = {:.2f} in (element {}, station {}), t = {:.4f} s; "
                 "peak normal stress {:.6g} MPa at X = {:.2f} in (element {}, station {}, corner {}), t = {:.4f} s\n",
                 rail.spec.name, c.bending_reference, c.bending_point.x() / 0.0254, c.bending_element, c.bending_local, c.bending_time,
                 c.stress_reference / 1e6, c.stress_point.x() / 0.0254, c.stress_element, c.stress_local, c.stress_fiber, c.stress_time);
    }

    const fem::ModalBasis basis = frame.all_modes();
    const int elastic = basis.elastic_count();
    fmt::print("\n{} elastic modes, {:.4g} Hz to {:.4g} Hz\n\n", elastic,
               std::sqrt(basis.eigenvalues(basis.eigenvalues.size() - elastic)) / kTwoPi,
               std::sqrt(basis.eigenvalues(basis.eigenvalues.size() - 1)) / kTwoPi);

    fmt::print("## {}: relative error at the critical points against converged Newmark\n\n", sc.name);
    fmt::print("| method | modes | left rail M | left rail sigma | right rail M | right rail sigma |\n|---|---:|---:|---:|---:|---:|\n");
    fem::TransientResult all_md;
    for (const auto method : {fem::ResponseMethod::mode_displacement, fem::ResponseMethod::mode_acceleration}) {
      const std::string mname = method == fem::ResponseMethod::mode_displacement ? "mode_displacement" : "mode_acceleration";
      report::PlotSeries sm{fmt::format("{}, {}, bending moment", sc.name, mname), {}, {}};
      report::PlotSeries ss{fmt::format("{}, {}, normal stress", sc.name, mname), {}, {}};
      for (int n : counts) {
        fem::ModalTransientOptions mo;
        mo.method = method;
        mo.damping = fem::ModalDamping::rayleigh_damping(alpha, beta);
        mo.mode_count = n;
        fem::TransientResult r = fem::modal_transient(frame, basis, in, mo);
        const auto rails = coupling::recover_rails(sc.model, r.times, r.displacement, kRails, kStations);
        const int used = n < 0 ? elastic : n;
        std::string line = fmt::format("| {} | {} |", mname, n < 0 ? fmt::format("all ({})", elastic) : std::to_string(n));
        double worst_m = 0.0, worst_s = 0.0;
        for (std::size_t k = 0; k < rails.size(); ++k) {
          const CriticalPoint& c = critical[k];
          Row row{sc.name, mname, used, rails[k].spec.name, rails[k].envelope_bending_moment(c.bending_station), 0.0,
                  rails[k].envelope_normal_stress(c.stress_station), 0.0};
          row.moment_error = std::abs(row.moment - c.bending_reference) / c.bending_reference;
          row.stress_error = std::abs(row.stress - c.stress_reference) / c.stress_reference;
          worst_m = std::max(worst_m, row.moment_error);
          worst_s = std::max(worst_s, row.stress_error);
          line += fmt::format(" {:.2f} % | {:.2f} % |", 100 * row.moment_error, 100 * row.stress_error);
          rows.push_back(row);
        }
        fmt::print("{}\n", line);
        sm.x.push_back(used);
        sm.y.push_back(std::log10(std::max(worst_m, 1e-8)));
        ss.x.push_back(used);
        ss.y.push_back(std::log10(std::max(worst_s, 1e-8)));
        if (n < 0 && method == fem::ResponseMethod::mode_displacement) all_md = std::move(r);
      }
      series.push_back(sm);
      series.push_back(ss);
    }

    // Each mode's part of the bending moment and the corner stress at the critical point and time.
    std::vector<int> elastic_columns;
    for (Eigen::Index i = 0; i < basis.eigenvalues.size(); ++i)
      if (!basis.rigid_body[static_cast<std::size_t>(i)]) elastic_columns.push_back(static_cast<int>(i));
    fmt::print("\n## {}: modal participation at the critical points (all modes, mode displacement)\n\n", sc.name);
    for (std::size_t k = 0; k < critical.size(); ++k) {
      const CriticalPoint& c = critical[k];
      const auto time_index = [&](double t) {
        Eigen::Index best = 0;
        for (Eigen::Index j = 0; j < all_md.times.size(); ++j)
          if (std::abs(all_md.times(j) - t) < std::abs(all_md.times(best) - t)) best = j;
        return best;
      };
      const Eigen::Index jm = time_index(c.bending_time), js = time_index(c.stress_time);
      const int n = static_cast<int>(elastic_columns.size());
      std::vector<Eigen::Vector2d> moment(static_cast<std::size_t>(n));
      std::vector<double> stress(static_cast<std::size_t>(n)), freq(static_cast<std::size_t>(n));
      Eigen::Vector2d moment_total = Eigen::Vector2d::Zero();
      double stress_total = 0.0;
      for (int i = 0; i < n; ++i) {
        const Eigen::VectorXd phi = basis.shapes.col(elastic_columns[static_cast<std::size_t>(i)]);
        freq[static_cast<std::size_t>(i)] = std::sqrt(std::max(basis.eigenvalues(elastic_columns[static_cast<std::size_t>(i)]), 0.0)) / kTwoPi;
        const auto at = [&](Eigen::Index j, int element, int local) {
          const Eigen::VectorXd u = frame.expand(phi * all_md.modal_coordinates(i, j));
          for (const fem::StationResult& s : fem::recover_stations(sc.model, u, kStations))
            if (s.element_id == element && s.station == local) return s;
          throw std::runtime_error("critical station not found");
        };
        const fem::StationResult sm = at(jm, c.bending_element, c.bending_local);
        moment[static_cast<std::size_t>(i)] = Eigen::Vector2d(sm.forces.my, sm.forces.mz);
        moment_total += moment[static_cast<std::size_t>(i)];
        const fem::StationResult ss = at(js, c.stress_element, c.stress_local);
        stress[static_cast<std::size_t>(i)] = ss.fiber_stress[static_cast<std::size_t>(c.stress_fiber)];
        stress_total += stress[static_cast<std::size_t>(i)];
      }
      // Share of mode i: its moment vector projected on the total (the shares add up to 1).
      std::vector<double> m_share(static_cast<std::size_t>(n)), s_share(static_cast<std::size_t>(n));
      for (int i = 0; i < n; ++i) {
        m_share[static_cast<std::size_t>(i)] = moment[static_cast<std::size_t>(i)].dot(moment_total) / moment_total.squaredNorm();
        s_share[static_cast<std::size_t>(i)] = stress[static_cast<std::size_t>(i)] / stress_total;
        part_csv.row().add(sc.name).add(kRails[k].name).add(std::string("bending_moment")).add(i + 1).add(freq[static_cast<std::size_t>(i)])
            .add(moment[static_cast<std::size_t>(i)].dot(moment_total) / moment_total.norm()).add(m_share[static_cast<std::size_t>(i)]);
        part_csv.row().add(sc.name).add(kRails[k].name).add(std::string("normal_stress")).add(i + 1).add(freq[static_cast<std::size_t>(i)])
            .add(stress[static_cast<std::size_t>(i)]).add(s_share[static_cast<std::size_t>(i)]);
      }
      std::vector<int> order(static_cast<std::size_t>(n));
      std::iota(order.begin(), order.end(), 0);
      std::sort(order.begin(), order.end(), [&](int a, int b) { return std::abs(m_share[static_cast<std::size_t>(a)]) > std::abs(m_share[static_cast<std::size_t>(b)]); });
      fmt::print("{}: |M| = {:.6g} N m at t = {:.4f} s (reference {:.6g}); sigma = {:.6g} MPa at t = {:.4f} s\n\n", kRails[k].name,
                 moment_total.norm(), all_md.times(jm), c.bending_reference, stress_total / 1e6, all_md.times(js));
      fmt::print("| mode | f (Hz) | share of M | share of sigma |\n|---:|---:|---:|---:|\n");
      for (int r = 0; r < std::min(8, n); ++r) {
        const std::size_t i = static_cast<std::size_t>(order[static_cast<std::size_t>(r)]);
        fmt::print("| {} | {:.1f} | {:.3f} | {:.3f} |\n", i + 1, freq[i], m_share[i], s_share[i]);
      }
      std::string cum = "cumulative share of M (sigma) in the lowest modes:";
      for (int upto : {5, 10, 20, 40}) {
        double a = 0.0, b = 0.0;
        for (int i = 0; i < std::min(upto, n); ++i) {
          a += m_share[static_cast<std::size_t>(i)];
          b += s_share[static_cast<std::size_t>(i)];
        }
        cum += fmt::format(" {}: {:.3f} ({:.3f});", upto, a, b);
      }
      fmt::print("\n{}\n\n", cum);
    }
  }

  report::CsvTable csv({"supports", "method", "modes", "rail", "peak_bending_moment_at_critical_point [N*m]", "relative_error_moment",
                      "peak_normal_stress_at_critical_point [Pa]", "relative_error_stress"});
  for (const Row& r : rows)
    csv.row().add(r.supports).add(r.method).add(r.modes).add(r.rail).add(r.moment).add(r.moment_error).add(r.stress).add(r.stress_error);
  std::ofstream(fs::path(out_dir) / "mode_truncation.csv") << csv.str();
  std::ofstream(fs::path(out_dir) / "mode_truncation_newmark.csv") << newmark_csv.str();
  std::ofstream(fs::path(out_dir) / "mode_truncation_participation.csv") << part_csv.str();

  report::LinePlot plot;
  plot.title = "Mode truncation, R-100-like frame, offset plowing: worse rail's error at the critical point";
  plot.x_label = "elastic modes used";
  plot.x_unit = "1";
  plot.y_label = "log10 of the relative error against converged Newmark";
  plot.y_unit = "1";
  plot.series = series;
  plot.mark_points = true;
  try {
    report::write_png(plot, png_path);
    fmt::print("figure: {}\n", png_path);
  } catch (const std::exception& e) {
    fmt::print(stderr, "no figure: {}\n", e.what());
  }
  fmt::print("tables: {}/mode_truncation.csv, mode_truncation_newmark.csv, mode_truncation_participation.csv\n", out_dir);
  return 0;
}
