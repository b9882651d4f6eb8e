// The frame transient study on the R-100-like frame: a load history at the
// load points through the mesh to the rail stresses, read from a YAML study.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <thread>

#include "core/error.h"
#include "core/results_folder.h"
#include "core/work_share.h"
#include "coupling/frame_study.h"
#include "fem/section_forces.h"
#include "fem/section_stress.h"
#include "report/frame_outputs.h"
#include "tests/support/temp_dir.h"

namespace {

using namespace framedyn;
constexpr double kPi = 3.14159265358979323846;

// Loads in in-lbf-s at the eight load points, 0.2 s at 1 kHz: 5 Hz and 31 Hz
// components (a vibratory plow's shaker runs near there), self-consistent
// enough to exercise every path; not a machine simulation.
std::string load_file() {
  const char* names[] = {"P24_REEL", "P25_FRONT_AXLE_PIN", "P26_REAR_AXLE_PIN", "P27_LEVELING_CYLINDER",
                         "P28_CAB_MOUNT_FL", "P29_CAB_MOUNT_FR", "P30_CAB_MOUNT_RL", "P31_CAB_MOUNT_RR"};
  const double xy[8][2] = {{-25, 0}, {0, 0}, {72, 0}, {68, 15}, {20, -15}, {20, 15}, {52, -15}, {52, 15}};
  coupling::LoadHistory h;
  const int n = 201;
  h.times = Eigen::VectorXd::LinSpaced(n, 0.0, 0.2);
  const core::UnitSystem u = core::UnitSystem::from_name("in-lbf-s");
  for (int p = 0; p < 8; ++p) {
    coupling::LoadPointHistory lp;
    lp.name = names[p];
    // P24 sits 10 in above its node: mapped by a rigid link.
    lp.location = Eigen::Vector3d(xy[p][0], xy[p][1], p == 0 ? 10.0 : 0.0) * 0.0254;
    lp.values.resize(n, 6);
    for (int k = 0; k < n; ++k) {
      const double t = h.times(k);
      for (int c = 0; c < 6; ++c) {
        const double amp = c < 3 ? (c == 2 ? 800.0 : 150.0) : 2000.0;
        const double v = amp * (0.5 + std::sin(2 * kPi * 5 * t + p + c) + 0.3 * std::sin(2 * kPi * 31 * t + 2 * p + c));
        lp.values(k, c) = u.to_si(v, c < 3 ? core::Quantity::force : core::Quantity::moment);
      }
    }
    h.points.push_back(lp);
  }
  return coupling::format_load_history(h, u);
}

std::string study(const std::string& frame_block) {
  return "framedyn_study: 1\nname: frame test\nunits: in-lbf-s\nmodel: frame_transient\nframe:\n  mesh: " + std::string(FRAMEDYN_SOURCE_DIR) +
         "/meshes/r100_frame.inp\n  loads: loads.csv\n" + frame_block +
         "  outputs:\n    left_rail: {element_set: LEFT_RAIL, history: false}\n    right_rail: {element_set: RIGHT_RAIL, history: false}\n";
}

TEST(FrameStudy, ModeAccelerationWithAllModesMatchesDirectIntegrationOnR100Frame) {
  framedyn::testing::TempDir dir;
  dir.write("loads.csv", load_file());
  const auto ma = coupling::read_frame_study(
      dir.write("ma.yaml", study("  supports: fixed_rear_end\n  modes: all\n  method: mode_acceleration\n"
                                 "  damping: {rayleigh: {alpha: 2.0, beta: 1.0e-5}}\n  stations: 5\n")).string());
  auto direct = ma;
  direct.method = coupling::FrameMethod::direct;
  direct.direct_substeps = 16;
  const auto a = coupling::run_frame_study(ma);
  const auto d = coupling::run_frame_study(direct);
  for (std::size_t k = 0; k < 2; ++k) {
    const double pa = a.rails[k].peak_bending_moment.value, pd = d.rails[k].peak_bending_moment.value;
    std::cout << "[ measured ] " << a.rails[k].spec.name << ": peak bending moment, all modes " << pa << " N m, Newmark/16 " << pd
              << " N m, relative difference " << std::abs(pa - pd) / pa << "\n";
    // Newmark with 16 substeps of 1 ms resolves the modes that carry the response (< 200 Hz) to
    // (2 pi 200 Hz 62.5 us)^2 / 12 ~ 5e-4 in frequency; a peak differs by less than 1e-2.
    EXPECT_NEAR(pd, pa, 1e-2 * pa);
    EXPECT_NEAR(d.rails[k].peak_normal_stress.value, a.rails[k].peak_normal_stress.value, 1e-2 * std::abs(a.rails[k].peak_normal_stress.value));
  }
  // The rails carry their loads mainly in bending, as the thesis found (>= 90 %).
  std::cout << "[ measured ] bending share at the peak stress: left " << a.rails[0].bending_share << ", right " << a.rails[1].bending_share << "\n";
  EXPECT_TRUE(a.mapping.points[1].at_node);
  EXPECT_FALSE(a.mapping.points[0].at_node);
}

TEST(FrameStudy, FreeFreeInertiaReliefRunsAndWritesSummaryAndParaViewSeries) {
  framedyn::testing::TempDir dir;
  dir.write("loads.csv", load_file());
  const auto q = coupling::read_frame_study(
      dir.write("ff.yaml", study("  supports: free_free_inertia_relief\n  modes: 20\n  method: mode_acceleration\n"
                                 "  damping: {modal_ratio: 0.02}\n  output_interval: 0.01\n  pvd: true\n")).string());
  const auto r = coupling::run_frame_study(q);
  EXPECT_EQ(r.response.times.size(), 21);  // every 10th of 201 times
  EXPECT_EQ(r.frequencies_hz.size(), 20);
  EXPECT_GT(r.frequencies_hz(0), 1.0);     // rigid-body modes are not among the elastic ones
  core::ResultsFolder folder(dir / "out");
  report::write_frame_outputs(r, q, folder);
  const std::string json = report::frame_summary_json(r, q);
  folder.write_text("frame_summary.json", json);
  folder.commit();
  for (const char* f : {"frame_modes.csv", "frame_rails_envelope.csv", "frame_rails_series.csv", "frame_response.pvd",
                        "frame_response_00000.vtu", "frame_response_00020.vtu"})
    EXPECT_TRUE(std::filesystem::exists(dir / "out" / f)) << f;
  for (const char* key : {"\"frequency\"", "\"Hz\"", "\"left_rail\"", "\"right_rail\"", "\"peak_normal_stress\"", "\"unit\": \"lbf*in\"", "\"unit\": \"psi\""})
    EXPECT_NE(json.find(key), std::string::npos) << key;
}

TEST(FrameStudyInput, StrictErrorsNameKeyAndLine) {
  framedyn::testing::TempDir dir;
  auto error_of = [&](const std::string& block) {
    try {
      coupling::read_frame_study(dir.write("s.yaml", study(block)).string());
    } catch (const core::InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(error_of("  method: modal\n").find("frame.method"), std::string::npos);
  EXPECT_NE(error_of("  mthod: direct\n").find("mthod"), std::string::npos);
  EXPECT_NE(error_of("  supports: pinned\n").find("clamped, mesh_boundary, none (free_free_inertia_relief), axle_pins or fixed_rear_end"), std::string::npos);
  EXPECT_NE(error_of("  supports: clamped\n").find("frame.supports: expected supports: clamped with support_set"), std::string::npos);
  EXPECT_NE(error_of("  method: direct\n  damping: {modal_ratio: 0.02}\n").find("rayleigh"), std::string::npos);
  EXPECT_NE(error_of("  modes: 0\n").find("frame.modes"), std::string::npos);
  EXPECT_NE(error_of("  damping: {modal_ratio: 1.5}\n").find("[0, 1)"), std::string::npos);
  EXPECT_NE(error_of("  stations: 1\n").find("s.yaml:"), std::string::npos);
}

// The hot spots of a frame study (coupling/hot_spots.h): the steady start
// from the rigid model's report before frame.steady_from; the top hot spot's
// von Mises stress recomputed from the displacements in double precision
// (fem::beam_stations, fem::point_stress) at its time; and no corner stress
// above the peak von Mises (sigma_vM >= |sigma| at every point).
TEST(FrameStudy, HotSpotsTakeTheSteadyStartInOrderAndMatchARecomputationFromTheDisplacements) {
  framedyn::testing::TempDir dir;
  dir.write("loads.csv", load_file());
  const auto q = coupling::read_frame_study(
      dir.write("hs.yaml", study("  supports: fixed_rear_end\n  modes: 20\n  stations: 5\n  steady_from: 0.15\n")).string());
  const coupling::FrameStudyResults own = coupling::run_frame_study(q);
  EXPECT_EQ(own.hot_spots.window.from, 0.15);
  EXPECT_EQ(own.hot_spots.window.source, "frame.steady_from");
  const coupling::FrameStudyResults r = coupling::run_frame_study(q, nullptr, nullptr, 0.08);
  EXPECT_EQ(r.hot_spots.window.from, 0.08);
  EXPECT_EQ(r.hot_spots.window.source, "rigid-body model's steady report");
  EXPECT_EQ(r.hot_spots.startup_times, 80u);  // t = 0 .. 0.079 s at 1 kHz
  ASSERT_EQ(r.hot_spots.by_von_mises.size(), 10u);
  const coupling::HotSpot& top = r.hot_spots.by_von_mises.front();
  const coupling::StressStation& st = r.stress.stations[top.station];
  Eigen::Index j = 0;
  while (std::abs(r.response.times(j) - top.time) > 1e-12) ++j;
  const int b = r.model.beam_index(st.element_id);
  const fem::StationResult at = fem::beam_stations(r.model, b, r.response.displacement.col(j), 5)[static_cast<std::size_t>(st.station)];
  const fem::SectionProperties& sec = r.model.sections[static_cast<std::size_t>(st.section)].properties;
  const double recomputed = fem::point_stress(sec, fem::section_points(sec)[static_cast<std::size_t>(top.point)], at.forces).von_mises;
  std::cout << "[ measured ] top hot spot " << st.set << " element " << st.element_id << " station " << st.station << " " << top.point_name
            << ": " << top.von_mises_total << " Pa at t = " << top.time << " s; recomputed in double " << recomputed << " Pa\n";
  // Single-precision section forces: 1e-6 relative.
  EXPECT_NEAR(top.von_mises_total, recomputed, 1e-6 * recomputed);
  EXPECT_EQ(top.von_mises_total, top.von_mises_dynamic);  // no static state: total = dynamic
  for (std::size_t k = 1; k < r.hot_spots.by_von_mises.size(); ++k)
    EXPECT_GE(r.hot_spots.by_von_mises[k - 1].von_mises_total, r.hot_spots.by_von_mises[k].von_mises_total * (1 - 1e-6));
  for (const coupling::RailRecovery& rail : r.rails)
    EXPECT_GE(r.hot_spots.peak.von_mises_total, std::abs(rail.peak_normal_stress.value) * (1 - 1e-6)) << rail.spec.name;
}

}  // namespace

namespace {

// The load file's history as a request built in code (R-100-like frame, free-free, dead load on: the pipeline's path).
coupling::FrameStudyRequest pipeline_request(const framedyn::testing::TempDir& dir, coupling::FrameSupports supports) {
  coupling::FrameStudyRequest q;
  q.file = (dir / "study.yaml").string();
  q.units = core::UnitSystem::from_name("in-lbf-s");
  q.mesh = std::string(FRAMEDYN_SOURCE_DIR) + "/meshes/r100_frame.inp";
  q.loads = dir / "loads.csv";
  q.supports = supports;
  q.support_sets = {"REAR_END"};
  q.modes = -1;  // all: the pipeline's (examples/offset_plowing.yaml)
  q.dead_load = true;
  q.output_interval = 0.01;
  return q;
}

double largest_difference(const Eigen::VectorXd& a, const Eigen::VectorXd& b) { return (a - b).cwiseAbs().maxCoeff(); }

}  // namespace

// Issue 17: the modes, the dynamic response (mode acceleration's static
// correction) and the static state share one assembly of K and M and one
// factorisation per support; the rigid-body mass is one mass-only assembly.
// Counted by fem/solver_counters.h, not timed.
TEST(FrameStudy, OnePipelineRunAssemblesAndFactorisesTheFrameOncePerSupport) {
  framedyn::testing::TempDir dir;
  dir.write("loads.csv", load_file());
  for (const coupling::FrameSupports s : {coupling::FrameSupports::free_free_inertia_relief, coupling::FrameSupports::fixed_rear_end,
                                          coupling::FrameSupports::axle_pins}) {
    const coupling::FrameStudyResults r = coupling::run_frame_study(pipeline_request(dir, s));
    ASSERT_TRUE(r.static_state) << coupling::supports_name(s);
    EXPECT_EQ(r.solver_counts.system_assemblies, 1) << coupling::supports_name(s);
    EXPECT_EQ(r.solver_counts.factorisations, 1) << coupling::supports_name(s);
    EXPECT_EQ(r.solver_counts.mass_assemblies, 1) << coupling::supports_name(s);
  }
  // modes: N adds the shift-invert Lanczos's own matrices (K - sigma M, M, the Sturm count's LDL^T), never a second K.
  coupling::FrameStudyRequest q = pipeline_request(dir, coupling::FrameSupports::free_free_inertia_relief);
  q.modes = 12;
  const coupling::FrameStudyResults r = coupling::run_frame_study(q);
  std::printf("[ measured ] modes: 12: %ld system assemblies, %ld mass assemblies, %ld factorisations\n", r.solver_counts.system_assemblies,
              r.solver_counts.mass_assemblies, r.solver_counts.factorisations);
  EXPECT_EQ(r.solver_counts.system_assemblies, 1);
  EXPECT_EQ(r.solver_counts.mass_assemblies, 2);  // the rigid-body mass and compute_modes' total mass over all DOFs (Eq. 7.4)
  EXPECT_GE(r.solver_counts.factorisations, 4);   // K on the auxiliary supports, K - sigma M, M, at least one Sturm count
}

// Section 12 of docs/theory/coupling.md: inertia relief leaves no reaction at a
// statically determinate support, so holding the free-free frame at the axle
// pins instead of the solver's 3-2-1 choice changes no stress, static or dynamic
// (the vehicle model's pin forces are loads on the frame model, as under none).
TEST(FrameStudy, AxlePinsGiveTheStressesOfFreeFreeInertiaReliefToSolverTolerance) {
  framedyn::testing::TempDir dir;
  dir.write("loads.csv", load_file());
  const coupling::FrameStudyResults none = coupling::run_frame_study(pipeline_request(dir, coupling::FrameSupports::free_free_inertia_relief));
  const coupling::FrameStudyResults pins = coupling::run_frame_study(pipeline_request(dir, coupling::FrameSupports::axle_pins));
  ASSERT_EQ(pins.pin_supports.size(), 6u);
  EXPECT_EQ(pins.free_rigid_motions, 6);
  // The pins: rear axle pin (node 50) UX UY UZ, front axle pin (node 47) UY UZ, leveling cylinder (node 41) UZ.
  EXPECT_EQ(pins.model.nodes[static_cast<std::size_t>(pins.pin_supports[0] / 6)].id, 50);
  EXPECT_EQ(pins.model.nodes[static_cast<std::size_t>(pins.pin_supports[3] / 6)].id, 47);
  EXPECT_EQ(pins.model.nodes[static_cast<std::size_t>(pins.pin_supports[5] / 6)].id, 41);
  ASSERT_EQ(none.rails.size(), pins.rails.size());
  for (std::size_t k = 0; k < none.rails.size(); ++k) {
    const coupling::RailRecovery &a = none.rails[k], &b = pins.rails[k];
    const double scale = a.envelope_normal_stress.cwiseAbs().maxCoeff();
    const double dynamic = largest_difference(a.envelope_normal_stress, b.envelope_normal_stress);
    const double total = largest_difference(a.envelope_total_normal_stress, b.envelope_total_normal_stress);
    std::printf("[ measured ] %s: none vs axle_pins: dynamic envelope %.2e, total %.2e of %.4g Pa\n", a.spec.name.c_str(), dynamic, total, scale);
    EXPECT_GT(scale, 1e5);  // the loads do stress the rails (the comparison is not of zeros)
    EXPECT_LT(dynamic, 1e-8 * scale);
    EXPECT_LT(total, 1e-8 * scale);
  }
  // The relieved loads leave the pins no reaction (Eq. T.11): the pin forces stay the vehicle model's.
  fem::FrameModel model = coupling::read_frame_mesh(pipeline_request(dir, coupling::FrameSupports::axle_pins));
  const fem::FrameDynamics frame(model, pins.pin_supports);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(frame.dofs().free_count());
  f(frame.dofs().free_index[6 * 44 + 2]) = 1000.0;  // a vertical load at one node, far from the pins
  f(frame.dofs().free_index[6 * 10 + 1]) = -400.0;
  const Eigen::VectorXd held = frame.auxiliary_reactions(frame.relieve(f));
  std::printf("[ measured ] pin reactions under a relieved load: %.2e N of 1000 N\n", held.cwiseAbs().maxCoeff());
  EXPECT_LT(held.cwiseAbs().maxCoeff(), 1e-9 * 1000.0);
  // Unrelieved, the pins do react (the test is not of a support that holds nothing).
  EXPECT_GT(frame.auxiliary_reactions(f).cwiseAbs().maxCoeff(), 100.0);
}

// Duty cycles (coupling/duty_cycle.cpp) hand a frame study's station and output-time loops to
// idle workers (core/work_share.h), and keep no output before the steady window
// (ModalTransientOptions::outputs_from). Neither may change a number: with a worker in
// help() beside the run, and against the run that keeps its whole record, the window's
// displacements, section forces, stresses, hot spots and life map are the same doubles.
TEST(FrameStudy, AnIdleWorkerTakingStationsAndTimesAndSkippingTheLeadInChangesNoNumber) {
  framedyn::testing::TempDir dir;
  dir.write("loads.csv", load_file());
  const coupling::FrameStudyRequest whole = coupling::read_frame_study(
      dir.write("life.yaml", study("  supports: fixed_rear_end\n  modes: 20\n  stations: 5\n  steady_from: 0.1\n"
                                   "  fatigue: {code: IIW, default: FAT71}\n"))
          .string());
  coupling::FrameStudyRequest windowed = whole;
  windowed.window_lead_in_decay = 1e-3;  // a lead-in longer than the record: integrated from its start, outputs from 0.1 s
  const coupling::FrameStudyResults serial = coupling::run_frame_study(windowed);
  const coupling::FrameStudyResults full = coupling::run_frame_study(whole);
  framedyn::core::WorkShare share;
  std::atomic<bool> done{false};
  std::thread helper([&] { share.help([&] { return done.load(); }); });
  const coupling::FrameStudyResults shared = coupling::run_frame_study(windowed, nullptr, nullptr, std::nullopt, nullptr, &share);
  done = true;
  share.wake();
  helper.join();
  std::printf("[ measured ] chunks taken by the idle worker: %zu\n", share.shared_chunks());

  ASSERT_TRUE(serial.window_only);
  ASSERT_EQ(serial.response.times.size(), 101);  // 0.1 .. 0.2 s at 1 kHz
  EXPECT_EQ(serial.response.times(0), 0.1);
  const Eigen::Index first = full.response.times.size() - serial.response.times.size();
  EXPECT_TRUE(serial.response.times == full.response.times.tail(serial.response.times.size()));
  EXPECT_TRUE(serial.response.displacement == full.response.displacement.rightCols(serial.response.times.size()));
  EXPECT_TRUE(serial.stress.forces == full.stress.forces.rightCols(serial.response.times.size()));
  EXPECT_EQ(first, 100);

  EXPECT_TRUE(shared.response.times == serial.response.times);
  EXPECT_TRUE(shared.response.displacement == serial.response.displacement);
  EXPECT_TRUE(shared.stress.forces == serial.stress.forces);
  for (std::size_t k = 0; k < serial.sections.size(); ++k) EXPECT_TRUE(shared.sections[k].values == serial.sections[k].values) << k;
  ASSERT_EQ(shared.hot_spots.by_von_mises.size(), serial.hot_spots.by_von_mises.size());
  for (std::size_t k = 0; k < serial.hot_spots.by_von_mises.size(); ++k) {
    const coupling::HotSpot &a = shared.hot_spots.by_von_mises[k], &b = serial.hot_spots.by_von_mises[k];
    EXPECT_EQ(a.station, b.station);
    EXPECT_EQ(a.point, b.point);
    EXPECT_EQ(a.von_mises_total, b.von_mises_total);
    EXPECT_EQ(a.time, b.time);
    EXPECT_EQ(a.normal_stress_range, b.normal_stress_range);
  }
  ASSERT_TRUE(serial.life && shared.life && full.life);
  EXPECT_EQ(shared.life->damage_per_hour, serial.life->damage_per_hour);
  EXPECT_EQ(shared.life->normal_max_range, serial.life->normal_max_range);
  EXPECT_EQ(shared.life->correlation, serial.life->correlation);
  EXPECT_EQ(full.life->damage_per_hour, serial.life->damage_per_hour);  // the window's histories are the same doubles
  EXPECT_GT(serial.life->max_damage_per_hour(), 0.0);
}
