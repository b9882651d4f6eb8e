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
//     gravity and the released contacts exactly;
//   - the shipped R-100-like machine's tire reactions against a hand
//     calculation from the weights and c.g.s its study file states (read here
//     with yaml-cpp, not with framedyn's reader): without its plow the machine
//     is statically determinate on its supports (2-D: two axles; 3-D: the
//     front axle rolling on its pin acts as one support at Y = 0, the rear
//     tires as two), so sum of forces and moments about the rear axle give
//     every reaction; with its plow the bounce tire is one support more, the
//     split among the three is indeterminate (it follows the stiffnesses),
//     and only the balance of forces and moments is checked.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "coupling/rigid_study.h"
#include "rigid/contact_statics.h"
#include "rigid/machine_2d.h"
#include "rigid/machine_3d.h"
#include "rigid/multibody.h"
#include "rigid/time_integration.h"
#include "rigid/vehicle_model.h"
#include "rigid/vehicle_run.h"
#include "tests/support/edited_example.h"
#include "tests/support/temp_dir.h"

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
  study.machine_2d().plow.shaker_amplitude = 0.0;
  study.machine_2d().forward_speed = 0.0;
  const rigid::VehicleModel machine = rigid::build_vehicle_model(study.machine_2d());
  EXPECT_LT(drift_from_statics(machine), 1e-9);
  // The soil carries nothing statically; the contacts carry the weight with the cab mounts and cylinder inside.
  for (int e : machine.soil_elements) EXPECT_EQ(machine.statics.element_forces[static_cast<std::size_t>(e)], 0.0);
}

TEST(ContactStatics, TheShipped3DOffsetPlowStartedFromItsStaticsStaysThere) {
  coupling::RigidStudy study = coupling::read_rigid_study(std::string(FRAMEDYN_SOURCE_DIR) + "/examples/offset_plowing.yaml");
  study.machine_3d().plow.shaker_amplitude = 0.0;
  study.machine_3d().forward_speed = 0.0;
  const rigid::VehicleModel machine = rigid::build_vehicle_model(study.machine_3d());
  EXPECT_LT(drift_from_statics(machine), 1e-9);
  double weight = 0.0;
  for (const rigid::Body& b : machine.multibody.bodies()) weight += b.mass * study.machine_3d().gravity;
  double carried = 0.0;
  for (std::size_t i = 0; i < machine.statics.contacts.size(); ++i)
    if (machine.statics.engaged[i]) carried += machine.statics.element_forces[static_cast<std::size_t>(machine.statics.contacts[i].normal)];
  EXPECT_NEAR(carried, weight, 1e-9 * weight);  // level ground: the vertical contacts carry the whole weight
}

// The shipped machine's statics against the hand calculation. Units of the
// study files: in, lbf; the model is SI (N), so its forces are divided by
// 1 lbf = 4.4482216152605 N (exact by definition).
constexpr double kNewtonsPerPound = 4.4482216152605;

// A shipped study's text with each (from, to) edit applied (each `from` must be there),
// written to `dir`; returns its path.
std::string shipped_variant(const framedyn::testing::TempDir& dir, const std::string& example,
                            const std::vector<std::pair<std::string, std::string>>& edits) {
  return dir.write("variant.yaml", framedyn::testing::edited_example_text(example, edits)).string();
}

// Removes a top-level block (its key line and every indented line after it).
std::pair<std::string, std::string> drop_block(const std::string& example, const std::string& key) {
  const std::string s = framedyn::testing::example_text(example);
  const std::size_t a = s.find("\n" + key + ":");
  if (a == std::string::npos) throw std::runtime_error("no block " + key + " in " + example);
  std::size_t b = s.find('\n', a + 1);
  while (b != std::string::npos && b + 1 < s.size() && (s[b + 1] == ' ' || s[b + 1] == '#' || s[b + 1] == '\n')) b = s.find('\n', b + 1);
  return {s.substr(a, b - a), ""};
}

