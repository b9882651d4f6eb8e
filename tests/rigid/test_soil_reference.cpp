// The soil springs' reference: the blade's equilibrium (Eq. 2.37 as printed)
// or the point where the current cut began (soil.spring_reference: contact).
#include <gtest/gtest.h>

#include "coupling/rigid_study.h"
#include "rigid/machine_2d.h"

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

}  // namespace
}  // namespace framedyn
