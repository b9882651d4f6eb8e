// Frames whose supports leave rigid motions free (docs/theory/fem.md,
// section 19), against closed forms:
//   - a free beam held only in its plane, loaded by a balanced set (P down at
//     the middle, P/2 up at each end): the middle deflects PL^3/48EI relative
//     to the ends, the symmetric half being a cantilever of L/2 under P/2;
//   - a pendulum on one pin: a sideways tip load is refused, the message
//     naming the rotation about z through the pin and the moment F L; a load
//     along the pendulum passes through the pin and stretches it by FL/EA;
//   - a beam on one pin at its middle under a balanced couple pair +-M at its
//     ends: pure bending, relative end rotation ML/EI, sag ML^2/8EI;
//   - inertia relief of a free beam under an end force F: rigid accelerations
//     F/m + 6F/(mL) (x - L/2) (the beam's mass and centroidal inertia mL^2/12);
//   - a beam free to slide along its axis under a constant axial force:
//     the rigid coordinate gives x = F t^2 / (2m) exactly, modal and Newmark.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <cmath>
#include <iostream>
#include <string>

#include "fem/direct_integration.h"
#include "fem/modal_transient.h"
#include "fem/partial_supports.h"
#include "fem/static_analysis.h"
#include "tests/support/beam_meshes.h"

