// The soil springs' reference: the blade's equilibrium (Eq. 2.37 as printed),
// the point where the current cut began (soil.spring_reference: contact),
// that point carried with the soil (soil_line), or the cut face (cut_face:
// no spring while the blade cuts; from the cut face it left while it backs off).
#include <gtest/gtest.h>

#include "coupling/rigid_study.h"
#include "rigid/machine_2d.h"
#include "rigid/machine_3d.h"
#include "rigid/vehicle_model.h"
#include "rigid/vehicle_run.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace framedyn {
namespace {

// The (X, Z) components of a force in machine axes.
Eigen::Vector2d xz(const Eigen::Vector3d& f) { return {f.x(), f.z()}; }

// A blade standing still at a displaced position: measured from equilibrium
// the springs push back with K5 times the displacement; measured from the
// contact where the cut began (here, the start of the run at that position)
// they carry nothing, and only the soil's relative velocity (the forward
// speed through C5) remains. Exact by construction: round-off tolerance.
TEST(SoilReference, ContactReferenceUnloadsTheSpringsAtTheStartOfACut) {
  coupling::RigidStudy study = coupling::read_rigid_study(FRAMEDYN_SOURCE_DIR "/examples/r100_plow_2d_vertical_path.yaml");
  rigid::Machine2DParameters p = study.machine_2d();
  p.forward_speed = 0.0;
  Eigen::VectorXd q = Eigen::VectorXd::Zero(6), v = Eigen::VectorXd::Zero(6);
  q(3) = 0.01;  // psi: the plow arm turned, the blade displaced

  const rigid::VehicleModel from_equilibrium = rigid::build_vehicle_model(p);
  rigid::VehicleRunState from_equilibrium_run = rigid::start_run(from_equilibrium, 0.0, q);
  const rigid::Jacobian& j = from_equilibrium.multibody.points()[static_cast<std::size_t>(from_equilibrium.blade_point)].displacement;
  const Eigen::Vector3d d = j * q;
  const Eigen::Vector2d f_eq = xz(rigid::plow_force(from_equilibrium, from_equilibrium_run, 0.0, q, v));
  EXPECT_NEAR(f_eq.x(), p.soil.stiffness * d(0), 1e-9 * p.soil.stiffness * d.norm());
  EXPECT_NEAR(f_eq.y(), p.soil.stiffness * d(2), 1e-9 * p.soil.stiffness * d.norm());

  p.soil.spring_from_contact = true;
  const rigid::VehicleModel from_contact = rigid::build_vehicle_model(p);
  rigid::VehicleRunState from_contact_run = rigid::start_run(from_contact, 0.0, q);
  rigid::VehicleDynamics from_contact_dyn(from_contact, from_contact_run);
  const Eigen::Vector2d f_contact = xz(rigid::plow_force(from_contact, from_contact_run, 0.0, q, v));
  EXPECT_NEAR(f_contact.norm(), 0.0, 1e-9 * p.soil.stiffness * d.norm());
  // And the equations of motion see the same: at rest there, the soil adds no force.
  Eigen::VectorXd a_contact, a_free;
  from_contact_dyn.acceleration(0.0, q, v, a_contact);
  p.soil.stiffness = 0.0;
  p.soil.spring_from_contact = false;
  const rigid::VehicleModel no_soil_spring = rigid::build_vehicle_model(p);
  rigid::VehicleRunState no_soil_spring_run = rigid::start_run(no_soil_spring, 0.0, q);
  rigid::VehicleDynamics no_soil_spring_dyn(no_soil_spring, no_soil_spring_run);
  no_soil_spring_dyn.acceleration(0.0, q, v, a_free);
  EXPECT_LT((a_contact - a_free).norm(), 1e-9 * a_free.norm() + 1e-12);
}


// soil.spring_reference: soil_line. The springs' ground end is the soil at the
// point of contact, and the soil streams rearward past the machine at VS
// (Eq. 2.23), so a blade held still after the cut began is pressed into the
// advancing soil: at time t after contact the X spring carries
// K5 (X5 - (X5 + VS t)) = -K5 VS t (with the damper's -C5 VS on top), the
// Z spring nothing on level ground. The contact reading, whose anchor stays
// put in the machine, carries only the damper's part. Exact: round-off.
TEST(SoilReference, SoilLineAnchorIsCarriedRearwardWithTheSoilFromTheStartOfTheCut) {
  coupling::RigidStudy study = coupling::read_rigid_study(FRAMEDYN_SOURCE_DIR "/examples/r100_plow_2d_vertical_path.yaml");
  rigid::Machine2DParameters p = study.machine_2d();
  p.ground_slope = 0.0;
  p.forward_speed = 0.05;  // m/s
  p.soil.spring_from_contact = true;
  Eigen::VectorXd q = Eigen::VectorXd::Zero(6), v = Eigen::VectorXd::Zero(6);
  q(3) = 0.01;
  const double t = 0.02, damper = -p.soil.damping * p.forward_speed;

  const rigid::VehicleModel fixed_contact = rigid::build_vehicle_model(p);
  rigid::VehicleRunState fixed_contact_run = rigid::start_run(fixed_contact, 0.0, q);
  rigid::VehicleDynamics fixed_contact_dyn(fixed_contact, fixed_contact_run);
  const Eigen::Vector2d f_fixed = xz(rigid::plow_force(fixed_contact, fixed_contact_run, t, q, v));
  EXPECT_NEAR(f_fixed.x(), damper, 1e-9 * std::abs(damper));
  EXPECT_NEAR(f_fixed.y(), 0.0, 1e-9 * std::abs(damper));

  p.soil.contact_moves_with_soil = true;
  const rigid::VehicleModel soil_line = rigid::build_vehicle_model(p);
  rigid::VehicleRunState soil_line_run = rigid::start_run(soil_line, 0.0, q);
  rigid::VehicleDynamics soil_line_dyn(soil_line, soil_line_run);
  const Eigen::Vector2d f_soil = xz(rigid::plow_force(soil_line, soil_line_run, t, q, v));
  const double spring = -p.soil.stiffness * p.forward_speed * t;
  EXPECT_NEAR(f_soil.x(), spring + damper, 1e-9 * std::abs(spring));
  EXPECT_NEAR(f_soil.y(), 0.0, 1e-9 * std::abs(spring));
  // The soil elements' tensions, which the frame loads use, say the same.
  const std::vector<int>& soil = soil_line.soil_elements;
  EXPECT_NEAR(rigid::element_tension(soil_line, soil_line_run, soil[0], t, q, v), f_soil.x(), 1e-9 * std::abs(spring));
  EXPECT_NEAR(rigid::element_tension(soil_line, soil_line_run, soil[1], t, q, v), f_soil.y(), 1e-9 * std::abs(spring));
  // And the equations of motion: the two readings' accelerations differ by
  // M^-1 G_x^T (K5 VS t), the anchor's motion, alone.
  Eigen::VectorXd a_fixed, a_soil;
  fixed_contact_dyn.acceleration(t, q, v, a_fixed);
  soil_line_dyn.acceleration(t, q, v, a_soil);
  const Eigen::VectorXd expected =
      soil_line.m.ldlt().solve(soil_line.multibody.elongation_map(soil[0]).transpose() * (p.soil.stiffness * p.forward_speed * t));
  EXPECT_LT((a_soil - a_fixed - expected).norm(), 1e-9 * expected.norm());
}

// soil.spring_reference: cut_face, while the blade cuts: the springs' ground
// end is at the blade, so the soil force is the damper's alone,
// C5 (v5 - v_soil), whatever the blade's displacement, and the equations of
// motion are those of the machine without soil springs. Exact: round-off.
TEST(SoilReference, CutFaceSpringsCarryNothingWhileTheBladeCuts) {
  rigid::Machine2DParameters p = coupling::read_rigid_study(FRAMEDYN_SOURCE_DIR "/examples/r100_plow_2d.yaml").machine_2d();
  ASSERT_TRUE(p.soil.cut_face);
  Eigen::VectorXd q = Eigen::VectorXd::Zero(6), v = Eigen::VectorXd::Zero(6);
  q(3) = 0.01;  // psi: the blade displaced
  v(3) = 0.3;   // and moving
  v(0) = -0.02;
  const rigid::VehicleModel cut_face = rigid::build_vehicle_model(p);
  // The cut began at equilibrium: the printed reading would load the spring.
  rigid::VehicleRunState cut_face_run = rigid::start_run(cut_face, 0.0, Eigen::VectorXd::Zero(6));
  rigid::VehicleDynamics cut_face_dyn(cut_face, cut_face_run);
  ASSERT_TRUE(cut_face_run.soil.cutting());
  const rigid::Jacobian& j = cut_face.multibody.points()[static_cast<std::size_t>(cut_face.blade_point)].displacement;
  const Eigen::Vector3d d = j * q, vel = j * v;
  ASSERT_GT(d.norm(), 1e-4);
  const double t = 0.01, vs = p.forward_speed * std::cos(p.ground_slope);
  const Eigen::Vector2d f = xz(rigid::plow_force(cut_face, cut_face_run, t, q, v));
  const Eigen::Vector2d damper(p.soil.damping * (vel(0) - vs), p.soil.damping * (vel(2) + p.forward_speed * std::sin(p.ground_slope)));
  EXPECT_LT((f - damper).norm(), 1e-12 * damper.norm());
  const std::vector<int>& soil = cut_face.soil_elements;
  EXPECT_NEAR(rigid::element_tension(cut_face, cut_face_run, soil[0], t, q, v), f.x(), 1e-12 * damper.norm());
  EXPECT_NEAR(rigid::element_tension(cut_face, cut_face_run, soil[1], t, q, v), f.y(), 1e-12 * damper.norm());

  Eigen::VectorXd a_cut_face, a_no_spring;
  cut_face_dyn.acceleration(t, q, v, a_cut_face);
  p.soil.stiffness = 0.0;
  p.soil.cut_face = p.soil.spring_from_contact = p.soil.contact_moves_with_soil = false;
  const rigid::VehicleModel no_spring = rigid::build_vehicle_model(p);
  rigid::VehicleRunState no_spring_run = rigid::start_run(no_spring, 0.0, Eigen::VectorXd::Zero(6));
  rigid::VehicleDynamics no_spring_dyn(no_spring, no_spring_run);
  no_spring_dyn.acceleration(t, q, v, a_no_spring);
  EXPECT_LT((a_cut_face - a_no_spring).norm(), 1e-12 * a_no_spring.norm());
}

// cut_face, while the blade backs off (REK > 0 here): the springs REK K5 act
// from the cut face the blade left, a_b + v_soil (t - t_b), a_b being the
// blade's displacement at the back-off instant t_b. A blade held at a_b is
// then pulled forward by REK K5 VS (t - t_b) in X, as the soil streams away.
TEST(SoilReference, CutFaceSpringsActFromTheCutFaceCarriedWithTheSoilWhileBacking) {
  rigid::Machine2DParameters p = coupling::read_rigid_study(FRAMEDYN_SOURCE_DIR "/examples/r100_plow_2d.yaml").machine_2d();
  p.ground_slope = 0.0;
  p.soil.stiffness_reduction = 0.5;
  const rigid::VehicleModel m = rigid::build_vehicle_model(p);
  Eigen::VectorXd q = Eigen::VectorXd::Zero(6), v = Eigen::VectorXd::Zero(6);
  q(3) = 0.01;
  rigid::VehicleRunState m_run = rigid::start_run(m, 0.0, Eigen::VectorXd::Zero(6));
  rigid::VehicleDynamics m_dyn(m, m_run);
  const double tb = 0.03, t = 0.05, vs = p.forward_speed;
  // The located back-off (event 0 crossing upwards) with the blade at q.
  const std::string what = m_dyn.on_event(tb, q, v, {0}, {+1});
  ASSERT_NE(what.find("backs off"), std::string::npos) << what;
  ASSERT_FALSE(m_run.soil.cutting());
  const Eigen::Vector2d f = xz(rigid::plow_force(m, m_run, t, q, v));
  const double rk = p.soil.stiffness * p.soil.stiffness_reduction, rc = p.soil.damping * p.soil.damping_reduction;
  const double expected_x = -rk * vs * (t - tb) - rc * vs;  // spring toward the receding cut face, damper against the soil's flow
  EXPECT_NEAR(f.x(), expected_x, 1e-9 * std::abs(expected_x));
  EXPECT_NEAR(f.y(), 0.0, 1e-9 * std::abs(expected_x));
  const std::vector<int>& soil = m.soil_elements;
  EXPECT_NEAR(rigid::element_tension(m, m_run, soil[0], t, q, v), f.x(), 1e-9 * std::abs(expected_x));
}

// With REK = 0 the cut-face springs never act in the response, so K5 drops
// out of it exactly (the thesis's K5 sweep: 0.2 % and 0.25 %), while the
// natural frequencies, computed with the blade at rest in the soil (K5 at
// full value), still depend on it.
// With the cut-face reading and REK = 0 the soil springs never act in the
// response; since section 11 of docs/theory/rigid.md they carry nothing in the
// one-sided statics either, and the modes see what the response sees: K5
// changes nothing, under the thesis's bilateral contacts and under one-sided ones
// (before section 11 it moved the one-sided response by 6.6 mm through the
// static contact forces, and the modes by more than 5 %).
TEST(SoilReference, CutFaceResponseAndModesAreIndependentOfK5) {
  for (rigid::ContactLaw law : {rigid::ContactLaw::linear, rigid::ContactLaw::unilateral}) {
    coupling::RigidStudy study = coupling::read_rigid_study(FRAMEDYN_SOURCE_DIR "/examples/r100_plow_2d.yaml");
    study.frame_output.reset();
    study.response->duration = 0.25;
    study.machine_2d().contacts = law;
    ASSERT_EQ(study.machine_2d().soil.stiffness_reduction, 0.0);
    std::vector<coupling::RigidResults> runs;
    for (double scale : {0.5, 1.5}) {
      coupling::RigidStudy s = study;
      s.machine_2d().soil.stiffness *= scale;
      runs.push_back(coupling::run_rigid_study(s));
    }
    const rigid::Trajectory &a = runs[0].trajectory, &b = runs[1].trajectory;
    ASSERT_GT(a.events.size(), 2u);  // the blade does back off and cut again
    ASSERT_EQ(a.time.size(), b.time.size());
    double largest = 0.0, difference = 0.0;
    for (std::size_t i = 0; i < a.time.size(); ++i) {
      largest = std::max(largest, a.q[i].cwiseAbs().maxCoeff());
      difference = std::max(difference, (a.q[i] - b.q[i]).cwiseAbs().maxCoeff());
    }
    // The two runs' matrices differ only by the round-off of taking K5's share
    // out of K; that can at most tip one of CVODE's step-size decisions, whose
    // effect its error control keeps near rtol (1e-8): 100 rtol. An acting
    // spring would move the blade by tens of percent (the printed reading: 50 %).
    EXPECT_LE(difference, 100 * study.response->relative_tolerance * largest) << (law == rigid::ContactLaw::linear ? "linear" : "unilateral");
    std::printf("largest coordinate %.6e, difference between K5 x0.5 and x1.5 %.3e\n", largest, difference);
    ASSERT_EQ(runs[0].modes.size(), runs[1].modes.size());
    for (std::size_t m = 0; m < runs[0].modes.size(); ++m)
      EXPECT_NEAR(runs[1].modes[m].frequency_hz, runs[0].modes[m].frequency_hz, 1e-9 * runs[0].modes[m].frequency_hz);
  }
}

// The moving anchor in 3-D, in closed form (docs/theory/rigid.md section 18),
// on the shipped offset plow (crab steering: heading 22 deg) on a 0.05 rad slope. The ground streams past
// the machine at VS along the heading in the tires' ground plane: the soil flow
// has length VS, lies in that plane, and its component along the cut c is the
// rate of the soil line. A blade held still after its cut began at t = 0 is
// pressed into the advancing soil: under soil_line each soil element e carries
// -(k_e t + c_e) (e . v_soil), its spring part growing at k_e (e . v_soil) per
// second; the contact reading (anchor fixed in the machine) carries only the
// damper's -c_e (e . v_soil), and the two readings' accelerations differ by
// M^-1 sum_e G_e^T k_e (e . v_soil) t, the anchor's motion alone. Exact: round-off.
TEST(SoilAnchor3D, SoilLineAnchorMovesWithTheSoilFlowInTheGroundPlane) {
  rigid::Machine3DParameters p = coupling::read_rigid_study(FRAMEDYN_SOURCE_DIR "/examples/r100_plow_offset.yaml").machine_3d();
  ASSERT_NE(p.travel_angle, 0.0);
  p.ground_slope = 0.05;   // rad
  p.forward_speed = 0.05;  // m/s
  p.soil.cut_face = false;
  p.soil.stiffness_reduction = 0.0;
  p.soil.spring_from_contact = true;
  p.soil.contact_moves_with_soil = false;
  const rigid::VehicleModel fixed = rigid::build_vehicle_model(p);
  p.soil.contact_moves_with_soil = true;
  const rigid::VehicleModel moving = rigid::build_vehicle_model(p);

  const Eigen::Vector3d normal(std::sin(p.ground_slope), 0.0, std::cos(p.ground_slope));  // the tires' ground
  const Eigen::Vector3d& flow = moving.soil_flow;
  EXPECT_NEAR(flow.norm(), p.forward_speed, 1e-15);
  EXPECT_NEAR(flow.dot(normal), 0.0, 1e-15);
  EXPECT_NEAR(moving.cut_direction.dot(flow), moving.soil_line_speed, 1e-15);
  EXPECT_GT(flow.dot(moving.cut_direction), 0.0);  // rearward along the cut

  Eigen::VectorXd q = Eigen::VectorXd::Zero(moving.size()), v = Eigen::VectorXd::Zero(moving.size());
  q(moving.coordinate("psi")) = 0.01;  // the blade displaced, held still
  rigid::VehicleRunState fixed_run = rigid::start_run(fixed, 0.0, q), moving_run = rigid::start_run(moving, 0.0, q);
  const double t = 0.02;
  Eigen::Vector3d resultant = Eigen::Vector3d::Zero();
  Eigen::VectorXd anchor_load = Eigen::VectorXd::Zero(moving.size());
  double scale = 0.0;
  for (int e : moving.soil_elements) {
    const rigid::SpringDamper& el = moving.multibody.elements()[static_cast<std::size_t>(e)];
    const double flow_e = el.direction.dot(flow);
    const double expected = -(el.stiffness * t + el.damping) * flow_e;
    scale = std::max(scale, el.stiffness * p.forward_speed * t);
    EXPECT_NEAR(rigid::element_tension(moving, moving_run, e, t, q, v), expected, 1e-9 * scale) << el.name;
    EXPECT_NEAR(rigid::element_tension(fixed, fixed_run, e, t, q, v), -el.damping * flow_e, 1e-9 * scale) << el.name;
    resultant += el.direction * expected;
    anchor_load += moving.multibody.elongation_map(e).transpose() * (el.stiffness * flow_e * t);
  }
  // The soil resultant (response.csv's plow force, the frame loads' blade force) is their sum.
  EXPECT_LT((rigid::plow_force(moving, moving_run, t, q, v) - resultant).norm(), 1e-9 * scale);
  rigid::VehicleDynamics fixed_dyn(fixed, fixed_run), moving_dyn(moving, moving_run);
  Eigen::VectorXd a_fixed, a_moving;
  fixed_dyn.acceleration(t, q, v, a_fixed);
  moving_dyn.acceleration(t, q, v, a_moving);
  const Eigen::VectorXd expected = moving.m.ldlt().solve(anchor_load);
  EXPECT_LT((a_moving - a_fixed - expected).norm(), 1e-9 * expected.norm());
}

}  // namespace
}  // namespace framedyn
