// A mass matrix that is not positive definite is named by its body
// (rigid::check_definiteness, run by both machine models when they are
// built): a negative or non-finite mass, an inertia tensor with a negative
// principal moment, or a coordinate that moves only bodies without mass or
// inertia, with the bodies that move with it and what they lack. The modes
// of the free coordinates name the coordinate (rigid::rigid_modes).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "core/error.h"
#include "rigid/multibody.h"
#include "rigid/rigid_modes.h"

namespace framedyn {
namespace {

using core::NumericalError;
using rigid::Body;
using rigid::Multibody;

// Three coordinates: the frame's bounce and pitch, the cab's bounce. The cab
// sits 2 m ahead of the frame's c.g. and moves with all three.
Multibody frame_and_cab(double cab_mass, const Eigen::Matrix3d& cab_inertia) {
  Multibody m({"z_frame", "theta_frame", "z_cab"}, {core::Quantity::length, core::Quantity::angle, core::Quantity::length});
  Body frame{"frame", 1000.0, Eigen::Vector3d(300.0, 2000.0, 2200.0).asDiagonal(), rigid::Jacobian::Zero(3, 3), rigid::Jacobian::Zero(3, 3)};
  frame.translation(2, 0) = 1.0;
  frame.rotation(1, 1) = 1.0;
  m.add_body(frame);
  Body cab{"cab", cab_mass, cab_inertia, rigid::Jacobian::Zero(3, 3), rigid::Jacobian::Zero(3, 3)};
  cab.translation(2, 0) = 1.0;
  cab.translation(2, 1) = -2.0;  // z = z_frame - 2 theta (pitch nose down positive)
  cab.translation(2, 2) = 1.0;
  cab.rotation(1, 1) = 1.0;
  m.add_body(cab);
  return m;
}

std::string message_of(const Multibody& m) {
  try {
    rigid::check_definiteness(m);
  } catch (const NumericalError& e) {
    std::printf("%s\n", e.what());
    return e.what();
  }
  return "";
}

void expect_contains(const std::string& message, const std::string& part) {
  EXPECT_NE(message.find(part), std::string::npos) << "'" << part << "' not in: " << message;
}

TEST(MassMatrixChecks, AWellPosedModelPasses) {
  EXPECT_EQ(message_of(frame_and_cab(400.0, Eigen::Vector3d(50.0, 80.0, 90.0).asDiagonal())), "");
}

TEST(MassMatrixChecks, ACoordinateThatMovesOnlyAMasslessBodyNamesItAndTheBody) {
  // The cab has rotary inertia but no mass: z_cab moves it in translation only.
  const std::string m = message_of(frame_and_cab(0.0, Eigen::Vector3d(50.0, 80.0, 90.0).asDiagonal()));
  expect_contains(m, "the mass matrix is not positive definite: coordinate z_cab has (almost) no inertia");
  expect_contains(m, "the bodies that move with it: cab (translating, mass 0 kg)");
  EXPECT_EQ(m.find("frame ("), std::string::npos);  // the frame does not move in that motion
}

TEST(MassMatrixChecks, ACoordinateThatMovesNoBodySaysSo) {
  Multibody m({"z_frame", "x_point"}, {core::Quantity::length, core::Quantity::length});
  Body frame{"frame", 1000.0, Eigen::Matrix3d::Identity(), rigid::Jacobian::Zero(3, 2), rigid::Jacobian::Zero(3, 2)};
  frame.translation(2, 0) = 1.0;
  m.add_body(frame);
  const std::string text = message_of(m);
  expect_contains(text, "coordinate x_point has (almost) no inertia; no body moves with it");
}

TEST(MassMatrixChecks, NegativeOrNonFiniteMassNamesTheBody) {
  expect_contains(message_of(frame_and_cab(-5.0, Eigen::Matrix3d::Identity())), "body cab has mass -5 kg");
  expect_contains(message_of(frame_and_cab(std::numeric_limits<double>::quiet_NaN(), Eigen::Matrix3d::Identity())),
                  "body cab has mass nan kg");
}

TEST(MassMatrixChecks, InertiaTensorWithANegativePrincipalMomentNamesTheBody) {
  Eigen::Matrix3d inertia = Eigen::Vector3d(50.0, 80.0, 90.0).asDiagonal();
  inertia(0, 2) = inertia(2, 0) = 100.0;  // |Ixz| > sqrt(Ixx Izz): one principal moment negative
  const std::string m = message_of(frame_and_cab(400.0, inertia));
  expect_contains(m, "body cab has an inertia tensor that is not positive semi-definite");
  // Principal moments of [[50, 100], [100, 90]] and 80: 70 -/+ sqrt(20^2 + 100^2), to 6 digits.
  expect_contains(m, "(principal moments -31.9804, 80, 171.98 kg m^2");
}

TEST(MassMatrixChecks, RigidModesOfASingularMassMatrixNameTheCoordinate) {
  Eigen::MatrixXd mass = Eigen::Vector3d(1000.0, 2000.0, 0.0).asDiagonal();
  const Eigen::MatrixXd stiffness = Eigen::Vector3d(1e5, 2e5, 3e5).asDiagonal();
  try {
    rigid::rigid_modes(mass, stiffness, {"z_frame", "theta_frame", "z_cab"});
    ADD_FAILURE() << "no NumericalError";
  } catch (const NumericalError& e) {
    expect_contains(e.what(), "a motion led by coordinate z_cab has no inertia");
  }
  // With z_cab fixed the rest is well posed: 1e5/1000 and 2e5/2000 rad^2/s^2.
  const auto modes = rigid::rigid_modes(mass, stiffness, {"z_frame", "theta_frame", "z_cab"}, {"z_cab"});
  ASSERT_EQ(modes.size(), 2u);
  EXPECT_NEAR(modes[0].frequency_hz, 10.0 / (2.0 * M_PI), 1e-12);
  EXPECT_NEAR(modes[1].frequency_hz, 10.0 / (2.0 * M_PI), 1e-12);
}

}  // namespace
}  // namespace framedyn