// The weight (lbf) and the moments sum W_i X_i and sum W_i Y_i (lbf in) of
// every body a study file states, by hand from its YAML: a 2-D file's uniform
// frame section (its weight at mid-length), added masses, cab and plow; a
// 3-D file's frame parts, reel, rear axle, front axle, cab and plow (its c.g.
// in the vertical plane through the swing pin, alpha' = 0).
struct WeightSums {
  double w = 0.0, wx = 0.0, wy = 0.0;
  void add(double weight, double x, double y = 0.0) { w += weight; wx += weight * x; wy += weight * y; }
};
WeightSums weights_of(const std::string& file) {
  const YAML::Node y = YAML::LoadFile(file);
  WeightSums s;
  const bool three_d = y["model"].as<std::string>() == "rigid_3d";
  const YAML::Node frame = y["frame"];
  if (three_d) {
    for (const YAML::Node& part : frame["parts"]) s.add(part["weight"].as<double>(), part["position"][0].as<double>(), part["position"][1].as<double>());
    for (const YAML::Node& part : {frame["reel_and_carrier"], frame["rear_axle"], y["front_axle"], y["cab"]})
      s.add(part["weight"].as<double>(), part["position"][0].as<double>(), part["position"][1].as<double>());
  } else {
    const YAML::Node u = frame["uniform_section"];
    const double length = u["length"].as<double>();
    s.add(u["weight_per_length"].as<double>() * length, u["front_end"].as<double>() + length / 2);
    for (const YAML::Node& m : frame["added_masses"]) s.add(m["weight"].as<double>(), m["position"][0].as<double>());
    s.add(y["cab"]["weight"].as<double>(), y["cab"]["position"][0].as<double>());
  }
  if (y["plow"]) s.add(y["plow"]["weight"].as<double>(), y["plow"]["cg"][0].as<double>());
  return s;
}

// Static force of contact `name` (its normal element), lbf, compression positive; and its tangential ones.
double contact_force(const rigid::VehicleModel& m, const std::string& name, std::vector<double>* tangential = nullptr) {
  for (std::size_t i = 0; i < m.statics.contacts.size(); ++i)
    if (m.statics.contacts[i].name == name) {
      if (tangential)
        for (int e : m.statics.contacts[i].tangential) tangential->push_back(m.statics.element_forces[static_cast<std::size_t>(e)] / kNewtonsPerPound);
      return m.statics.element_forces[static_cast<std::size_t>(m.statics.contacts[i].normal)] / kNewtonsPerPound;
    }
  std::string names;
  for (const auto& c : m.statics.contacts) names += " " + c.name;
  throw std::runtime_error("no contact " + name + " among" + names);
}

// Tire contact X (in) of the shipped machine: front axle at 0, rear at 72 (the
// study files' tire contacts); the rear tires at Y = -30 (left) and +30 (right).
constexpr double kFrontX = 0.0, kRearX = 72.0, kHalfTrack = 30.0;

