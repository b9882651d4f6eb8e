// The parameters of the 3-D vehicle model of the thesis's Chapter III (program
// CMW3D), the input of its builder (rigid::build_vehicle_model, rigid/vehicle_model.h;
// a run: rigid/vehicle_run.h). The model is the multibody assembly (rigid/multibody.h) of: frame assembly (6 DOF), cab on
// four mounts with spring-dampers in X, Y, Z (6 DOF), front axle pinned to
// the frame at point 20 and free to roll (eta; Eq. 3.4, Appendix F), rear
// axle rigid with the frame (pin 26 plus leveling cylinder 27), four tires
// with vertical, longitudinal and lateral spring-dampers turned exactly by
// the steering angles deltaF, deltaR; and either the vibratory plow (boom
// swing alpha about a vertical pin at point 19, four-bar linkage in the
// boom plane, blade plane turned by beta; Appendix E, Table II; rotational
// spring K30, lift cylinder, bounce tire; shaker at point 22, Eq. 3.12) or
// the digging chain (boom rigid on the frame, parallel to X-Z and offset in
// Y; RCH and RMCH at point 19, Appendix D). Tires and the bounce tire push
// only unless contacts is linear (rigid/unilateral_contact.h). The soil law is the 2-D one
// (Eq. 2.36) along the direction of travel. docs/theory/rigid.md, section 10.
//
// Coordinates (fixed axes X rearward, Y right, Z up; rotations right-handed
// about the fixed axes; SI):
//   plow:  q = (x, y, z, theta_x, theta_y, theta_z, u, v, w, theta_u, theta_v, theta_w, eta, psi, alpha)
//   chain: q = (x, y, z, theta_x, theta_y, theta_z, u, v, w, theta_u, theta_v, theta_w, eta)
//   x, y, z           frame displacement at its reference point, m
//   theta_x, _y, _z   frame roll, pitch, yaw, rad
//   u, v, w           cab c.g. displacement, m
//   theta_u, _v, _w   cab roll, pitch, yaw, rad
//   eta               front axle roll about the pin axis (parallel to X), absolute, rad
//   psi               upper plow arm rotation about the arm pin axis, absolute, rad
//   alpha             plow boom yaw about the vertical swing pin, absolute, rad
#pragma once

#include <Eigen/Dense>

#include <optional>
#include <string>
#include <vector>

#include "rigid/ground_input.h"
#include "rigid/machine_2d.h"
#include "rigid/multibody.h"
#include "rigid/plow_linkage.h"
#include "rigid/soil_contact.h"
#include "rigid/unilateral_contact.h"
#include "rigid/vehicle_model.h"

