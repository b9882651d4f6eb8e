// Every load on the frame reaches the frame model, and the model balances it
// (issue 17). On the shipped R-100-like machine plowing offset (the README's
// main job, examples/offset_plowing.yaml, first 0.25 s: the start-up with
// the clamped run's peak at 0.122 s) and its mesh (meshes/r100_frame.inp):
//  - the bare frame model's rigid-body mass equals the mesh's hand-computed
//    mass properties (docs/meshes/r100_frame.md, checked there against
//    CalculiX), an independent route to Eq. C.9;
//  - the resultant of the loads as the mesh receives them (points 24-31 and
//    the plow's at its swing pin, point 19, through the hitch spider) equals
//    the vehicle model's d'Alembert force of the frame assembly at every
//    sample: nothing is lost between the vehicle model and the mesh; without
//    point 19 the loads are far from balanced;
//  - free-free with inertia relief, the applied loads minus the model's
//    inertia forces (rigid-body acceleration plus the elastic modes'
//    accelerations) have zero resultant force and moment at every output time.
// The inertia-relief acceleration is printed beside the vehicle model's
// frame acceleration (docs/validation.md, "Supports side by side").
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "coupling/frame_balance.h"
#include "coupling/frame_loads_3d.h"
#include "coupling/frame_study.h"
#include "coupling/load_mapping.h"
#include "coupling/rigid_study.h"
#include "fem/assembly.h"
#include "fem/inp_reader.h"
#include "rigid/machine_3d.h"
#include "tests/support/temp_dir.h"

