// The static equilibrium on contacts that only push (rigid/contact_statics.h,
// docs/theory/rigid.md section 11) against hand computations:
//   - a rigid platform of weight W on four equal tires at the corners of a
//     rectangle (+-a, +-b), c.g. at (xg, yg): the reactions are linear in the
//     corner's position, R_i = W/4 (1 + xg x_i / a^2 + yg y_i / b^2), the
//     only distribution that satisfies force and moment balance with the
//     platform staying plane (equal springs);
//   - a beam on a front tire (x = +a), a rear tire (x = -a) and a bounce tire
//     far behind (x = -c): with the c.g. near the front the bilateral
//     solution pulls on the bounce tire; the one-sided statics lifts it and
//     the tires carry W by the lever rule, R_f = W (a + xg) / 2a, R_r = W (a - xg) / 2a,
//     and the bounce tire's "force" is k times its gap (negative);
//   - a c.g. beyond the tires (a beam on two): no equilibrium, and the error
//     names the lifted contact and the motion left free (Eq. 11.6);
//   - the shipped 2-D plow and 3-D offset-plowing machines started from
//     their statics stay there (to 1e-9) with no input: Eq. 11.4's b balances
//     gravity and the released contacts exactly.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <string>
#include <vector>

#include "coupling/rigid_study.h"
#include "coupling/rigid_study_3d.h"
#include "rigid/contact_statics.h"
#include "rigid/machine_2d.h"
#include "rigid/machine_3d.h"
#include "rigid/multibody.h"
#include "rigid/time_integration.h"
#include "rigid/vehicle_model.h"
#include "rigid/vehicle_run.h"

namespace {

using namespace framedyn;
constexpr double kG = 9.80665;

// A platform with coordinates (z, theta_x, theta_y), or a beam with (z, theta_y)
// (roll = false), and vertical contacts at (x, y).
struct Platform {
  bool roll;
  rigid::Multibody model;
  std::vector<rigid::ContactDefinition> contacts;
  Platform(double mass, const Eigen::Vector2d& cg, bool with_roll = true)
      : roll(with_roll), model(with_roll ? std::vector<std::string>{"z", "theta_x", "theta_y"} : std::vector<std::string>{"z", "theta_y"},
              with_roll ? std::vector<core::Quantity>{core::Quantity::length, core::Quantity::angle, core::Quantity::angle}
                        : std::vector<core::Quantity>{core::Quantity::length, core::Quantity::angle}) {
    rigid::Body b;
    b.name = "platform";
    b.mass = mass;
    b.inertia = Eigen::Matrix3d::Identity() * mass;
    b.translation = point(cg);
    b.rotation = rigid::Jacobian::Zero(3, model.size());
    if (roll) b.rotation(0, 1) = 1.0;
    b.rotation(1, model.size() - 1) = 1.0;
    model.add_body(b);
  }
  // Vertical displacement of a platform point: z + theta_x y - theta_y x.
  rigid::Jacobian point(const Eigen::Vector2d& p) const {
    rigid::Jacobian j = rigid::Jacobian::Zero(3, model.size());
    j(2, 0) = 1.0;
    if (roll) j(2, 1) = p.y();
    j(2, model.size() - 1) = -p.x();
    return j;
  }
  void add_contact(const std::string& name, const Eigen::Vector2d& at, double k) {
    const int pt = model.add_point({name, point(at)});
    const int e = model.add_element({name, pt, -1, Eigen::Vector3d::UnitZ(), k, 0.0});
    contacts.push_back({name, e, {}});
  }
  rigid::ContactStatics solve(rigid::ContactLaw law = rigid::ContactLaw::unilateral) const {
    return rigid::solve_contact_statics(model, rigid::gravity_force(model, kG), contacts, {}, law);
  }
};

TEST(ContactStatics, FourTiresCarryTheWeightByMomentBalance) {
  const double m = 3000.0, a = 1.5, b = 0.9, xg = 0.4, yg = -0.15, k = 4e5;
  Platform p(m, {xg, yg});
  const std::vector<Eigen::Vector2d> corners = {{a, b}, {a, -b}, {-a, b}, {-a, -b}};
  for (std::size_t i = 0; i < corners.size(); ++i) p.add_contact("tire_" + std::to_string(i), corners[i], k);
  const rigid::ContactStatics s = p.solve();
  const double w = m * kG;
  double total = 0.0;
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const double hand = w / 4.0 * (1.0 + xg * corners[i].x() / (a * a) + yg * corners[i].y() / (b * b));
    EXPECT_NEAR(s.element_forces[i], hand, 1e-9 * w) << p.contacts[i].name;
    EXPECT_TRUE(s.engaged[i]);
    total += s.element_forces[i];
  }
  EXPECT_NEAR(total, w, 1e-9 * w);
  EXPECT_EQ(s.changes, 0);
  EXPECT_LT(s.preload.norm(), 1e-9 * w);  // every contact engaged: the linear statics, b = 0
}

