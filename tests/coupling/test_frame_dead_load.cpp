// The static state of the frame model and static + dynamic superposition
// (issue 17; coupling/frame_dead_load.h, docs/theory/coupling.md section 11):
//  - gravity on a cantilever: root moment rho A g L^2 / 2 (+ m g L of a tip
//    mass), and rho A g (L - x)^2 / 2 inside the root element (the line load
//    added back by statics);
//  - a clamped-clamped beam under its weight: fixed-end moments w L^2 / 12,
//    w L^2 / 24 at mid-span;
//  - the shipped offset-plowing machine: the static loads at points 24-31 and
//    19 plus gravity on the frame model (tubes and parts) balance to
//    round-off, level and on a 10 degree slope (gravity stays along -Z of the
//    vehicle axes; along the ground normal the balance fails by sin 10 deg);
//  - static + dynamic against one Newmark integration started from the static
//    equilibrium under gravity (the same integrator and steps, linear: exact
//    superposition, to solver round-off);
//  - dead_load false leaves the dynamic outputs as they are.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <cstdio>

#include "coupling/frame_dead_load.h"
#include "coupling/frame_loads_3d.h"
#include "coupling/frame_study.h"
#include "coupling/load_mapping.h"
#include "coupling/rigid_study.h"
#include "fem/direct_integration.h"
#include "fem/distributed_loads.h"
#include "fem/section_forces.h"
#include "report/frame_outputs.h"
#include "rigid/machine_3d.h"
#include "tests/support/beam_meshes.h"
#include "tests/support/temp_dir.h"

