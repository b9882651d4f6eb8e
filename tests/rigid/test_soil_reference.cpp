// The soil springs' reference: the blade's equilibrium (Eq. 2.37 as printed)
// or the point where the current cut began (soil.spring_reference: contact).
#include <gtest/gtest.h>

#include "coupling/rigid_study.h"
#include "rigid/machine_2d.h"

#include <cmath>

namespace framedyn {
namespace {

// A blade standing still at a displaced position: measured from equilibrium
// the springs push back with K5 times the displacement; measured from the
// contact where the cut began (here, the start of the run at that position)
// they carry nothing, and only the soil's relative velocity (the forward
// speed through C5) remains. Exact by construction: round-off tolerance.
TEST(SoilReference, ContactReferenceUnloadsTheSpringsAtTheStartOfACut) {
  coupling::RigidStudy study = coupling::read_rigid_study(FRAMEDYN_SOURCE_DIR "/examples/r100_plow_2d.yaml");
  rigid::Machine2DParameters p = study.machine;
  p.forward_speed = 0.0;
  Eigen::VectorXd q = Eigen::VectorXd::Zero(6), v = Eigen::VectorXd::Zero(6);
  q(3) = 0.01;  // psi: the plow arm turned, the blade displaced

  rigid::Machine2D from_equilibrium(p);
  from_equilibrium.reset(0.0, q);
  const rigid::Jacobian& j = from_equilibrium.model().points()[static_cast<std::size_t>(from_equilibrium.blade_point())].displacement;
  const Eigen::Vector3d d = j * q;
  const Eigen::Vector2d f_eq = from_equilibrium.plow_force(0.0, q, v);
  EXPECT_NEAR(f_eq.x(), p.soil.stiffness * d(0), 1e-9 * p.soil.stiffness * d.norm());
  EXPECT_NEAR(f_eq.y(), p.soil.stiffness * d(2), 1e-9 * p.soil.stiffness * d.norm());

  p.soil.spring_from_contact = true;
  rigid::Machine2D from_contact(p);
  from_contact.reset(0.0, q);
  const Eigen::Vector2d f_contact = from_contact.plow_force(0.0, q, v);
  EXPECT_NEAR(f_contact.norm(), 0.0, 1e-9 * p.soil.stiffness * d.norm());
  // And the equations of motion see the same: at rest there, the soil adds no force.
  Eigen::VectorXd a_contact, a_free;
  from_contact.acceleration(0.0, q, v, a_contact);
  p.soil.stiffness = 0.0;
  p.soil.spring_from_contact = false;
  rigid::Machine2D no_soil_spring(p);
  no_soil_spring.reset(0.0, q);
  no_soil_spring.acceleration(0.0, q, v, a_free);
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
  coupling::RigidStudy study = coupling::read_rigid_study(FRAMEDYN_SOURCE_DIR "/examples/r100_plow_2d.yaml");
  rigid::Machine2DParameters p = study.machine;
  p.ground_slope = 0.0;
  p.forward_speed = 0.05;  // m/s
  p.soil.spring_from_contact = true;
  Eigen::VectorXd q = Eigen::VectorXd::Zero(6), v = Eigen::VectorXd::Zero(6);
  q(3) = 0.01;
  const double t = 0.02, damper = -p.soil.damping * p.forward_speed;

  rigid::Machine2D fixed_contact(p);
  fixed_contact.reset(0.0, q);
  const Eigen::Vector2d f_fixed = fixed_contact.plow_force(t, q, v);
  EXPECT_NEAR(f_fixed.x(), damper, 1e-9 * std::abs(damper));
  EXPECT_NEAR(f_fixed.y(), 0.0, 1e-9 * std::abs(damper));

  p.soil.contact_moves_with_soil = true;
  rigid::Machine2D soil_line(p);
  soil_line.reset(0.0, q);
  const Eigen::Vector2d f_soil = soil_line.plow_force(t, q, v);
  const double spring = -p.soil.stiffness * p.forward_speed * t;
  EXPECT_NEAR(f_soil.x(), spring + damper, 1e-9 * std::abs(spring));
  EXPECT_NEAR(f_soil.y(), 0.0, 1e-9 * std::abs(spring));
  // The soil elements' tensions, which the frame loads use, say the same.
  const std::vector<int>& soil = soil_line.soil_elements();
  EXPECT_NEAR(soil_line.element_tension(soil[0], t, q, v), f_soil.x(), 1e-9 * std::abs(spring));
  EXPECT_NEAR(soil_line.element_tension(soil[1], t, q, v), f_soil.y(), 1e-9 * std::abs(spring));
  // And the equations of motion: the two readings' accelerations differ by
  // M^-1 G_x^T (K5 VS t), the anchor's motion, alone.
  Eigen::VectorXd a_fixed, a_soil;
  fixed_contact.acceleration(t, q, v, a_fixed);
  soil_line.acceleration(t, q, v, a_soil);
  const Eigen::VectorXd expected =
      soil_line.mass_matrix().ldlt().solve(soil_line.model().elongation_map(soil[0]).transpose() * (p.soil.stiffness * p.forward_speed * t));
  EXPECT_LT((a_soil - a_fixed - expected).norm(), 1e-9 * expected.norm());
}

}  // namespace
}  // namespace framedyn
