// The parameters of the 2-D vehicle model of the thesis's Chapter II (program
// CMW2D), the input of its builder (rigid::build_vehicle_model, rigid/vehicle_model.h;
// a run: rigid/vehicle_run.h). The model is the multibody assembly of: frame (uniform section plus added masses, Appendix C),
// cab (w, theta_v; its X motion tied to the frame, Eq. 2.8), front and rear
// tires (normal and tractive spring-dampers along the ground slope), and
// either the vibratory plow (four-bar linkage, Appendix A; lift cylinder,
// Appendix B; bounce tire; rotating shaker force, Eq. 2.28) or the digging
// chain (boom rigid on the frame, chain force and moment, Eq. 2.33, tooth
// force of Appendix D), with the soil law of Eq. 2.36 at the blade or boom.
// Tires and the bounce tire push only unless contacts is linear (rigid/unilateral_contact.h).
//
// Coordinates (fixed axes X rearward, Z up, rotations about +Y):
//   plow:  q = (x, z, theta_y, psi, w, theta_v)
//   chain: q = (x, z, theta_y, w, theta_v)
//   none:  q = (x, z, theta_y, w, theta_v)
// x, z: displacement of the frame reference point (the thesis's c.g. point,
// Eqs. C.3-C.4), m; theta_y: frame pitch, rad; psi: upper plow arm rotation,
// rad; w: cab vertical displacement, m; theta_v: cab pitch, rad.
// All values SI. docs/theory/rigid.md.
#pragma once

#include <Eigen/Dense>

#include <string>
#include <vector>

#include "rigid/ground_input.h"
#include "rigid/multibody.h"
#include "rigid/plow_linkage.h"
#include "rigid/soil_contact.h"
#include "rigid/unilateral_contact.h"
#include "rigid/vehicle_model.h"

namespace framedyn::rigid {

struct SpringDamperValues {
  double stiffness = 0.0;  // N/m
  double damping = 0.0;    // N s/m
};

// A mass rigidly attached to the frame (engine, reel, ballast, chain boom).
struct AddedMass {
  std::string name;
  double mass = 0.0;                     // CCM_i, kg
  double inertia = 0.0;                  // CCI_i, kg m^2 about its own c.g. (Y axis)
  Eigen::Vector2d position{0, 0};        // (XIM_i, ZIM_i), m
  Eigen::Vector2d attachment{0, 0};      // (XIC_i, ZIC_i): where its connection force acts on the frame
};

struct Frame2D {
  double front_end = 0.0;           // X of the uniform section's front end (-FLF), m
  double length = 0.0;              // FLT, m
  double mass_per_length = 0.0;     // rho, kg/m
  std::vector<AddedMass> added_masses;  // up to 30
};

struct CabMount {
  Eigen::Vector2d position{0, 0};   // on frame and cab alike at equilibrium, m
  SpringDamperValues vertical;
};

struct Cab2D {
  double mass = 0.0, inertia = 0.0;  // M3, I3
  Eigen::Vector2d cg{0, 0};
  CabMount front, rear;              // elements 12 and 14
};

struct Tire2D {
  Eigen::Vector2d contact{0, 0};     // contact point (both tires of the axle together)
  SpringDamperValues normal, tractive;
  GroundInput normal_input, tractive_input;
};

// SoilLaw (K5, C5, REK, REC, where the soil springs are unstretched): rigid/soil_contact.h.

struct Plow2D {
  double mass = 0.0, inertia = 0.0;  // M2, I2: all on the shank (link l2)
  Eigen::Vector2d cg{0, 0};
  FourBarGeometry linkage;
  Eigen::Vector2d blade_point{0, 0};       // point 5
  Eigen::Vector2d shaker_point{0, 0};      // point 22
  double shaker_amplitude = 0.0;           // N, the rotating force's magnitude
  double shaker_frequency = 0.0;           // Hz
  double shaker_phase = 0.0;               // rad
  Eigen::Vector2d bounce_tire_point{0, 0}; // point 18
  SpringDamperValues bounce_tire;          // K8, C8 (along the ground normal)
  GroundInput bounce_input;
  Eigen::Vector2d cylinder_frame_point{0, 0};  // point 7
  Eigen::Vector2d cylinder_arm_point{0, 0};    // point 8, on the upper arm
  SpringDamperValues lift_cylinder;            // K7, C7
};

// The digging chain: where it acts, and its tooth law (FTG, CCH, VCH, REH,
// RED, TS, LC, ramp time: rigid::ChainTeeth, Appendix D).
struct Chain2D : ChainTeeth {
  Eigen::Vector2d boom_point{0, 0};  // point 5, where the soil acts on the boom
  Eigen::Vector2d chain_pin{0, 0};   // point 6, where RCH and RMCH act on the frame
  double chain_angle = 0.0;          // theta_ch, rad
  double moment_arm = 0.0;           // l2 of Eq. 2.32, m
};

struct Machine2DParameters {
  double ground_slope = 0.0;     // theta_g, rad
  double forward_speed = 0.0;    // VS, m/s, positive forward (-X)
  double gravity = 9.80665;      // m/s^2, for static forces
  Frame2D frame;
  Cab2D cab;
  Tire2D front_tire, rear_tire;
  Attachment attachment = Attachment::plow;
  Plow2D plow;
  Chain2D chain;
  SoilLaw soil;
  // Tires and the bounce tire push only (unilateral, rigid/unilateral_contact.h),
  // or act as the thesis's bilateral springs (linear).
  ContactLaw contacts = ContactLaw::unilateral;
};

// The frame's mass, c.g. and pitch inertia about its c.g. (Appendix C,
// Eqs. C.2, C.4, C.5 with the errata's rho FLT), and the reference point of
// x, z, theta_y (Eqs. C.3-C.4: the cab's mass enters the reference height).
struct FrameMassProperties {
  double mass = 0.0;              // M1
  Eigen::Vector2d cg{0, 0};       // of M1
  double inertia = 0.0;           // about cg
  Eigen::Vector2d reference{0, 0};  // (XCG, ZCG) of the thesis
};
FrameMassProperties frame_mass_properties(const Frame2D& frame, const Cab2D& cab);

}  // namespace framedyn::rigid