// Without its plow the 2-D machine stands on two axles: by the sum of moments
// about the rear axle R_f = sum W_i (72 - X_i) / 72 and by the sum of forces
// R_r = W - R_f (the lever rule, determinate). The tractive springs are both at
// the ground (Z = -26 in), so with no horizontal load they carry nothing.
// Round-off: the model's reactions come from K q_s = Q_g, about 1e-12 of W.
TEST(ShippedMachineStatics, TwoDimensionalMachineWithoutItsPlowRestsOnItsAxlesByTheLeverRule) {
  framedyn::testing::TempDir dir("framedyn_statics_2d");
  const std::string file = shipped_variant(dir, "r100_plow_2d.yaml",
      {{"attachment: plow", "attachment: none"}, drop_block("r100_plow_2d.yaml", "plow"), drop_block("r100_plow_2d.yaml", "soil")});
  const WeightSums s = weights_of(file);
  const rigid::VehicleModel m = rigid::build_vehicle_model(coupling::read_rigid_study(file).machine_2d());
  std::vector<double> tf, tr;
  const double front = contact_force(m, "front_tire", &tf), rear = contact_force(m, "rear_tire", &tr);
  const double hand_front = (kRearX * s.w - s.wx) / (kRearX - kFrontX);
  EXPECT_NEAR(front, hand_front, 1e-9 * s.w);
  EXPECT_NEAR(rear, s.w - hand_front, 1e-9 * s.w);
  for (double t : tf) EXPECT_NEAR(t, 0.0, 1e-9 * s.w);
  for (double t : tr) EXPECT_NEAR(t, 0.0, 1e-9 * s.w);
  std::printf("[ statics ] 2-D without plow: W %.3f lbf, front %.6f (hand %.6f), rear %.6f (hand %.6f)\n", s.w, front, hand_front, rear, s.w - hand_front);
}

// Without its plow the 3-D machine stands on its front axle, free to roll on
// its pin (eta), and its rear tires, the rear axle rigid with the frame. The
// sum of forces and the moments about the rear axle (Y) and the centre line
// (X) give, determinately, R_front = sum W_i (72 - X_i) / 72, R_rear = W - R_front
// and 30 (R_right - R_left) = sum W_i Y_i, the tire springs' horizontal
// forces summing to nothing at the common height Z = -26 in. How the roll
// moment is shared between the axles is not fixed by statics: the front
// axle's roll balance about its pin (Z = 0) takes the moment of its tires'
// lateral springs, 26 in below it, so the split follows the lateral
// stiffnesses (indeterminate). On the shipped machine, symmetric about X-Z,
// no lateral force arises and each tire carries half its axle's load; on a
// variant with the fuel tank moved 12 in to the right only the determinate
// sums are checked (the split is printed).
TEST(ShippedMachineStatics, ThreeDimensionalMachineWithoutItsPlowRestsOnItsAxlesAsTheHandCalculationGives) {
  const std::string ex = "r100_plow_straight.yaml";
  for (const std::string tank : {"position: [58, 0, 10]", "position: [58, 12, 10]"}) {
    const bool symmetric = tank == "position: [58, 0, 10]";
    framedyn::testing::TempDir dir("framedyn_statics_3d");
    const std::string file = shipped_variant(dir, ex,
        {{"attachment: plow", "attachment: none"}, drop_block(ex, "plow"), drop_block(ex, "soil"), {"position: [58, 0, 10]", tank}});
    const WeightSums s = weights_of(file);
    const rigid::VehicleModel m = rigid::build_vehicle_model(coupling::read_rigid_study(file).machine_3d());
    std::vector<double> tangential;
    const double fl = contact_force(m, "front_left_tire", &tangential), fr = contact_force(m, "front_right_tire", &tangential);
    const double rl = contact_force(m, "rear_left_tire", &tangential), rr = contact_force(m, "rear_right_tire", &tangential);
    const double front = (kRearX * s.w - s.wx) / (kRearX - kFrontX), rear = s.w - front;
    EXPECT_NEAR(fl + fr, front, 1e-9 * s.w) << tank;
    EXPECT_NEAR(rl + rr, rear, 1e-9 * s.w) << tank;
    EXPECT_NEAR(kHalfTrack * (fr + rr - fl - rl), s.wy, 1e-9 * s.w * kHalfTrack) << tank;
    if (symmetric) {
      EXPECT_EQ(s.wy, 0.0);
      EXPECT_NEAR(fl, front / 2, 1e-9 * s.w);
      EXPECT_NEAR(fr, front / 2, 1e-9 * s.w);
      EXPECT_NEAR(rl, rear / 2, 1e-9 * s.w);
      EXPECT_NEAR(rr, rear / 2, 1e-9 * s.w);
      for (double t : tangential) EXPECT_NEAR(t, 0.0, 1e-9 * s.w);
    }
    std::printf("[ statics ] 3-D without plow (fuel tank %s): W %.3f lbf; front %.6f (hand %.6f), rear %.6f (hand %.6f); "
                "FL %.6f FR %.6f RL %.6f RR %.6f; right - left %.6f (hand sum W_i Y_i / 30 = %.6f)\n",
                tank.c_str(), s.w, fl + fr, front, rl + rr, rear, fl, fr, rl, rr, fr + rr - fl - rl, s.wy / kHalfTrack);
  }
}