namespace {

using namespace framedyn;
using Eigen::Vector3d;
const std::string kSource = FRAMEDYN_SOURCE_DIR;
constexpr double kInch = 0.0254, kLbf = 4.4482216152605;
constexpr double kMassUnit = kLbf / kInch;  // lbf s^2/in in kg

std::string read_text(const std::string& p) {
  std::ifstream in(p);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The main job's first 0.25 s, vehicle model only (the frame block is read, not run).
struct Start {
  coupling::RigidStudy study;
  coupling::RigidResults results;
};
const Start& offset_plowing() {
  static const Start start = [] {
    const framedyn::testing::TempDir dir("framedyn_test_frame_balance");
    std::string t = read_text(kSource + "/examples/offset_plowing.yaml");
    const auto swap = [&](const std::string& from, const std::string& to) {
      const std::size_t at = t.find(from);
      if (at == std::string::npos) throw std::logic_error("examples/offset_plowing.yaml has no '" + from + "'");
      t.replace(at, from.size(), to);
    };
    swap("duration: 10.0", "duration: 0.25");
    swap("../meshes/r100_frame.inp", kSource + "/meshes/r100_frame.inp");
    Start out;
    out.study = coupling::read_rigid_study(dir.write("offset.yaml", t).string());
    out.results = coupling::run_rigid_study(out.study);
    return out;
  }();
  return start;
}
const coupling::RigidResults& offset_plowing_start() { return offset_plowing().results; }

fem::FrameModel r100_mesh() { return fem::read_inp(kSource + "/meshes/r100_frame.inp"); }

// The vehicle model's frame assembly: its d'Alembert force m a and moment about
// `about` (I alpha + (c - about) x m a) at sample i; its acceleration at `about`.
struct FrameAssemblyMotion {
  coupling::Vector6d inertia_force;   // force, moment about `about`
  Vector3d acceleration_at;           // m/s^2 at `about`
  Vector3d angular_acceleration;      // rad/s^2
};
FrameAssemblyMotion vehicle_frame(const rigid::VehicleModel& m, const rigid::Trajectory& tr, std::size_t i, const Vector3d& about) {
  const rigid::Body& frame = m.multibody.bodies()[static_cast<std::size_t>(m.frame_body)];
  const Vector3d cg = m.frame_cg;  // the frame parts' c.g. (rigid::combine)
  const Vector3d a = frame.translation * tr.a[i], alpha = frame.rotation * tr.a[i];
  FrameAssemblyMotion out;
  out.inertia_force << frame.mass * a, frame.inertia * alpha + (cg - about).cross(frame.mass * a);
  out.acceleration_at = a + alpha.cross(about - cg);
  out.angular_acceleration = alpha;
  return out;
}

TEST(FrameBalance, BareFrameModelHasTheTubesMassCentreOfGravityAndInertiaOfTheMeshDocument) {
  const coupling::RigidBodyMass b = coupling::frame_rigid_body_mass(r100_mesh());
  std::printf("[ measured ] bare frame model: mass %.6f lbf s^2/in (%.2f lb), c.g. (%.4f, %.2e, %.2e) in, IXX %.2f IYY %.2f IZZ %.2f lbf s^2 in\n",
              b.mass / kMassUnit, b.mass / kMassUnit * 386.09, b.cg.x() / kInch, b.cg.y() / kInch, b.cg.z() / kInch,
              b.inertia(0, 0) / (kMassUnit * kInch * kInch), b.inertia(1, 1) / (kMassUnit * kInch * kInch),
              b.inertia(2, 2) / (kMassUnit * kInch * kInch));
  // docs/meshes/r100_frame.md: 1.46508 lbf s^2/in (565.6 lb), c.g. X = 30.71 in on the centreline,
  // IXX 214.6, IYY 1719.2, IZZ 1922.5 lbf s^2 in about it; the tolerances are the document's rounding.
  EXPECT_NEAR(b.mass / kMassUnit, 1.46508, 0.5e-5);
  EXPECT_NEAR(b.cg.x() / kInch, 30.71, 0.005);
  EXPECT_NEAR(b.cg.y() / kInch, 0.0, 1e-9);
  EXPECT_NEAR(b.cg.z() / kInch, 0.0, 1e-9);
  const double iu = kMassUnit * kInch * kInch;
  EXPECT_NEAR(b.inertia(0, 0) / iu, 214.6, 0.05);
  EXPECT_NEAR(b.inertia(1, 1) / iu, 1719.2, 0.05);
  EXPECT_NEAR(b.inertia(2, 2) / iu, 1922.5, 0.05);
  EXPECT_NEAR(b.inertia(0, 1) / iu, 0.0, 1e-9);
}

TEST(FrameBalance, LoadsOnTheMeshIncludingTheSwingPinEqualTheVehicleFrameAssemblysInertiaForceAtEverySample) {
  const coupling::RigidResults& r = offset_plowing_start();
  ASSERT_TRUE(r.frame_loads_3d);
  const coupling::LoadHistory all = coupling::all_frame_loads(*r.frame_loads_3d);
  ASSERT_EQ(all.points.size(), 9u);
  EXPECT_EQ(all.points.back().name, "P19_PLOW_SWING_PIN");
  const fem::FrameModel mesh = r100_mesh();
  const coupling::RigidBodyMass body = coupling::frame_rigid_body_mass(mesh);
  std::vector<coupling::LoadPointLocation> where;
  for (const auto& p : all.points) where.push_back({p.name, p.location});
  const coupling::LoadMapping mapping = coupling::map_load_points(mesh, where);
  // Point 19 reaches the frame through the hitch spider on the rear end plate (nodes 22, 51, 44).
  EXPECT_EQ(mapping.points.back().nodes.size(), 3u);
  EXPECT_TRUE(mapping.points.back().from_node_set);
  const coupling::LoadResultants with = coupling::applied_load_resultants(mesh, body, mapping, all);
  // The same without point 19 (the mapping of points 24-31 alone).
  coupling::LoadHistory without = all;
  without.points.pop_back();
  where.pop_back();
  const coupling::LoadResultants without_19 = coupling::applied_load_resultants(mesh, body, coupling::map_load_points(mesh, where), without);

  const rigid::VehicleModel machine = rigid::build_vehicle_model(r.machine_3d());
  double scale_f = 0, scale_m = 0, worst_f = 0, worst_m = 0, missing_f = 0;
  // Inertia relief's rigid-body acceleration of the bare model against the vehicle model's frame
  // acceleration at the mesh's c.g., with and without point 19: least-squares slope and correlation.
  double sxy[2][3] = {}, sxx[3] = {}, syy[2][3] = {};
  for (std::size_t i = 0; i < r.trajectory.time.size(); ++i) {
    const FrameAssemblyMotion motion = vehicle_frame(machine, r.trajectory, i, body.cg);
    for (int k = 0; k < 3; ++k) {
      sxx[k] += motion.acceleration_at(k) * motion.acceleration_at(k);
      for (int w = 0; w < 2; ++w) {
        const double a = (w == 0 ? with : without_19).acceleration(k, static_cast<Eigen::Index>(i));
        sxy[w][k] += motion.acceleration_at(k) * a;
        syy[w][k] += a * a;
      }
    }
    const coupling::Vector6d inertia = motion.inertia_force;
    const coupling::Vector6d applied = with.resultant.col(static_cast<Eigen::Index>(i));
    scale_f = std::max(scale_f, inertia.head<3>().norm());
    scale_m = std::max(scale_m, inertia.tail<3>().norm());
    worst_f = std::max(worst_f, (applied - inertia).head<3>().norm());
    worst_m = std::max(worst_m, (applied - inertia).tail<3>().norm());
    missing_f = std::max(missing_f, (without_19.resultant.col(static_cast<Eigen::Index>(i)) - inertia).head<3>().norm());
  }
  std::printf("[ measured ] %zu samples: frame assembly's inertia force up to %.1f lbf, moment %.1f lbf in; applied minus inertia: %.2e lbf, "
              "%.2e lbf in; without point 19: %.1f lbf\n",
              r.trajectory.time.size(), scale_f / kLbf, scale_m / (kLbf * kInch), worst_f / kLbf, worst_m / (kLbf * kInch), missing_f / kLbf);
  for (int w = 0; w < 2; ++w)
    for (int k = 0; k < 3; ++k)
      std::printf("[ measured ] inertia relief (%s point 19) vs vehicle frame acceleration at the mesh c.g., %c: slope %.3f, correlation %.3f\n",
                  w == 0 ? "with" : "without", "XYZ"[k], sxy[w][k] / sxx[k], sxy[w][k] / std::sqrt(sxx[k] * syy[w][k]));
  // The vehicle model's frame free body balances to round-off (tests/rigid/test_vehicle_3d.cpp); the
  // spider keeps every point load's resultant (Eq. C.4): the two agree to round-off of the loads' size.
  EXPECT_LT(worst_f, 1e-9 * scale_f);
  EXPECT_LT(worst_m, 1e-9 * scale_m);
  // Without the plow's load at its swing pin the mesh misses most of the frame's loading.
  EXPECT_GT(missing_f, 0.5 * scale_f);
}

TEST(InertiaRelief, AppliedLoadsMinusTheFreeFrameModelsInertiaForcesHaveNoResultantAtEveryOutputTime) {
  const coupling::RigidResults& r = offset_plowing_start();
  const framedyn::testing::TempDir dir("framedyn_test_inertia_relief");
  // The shipped mesh with one node set of all its nodes, for the accelerations of every node.
  const std::string mesh = dir.write("frame.inp", "*INCLUDE, INPUT=" + kSource + "/meshes/r100_frame.inp\n*NSET, NSET=ALL_NODES, GENERATE\n1, 51, 1\n").string();
  coupling::FrameStudyRequest q;
  q.file = "test";
  q.units = core::UnitSystem::from_name("in-lbf-s");
  q.mesh = mesh;
  q.supports = coupling::FrameSupports::free_free_inertia_relief;
  q.modes = -1;
  q.method = coupling::FrameMethod::mode_acceleration;
  q.node_outputs = {{"all", "ALL_NODES"}};
  const coupling::LoadHistory loads = coupling::all_frame_loads(*r.frame_loads_3d);
  const coupling::FrameStudyResults f = coupling::run_frame_study(q, &loads);
  ASSERT_EQ(f.response.times.size(), loads.times.size());
  const fem::FrameModel& model = f.model;
  ASSERT_EQ(f.nodal.size(), 1u);
  ASSERT_EQ(f.nodal[0].nodes.size(), model.nodes.size());
  const coupling::RigidBodyMass body = coupling::frame_rigid_body_mass(model);
  const coupling::LoadResultants res = coupling::applied_load_resultants(model, body, f.mapping, f.loads);
  // M on all DOFs (no supports) and the rigid-body motions about the c.g.
  fem::AssemblyOptions full;
  full.storage = fem::Storage::full;
  const fem::SparseMatrix mass = fem::assemble(model, fem::make_dof_map(model), full).mass;
  const Eigen::MatrixXd t = fem::rigid_body_vectors(model, body.cg);
  Eigen::VectorXd el(model.dof_count());
  double worst_f = 0, worst_m = 0, scale_f = 0, scale_m = 0;
  for (Eigen::Index j = 0; j < f.response.times.size(); ++j) {
    const Eigen::VectorXd load = f.mapping.distribution * f.loads.components_at(static_cast<int>(j));
    for (std::size_t n = 0; n < f.nodal[0].nodes.size(); ++n)
      el.segment<6>(6 * f.nodal[0].nodes[n]) = f.nodal[0].acceleration.col(j).segment<6>(6 * static_cast<Eigen::Index>(n));
    const Eigen::VectorXd acceleration = t * res.acceleration.col(j) + el;  // rigid-body plus elastic
    const coupling::Vector6d residual = t.transpose() * (load - mass * acceleration);
    const coupling::Vector6d applied = t.transpose() * load;
    scale_f = std::max(scale_f, applied.head<3>().norm());
    scale_m = std::max(scale_m, applied.tail<3>().norm());
    worst_f = std::max(worst_f, residual.head<3>().norm());
    worst_m = std::max(worst_m, residual.tail<3>().norm());
  }
  std::printf("[ measured ] %lld output times: resultant of applied minus inertia forces %.2e of %.2e N, %.2e of %.2e N m\n",
              static_cast<long long>(f.response.times.size()), worst_f, scale_f, worst_m, scale_m);
  // Solver tolerance: the modal accelerations are M-orthogonal to the rigid-body motions to round-off of
  // the dense eigensolution (about 1e-12 of the loads).
  EXPECT_LT(worst_f, 1e-8 * scale_f);
  EXPECT_LT(worst_m, 1e-8 * scale_m);
}

}  // namespace

namespace {

// Least-squares slope of y on x and their correlation.
struct Fit {
  double slope, correlation;
};
Fit fit(const std::vector<double>& x, const std::vector<double>& y) {
  double sxy = 0, sxx = 0, syy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sxy += x[i] * y[i];
    sxx += x[i] * x[i];
    syy += y[i] * y[i];
  }
  return {sxy / sxx, sxy / std::sqrt(sxx * syy)};
}

// The shipped pipeline free-free (docs/theory/coupling.md, section 9): its frame
// model carries the frame assembly's parts, so its rigid-body mass is the vehicle
// model's frame assembly and inertia relief accelerates it as the vehicle model
// accelerates its frame, sample by sample, in translation and rotation.
TEST(FrameParts, ShippedPipelinesInertiaReliefAccelerationIsTheVehicleModelsFrameAcceleration) {
  const Start& s = offset_plowing();
  ASSERT_TRUE(s.study.frame_response);
  coupling::FrameStudyRequest q = *s.study.frame_response;  // the pipeline's own request: its parts from the study
  q.supports = coupling::FrameSupports::free_free_inertia_relief;
  q.support_sets.clear();
  q.paraview = coupling::ParaviewOutput::none;
  EXPECT_EQ(q.structure_part, "frame_structure");
  EXPECT_EQ(q.parts.size(), 5u);
  const coupling::LoadHistory loads = coupling::all_frame_loads(*s.results.frame_loads_3d);
  const coupling::FrameStudyResults f = coupling::run_frame_study(q, &loads);
  // The frame model's rigid-body mass is the vehicle model's frame assembly (Eq. 9.3), to round-off.
  const rigid::RigidPart3D vehicle = rigid::combine(s.results.machine_3d().frame.parts, "frame");
  const double iu = kMassUnit * kInch * kInch;
  std::printf("[ measured ] frame model with parts: %.6f lbf s^2/in (%.2f lb), c.g. (%.4f, %.2e, %.4f) in; vehicle frame assembly %.6f lbf s^2/in, "
              "c.g. (%.4f, %.2e, %.4f) in; inertia differs by %.1e relative\n",
              f.mass.mass / kMassUnit, f.mass.mass / kMassUnit * 386.09, f.mass.cg.x() / kInch, f.mass.cg.y() / kInch, f.mass.cg.z() / kInch,
              vehicle.mass / kMassUnit, vehicle.cg.x() / kInch, vehicle.cg.y() / kInch, vehicle.cg.z() / kInch,
              (f.mass.inertia - vehicle.inertia).norm() / vehicle.inertia.norm());
  EXPECT_NEAR(f.mass.mass, vehicle.mass, 1e-12 * vehicle.mass);
  EXPECT_LT((f.mass.cg - vehicle.cg).norm(), 1e-12 * kInch * 100);
  EXPECT_LT((f.mass.inertia - vehicle.inertia).norm(), 1e-11 * vehicle.inertia.norm());
  EXPECT_NEAR(f.mass.inertia(0, 0) / iu, vehicle.inertia(0, 0) / iu, 1e-9 * vehicle.inertia(0, 0) / iu);

  // Inertia relief's rigid-body acceleration at the assembly's c.g. against the vehicle model's, every sample.
  const coupling::LoadResultants res = coupling::applied_load_resultants(f.model, f.mass, f.mapping, f.loads);
  const rigid::VehicleModel machine = rigid::build_vehicle_model(s.results.machine_3d());
  std::vector<double> vehicle_a[6], relief_a[6];
  double worst = 0, scale = 0, worst_rot = 0, scale_rot = 0;
  for (std::size_t i = 0; i < s.results.trajectory.time.size(); ++i) {
    const FrameAssemblyMotion motion = vehicle_frame(machine, s.results.trajectory, i, f.mass.cg);
    const Eigen::Index j = static_cast<Eigen::Index>(i);
    for (int k = 0; k < 3; ++k) {
      vehicle_a[k].push_back(motion.acceleration_at(k));
      relief_a[k].push_back(res.acceleration(k, j));
      vehicle_a[3 + k].push_back(motion.angular_acceleration(k));
      relief_a[3 + k].push_back(res.acceleration(3 + k, j));
    }
    worst = std::max(worst, (res.acceleration.col(j).head<3>() - motion.acceleration_at).norm());
    scale = std::max(scale, motion.acceleration_at.norm());
    worst_rot = std::max(worst_rot, (res.acceleration.col(j).tail<3>() - motion.angular_acceleration).norm());
    scale_rot = std::max(scale_rot, motion.angular_acceleration.norm());
  }
  for (int k = 0; k < 6; ++k) {
    const Fit v = fit(vehicle_a[k], relief_a[k]);
    std::printf("[ measured ] inertia relief vs vehicle frame acceleration, %s: slope %.12f, correlation %.12f\n",
                (k < 3 ? std::string(1, "XYZ"[k]) : std::string("rotation ") + "XYZ"[k - 3]).c_str(), v.slope, v.correlation);
    EXPECT_NEAR(v.slope, 1.0, 1e-9);
  }
  std::printf("[ measured ] %zu samples: largest difference %.2e in/s^2 of %.4g in/s^2, %.2e rad/s^2 of %.4g rad/s^2\n",
              s.results.trajectory.time.size(), worst / kInch, scale / kInch, worst_rot, scale_rot);
  // The loads equal the vehicle model's frame-assembly inertia force to 1e-11 of their size (above) and
  // the masses agree to round-off: the accelerations agree to the same order.
  EXPECT_LT(worst, 1e-9 * scale);
  EXPECT_LT(worst_rot, 1e-9 * scale_rot);
}

}  // namespace