TEST(ContactStatics, ABounceTireThatWouldPullIsLiftedAndTheTiresCarryTheWeightByTheLeverRule) {
  const double m = 2000.0, a = 1.2, c = 3.0, xg = 0.9, k = 3e5, kb = 1e5;
  Platform p(m, {xg, 0.0}, false);
  p.add_contact("front_tire", {a, 0.0}, k);
  p.add_contact("rear_tire", {-a, 0.0}, k);
  p.add_contact("bounce_tire", {-c, 0.0}, kb);
  // Bilateral (the thesis's springs): the bounce tire pulls.
  const rigid::ContactStatics linear = p.solve(rigid::ContactLaw::linear);
  EXPECT_LT(linear.element_forces[2], -0.01 * m * kG);
  const rigid::ContactStatics s = p.solve();
  const double w = m * kG;
  EXPECT_TRUE(s.engaged[0]);
  EXPECT_TRUE(s.engaged[1]);
  EXPECT_FALSE(s.engaged[2]);
  EXPECT_NEAR(s.element_forces[0], w * (a + xg) / (2 * a), 1e-9 * w);
  EXPECT_NEAR(s.element_forces[1], w * (a - xg) / (2 * a), 1e-9 * w);
  // The lifted tire's force is k times its gap: the beam turns about its mid-point by
  // (R_f - R_r) / (2 k a) (nose down) and drops by W / 2k, so the point at -c rises by
  // theta c - W / 2k.
  const double theta = (s.element_forces[0] - s.element_forces[1]) / (2.0 * k * a);
  EXPECT_NEAR(s.element_forces[2], -kb * (theta * c - w / (2 * k)), 1e-9 * w);
  EXPECT_EQ(s.changes, 1);
}

TEST(ContactStatics, ACentreOfGravityBeyondTheTiresHasNoEquilibriumAndTheErrorNamesTheFreeMotion) {
  Platform p(1000.0, {2.0, 0.0}, false);
  p.add_contact("front_tire", {1.0, 0.0}, 1e5);
  p.add_contact("rear_tire", {-1.0, 0.0}, 1e5);
  try {
    p.solve();
    FAIL() << "expected StaticsError";
  } catch (const rigid::StaticsError& e) {
    EXPECT_EQ(e.lifted(), std::vector<std::string>{"rear_tire"});
    // Tipping about the front tire moves z and theta_y, in the coordinate table's order.
    EXPECT_EQ(e.motion(), (std::vector<std::string>{"z", "theta_y"}));
    EXPECT_EQ(std::string(e.what()),
              "no static equilibrium under gravity on contacts that only push: with rear_tire lifted (in tension when engaged), a motion of "
              "z, theta_y that nothing restrains (the machine would tip or roll)");
  }
}

// Starts a machine from q = v = 0 with no shaker, no travel and no ground input, and returns max |q| over 0.3 s.
double drift_from_statics(const rigid::VehicleModel& machine) {
  rigid::IntegrationOptions o;
  o.end_time = 0.3;
  o.output_interval = 0.01;
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(machine.size());
  rigid::VehicleRunState run = rigid::start_run(machine, 0.0, zero);
  rigid::VehicleDynamics dynamics(machine, run);
  const rigid::Trajectory tr = rigid::integrate_rk4(dynamics, zero, zero, 5e-4, o);
  double drift = 0.0;
  for (const Eigen::VectorXd& q : tr.q) drift = std::max(drift, q.cwiseAbs().maxCoeff());
  return drift;
}

TEST(ContactStatics, TheShipped2DPlowStartedFromItsStaticsStaysThere) {
  coupling::RigidStudy study = coupling::read_rigid_study(std::string(FRAMEDYN_SOURCE_DIR) + "/examples/r100_plow_2d.yaml");
  study.machine.plow.shaker_amplitude = 0.0;
  study.machine.forward_speed = 0.0;
  const rigid::VehicleModel machine = rigid::build_vehicle_model(study.machine);
  EXPECT_LT(drift_from_statics(machine), 1e-9);
  // The soil carries nothing statically; the contacts carry the weight with the cab mounts and cylinder inside.
  for (int e : machine.soil_elements) EXPECT_EQ(machine.statics.element_forces[static_cast<std::size_t>(e)], 0.0);
}

TEST(ContactStatics, TheShipped3DOffsetPlowStartedFromItsStaticsStaysThere) {
  coupling::RigidStudy3D study = coupling::read_rigid_study_3d(std::string(FRAMEDYN_SOURCE_DIR) + "/examples/offset_plowing.yaml");
  study.machine.plow.shaker_amplitude = 0.0;
  study.machine.forward_speed = 0.0;
  const rigid::VehicleModel machine = rigid::build_vehicle_model(study.machine);
  EXPECT_LT(drift_from_statics(machine), 1e-9);
  double weight = 0.0;
  for (const rigid::Body& b : machine.multibody.bodies()) weight += b.mass * study.machine.gravity;
  double carried = 0.0;
  for (std::size_t i = 0; i < machine.statics.contacts.size(); ++i)
    if (machine.statics.engaged[i]) carried += machine.statics.element_forces[static_cast<std::size_t>(machine.statics.contacts[i].normal)];
  EXPECT_NEAR(carried, weight, 1e-9 * weight);  // level ground: the vertical contacts carry the whole weight
}

}  // namespace