// With its plow, the machine stands on one support more, the bounce tire
// (X = 124 in; the soil carries nothing statically, Eq. 2.37): three vertical
// reactions in 2-D for two equations, so their split follows the stiffnesses
// (indeterminate). What statics alone fixes is checked: the sum of the vertical
// reactions equals the weight and their moment about the rear axle equals the
// weights' (sum R_j (X_j - 72) = sum W_i (X_i - 72)); in 3-D also the moment
// about the centre line, and the front tires stay equal (the pinned axle).
TEST(ShippedMachineStatics, PlowMachinesBalanceTheirWeightAboutTheRearAxleWithTheBounceTireSharingIndeterminately) {
  {
    const std::string file = std::string(FRAMEDYN_SOURCE_DIR) + "/examples/r100_plow_2d.yaml";
    const WeightSums s = weights_of(file);
    const YAML::Node y = YAML::LoadFile(file);
    const double xb = y["plow"]["bounce_tire"]["point"][0].as<double>();
    const rigid::VehicleModel m = rigid::build_vehicle_model(coupling::read_rigid_study(file).machine_2d());
    const double f = contact_force(m, "front_tire"), r = contact_force(m, "rear_tire"), b = contact_force(m, "bounce_tire");
    EXPECT_NEAR(f + r + b, s.w, 1e-9 * s.w);
    EXPECT_NEAR(f * (kFrontX - kRearX) + b * (xb - kRearX), s.wx - kRearX * s.w, 1e-9 * s.w * kRearX);
    EXPECT_GT(b, 0.0);  // engaged: the split is the stiffnesses', not a lever rule
    std::printf("[ statics ] 2-D with plow: W %.3f lbf; front %.6f rear %.6f bounce %.6f\n", s.w, f, r, b);
  }
  {
    const std::string file = std::string(FRAMEDYN_SOURCE_DIR) + "/examples/r100_plow_straight.yaml";
    const WeightSums s = weights_of(file);
    const YAML::Node y = YAML::LoadFile(file);
    const double xb = y["plow"]["bounce_tire"]["point"][0].as<double>();
    const rigid::VehicleModel m = rigid::build_vehicle_model(coupling::read_rigid_study(file).machine_3d());
    const double fl = contact_force(m, "front_left_tire"), fr = contact_force(m, "front_right_tire");
    const double rl = contact_force(m, "rear_left_tire"), rr = contact_force(m, "rear_right_tire"), b = contact_force(m, "bounce_tire");
    EXPECT_NEAR(fl + fr + rl + rr + b, s.w, 1e-9 * s.w);
    EXPECT_NEAR((fl + fr) * (kFrontX - kRearX) + b * (xb - kRearX), s.wx - kRearX * s.w, 1e-9 * s.w * kRearX);
    EXPECT_NEAR(kHalfTrack * (fr + rr - fl - rl), s.wy, 1e-9 * s.w * kHalfTrack);
    EXPECT_NEAR(fl, fr, 1e-9 * s.w);
    EXPECT_GT(b, 0.0);
    std::printf("[ statics ] 3-D with plow: W %.3f lbf; FL %.6f FR %.6f RL %.6f RR %.6f bounce %.6f\n", s.w, fl, fr, rl, rr, b);
  }
}

}  // namespace
