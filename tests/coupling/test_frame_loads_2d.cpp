// Frame loads and stress resultants of the 2-D machine: the frame's free body
// must balance, and the resultants follow from the loads by statics.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>

#include "coupling/frame_loads_2d.h"
#include "coupling/rigid_study.h"
#include "rigid/time_integration.h"
#include "rigid/vehicle_model.h"
#include "rigid/vehicle_run.h"

namespace framedyn {
namespace {

// A study's model and one run of it (the state it left, its trajectory).
struct PlowRun {
  coupling::RigidStudy study;
  rigid::VehicleModel model;
  rigid::VehicleRunState state;
  rigid::Trajectory trajectory;
  std::vector<coupling::FrameLoad2D> loads() const { return coupling::frame_loads_2d(model, study.machine_2d(), state, trajectory); }
  coupling::StressResultants resultants(const std::vector<coupling::FrameLoad2D>& loads, const std::vector<double>& x) const {
    return coupling::frame_stress_resultants(model, study.machine_2d().frame, trajectory, loads, x);
  }
};

PlowRun plowing(double duration, const std::string& example = "r100_plow_2d.yaml") {
  PlowRun r;
  r.study = coupling::read_rigid_study(FRAMEDYN_SOURCE_DIR "/examples/" + example);
  r.model = rigid::build_vehicle_model(r.study.machine_2d());
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(r.model.size());
  rigid::IntegrationOptions o;
  o.end_time = duration;
  o.output_interval = 1e-3;
  rigid::VehicleRun run = rigid::run_vehicle(r.model, zero, zero, o);
  r.state = std::move(run.state);
  r.trajectory = std::move(run.trajectory);
  return r;
}

// Every force on the frame — tires, cab, added masses' inertia, the plow's
// pins and cylinder — plus the uniform section's own inertia must sum to zero
// in force and moment at every instant (d'Alembert on the frame body), since
// the loads come from Newton's laws on each attached part and the motion from
// the whole machine's equations. Cutting behind the rear end of everything
// leaves no load outside: SRX, SRZ and SRMY there are the frame's residual.
// Tolerance: round-off relative to the largest load (the shaker's 1.2e5 N).
TEST(FrameLoads2D, FrameFreeBodyBalancesAtEveryInstant) {
  const PlowRun r = plowing(0.2);
  const std::vector<coupling::FrameLoad2D> loads = r.loads();
  const double behind_everything = 10.0;  // m
  const coupling::StressResultants sr = r.resultants(loads, {behind_everything});
  double scale = 0.0;
  for (const auto& l : loads)
    for (const auto& f : l.force) scale = std::max(scale, f.norm());
  ASSERT_GT(scale, 1e3);
  for (std::size_t i = 0; i < r.trajectory.time.size(); ++i) {
    EXPECT_NEAR(sr.srx[i][0], 0.0, 1e-9 * scale) << "t = " << r.trajectory.time[i];
    EXPECT_NEAR(sr.srz[i][0], 0.0, 1e-9 * scale) << "t = " << r.trajectory.time[i];
    EXPECT_NEAR(sr.srmy[i][0], 0.0, 1e-9 * scale * 5.0) << "t = " << r.trajectory.time[i];  // moment arms up to ~5 m
  }
}

// The study reader refuses an added mass named like one of the machine's own
// loads (its inertia would be summed into that load at the wrong point), by
// the list part_load_names_2d. That list must be exactly the loads the plow
// and chain machines give besides their added masses.
TEST(FrameLoads2D, PartLoadNamesAreTheLoadsOfThePlowAndChainMachines) {
  std::set<std::string> given;
  for (const char* example : {"r100_plow_2d.yaml", "r100_chain_2d.yaml"}) {
    const PlowRun r = plowing(0.01, example);
    std::set<std::string> added;
    for (const rigid::AddedMass& a : r.study.machine_2d().frame.added_masses) added.insert(a.name);
    ASSERT_FALSE(added.empty()) << example;
    for (const coupling::FrameLoad2D& l : r.loads())
      if (!added.count(l.name)) given.insert(l.name);
  }
  const std::vector<std::string>& listed = coupling::part_load_names_2d();
  EXPECT_EQ(given, std::set<std::string>(listed.begin(), listed.end()));
}

// In front of the frame's front end there is nothing to cut: all resultants zero.
TEST(FrameLoads2D, ResultantsVanishInFrontOfTheFrame) {
  const PlowRun r = plowing(0.05);
  const auto loads = r.loads();
  const auto sr = r.resultants(loads, {-2.0});
  for (std::size_t i = 0; i < r.trajectory.time.size(); ++i) {
    EXPECT_EQ(sr.srx[i][0], 0.0);
    EXPECT_EQ(sr.srz[i][0], 0.0);
    EXPECT_EQ(sr.srmy[i][0], 0.0);
  }
}

// Statics of one cut by hand: with only the loads in front, the shear jumps
// by a load's Z force where the cut passes it, and the moment grows linearly
// with the distance between loads (dM/dX = the shear of the loads in front,
// plus the tube's share, which vanishes as the two cuts close in).
TEST(FrameLoads2D, MomentChangesBetweenCutsByShearTimesDistance) {
  const PlowRun r = plowing(0.05);
  const auto loads = r.loads();
  // Two cuts 1 mm apart between two loads (the front axle at X = 0 and the
  // ballast at -22 in): no load between them.
  const double xa = -0.20, xb = -0.199;
  const auto sr = r.resultants(loads, {xa, xb});
  for (std::size_t i = 0; i < r.trajectory.time.size(); ++i) {
    // SRMY(x) = sum M + sum F_x (Z_j - Z_op) + F_z (X_op - X_j) + tube: d SRMY/dX = sum F_z + tube share = -SRZ.
    const double slope = (sr.srmy[i][1] - sr.srmy[i][0]) / (xb - xa);
    EXPECT_NEAR(slope, -0.5 * (sr.srz[i][0] + sr.srz[i][1]), 1e-6 * std::max(1.0, std::abs(sr.srz[i][0])) + 1e-3);
  }
}

}  // namespace
}  // namespace framedyn