namespace {

namespace fem = framedyn::fem;
namespace support = framedyn::testing;

constexpr double kE = 2.1e11, kNu = 0.3, kRho = 7850.0, kSide = 0.05;
constexpr double kI = kSide * kSide * kSide * kSide / 12.0, kA = kSide * kSide;

// A steel Euler-Bernoulli beam of `elements` elements from `start` along `direction`, length `length`.
fem::FrameModel beam(double length, int elements, const Eigen::Vector3d& start = Eigen::Vector3d::Zero(),
                     const Eigen::Vector3d& direction = Eigen::Vector3d::UnitX()) {
  support::StraightBeamSpec s;
  s.start = start;
  s.direction = direction;
  s.length = length;
  s.elements = elements;
  s.section = fem::rectangle_section(kSide, kSide, kNu);
  s.material = support::isotropic_material("STEEL", kE, kNu, kRho);
  s.theory = fem::BeamTheory::euler_bernoulli;
  if (direction.cwiseAbs().isApprox(Eigen::Vector3d::UnitZ())) s.n1_direction = Eigen::Vector3d::UnitX();
  return support::straight_beam(s);
}

Eigen::Vector3d displacement(const fem::StaticResult& r, int node) { return r.displacement.segment<3>(6 * node); }

TEST(PartialSupports, FreeBeamHeldInItsPlaneUnderBalancedLoadsBendsAsTheClampedSymmetricHalf) {
  constexpr double kL = 2.0, kP = 1000.0;
  constexpr int kN = 20;
  fem::FrameModel m = beam(kL, kN);
  for (int i = 0; i <= kN; ++i) support::pin_dofs(m, i, {2, 3, 4});  // held in the x-y plane: ux, uy, rz free
  support::add_nodal_force(m, kN / 2, Eigen::Vector3d(0.0, -kP, 0.0));
  support::add_nodal_force(m, 0, Eigen::Vector3d(0.0, kP / 2, 0.0));
  support::add_nodal_force(m, kN, Eigen::Vector3d(0.0, kP / 2, 0.0));
  const fem::StaticResult r = fem::solve_static(m);
  EXPECT_EQ(r.free_rigid_motions, 3);
  EXPECT_EQ(r.auxiliary_dofs.size(), 3u);
  const double relative = displacement(r, 0).y() - displacement(r, kN / 2).y();
  const double closed = (kP / 2) * std::pow(kL / 2, 3) / (3.0 * kE * kI);  // = P L^3 / 48 EI
  std::cout << "[ measured ] end - middle " << relative << " m, (P/2)(L/2)^3/3EI " << closed << " m\n";
  EXPECT_NEAR(relative / closed, 1.0, 1e-9);
  EXPECT_NEAR(displacement(r, kN).y() - displacement(r, 0).y(), 0.0, 1e-9 * closed);  // symmetric
  EXPECT_LT(r.relative_residual, 1e-10);  // the auxiliary supports take nothing
}

TEST(PartialSupports, PendulumOnOnePinRefusesASidewaysLoadNamingTheRotationAboutThePin) {
  constexpr double kL = 2.0, kF = 1000.0;
  fem::FrameModel m = beam(kL, 10, Eigen::Vector3d::Zero(), -Eigen::Vector3d::UnitY());  // hanging down from node 1
  support::pin_dofs(m, 0, {0, 1, 2});
  support::add_nodal_force(m, 10, Eigen::Vector3d(kF, 0.0, 0.0));
  std::string message;
  try {
    fem::solve_static(m);
  } catch (const fem::UnbalancedLoadError& e) {
    message = e.what();
  }
  std::cout << "[ measured ] " << message << "\n";
  EXPECT_NE(message.find("3 free rigid motions): the loads drive its rotation about the z axis through node 1, unbalanced moment 2000 N*m about that axis"),
            std::string::npos)
      << message;
}

TEST(PartialSupports, PendulumOnOnePinUnderALoadThroughThePinStretchesByFLOverEA) {
  constexpr double kL = 2.0, kF = 1000.0;
  fem::FrameModel m = beam(kL, 10, Eigen::Vector3d::Zero(), -Eigen::Vector3d::UnitY());
  support::pin_dofs(m, 0, {0, 1, 2});
  support::add_nodal_force(m, 10, Eigen::Vector3d(0.0, -kF, 0.0));
  const fem::StaticResult r = fem::solve_static(m);
  EXPECT_EQ(r.free_rigid_motions, 3);
  EXPECT_NEAR(displacement(r, 10).y() / (-kF * kL / (kE * kA)), 1.0, 1e-9);
  EXPECT_NEAR(r.reaction(1), kF, 1e-9 * kF);  // the pin carries the load
}

TEST(PartialSupports, BeamOnOnePinUnderABalancedCouplePairIsInPureBending) {
  constexpr double kL = 2.0, kM = 500.0;
  constexpr int kN = 20;
  fem::FrameModel m = beam(kL, kN);
  support::pin_dofs(m, kN / 2, {0, 1, 2});
  support::add_nodal_moment(m, 0, Eigen::Vector3d(0.0, 0.0, -kM));
  support::add_nodal_moment(m, kN, Eigen::Vector3d(0.0, 0.0, kM));
  const fem::StaticResult r = fem::solve_static(m);
  EXPECT_EQ(r.free_rigid_motions, 3);
  const double rotation = r.displacement(6 * kN + 5) - r.displacement(5);
  const double sag = 0.5 * (displacement(r, 0).y() + displacement(r, kN).y()) - displacement(r, kN / 2).y();
  std::cout << "[ measured ] relative rotation " << rotation << " rad (ML/EI " << kM * kL / (kE * kI) << "), sag " << sag << " m (ML^2/8EI "
            << kM * kL * kL / (8 * kE * kI) << ")\n";
  EXPECT_NEAR(rotation / (kM * kL / (kE * kI)), 1.0, 1e-9);
  EXPECT_NEAR(sag / (kM * kL * kL / (8.0 * kE * kI)), 1.0, 1e-9);
}

TEST(PartialSupports, InertiaReliefOfAFreeBeamGivesTheRigidBodyAccelerationsOfTheEndForce) {
  constexpr double kL = 2.0, kF = 1000.0;
  constexpr int kN = 20;
  fem::FrameModel m = beam(kL, kN);
  support::add_nodal_force(m, kN, Eigen::Vector3d(0.0, kF, 0.0));
  EXPECT_THROW(fem::solve_static(m), fem::UnbalancedLoadError);
  fem::StaticOptions o;
  o.inertia_relief = true;
  const fem::StaticResult r = fem::solve_static(m, {}, o);
  EXPECT_EQ(r.free_rigid_motions, 6);
  const double mass = kRho * kA * kL;
  // a(x) = F/m + (F L/2) / (m L^2/12) (x - L/2): 4 F/m at the loaded end, -2 F/m at the other.
  EXPECT_NEAR(r.rigid_acceleration(6 * kN + 1) / (4.0 * kF / mass), 1.0, 1e-9);
  EXPECT_NEAR(r.rigid_acceleration(1) / (-2.0 * kF / mass), 1.0, 1e-9);
  EXPECT_NEAR(r.rigid_acceleration(6 * kN + 5) / (6.0 * kF / (mass * kL)), 1.0, 1e-9);
  EXPECT_LT(r.relative_residual, 1e-10);
}

TEST(PartialSupports, FreeAxialRigidMotionUnderAConstantForceMovesAsFtSquaredOverTwoM) {
  constexpr double kL = 1.0, kF = 200.0;
  constexpr int kN = 6;
  fem::FrameModel m = beam(kL, kN);
  for (int i = 0; i <= kN; ++i) support::pin_dofs(m, i, {1, 2, 3, 4, 5});  // only ux free: one rigid motion, sliding
  const fem::FrameDynamics frame(m);
  ASSERT_EQ(frame.rigid_count(), 1);
  const double mass = kRho * kA * kL;
  fem::TransientInput in;
  in.times = Eigen::VectorXd::LinSpaced(51, 0.0, 0.05);
  in.distribution.resize(m.dof_count(), 1);
  in.distribution.insert(6 * kN, 0) = kF;
  in.components = Eigen::MatrixXd::Ones(1, in.times.size());
  fem::ModalTransientOptions mo;
  mo.method = fem::ResponseMethod::mode_displacement;
  mo.damping = fem::ModalDamping::ratio(0.0);
  mo.initial = fem::InitialState::rest;
  mo.include_rigid_motion = true;
  const fem::TransientResult r = fem::modal_transient(frame, frame.all_modes(), in, mo);
  fem::NewmarkOptions no;
  no.initial = fem::InitialState::rest;
  no.include_rigid_motion = true;
  const fem::TransientResult d = fem::direct_transient(frame, in, no);
  // The rigid motion: its M-orthonormal coordinate over sqrt(m); Newmark's: the mass-weighted mean ux.
  Eigen::VectorXd ux_rigid = Eigen::VectorXd::Zero(m.dof_count());
  for (int i = 0; i <= kN; ++i) ux_rigid(6 * i) = 1.0;
  const Eigen::VectorXd mr = frame.mass_times(fem::rigid_motions_on_equations(frame.dofs(), ux_rigid));
  double worst_modal = 0.0, worst_direct = 0.0;
  for (Eigen::Index j = 1; j < r.times.size(); ++j) {
    const double t = r.times(j), x = kF * t * t / (2.0 * mass);
    const double modal = std::abs(r.rigid_coordinates(0, j)) / std::sqrt(mass);
    Eigen::VectorXd u(frame.dofs().free_count());
    for (int e = 0; e < frame.dofs().free_count(); ++e) u(e) = d.displacement(frame.dofs().free_dofs[static_cast<std::size_t>(e)], j);
    const double direct = mr.dot(u) / mass;
    worst_modal = std::max(worst_modal, std::abs(modal / x - 1.0));
    worst_direct = std::max(worst_direct, std::abs(direct / x - 1.0));
  }
  std::cout << "[ measured ] largest relative difference from F t^2/2m: modal " << worst_modal << ", Newmark " << worst_direct << "\n";
  EXPECT_LT(worst_modal, 1e-10);
  EXPECT_LT(worst_direct, 1e-10);
}

TEST(PartialSupports, BeamHeldInItsPlaneHasThreeRigidMotionsInTheTransientSolvers) {
  fem::FrameModel m = beam(2.0, 10);
  for (int i = 0; i <= 10; ++i) support::pin_dofs(m, i, {2, 3, 4});
  const fem::FrameDynamics frame(m);
  EXPECT_FALSE(frame.free_free());
  EXPECT_EQ(frame.rigid_count(), 3);
  EXPECT_EQ(frame.auxiliary_supports().size(), 3u);
  const fem::ModalBasis b = frame.all_modes();
  EXPECT_EQ(b.elastic_count(), b.eigenvalues.size() - 3);
}

}  // namespace
