// Issue 5, studies (a) and (b): the 2-D quasi-static cut (thesis Eq. 2.47)
// against the beam frame for straight plowing, and the thesis's qualitative
// results 2-5 measured through the pipeline (straight plowing and the
// centred digging chain). docs/validation.md, "Quasi-static cut against the
// beam frame, and the thesis's results 2-5 (issue 5)".
//
//   quasi_static_vs_fe [OUT_DIR]        (default: quasi_static_vs_fe_results)
//
// Runs examples/r100_plow_2d.yaml and examples/r100_chain_2d.yaml (2-D, 1.0 s),
// examples/straight_plowing.yaml and examples/chain_pipeline.yaml (3-D with
// the beam frame: fixed rear end, all modes, mode acceleration, 2 % damping,
// output at every load time; and the same frame free-free with inertia
// relief). At cuts X along the frame it sets beside each other, per time:
//   2-D SRMY, SRX (Eq. 2.47, the machine's full frame with all added masses
//     and the tube's distributed inertia), split into its parts;
//   the static cut of the 3-D loads at points 24-31 in front of X;
//   the beam frame's sum over both rails of the vertical bending moment
//     (about +Y, sign of SRMY) and of the axial force, statically (K u = F at
//     every time) and dynamically (modal transient), at the rails' cut just
//     in front of the node at X.
// Prints tables (in-lbf-s) and writes CSV files and PNG figures to OUT_DIR.
#include <Eigen/Dense>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "report/plot.h"
#include "coupling/frame_loads_2d.h"
#include "coupling/frame_study.h"
#include "coupling/rigid_study.h"
#include "fem/modal_transient.h"
#include "fem/section_forces.h"
#include "rigid/machine_2d.h"

namespace c = framedyn::coupling;
namespace fem = framedyn::fem;
namespace core = framedyn::core;
namespace report = framedyn::report;