namespace framedyn::rigid {

// Inertia tensor about a body's c.g. in the fixed axes from its moments and
// products of inertia, the products as integrals (P_xy = integral of x y dm,
// the convention of Eqs. F.7-F.9): I = [[Ixx, -Pxy, -Pxz], [-Pxy, Iyy, -Pyz], [-Pxz, -Pyz, Izz]].
Eigen::Matrix3d inertia_tensor(double ixx, double iyy, double izz, double pxy = 0.0, double pxz = 0.0, double pyz = 0.0);

// A rigid body's mass properties: mass (kg), c.g. (m, fixed axes), inertia
// tensor about the c.g. (kg m^2, fixed axes, products included).
struct RigidPart3D {
  std::string name;
  double mass = 0.0;
  Eigen::Vector3d cg{0, 0, 0};
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
};

// Mass, c.g. and inertia of several rigid parts taken as one body (the
// parallel-axis theorem with products, Eqs. F.1-F.12 done as a tensor sum).
RigidPart3D combine(const std::vector<RigidPart3D>& parts, const std::string& name);

struct FrameAssembly3D {
  // Everything rigidly attached to the frame (frame tubes, engine, ballast,
  // hitch, digging-chain boom, ...), each with its own mass properties.
  std::vector<RigidPart3D> parts;
  // The two attached bodies whose connection loads are recovered separately
  // (frame loads 24, 26/27): also rigid with the frame.
  RigidPart3D reel_and_carrier;
  Eigen::Vector3d reel_attachment{0, 0, 0};      // point 24
  RigidPart3D rear_axle;                          // axle, drive and both rear wheels
  Eigen::Vector3d rear_pin{0, 0, 0};              // point 26 (pin axis parallel to X)
  Eigen::Vector3d leveling_cylinder{0, 0, 0};     // point 27, where the cylinder acts on the frame (vertical)
  // Where x, y, z are measured; unset: the c.g. of the frame assembly with
  // the front axle (Eqs. F.1, F.2, F.4).
  std::optional<Eigen::Vector3d> reference;
};

struct FrontAxle3D {
  RigidPart3D axle;                     // M4, [I4]: axle and both front wheels
  Eigen::Vector3d pin{0, 0, 0};         // point 20 on the frame; the pin axis is parallel to X
};

struct Tire3D {
  Eigen::Vector3d contact{0, 0, 0};     // contact point
  SpringDamperValues vertical;          // along the ground normal
  SpringDamperValues longitudinal;      // along the wheel's rolling direction (steered)
  SpringDamperValues lateral;           // along the wheel's axle direction (steered)
  GroundInput vertical_input, longitudinal_input;
};

struct Axle3D {
  Tire3D left, right;                   // -Y and +Y tires
  double steering_angle = 0.0;          // delta, rad, positive steered to the right (+Y)
};

struct CabMount3D {
  std::string name;
  Eigen::Vector3d position{0, 0, 0};    // on frame and cab alike at equilibrium (points 28-31)
  SpringDamperValues x, y, z;
};

struct Cab3D {
  RigidPart3D body;                     // M3, [I3]
  std::vector<CabMount3D> mounts;       // four in the thesis
};

// The plow (Appendix E). Every position is given in the machine's axes for
// the boom straight (alpha' = 0) and the blade in the boom plane (beta = 0);
// the model turns the blade-plane points (cg, blade, shaker, bounce tire) by
// beta about the shank (link l2, pin 10 to pin 9) and then every plow point
// by alpha' about the vertical through the swing pin. The linkage pins'
// X, Z are those of the four-bar in the boom plane (plow_linkage.h).
struct Plow3D {
  Eigen::Vector3d swing_pin{0, 0, 0};   // point 19 on the frame; vertical axis
  double boom_angle = 0.0;              // alpha', rad, positive turning the boom's rear end to +Y
  double blade_angle = 0.0;             // beta, rad, positive turning the blade's rear edge to -Y
  double boom_offset = 0.0;             // Y of the boom plane at alpha' = 0, m
  double mass = 0.0;                    // M2, all on the shank
  Eigen::Vector2d cg{0, 0};             // (X, Z) in the boom plane
  Eigen::Matrix3d inertia_boom_axes = Eigen::Matrix3d::Zero();  // [I2] about the cg: x along the boom, z vertical
  FourBarGeometry linkage;              // (X, Z) of pins 6, 11, 9, 10
  Eigen::Vector2d blade_point{0, 0};    // point 5, where the soil acts
  Eigen::Vector2d shaker_point{0, 0};   // point 22
  double shaker_amplitude = 0.0;        // N
  double shaker_frequency = 0.0;        // Hz
  double shaker_phase = 0.0;            // rad
  Eigen::Vector2d bounce_tire_point{0, 0};
  SpringDamperValues bounce_tire;       // along the ground normal
  GroundInput bounce_input;
  Eigen::Vector2d cylinder_base{0, 0};  // lift cylinder on the swing carrier
  Eigen::Vector2d cylinder_arm_point{0, 0};  // point 8, on the upper arm
  SpringDamperValues lift_cylinder;
  SpringDamperValues swing_spring;      // K30 (N m/rad), C30 (N m s/rad): boom yaw against the frame
};

// The digging chain; its tooth law is rigid::ChainTeeth (Appendix D), as in 2-D.
struct Chain3D : ChainTeeth {
  Eigen::Vector3d boom_point{0, 0, 0};  // where the soil acts on the boom
  Eigen::Vector3d chain_pin{0, 0, 0};   // point 19: RCH and RMCH act on the frame here
  double chain_angle = 0.0;             // theta_ch, rad, in a plane parallel to X-Z
  double moment_arm = 0.0;              // m
};

struct Machine3DParameters {
  double ground_slope = 0.0;            // theta_g, rad (pitch of the ground about Y)
  double forward_speed = 0.0;           // VS, m/s, positive forward
  double travel_angle = 0.0;            // tau, rad: heading of travel from -X towards +Y (crab steering: the steering angle)
  double gravity = 9.80665;
  FrameAssembly3D frame;
  FrontAxle3D front_axle;
  Cab3D cab;
  Axle3D front_tires, rear_tires;
  Attachment attachment = Attachment::plow;  // none, plow or chain
  Plow3D plow;
  Chain3D chain;
  SoilLaw soil;                         // K5, C5 along and normal to the travel; REK, REC
  SpringDamperValues soil_lateral;      // K15, C15: across the travel, at the blade / boom point
  // Tires and the bounce tire push only (unilateral, rigid/unilateral_contact.h),
  // or act as the thesis's bilateral springs (linear).
  ContactLaw contacts = ContactLaw::unilateral;
};

}  // namespace framedyn::rigid