namespace {

using namespace framedyn;
using Eigen::Vector3d;
const std::string kSource = FRAMEDYN_SOURCE_DIR;
constexpr double kG = 9.80665;

// A horizontal steel beam along X of `elements` elements, 2 m, a 60 x 40 mm rectangle; element set BEAM.
fem::FrameModel horizontal_beam(int elements) {
  framedyn::testing::StraightBeamSpec spec;
  spec.length = 2.0;
  spec.elements = elements;
  spec.section = fem::rectangle_section(0.06, 0.04, 0.3);
  spec.material = framedyn::testing::steel();
  fem::FrameModel m = framedyn::testing::straight_beam(spec);
  for (int e = 1; e <= elements; ++e) m.element_sets["BEAM"].push_back(e);
  return m;
}

double moment(const fem::SectionForces& f) { return std::hypot(f.my, f.mz); }

TEST(FrameDeadLoad, GravityOnACantileverGivesTheRootMomentRhoAgLSquaredOverTwoPlusTheTipMassesMgL) {
  fem::FrameModel m = horizontal_beam(4);
  framedyn::testing::clamp_node(m, 0);
  const double tip_mass = 12.0;
  m.point_masses.push_back({100, 4, tip_mass, Eigen::Matrix3d::Zero()});
  const coupling::FrameStaticState s = coupling::frame_static_state(m, Vector3d(0, 0, -kG), nullptr, nullptr, {{"beam", "BEAM"}}, 3);
  const double w = 7850.0 * 0.06 * 0.04 * kG, L = 2.0;  // N/m
  ASSERT_EQ(s.outputs.size(), 1u);
  const coupling::StaticStations& st = s.outputs[0];
  ASSERT_EQ(st.forces.size(), 12u);
  const double root = w * L * L / 2 + tip_mass * kG * L;
  std::printf("[ measured ] cantilever root moment %.9g N m (w L^2/2 + m g L = %.9g)\n", moment(st.forces[0]), root);
  EXPECT_NEAR(moment(st.forces[0]), root, 1e-9 * root);
  // Mid-element station of the root element, x = L/8: w (L - x)^2 / 2 + m g (L - x), exact with the line load.
  const double x = L / 8, inside = w * (L - x) * (L - x) / 2 + tip_mass * kG * (L - x);
  EXPECT_NEAR(moment(st.forces[1]), inside, 1e-9 * inside);
  // The shear at the root carries the whole weight; the reaction too.
  const double weight = w * L + tip_mass * kG;
  EXPECT_NEAR(std::hypot(st.forces[0].vy, st.forces[0].vz), weight, 1e-9 * weight);
  EXPECT_NEAR(s.reaction(2), weight, 1e-9 * weight);
  EXPECT_NEAR(s.weight, weight, 1e-9 * weight);
  // The peak: at the root's top or bottom fiber, M c / I = 6 M / (b h^2) for the section's bending plane.
  EXPECT_EQ(s.peak_normal_stress.element_id, 1);
  EXPECT_EQ(s.peak_normal_stress.station, 0);
}

TEST(FrameDeadLoad, ClampedClampedBeamUnderItsWeightHasFixedEndMomentsWLSquaredOverTwelve) {
  fem::FrameModel m = horizontal_beam(4);
  framedyn::testing::clamp_node(m, 0);
  framedyn::testing::clamp_node(m, 4);
  const coupling::FrameStaticState s = coupling::frame_static_state(m, Vector3d(0, 0, -kG), nullptr, nullptr, {{"beam", "BEAM"}}, 5);
  const double w = 7850.0 * 0.06 * 0.04 * kG, L = 2.0;
  const std::vector<fem::SectionForces>& f = s.outputs[0].forces;
  ASSERT_EQ(f.size(), 20u);
  const double end = w * L * L / 12, mid = w * L * L / 24;
  std::printf("[ measured ] clamped-clamped: end moments %.9g, %.9g N m (w L^2/12 = %.9g), mid-span %.9g N m (w L^2/24 = %.9g)\n", moment(f[0]),
              moment(f[19]), end, moment(f[9]), mid);
  EXPECT_NEAR(moment(f[0]), end, 1e-9 * end);
  EXPECT_NEAR(moment(f[19]), end, 1e-9 * end);
  EXPECT_NEAR(moment(f[9]), mid, 1e-9 * mid);   // element 2's end station: the middle of the span
  EXPECT_NEAR(moment(f[10]), mid, 1e-9 * mid);  // element 3's start station: the same point
  // Sagging at mid-span, hogging at the ends: opposite signs of the same component.
  EXPECT_LT(f[0].my * f[9].my + f[0].mz * f[9].mz, 0.0);
}

// The shipped machine's static loads and the frame model as the pipeline builds it, free-free (supports: none).
struct ShippedStatics {
  coupling::FrameStaticState state;
  double frame_assembly_weight = 0.0;  // N, the vehicle model's frame assembly (mesh tubes and parts)
};
ShippedStatics shipped_statics(double slope_deg, bool gravity_along_ground_normal = false) {
  coupling::RigidStudy study = coupling::read_rigid_study(kSource + "/examples/offset_plowing.yaml");
  study.machine_3d().ground_slope = slope_deg * 3.14159265358979323846 / 180.0;
  const rigid::VehicleModel machine = rigid::build_vehicle_model(study.machine_3d());
  const coupling::LoadHistory loads = coupling::all_frame_loads(coupling::static_frame_loads_3d(machine, study.machine_3d()));
  coupling::FrameStudyRequest q = *study.frame_response;
  fem::FrameModel model = coupling::read_frame_mesh(q);
  std::vector<coupling::LoadPointLocation> where;
  for (const auto& p : loads.points) where.push_back({p.name, p.location});
  coupling::LoadMapping mapping = coupling::map_load_points(model, where);
  coupling::mount_frame_parts(model, q.parts);
  mapping.distribution.conservativeResize(model.dof_count(), mapping.distribution.cols());
  const Eigen::VectorXd p = loads.component_matrix().col(0);
  const double g = study.machine_3d().gravity, th = study.machine_3d().ground_slope;
  const Vector3d gravity = gravity_along_ground_normal ? Vector3d(-g * std::sin(th), 0, -g * std::cos(th)) : q.gravity;
  ShippedStatics out;
  out.state = coupling::frame_static_state(model, gravity, &mapping.distribution, &p, q.rails, q.stations);
  out.frame_assembly_weight = rigid::combine(study.machine_3d().frame.parts, "frame").mass * g;
  return out;
}

TEST(FrameDeadLoad, ShippedOffsetPlowingStaticLoadsAndGravityBalanceToRoundOffLevelAndOnASlope) {
  for (double slope : {0.0, 10.0}) {
    const ShippedStatics s = shipped_statics(slope);
    std::printf("[ measured ] slope %g deg: weight %.6g N (vehicle frame assembly %.6g N); residual force %.2e W, moment %.2e W L; "
                "static peak %.6g Pa on %s element %d\n",
                slope, s.state.weight, s.frame_assembly_weight, s.state.force_residual, s.state.moment_residual, s.state.peak_normal_stress.value,
                s.state.peak_output.c_str(), s.state.peak_normal_stress.element_id);
    EXPECT_NEAR(s.state.weight, s.frame_assembly_weight, 1e-9 * s.frame_assembly_weight);
    EXPECT_LT(s.state.force_residual, 1e-9);
    EXPECT_LT(s.state.moment_residual, 1e-9);
    EXPECT_EQ(s.state.free_rigid_motions, 6);  // the mesh without the study's clamp: free-free, relief takes the round-off only
  }
  // Gravity turned with the ground (the wrong axes) leaves sin 10 deg of the weight unbalanced.
  const ShippedStatics wrong = shipped_statics(10.0, true);
  std::printf("[ measured ] gravity along the ground normal: residual force %.3e W (sin 10 deg = %.3e)\n", wrong.state.force_residual,
              std::sin(10.0 * 3.14159265358979323846 / 180.0));
  EXPECT_GT(wrong.state.force_residual, 0.1);
}

TEST(FrameDeadLoad, StaticPlusDynamicEqualsOneNewmarkIntegrationStartedFromTheStaticEquilibriumUnderGravity) {
  fem::FrameModel m = horizontal_beam(6);
  framedyn::testing::clamp_node(m, 0);
  m.point_masses.push_back({100, 6, 5.0, Eigen::Matrix3d::Zero()});
  // The dynamic load: a tip force, a ramp then a 25 Hz oscillation, 0.1 s at 1 ms.
  fem::TransientInput dyn;
  const int n = 101;
  dyn.times = Eigen::VectorXd::LinSpaced(n, 0.0, 0.1);
  dyn.components.resize(2, n);
  for (int k = 0; k < n; ++k) {
    const double t = dyn.times(k);
    dyn.components(0, k) = 300.0 * std::min(1.0, t / 0.02) * std::sin(2 * 3.14159265358979323846 * 25 * t);  // Z
    dyn.components(1, k) = 150.0 * std::min(1.0, t / 0.05);                                                  // Y
  }
  std::vector<Eigen::Triplet<double>> trip = {{6 * 6 + 2, 0, 1.0}, {6 * 6 + 1, 1, 1.0}};
  dyn.distribution.resize(m.dof_count(), 2);
  dyn.distribution.setFromTriplets(trip.begin(), trip.end());
  fem::NewmarkOptions no;
  no.rayleigh_alpha = 1.0;
  no.rayleigh_beta = 2e-4;
  no.substeps = 2;
  const Vector3d g(0, 0, -kG);
  // Static + dynamic: the static state, and Newmark on the dynamic load alone from rest at u = 0.
  const coupling::FrameStaticState s = coupling::frame_static_state(m, g, nullptr, nullptr, {{"beam", "BEAM"}}, 3);
  const fem::FrameDynamics frame(m);
  const fem::TransientResult d = fem::direct_transient(frame, dyn, no);
  // One integration: gravity as one more constant component, started from the static equilibrium under it.
  const fem::FrameModel weighted = coupling::with_gravity(m, g);
  fem::TransientInput all = dyn;
  const Eigen::VectorXd fg = fem::applied_load_vector(weighted);
  for (Eigen::Index i = 0; i < fg.size(); ++i)
    if (fg(i) != 0.0) trip.emplace_back(static_cast<int>(i), 2, fg(i));
  all.distribution.resize(m.dof_count(), 3);
  all.distribution.setFromTriplets(trip.begin(), trip.end());
  all.components.conservativeResize(3, Eigen::NoChange);
  all.components.row(2).setOnes();
  const fem::TransientResult one = fem::direct_transient(frame, all, no);
  ASSERT_EQ(one.displacement.cols(), d.displacement.cols());
  double scale = 0.0, worst = 0.0, m_scale = 0.0, m_worst = 0.0;
  const std::vector<fem::BeamLineLoad> line = fem::beam_line_loads(weighted);
  for (Eigen::Index j = 0; j < one.displacement.cols(); ++j) {
    const Eigen::VectorXd total = s.displacement + d.displacement.col(j);
    scale = std::max(scale, one.displacement.col(j).cwiseAbs().maxCoeff());
    worst = std::max(worst, (total - one.displacement.col(j)).cwiseAbs().maxCoeff());
    // The root section forces: static (with the weight by statics) + dynamic against the one run's.
    const fem::SectionForces fd = fem::beam_stations(m, 0, d.displacement.col(j), 3)[0].forces;
    const fem::SectionForces fo = fem::beam_stations(weighted, 0, one.displacement.col(j), 3, line[0])[0].forces;
    const fem::SectionForces& fs = s.outputs[0].forces[0];
    m_scale = std::max(m_scale, std::hypot(fo.my, fo.mz));
    m_worst = std::max({m_worst, std::abs(fs.my + fd.my - fo.my), std::abs(fs.mz + fd.mz - fo.mz), std::abs(fs.vz + fd.vz - fo.vz)});
  }
  std::printf("[ measured ] static + dynamic vs one Newmark run: displacement %.2e of %.3e m, root moment %.2e of %.4g N m\n", worst, scale, m_worst,
              m_scale);
  // Newmark is linear in the load and the initial state, both runs take the same steps: only round-off separates them.
  EXPECT_LT(worst, 1e-9 * scale);
  EXPECT_LT(m_worst, 1e-9 * m_scale);
}

TEST(FrameDeadLoad, WithoutTheDeadLoadTheDynamicOutputsAreUnchangedAndNoStaticOutputAppears) {
  framedyn::testing::TempDir dir;
  // A short history at the front axle pin of the R-100-like frame, clamped at the rear end.
  coupling::LoadHistory h;
  h.times = Eigen::VectorXd::LinSpaced(41, 0.0, 0.04);
  h.points.push_back({"P25_FRONT_AXLE_PIN", Vector3d::Zero(), Eigen::MatrixXd::Zero(41, 6)});
  for (int k = 0; k < 41; ++k) h.points[0].values(k, 2) = 2000.0 * std::sin(2 * 3.14159265358979323846 * 30 * h.times(k));
  coupling::FrameStudyRequest q;
  q.file = (dir / "study.yaml").string();
  q.units = core::UnitSystem::from_name("in-lbf-s");
  q.mesh = kSource + "/meshes/r100_frame.inp";
  q.dead_load = false;
  const coupling::FrameStudyResults off = coupling::run_frame_study(q, &h);
  q.dead_load = true;
  const coupling::FrameStudyResults on = coupling::run_frame_study(q, &h);
  ASSERT_FALSE(off.static_state);
  ASSERT_TRUE(on.static_state);
  for (std::size_t r = 0; r < off.rails.size(); ++r) {
    EXPECT_FALSE(off.rails[r].has_static());
    EXPECT_TRUE(on.rails[r].has_static());
    // The dynamic part is computed as before, bit for bit.
    EXPECT_EQ(off.rails[r].envelope_normal_stress, on.rails[r].envelope_normal_stress);
    EXPECT_EQ(off.rails[r].series_bending_moment, on.rails[r].series_bending_moment);
    EXPECT_EQ(off.rails[r].peak_normal_stress.value, on.rails[r].peak_normal_stress.value);
    // Total at each station between |static - dynamic| and static + dynamic envelopes (the triangle inequality per point).
    for (Eigen::Index k = 0; k < on.rails[r].envelope_total_normal_stress.size(); ++k)
      EXPECT_LE(on.rails[r].envelope_total_normal_stress(k),
                on.rails[r].static_normal_stress(k) + on.rails[r].envelope_normal_stress(k) + 1e-9 * on.rails[r].envelope_normal_stress.maxCoeff());
  }
  const nlohmann::ordered_json js_off = report::frame_summary(off, q);
  EXPECT_FALSE(js_off.contains("static"));
  EXPECT_FALSE(js_off.contains("peak_total_normal_stress"));
  const nlohmann::ordered_json js_on = report::frame_summary(on, q);
  EXPECT_TRUE(js_on.contains("static"));
  EXPECT_TRUE(js_on.contains("peak_total_normal_stress"));
  // Everything that was in the summary without the dead load is there unchanged with it (the rails gain their total peaks only),
  // but the hot spots, which rank the total von Mises stress (static + dynamic; docs/theory/coupling.md section 10).
  const std::set<std::string> of_the_total = {"hot_spots", "hot_spots_by_normal_stress_range", "peak_von_mises", "hot_spot_window"};
  for (const auto& [key, value] : js_off.items()) {
    if (key == "rails" || of_the_total.count(key)) continue;
    EXPECT_EQ(js_on[key], value) << key;
  }
  // Without the dead load the hot spots' static part is zero and their total is the dynamic part;
  // with it the static part is the static state's von Mises stress at the point, nonzero on the clamped frame.
  for (const auto& h : js_off["hot_spots"]) {
    EXPECT_EQ(h["von_mises"]["static"].get<double>(), 0.0);
    EXPECT_EQ(h["von_mises"]["total"], h["von_mises"]["dynamic"]);
  }
  EXPECT_GT(js_on["hot_spots"][0]["von_mises"]["static"].get<double>(), 0.0);
  EXPECT_EQ(js_on["hot_spot_window"]["static_state"], "static section forces added: total = static + dynamic");
  for (const auto& [rail, value] : js_off["rails"].items())
    for (const auto& [key, v] : value.items()) {
      EXPECT_EQ(js_on["rails"][rail][key], v) << rail << "." << key;
    }
}

}  // namespace