namespace {

constexpr double kIn = 0.0254, kLbf = 4.4482216152605, kLbfIn = kLbf * kIn, kPsi = kLbf / (kIn * kIn);
constexpr double kPi = 3.141592653589793;

using Series = std::vector<double>;

// Least-squares fit y = m + a cos(wt) + b sin(wt) over whole cycles from t0.
struct Fit {
  double mean = 0, amp = 0, phase = 0, rms = 0, peak = 0, harmonic_share = 0;
};
Fit harmonic_fit(const Series& t, const Series& y, double f, double t0, double t1) {
  const double cycles = std::floor((t1 - t0) * f + 1e-9);
  const double te = t0 + cycles / f;
  Eigen::Matrix3d ata = Eigen::Matrix3d::Zero();
  Eigen::Vector3d atb = Eigen::Vector3d::Zero();
  std::vector<std::size_t> idx;
  for (std::size_t i = 0; i < t.size(); ++i)
    if (t[i] >= t0 - 1e-12 && t[i] < te - 1e-12) {
      const Eigen::Vector3d r(1.0, std::cos(2 * kPi * f * t[i]), std::sin(2 * kPi * f * t[i]));
      ata += r * r.transpose();
      atb += r * y[i];
      idx.push_back(i);
    }
  const Eigen::Vector3d x = ata.ldlt().solve(atb);
  Fit out;
  out.mean = x(0);
  out.amp = std::hypot(x(1), x(2));
  out.phase = std::atan2(-x(2), x(1));  // y ~ amp cos(wt + phase)
  double var = 0, m = 0;
  for (std::size_t i : idx) m += y[i];
  m /= static_cast<double>(idx.size());
  for (std::size_t i : idx) {
    var += (y[i] - m) * (y[i] - m);
    out.peak = std::max(out.peak, std::abs(y[i]));
  }
  var /= static_cast<double>(idx.size());
  out.rms = std::sqrt(var);
  out.harmonic_share = var > 0 ? 0.5 * out.amp * out.amp / var : 0.0;
  return out;
}

// Share of the variance (mean removed) of y over [t0, t1] below f_cut, by DFT, and the frequency of the largest line.
struct Spectrum {
  double share_below = 0, dominant_hz = 0;
};
Spectrum spectrum(const Series& t, const Series& y, double t0, double t1, double f_cut) {
  std::vector<double> v;
  double dt = 0;
  for (std::size_t i = 0; i < t.size(); ++i)
    if (t[i] >= t0 - 1e-12 && t[i] <= t1 + 1e-12) {
      v.push_back(y[i]);
      if (i > 0 && dt == 0) dt = t[i] - t[i - 1];
    }
  const std::size_t n = v.size();
  double m = 0;
  for (double x : v) m += x;
  m /= static_cast<double>(n);
  double below = 0, total = 0, best = 0;
  Spectrum s;
  for (std::size_t k = 1; k <= n / 2; ++k) {
    std::complex<double> z = 0;
    for (std::size_t i = 0; i < n; ++i) z += (v[i] - m) * std::polar(1.0, -2 * kPi * static_cast<double>(k * i) / static_cast<double>(n));
    const double p = std::norm(z), f = static_cast<double>(k) / (static_cast<double>(n) * dt);
    total += p;
    if (f < f_cut) below += p;
    if (p > best) {
      best = p;
      s.dominant_hz = f;
    }
  }
  s.share_below = total > 0 ? below / total : 0.0;
  // The dominant line more finely: |sum (y - m) e^(-i w t)| scanned every 0.01 Hz around the largest DFT bin.
  const double df = 1.0 / (static_cast<double>(n) * dt);
  double bestf = s.dominant_hz, bestp = 0;
  for (double f = std::max(0.01, s.dominant_hz - df); f <= s.dominant_hz + df; f += 0.01) {
    std::complex<double> z = 0;
    for (std::size_t i = 0; i < n; ++i) z += (v[i] - m) * std::polar(1.0, -2 * kPi * f * dt * static_cast<double>(i));
    if (std::norm(z) > bestp) {
      bestp = std::norm(z);
      bestf = f;
    }
  }
  s.dominant_hz = bestf;
  return s;
}

// Static cut of point loads in front of X: {SRX, SRMY} with the signs of Eq. 2.47 (no distributed inertia).
struct Cut {
  double srx = 0, srmy = 0;
};
Cut cut_2d(const std::vector<c::FrameLoad2D>& loads, std::size_t i, double x, const std::vector<std::string>* only) {
  Cut out;
  for (const c::FrameLoad2D& l : loads) {
    if (only && std::find(only->begin(), only->end(), l.name) == only->end()) continue;
    if (!(l.point.x() < x)) continue;
    const Eigen::Vector2d r = l.point - Eigen::Vector2d(x, 0.0), f = l.force[i];
    out.srx -= f.x();
    out.srmy += l.moment[i] + r.y() * f.x() - r.x() * f.y();
  }
  return out;
}
Cut cut_3d(const c::LoadHistory& h, int k, double x) {
  Cut out;
  for (const c::LoadPointHistory& p : h.points) {
    if (!(p.location.x() < x)) continue;
    const Eigen::Vector3d r = p.location - Eigen::Vector3d(x, 0, 0);
    const Eigen::Vector3d f = p.values.row(k).head<3>().transpose(), m = p.values.row(k).tail<3>().transpose();
    out.srx -= f.x();
    out.srmy += (m + r.cross(f)).y();
  }
  return out;
}

// The rail elements whose node b is at X (the cut just in front of that node), one per rail.
struct RailCut {
  std::vector<int> beams;  // indices into model.beams
  std::vector<fem::BeamGeometry> geometry;
};
RailCut rail_cut(const fem::FrameModel& m, double x) {
  RailCut rc;
  for (const char* set : {"LEFT_RAIL", "RIGHT_RAIL"})
    for (int id : m.element_sets.at(set)) {
      const int b = m.beam_index(id);
      const fem::BeamElement& e = m.beams[static_cast<std::size_t>(b)];
      if (std::abs(m.nodes[static_cast<std::size_t>(e.node_b)].position.x() - x) < 1e-9 &&
          m.nodes[static_cast<std::size_t>(e.node_a)].position.x() < x) {
        rc.beams.push_back(b);
        rc.geometry.push_back(fem::beam_geometry(m, e));
      }
    }
  return rc;
}
// Both rails: {sum of N t_x, sum of -(moment on the front part's face).y} = {SRX, SRMY} signs; and the largest corner stress.
struct RailSum {
  double srx = 0, srmy = 0, max_stress = 0, axial_stress = 0, bending_stress = 0;
};
RailSum rail_sum(const fem::FrameModel& m, const RailCut& rc, const Eigen::VectorXd& u) {
  RailSum s;
  for (std::size_t j = 0; j < rc.beams.size(); ++j) {
    const fem::BeamGeometry& g = rc.geometry[j];
    const fem::SectionForces f = fem::section_forces_at(fem::element_end_forces(g, m.beams[static_cast<std::size_t>(rc.beams[j])], u), g.data.length);
    const Eigen::Vector3d t = g.axes.row(0).transpose(), n1 = g.axes.row(1).transpose(), n2 = g.axes.row(2).transpose();
    s.srx += f.n * t.x();
    s.srmy += -(f.t * t + f.my * n1 + f.mz * n2).y();
    for (double v : fem::fiber_stresses(g.data.section, f))
      if (std::abs(v) > std::abs(s.max_stress)) {
        s.max_stress = v;
        s.axial_stress = f.n / g.data.section.area;
        s.bending_stress = v - s.axial_stress;
      }
  }
  return s;
}

struct FrameRun {
  c::FrameStudyResults r;
  Series t;
};
FrameRun run_frame(const c::FrameStudyRequest& q0, const c::LoadHistory& loads, c::FrameSupports supports) {
  c::FrameStudyRequest q = q0;
  q.output_interval.reset();
  q.paraview = c::ParaviewOutput::none;
  q.supports = supports;
  FrameRun fr{c::run_frame_study(q, &loads), {}};
  for (Eigen::Index j = 0; j < fr.r.response.times.size(); ++j) fr.t.push_back(fr.r.response.times(j));
  return fr;
}

void plot(const std::filesystem::path& png, const std::string& title, const std::string& xl, const std::string& xu, const std::string& yl,
          const std::string& yu, std::vector<report::PlotSeries> series) {
  report::LinePlot p;
  p.title = title;
  p.x_label = xl;
  p.x_unit = xu;
  p.y_label = yl;
  p.y_unit = yu;
  p.series = std::move(series);
  try {
    report::write_png(p, png);
  } catch (const std::exception& e) {
    fmt::print("(figure {} not drawn: {})\n", png.string(), e.what());
  }
}

}  // namespace

int main(int argc, char** argv) {
  const std::string src = FRAMEDYN_SOURCE_DIR;
  const std::filesystem::path out = argc > 1 ? argv[1] : "quasi_static_vs_fe_results";
  std::filesystem::create_directories(out);
  const double duration = 1.0, t0 = 0.3, fs = 18.33;

  // ---- 2-D plow (Eq. 2.47) ----
  c::RigidStudy s2 = c::read_rigid_study(src + "/examples/r100_plow_2d.yaml");
  s2.response->duration = duration;
  const c::RigidResults r2 = c::run_rigid_study(s2);
  const c::StressResultants& sr = *r2.resultants;
  const Series t2 = r2.trajectory.time;
  const std::vector<std::string> fe_carried = {"reel_and_carrier", "front_axle_and_wheels", "front_tire", "rear_axle_drive_and_wheels",
                                               "rear_tire", "cab_mount_front", "cab_mount_rear", "cab_x_tie"};
  const std::vector<std::string> mounted = {"front_ballast", "hydraulic_pumps_and_tank", "engine", "fuel_tank", "hitch_box"};
  {
    std::vector<std::string> names;
    for (const auto& l : r2.frame_loads_2d) names.push_back(fmt::format("{}@{:g}", l.name, l.point.x() / kIn));
    fmt::print("2-D frame loads: {}\n", fmt::join(names, ", "));
  }

  // ---- 3-D straight plowing and the beam frame ----
  c::RigidStudy s3 = c::read_rigid_study(src + "/examples/straight_plowing.yaml");
  s3.response->duration = duration;  // the 2-D run's 1 s (the shipped study runs 20 s, to its steady operation)
  const c::RigidResults r3 = c::run_rigid_study(s3);
  const c::LoadHistory& h3 = r3.frame_loads_3d->points;
  FrameRun fx = run_frame(*s3.frame_response, h3, c::FrameSupports::fixed_rear_end);
  FrameRun ff = run_frame(*s3.frame_response, h3, c::FrameSupports::free_free_inertia_relief);
  fmt::print("beam frame, fixed rear end: first modes {:.2f} {:.2f} {:.2f} Hz; free-free: {:.2f} {:.2f} {:.2f} Hz\n", fx.r.frequencies_hz(0),
             fx.r.frequencies_hz(1), fx.r.frequencies_hz(2), ff.r.frequencies_hz(0), ff.r.frequencies_hz(1), ff.r.frequencies_hz(2));
  // Static FE solution at every load time (the quasi-static limit of the same frame).
  fem::FrameDynamics fdyn(fx.r.model);
  const Eigen::MatrixXd ffree = fdyn.free_loads(fx.r.mapping.distribution);
  const Eigen::MatrixXd comps = h3.component_matrix();
  std::vector<Eigen::VectorXd> ustat;
  for (Eigen::Index k = 0; k < comps.cols(); ++k) ustat.push_back(fdyn.expand(fdyn.static_response(ffree * comps.col(k))));
  if (fx.t.size() != static_cast<std::size_t>(comps.cols()) || t2.size() != fx.t.size()) {
    fmt::print("sample times differ: 2-D {}, loads {}, frame {}\n", t2.size(), comps.cols(), fx.t.size());
    return 1;
  }

  const std::vector<double> cuts_in = {-20, -15, -10, -5, 0, 5, 10, 15, 20, 31, 36, 41, 46, 52, 57, 62, 68, 72, 76, 80};
  std::ofstream along(out / "plow_cut_along_frame.csv");
  along << "X [in],quantity,2d_full_mean,2d_full_amp,2d_fe_carried_amp,2d_mounted_amp,2d_tube_amp,2d_plow_amp,3d_cut_amp,fe_static_amp,"
           "fe_dynamic_amp,fe_dynamic_phase_lag_deg,fe_free_free_amp,fe_dynamic_mean,2d_harmonic_share,fe_dynamic_harmonic_share,"
           "max_abs_fe_static_minus_3d_cut\n";
  fmt::print("\nStraight plowing, first harmonic (18.33 Hz) amplitude over {:.3f}-{:.3f} s, both rails together, lbf*in (SRMY) / lbf (SRX)\n", t0,
             duration);
  fmt::print("{:>6} {:>5} | {:>9} {:>9} | {:>9} {:>9} {:>9} {:>9} | {:>9} {:>9} {:>9} {:>6} {:>9} | {:>6}\n", "X", "q", "2D mean", "2D full",
             "2D FEld", "2D mnt", "2D tube", "2D plow", "3D cut", "FE stat", "FE dyn", "lag", "FE free", "dyn/st");
  std::map<double, std::map<std::string, Series>> keep;
  const framedyn::rigid::VehicleModel model2 = framedyn::rigid::build_vehicle_model(s2.machine_2d());
  double max_dev_2d = 0;
  for (double xin : cuts_in) {
    const double x = xin * kIn;
    const auto it = std::find_if(sr.output_x.begin(), sr.output_x.end(), [&](double v) { return std::abs(v - x) < 1e-9; });
    const RailCut rc = rail_cut(fx.r.model, x);
    if (rc.beams.size() != 2) continue;
    const RailCut rcf = rail_cut(ff.r.model, x);
    std::map<std::string, Series> srs;
    for (std::size_t i = 0; i < t2.size(); ++i) {
      const Cut all = cut_2d(r2.frame_loads_2d, i, x, nullptr), fe = cut_2d(r2.frame_loads_2d, i, x, &fe_carried),
                   mnt = cut_2d(r2.frame_loads_2d, i, x, &mounted);
      // Eq. 2.47 at X: the loads in front and the tube's distributed inertia in front (as frame_stress_resultants).
      const c::SectionLoad d = c::tube_inertia_in_front(model2, s2.machine_2d().frame, r2.trajectory.a[i], x, 0.0);
      const double full_srx = all.srx - d.force.x(), full_srmy = all.srmy + d.moment;
      if (it != sr.output_x.end()) {  // the study's own output agrees
        const std::size_t k = static_cast<std::size_t>(it - sr.output_x.begin());
        max_dev_2d = std::max(max_dev_2d, std::abs(full_srmy - sr.srmy[i][k]) / kLbfIn + std::abs(full_srx - sr.srx[i][k]) / kLbf);
      }
      const Cut c3 = cut_3d(h3, static_cast<int>(i), x);
      const RailSum st = rail_sum(fx.r.model, rc, ustat[i]);
      const RailSum dy = rail_sum(fx.r.model, rc, fx.r.response.displacement.col(static_cast<Eigen::Index>(i)));
      const RailSum fr = rail_sum(ff.r.model, rcf, ff.r.response.displacement.col(static_cast<Eigen::Index>(i)));
      const double plow_srmy = all.srmy - fe.srmy - mnt.srmy, plow_srx = all.srx - fe.srx - mnt.srx;
      srs["SRMY.2d_full"].push_back(full_srmy / kLbfIn);
      srs["SRMY.2d_fe_carried"].push_back(fe.srmy / kLbfIn);
      srs["SRMY.2d_mounted"].push_back(mnt.srmy / kLbfIn);
      srs["SRMY.2d_tube"].push_back((full_srmy - all.srmy) / kLbfIn);
      srs["SRMY.2d_plow"].push_back(plow_srmy / kLbfIn);
      srs["SRMY.3d_cut"].push_back(c3.srmy / kLbfIn);
      srs["SRMY.fe_static"].push_back(st.srmy / kLbfIn);
      srs["SRMY.fe_dynamic"].push_back(dy.srmy / kLbfIn);
      srs["SRMY.fe_free_free"].push_back(fr.srmy / kLbfIn);
      srs["SRX.2d_full"].push_back(full_srx / kLbf);
      srs["SRX.2d_fe_carried"].push_back(fe.srx / kLbf);
      srs["SRX.2d_mounted"].push_back(mnt.srx / kLbf);
      srs["SRX.2d_tube"].push_back((full_srx - all.srx) / kLbf);
      srs["SRX.2d_plow"].push_back(plow_srx / kLbf);
      srs["SRX.3d_cut"].push_back(c3.srx / kLbf);
      srs["SRX.fe_static"].push_back(st.srx / kLbf);
      srs["SRX.fe_dynamic"].push_back(dy.srx / kLbf);
      srs["SRX.fe_free_free"].push_back(fr.srx / kLbf);
      srs["stress.fe_dynamic"].push_back(dy.max_stress / kPsi);
      srs["stress.fe_dynamic_axial"].push_back(dy.axial_stress / kPsi);
      srs["stress.fe_dynamic_bending"].push_back(dy.bending_stress / kPsi);
    }
    for (const char* q : {"SRMY", "SRX"}) {
      const std::string Q = q;
      auto F = [&](const std::string& k) { return harmonic_fit(t2, srs[Q + "." + k], fs, t0, duration); };
      const Fit full = F("2d_full"), fe = F("2d_fe_carried"), mnt = F("2d_mounted"), tube = F("2d_tube"), pl = F("2d_plow"), c3 = F("3d_cut"),
                st = F("fe_static"), dy = F("fe_dynamic"), fr = F("fe_free_free");
      double dev = 0;
      for (std::size_t i = 0; i < t2.size(); ++i) dev = std::max(dev, std::abs(srs[Q + ".fe_static"][i] - srs[Q + ".3d_cut"][i]));
      double lag = (st.phase - dy.phase) * 180 / kPi;
      while (lag > 180) lag -= 360;
      while (lag <= -180) lag += 360;
      fmt::print("{:>6g} {:>5} | {:>9.0f} {:>9.0f} | {:>9.0f} {:>9.0f} {:>9.0f} {:>9.0f} | {:>9.0f} {:>9.0f} {:>9.0f} {:>6.0f} {:>9.0f} | {:>6.2f}\n",
                 xin, q, full.mean, full.amp, fe.amp, mnt.amp, tube.amp, pl.amp, c3.amp, st.amp, dy.amp, lag, fr.amp,
                 st.amp > 0 ? dy.amp / st.amp : 0.0);
      along << fmt::format("{:g},{},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.4g},{:.6g},{:.6g},{:.4f},{:.4f},{:.3g}\n", xin, q,
                           full.mean, full.amp, fe.amp, mnt.amp, tube.amp, pl.amp, c3.amp, st.amp, dy.amp, lag, fr.amp, dy.mean,
                           full.harmonic_share, dy.harmonic_share, dev);
    }
    keep[xin] = std::move(srs);
  }
  along.close();
  fmt::print("(Eq. 2.47 recomputed here against the 2-D study's own resultants at its output points: largest difference {:.2g} lbf*in + lbf;\n"
             " beam frame static against the static cut of the 3-D loads: see max_abs_fe_static_minus_3d_cut in plow_cut_along_frame.csv)\n",
             max_dev_2d);

  // Time series at X = 36 in and X = 10 in.
  for (double xin : {10.0, 36.0, 62.0}) {
    auto& s = keep[xin];
    std::ofstream f(out / fmt::format("plow_cut_series_X{:g}.csv", xin));
    f << "time [s],SRMY_2d_full [lbf*in],SRMY_2d_fe_carried [lbf*in],SRMY_3d_cut [lbf*in],SRMY_fe_static [lbf*in],SRMY_fe_dynamic [lbf*in],"
         "SRMY_fe_free_free [lbf*in],SRX_2d_full [lbf],SRX_3d_cut [lbf],SRX_fe_dynamic [lbf],stress_fe_dynamic [psi]\n";
    for (std::size_t i = 0; i < t2.size(); ++i)
      f << fmt::format("{:.5f},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g}\n", t2[i], s["SRMY.2d_full"][i],
                       s["SRMY.2d_fe_carried"][i], s["SRMY.3d_cut"][i], s["SRMY.fe_static"][i], s["SRMY.fe_dynamic"][i], s["SRMY.fe_free_free"][i],
                       s["SRX.2d_full"][i], s["SRX.3d_cut"][i], s["SRX.fe_dynamic"][i], s["stress.fe_dynamic"][i]);
    std::vector<report::PlotSeries> ps;
    auto add = [&](const std::string& name, const std::string& key) {
      report::PlotSeries p{name, {}, {}};
      for (std::size_t i = 0; i < t2.size(); ++i)
        if (t2[i] >= 0.6 - 1e-12 && t2[i] <= 0.8 + 1e-12) {
          p.x.push_back(t2[i]);
          p.y.push_back(s[key][i]);
        }
      ps.push_back(p);
    };
    add("2-D Eq. 2.47 SRMY (all parts, tube inertia)", "SRMY.2d_full");
    add("2-D, only the loads the beam frame gets", "SRMY.2d_fe_carried");
    add("static cut of the 3-D loads 24-31 (= beam frame, static)", "SRMY.3d_cut");
    add("beam frame, fixed rear end, dynamic", "SRMY.fe_dynamic");
    add("beam frame, free-free inertia relief, dynamic", "SRMY.fe_free_free");
    plot(out / fmt::format("qs_cut_vs_fe_X{:g}.png", xin), fmt::format("Straight plowing: vertical bending moment of the whole frame at X = {:g} in", xin),
         "time", "s", "SRMY (both rails)", "lbf*in", ps);
  }
  {  // Amplitude along the frame.
    std::vector<report::PlotSeries> ps(5);
    const char* names[] = {"2-D Eq. 2.47 (all parts, tube inertia)", "2-D, only the loads the beam frame gets", "static cut of the 3-D loads 24-31",
                           "beam frame, fixed rear end, dynamic", "beam frame, free-free inertia relief, dynamic"};
    const char* keys[] = {"SRMY.2d_full", "SRMY.2d_fe_carried", "SRMY.3d_cut", "SRMY.fe_dynamic", "SRMY.fe_free_free"};
    for (int k = 0; k < 5; ++k) {
      ps[static_cast<std::size_t>(k)].name = names[k];
      for (auto& [xin, s] : keep) {
        const Fit f = harmonic_fit(t2, s[keys[k]], fs, t0, duration);
        if (!std::isfinite(f.amp)) continue;
        ps[static_cast<std::size_t>(k)].x.push_back(xin);
        ps[static_cast<std::size_t>(k)].y.push_back(f.amp);
      }
    }
    plot(out / "qs_cut_vs_fe_amplitude.png", "Straight plowing: 18.33 Hz amplitude of the whole frame's vertical bending moment", "X", "in",
         "amplitude of SRMY (both rails)", "lbf*in", ps);
  }

  // ---- (b) results 2-5 ----
  fmt::print("\nResult 2 (plow: resultants alternate at 18.33 Hz about a near-zero mean), 2-D Eq. 2.47 over {:.2f}-{:.2f} s:\n", t0, duration);
  {
    double worst_mean[3] = {0, 0, 0}, min_share[3] = {1, 1, 1};
    for (std::size_t k = 0; k < sr.output_x.size(); ++k) {
      if (sr.output_x[k] >= 79.9 * kIn || sr.output_x[k] < -24.9 * kIn) continue;  // nothing in front of -25; X = 80 at the hitch
      const std::vector<std::vector<double>>* qs[3] = {&sr.srx, &sr.srz, &sr.srmy};
      for (int q = 0; q < 3; ++q) {
        Series y;
        for (std::size_t i = 0; i < t2.size(); ++i) y.push_back((*qs[q])[i][k]);
        const Fit f = harmonic_fit(t2, y, fs, t0, duration);
        if (f.amp > 0) worst_mean[q] = std::max(worst_mean[q], std::abs(f.mean) / f.amp);
        min_share[q] = std::min(min_share[q], f.harmonic_share);
      }
    }
    fmt::print("  largest |mean| / 18.33-Hz amplitude over X = -20..78 in: SRX {:.3f}, SRZ {:.3f}, SRMY {:.3f}\n", worst_mean[0], worst_mean[1],
               worst_mean[2]);
    fmt::print("  smallest share of the variance at 18.33 Hz: SRX {:.3f}, SRZ {:.3f}, SRMY {:.3f}\n", min_share[0], min_share[1], min_share[2]);
    double wm = 0, ms = 1;
    for (auto& [xin, s] : keep) {
      if (xin >= 80) continue;
      const Fit f = harmonic_fit(t2, s["SRMY.fe_dynamic"], fs, t0, duration);
      wm = std::max(wm, std::abs(f.mean) / f.amp);
      ms = std::min(ms, f.harmonic_share);
    }
    fmt::print("  beam frame (both rails' Mz), X = -20..76 in: largest |mean|/amplitude {:.3f}, smallest variance share at 18.33 Hz {:.3f}\n", wm, ms);
    fmt::print("  per X: mean/amplitude and variance share at 18.33 Hz, SRX SRZ SRMY (2-D) | both rails' Mz (beam frame)\n");
    for (double xin : {-15.0, 0.0, 20.0, 36.0, 50.0, 72.0}) {
      const std::size_t k = static_cast<std::size_t>(std::find_if(sr.output_x.begin(), sr.output_x.end(), [&](double v) { return std::abs(v - xin * kIn) < 1e-9; }) - sr.output_x.begin());
      std::string line = fmt::format("    X = {:>4g} in:", xin);
      const std::vector<std::vector<double>>* qs[3] = {&sr.srx, &sr.srz, &sr.srmy};
      for (int q = 0; q < 3; ++q) {
        Series y;
        for (std::size_t i = 0; i < t2.size(); ++i) y.push_back((*qs[q])[i][k]);
        const Fit f = harmonic_fit(t2, y, fs, t0, duration);
        line += fmt::format("  {:+.3f} {:.3f}", f.mean / f.amp, f.harmonic_share);
      }
      if (keep.count(xin)) {
        const Fit f = harmonic_fit(t2, keep[xin]["SRMY.fe_dynamic"], fs, t0, duration);
        line += fmt::format("  | {:+.3f} {:.3f}", f.mean / f.amp, f.harmonic_share);
      }
      fmt::print("{}\n", line);
    }
  }

  // 2-D chain and 3-D chain pipeline.
  c::RigidStudy s2c = c::read_rigid_study(src + "/examples/r100_chain_2d.yaml");
  s2c.response->duration = duration;
  s2c.response->output_interval = 0.00025;  // the 3-D chain run's samples
  const c::RigidResults r2c = c::run_rigid_study(s2c);
  const c::RigidStudy s3c = c::read_rigid_study(src + "/examples/chain_pipeline.yaml");
  const c::RigidResults r3c = c::run_rigid_study(s3c);
  FrameRun fc = run_frame(*s3c.frame_response, r3c.frame_loads_3d->points, c::FrameSupports::fixed_rear_end);

  // Stress at X = 36 in: 2-D (rail top, Eq. 2.47d) and beam frame (largest corner); plow and chain.
  auto point_index = [](const c::StressResultants& s, double xin) {
    for (std::size_t k = 0; k < s.output_x.size(); ++k)
      if (std::abs(s.output_x[k] - xin * kIn) < 1e-9) return k;
    return s.output_x.size();
  };
  // Rail stress at the top and bottom fibers from the whole frame's resultants, one rail taking half (Eq. 2.47d):
  // sigma = (SRX/2)/A -+ (SRMY/2) c / I. The beam frame's rails share equally under these symmetric loads (straight
  // plowing, chain on the centre line), so its rail sums give the rail's own top and bottom stress.
  const c::FrameOutputRequest& rail = *s2.frame_output;
  auto top_bottom = [&](double srx, double srmy, bool top) {
    const double sb = (srmy / 2) * rail.rail_top_fiber / rail.rail_second_moment;
    return ((srx / 2) / rail.rail_area + (top ? -sb : sb)) / kPsi;
  };
  auto stress_2d = [&](const c::RigidResults& r, bool top) {
    Series y;
    const std::size_t k = point_index(*r.resultants, 36.0);
    for (std::size_t i = 0; i < r.trajectory.time.size(); ++i) y.push_back(top_bottom(r.resultants->srx[i][k], r.resultants->srmy[i][k], top));
    return y;
  };
  auto stress_fe = [&](const FrameRun& f, double xin, Series* moment, bool top) {
    Series y;
    const RailCut rc = rail_cut(f.r.model, xin * kIn);
    for (Eigen::Index j = 0; j < f.r.response.times.size(); ++j) {
      const RailSum s = rail_sum(f.r.model, rc, f.r.response.displacement.col(j));
      y.push_back(top_bottom(s.srx, s.srmy, top));
      if (moment) moment->push_back(s.srmy / kLbfIn);
    }
    return y;
  };
  auto absmax = [](const Series& a, const Series& b) {
    Series y;
    for (std::size_t i = 0; i < a.size(); ++i) y.push_back(std::max(std::abs(a[i]), std::abs(b[i])));
    return y;
  };
  // "Average maximum": the mean over the steady window of the largest |stress| in each 0.1 s block.
  auto avg_block_max = [&](const Series& t, const Series& y, double block) {
    double sum = 0;
    int n = 0;
    for (double a = t0; a + block <= duration + 1e-9; a += block) {
      double m = 0;
      for (std::size_t i = 0; i < t.size(); ++i)
        if (t[i] >= a - 1e-12 && t[i] < a + block - 1e-12) m = std::max(m, std::abs(y[i]));
      sum += m;
      ++n;
    }
    return sum / n;
  };
  const Series sp2 = stress_2d(r2, true), sc2 = stress_2d(r2c, true);
  Series mp, mc;
  const Series spf = stress_fe(fx, 36, &mp, true), scf = stress_fe(fc, 36, &mc, true);
  const Series sp2m = absmax(sp2, stress_2d(r2, false)), sc2m = absmax(sc2, stress_2d(r2c, false));
  const Series spfm = absmax(spf, stress_fe(fx, 36, nullptr, false)), scfm = absmax(scf, stress_fe(fc, 36, nullptr, false));
  const Spectrum p2s = spectrum(t2, sp2, t0, duration, 10), c2s = spectrum(r2c.trajectory.time, sc2, t0, duration, 10);
  const Spectrum pfs = spectrum(fx.t, spf, t0, duration, 10), cfs = spectrum(fc.t, scf, t0, duration, 10);
  const double ap2 = avg_block_max(t2, sp2m, 0.1), ac2 = avg_block_max(r2c.trajectory.time, sc2m, 0.1);
  const double apf = avg_block_max(fx.t, spfm, 0.1), acf = avg_block_max(fc.t, scfm, 0.1);
  fmt::print("\nResult 5 (plow's average max normal stress about twice the chain's, at a much higher frequency), X = 36 in, {:.1f}-{:.1f} s:\n", t0,
             duration);
  fmt::print("  (mean over 0.1 s blocks of the largest |stress| at the top or bottom fiber; frequency: the largest line of the top-fiber stress)\n"
             "  2-D (Eq. 2.47d): plow {:.0f} psi at {:.2f} Hz, chain {:.0f} psi at {:.2f} Hz: ratio {:.2f}\n", ap2, p2s.dominant_hz, ac2,
             c2s.dominant_hz, ap2 / ac2);
  fmt::print("  beam frame (its rails' section forces, same formula): plow {:.0f} psi at {:.2f} Hz, chain {:.0f} psi at {:.2f} Hz: ratio {:.2f}\n", apf, pfs.dominant_hz, acf,
             cfs.dominant_hz, apf / acf);
  {
    double pmax = 0, cmax = 0, psum = 0, csum = 0;
    int pn = 0, cn = 0;
    for (Eigen::Index j = 0; j < fx.r.response.times.size(); ++j)
      if (fx.t[static_cast<std::size_t>(j)] >= t0) {
        const double v = std::max(fx.r.rails[0].series_normal_stress(j), fx.r.rails[1].series_normal_stress(j)) / kPsi;
        pmax = std::max(pmax, v);
        psum += v;
        ++pn;
      }
    for (Eigen::Index j = 0; j < fc.r.response.times.size(); ++j)
      if (fc.t[static_cast<std::size_t>(j)] >= t0) {
        const double v = std::max(fc.r.rails[0].series_normal_stress(j), fc.r.rails[1].series_normal_stress(j)) / kPsi;
        cmax = std::max(cmax, v);
        csum += v;
        ++cn;
      }
    fmt::print("  beam frame, largest stress anywhere on the rails: plow peak {:.0f} psi, mean {:.0f}; chain peak {:.0f}, mean {:.0f}; ratios {:.2f}, {:.2f}\n",
               pmax, psum / pn, cmax, csum / cn, pmax / cmax, (psum / pn) / (csum / cn));
  }

  fmt::print("\nResult 3 (at least 90 % of the peak normal stress from bending):\n");
  auto share_2d = [&](const c::RigidResults& r, const c::RigidStudy& s) {
    const std::size_t k = point_index(*r.resultants, 36.0);
    double best = 0, share = 0;
    for (std::size_t i = 0; i < r.trajectory.time.size(); ++i) {
      const double sn = r.resultants->srx[i][k] / 2 / s.frame_output->rail_area,
                   sb = -r.resultants->srmy[i][k] / 2 * s.frame_output->rail_top_fiber / s.frame_output->rail_second_moment;
      if (std::abs(sn + sb) > best) {
        best = std::abs(sn + sb);
        share = std::abs(sb) / (std::abs(sn) + std::abs(sb));
      }
    }
    return share;
  };
  fmt::print("  2-D at X = 36 in (rail top, Eq. 2.47d): plow {:.3f}, chain {:.3f}\n", share_2d(r2, s2), share_2d(r2c, s2c));
  for (const auto* f : {&fx, &ff, &fc}) {
    const char* what = f == &fx ? "plow, fixed rear end" : f == &ff ? "plow, free-free" : "chain, fixed rear end";
    fmt::print("  beam frame, {}: at the peak corner stress {:.0f} psi (X = {:.0f} in): {:.3f} / {:.3f} (left/right rail)\n", what,
               f->r.rails[1].peak_normal_stress.value / kPsi, f->r.rails[1].peak_normal_stress.point.x() / kIn, f->r.rails[0].bending_share,
               f->r.rails[1].bending_share);
  }
  {
    double best = 0, share = 0, when = 0;
    for (std::size_t i = 0; i < keep[36.0]["stress.fe_dynamic"].size(); ++i) {
      const double a = std::abs(keep[36.0]["stress.fe_dynamic_axial"][i]), b = std::abs(keep[36.0]["stress.fe_dynamic_bending"][i]);
      if (t2[i] >= t0 && std::abs(keep[36.0]["stress.fe_dynamic"][i]) > best) {
        best = std::abs(keep[36.0]["stress.fe_dynamic"][i]);
        share = b / (a + b);
        when = t2[i];
      }
    }
    fmt::print("  beam frame, plow, X = 36 in: at its peak corner stress {:.0f} psi (t = {:.4f} s): {:.3f}\n", best, when, share);
  }

  fmt::print("\nResult 4 (chain: resultants dominated by the low rigid-body modes; sharp changes when the chain force jumps):\n");
  {
    Series m2c;
    const std::size_t k = point_index(*r2c.resultants, 36.0);
    for (std::size_t i = 0; i < r2c.trajectory.time.size(); ++i) m2c.push_back(r2c.resultants->srmy[i][k] / kLbfIn);
    Series m2p;
    for (std::size_t i = 0; i < t2.size(); ++i) m2p.push_back(sr.srmy[i][point_index(sr, 36.0)] / kLbfIn);
    const Spectrum a = spectrum(r2c.trajectory.time, m2c, t0, duration, 10), b = spectrum(fc.t, mc, t0, duration, 10),
                   p = spectrum(t2, m2p, t0, duration, 10), q = spectrum(fx.t, mp, t0, duration, 10);
    fmt::print("  share of SRMY(36)'s variance below 10 Hz (the machine's rigid-body modes are 1.6-9 Hz):\n");
    fmt::print("    chain: 2-D {:.3f} (dominant {:.2f} Hz), beam frame {:.3f} (dominant {:.2f} Hz)\n", a.share_below, a.dominant_hz, b.share_below,
               b.dominant_hz);
    fmt::print("    plow:  2-D {:.3f} (dominant {:.2f} Hz), beam frame {:.3f} (dominant {:.2f} Hz)\n", p.share_below, p.dominant_hz, q.share_below,
               q.dominant_hz);
    const Spectrum a0 = spectrum(r2c.trajectory.time, m2c, 0.0, duration, 10), b0 = spectrum(fc.t, mc, 0.0, duration, 10);
    fmt::print("    chain over the whole run 0-{:.1f} s (start-up included): 2-D {:.3f}, beam frame {:.3f}\n", duration, a0.share_below, b0.share_below);
    Series m3s;
    for (int i = 0; i < r3c.frame_loads_3d->points.time_count(); ++i) m3s.push_back(cut_3d(r3c.frame_loads_3d->points, i, 36 * kIn).srmy / kLbfIn);
    const Spectrum c0 = spectrum(fc.t, m3s, t0, duration, 10);
    double rd = 0, rs = 0;
    int nn = 0;
    double md = 0, ms = 0;
    for (std::size_t i = 0; i < fc.t.size(); ++i)
      if (fc.t[i] >= t0) {
        md += mc[i];
        ms += m3s[i];
        ++nn;
      }
    md /= nn;
    ms /= nn;
    for (std::size_t i = 0; i < fc.t.size(); ++i)
      if (fc.t[i] >= t0) {
        rd += (mc[i] - md) * (mc[i] - md);
        rs += (m3s[i] - ms) * (m3s[i] - ms);
      }
    fmt::print("    chain, static cut of the 3-D loads at 36 in: {:.3f} below 10 Hz (dominant {:.2f} Hz); beam frame dynamic / static RMS about the mean {:.2f}; "
               "means {:.0f} / {:.0f} lbf*in\n", c0.share_below, c0.dominant_hz, std::sqrt(rd / rs), md, ms);
    // Jumps: the change of the chain's loads across each tooth-count change against an ordinary sample step.
    const Series& cf = r3c.series.back().values;
    const Series& tc = r3c.trajectory.time;
    std::vector<double> ordinary, at_jump, force_jump;
    const double dt = tc[1] - tc[0];
    std::vector<double> jump_times;
    for (const auto& e : r3c.trajectory.events) jump_times.push_back(e.time);
    Series m3c;  // static cut of the 3-D chain loads at 36
    for (int i = 0; i < r3c.frame_loads_3d->points.time_count(); ++i) m3c.push_back(cut_3d(r3c.frame_loads_3d->points, i, 36 * kIn).srmy / kLbfIn);
    for (std::size_t i = 1; i < tc.size(); ++i) {
      if (tc[i] < t0) continue;
      bool jump = false;
      for (double tj : jump_times)
        if (tj > tc[i - 1] - 1e-12 && tj <= tc[i] + 1e-12) jump = true;
      const double d = std::abs(m3c[i] - m3c[i - 1]);
      if (jump && std::abs(cf[i] - cf[i - 1]) > 10 * kLbf) {
        at_jump.push_back(d);
        force_jump.push_back(std::abs(cf[i] - cf[i - 1]) / kLbf);
      } else if (!jump) {
        ordinary.push_back(d);
      }
    }
    auto median = [](std::vector<double> v) {
      if (v.empty()) return 0.0;
      std::sort(v.begin(), v.end());
      return v[v.size() / 2];
    };
    fmt::print("  3-D chain loads' cut at X = 36 in: {} chain-force jumps after {:.1f} s (median jump {:.0f} lbf); change of SRMY over one {:.5f} s "
               "step: median {:.0f} lbf*in at a jump, {:.1f} lbf*in otherwise (ratio {:.0f})\n",
               at_jump.size(), t0, median(force_jump), dt, median(at_jump), median(ordinary), median(at_jump) / std::max(median(ordinary), 1e-300));
    std::ofstream f(out / "chain_series_X36.csv");
    f << "time [s],chain_force [lbf],SRMY_2d [lbf*in],SRMY_3d_cut [lbf*in],SRMY_fe_dynamic [lbf*in],stress_top_fe_dynamic [psi],stress_top_2d [psi]\n";
    for (std::size_t i = 0; i < tc.size(); ++i)
      f << fmt::format("{:.5f},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g}\n", tc[i], cf[i] / kLbf, i < m2c.size() ? m2c[i] : std::nan(""), m3c[i],
                       mc[i], scf[i], i < sc2.size() ? sc2[i] : std::nan(""));
    std::vector<report::PlotSeries> ps(3);
    ps[0].name = "2-D Eq. 2.47 SRMY";
    ps[1].name = "static cut of the 3-D loads 24-31";
    ps[2].name = "beam frame, fixed rear end, dynamic";
    for (std::size_t i = 0; i < tc.size(); ++i) {
      if (i < m2c.size() && i < r2c.trajectory.time.size()) {
        ps[0].x.push_back(r2c.trajectory.time[i]);
        ps[0].y.push_back(m2c[i]);
      }
      ps[1].x.push_back(tc[i]);
      ps[1].y.push_back(m3c[i]);
      ps[2].x.push_back(tc[i]);
      ps[2].y.push_back(mc[i]);
    }
    plot(out / "qs_chain_cut_X36.png", "Digging chain, centred: vertical bending moment of the whole frame at X = 36 in", "time", "s", "SRMY (both rails)",
         "lbf*in", ps);
  }
  {  // Result 5 figure: stress at X = 36, plow and chain.
    std::vector<report::PlotSeries> ps(4);
    ps[0].name = "plow, 2-D Eq. 2.47d";
    ps[1].name = "plow, beam frame";
    ps[2].name = "chain, 2-D Eq. 2.47d";
    ps[3].name = "chain, beam frame";
    for (std::size_t i = 0; i < t2.size(); ++i) {
      ps[0].x.push_back(t2[i]);
      ps[0].y.push_back(sp2[i]);
      ps[1].x.push_back(fx.t[i]);
      ps[1].y.push_back(spf[i]);
    }
    for (std::size_t i = 0; i < r2c.trajectory.time.size(); ++i) {
      ps[2].x.push_back(r2c.trajectory.time[i]);
      ps[2].y.push_back(sc2[i]);
    }
    for (std::size_t i = 0; i < fc.t.size(); ++i) {
      ps[3].x.push_back(fc.t[i]);
      ps[3].y.push_back(scf[i]);
    }
    plot(out / "qs_stress_X36_plow_vs_chain.png", "Normal stress at the top of the rail at X = 36 in: plow and digging chain", "time", "s", "top-fiber normal stress", "psi", ps);
  }
  fmt::print("\nfiles in {}\n", out.string());
  return 0;
}
