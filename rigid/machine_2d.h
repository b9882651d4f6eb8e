// The 2-D vehicle model of the thesis's Chapter II (program CMW2D) on the
// multibody assembly: frame (uniform section plus added masses, Appendix C),
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

#include "rigid/contact_statics.h"
#include "rigid/ground_input.h"
#include "rigid/multibody.h"
#include "rigid/plow_linkage.h"
#include "rigid/soil_contact.h"
#include "rigid/switched_system.h"
#include "rigid/unilateral_contact.h"

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

enum class Attachment { none, plow, chain };

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

// The assembled 2-D machine: its multibody model, and the switched dynamics
// (soil law, chain teeth, shaker) for the integrators.
class Machine2D : public SwitchedSystem {
 public:
  explicit Machine2D(const Machine2DParameters& p);

  const Multibody& model() const { return model_; }
  const Machine2DParameters& parameters() const { return p_; }
  const FrameMassProperties& frame_mass() const { return frame_; }
  // Index of a coordinate by name ("x", "psi", ...), -1 if absent.
  int coordinate(const std::string& name) const;

  // K and C with every element at full value (soil K5 included, every contact engaged).
  Eigen::MatrixXd stiffness_matrix() const { return k_full_; }
  // The stiffness the response sees in a contact state (docs/theory/rigid.md
  // section 11.3): the blade cutting (the soil law's cutting factor on K5: 1,
  // or 0 in the cut-face reading), backing off (REK K5), or out of the soil
  // (no soil spring); the tires and bounce tire lifted in the statics are left out.
  enum class ModalSoil { cutting, backing, none };
  Eigen::MatrixXd stiffness_matrix(ModalSoil soil) const;
  Eigen::MatrixXd damping_matrix() const { return c_full_; }
  Eigen::MatrixXd mass_matrix() const { return m_; }

  // Static equilibrium under gravity from the unloaded springs, with the
  // contact law the response starts in (rigid/contact_statics.h): q_static and
  // the static force in every element (compression positive). The response's
  // q is measured from it.
  Eigen::VectorXd static_deflection() const { return statics_.deflection; }
  std::vector<double> static_element_forces() const { return statics_.element_forces; }
  const ContactStatics& statics() const { return statics_; }  // which contacts are engaged, b of Eq. 11.4

  // SwitchedSystem
  int size() const override { return model_.size(); }
  void acceleration(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v, Eigen::VectorXd& a) const override;
  int event_count() const override;
  void events(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v, double* g) const override;
  std::string on_event(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v, const std::vector<int>& fired,
                       const std::vector<int>& directions) override;
  EventLength last_event_length() const override { return last_event_length_; }
  double next_scheduled_change(double t) const override;
  std::string on_scheduled_change(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v) override;

  // Resets the discrete state for a run starting at t with (q, v): blade cutting, soil line at the blade.
  void reset(double t, const Eigen::VectorXd& q);

  // The soil law's state (rigid/soil_contact.h): set at reset and at every
  // located switch, so that forces can be recovered afterwards at any sample
  // time. anchor: the (X, Z) blade displacement at which the soil springs are
  // unstretched, set at anchor_time (it moves with the soil from then on if
  // contact_moves_with_soil); line: x of the unpenetrated soil line at time.
  using SoilState = SoilContactState<Eigen::Vector2d>;
  const std::vector<SoilState>& soil_history() const { return soil_.history(); }
  SoilState soil_state_at(double t) const;  // the state in force at t (after a switch at exactly t)

  // Forces for recovery. Plow resultant RPF (Eq. 2.37), N, in (X, Z), with
  // the soil law in force at t.
  Eigen::Vector2d plow_force(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v) const;
  double chain_force(double t) const;  // RCH, N, with the teeth and soil law in force at t
  bool cutting() const { return soil_.cutting(); }
  double soil_line_at(double t) const;

  // Displacement Jacobian of a point fixed to the frame at (X, Z).
  Jacobian frame_point_jacobian(const Eigen::Vector2d& point) const;
  // Tension in an element (N, positive when stretched): k (G q - xr) + c (G v - vr),
  // with the soil law in force at t for the soil elements. For an element of a
  // contact lost at t (unilateral contacts) it is the static force SF_e, so
  // that the total force SF_e - tension is zero.
  double element_tension(int element, double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v) const;
  // The shaker's force vector at t (X, Z), N; zero without a plow.
  Eigen::Vector2d shaker_force(double t) const;

  // The reference ground input of a grounded element (tires, bounce tire), or nullptr.
  const GroundInput* ground_input_of(int element) const;

  // The tires' and bounce tire's contacts (names front_tire, rear_tire,
  // bounce_tire) and their state: rigid/unilateral_contact.h.
  const UnilateralContacts& contacts() const { return contacts_; }

  // Element and point indices.
  int blade_point() const { return blade_point_; }
  const std::vector<int>& soil_elements() const { return soil_elements_; }

 private:
  EventLength last_event_length_;  // of the last on_event
  Machine2DParameters p_;
  FrameMassProperties frame_;
  Multibody model_;
  Eigen::MatrixXd m_, k_full_, c_full_, k_cut_, c_cut_, k_back_, c_back_, k_no_soil_;
  Eigen::LDLT<Eigen::MatrixXd> m_solver_;
  int blade_point_ = -1, shaker_point_ = -1, chain_point_ = -1;
  std::vector<int> soil_elements_;
  // Discrete state: the soil law (x of the blade along X, moving at VS cos theta_g
  // while backing) and the chain's tooth count (XNN).
  SoilContact<Eigen::Vector2d> soil_;
  ToothCount teeth_;
  UnilateralContacts contacts_;  // one-sided tires (events after the soil's)
  ContactStatics statics_;       // the equilibrium q is measured from (Eqs. 11.1-11.4)
  int soil_event_count() const { return blade_point_ >= 0 ? 1 : 0; }
  std::string soil_switch(double t, const Eigen::VectorXd& q, int direction);  // Eq. 2.36's event
  // The anchor at t: fixed in the machine, or carried rearward with the soil.
  Eigen::Vector2d anchor_at(const Eigen::Vector2d& anchor, double anchor_time, double t) const;

  Eigen::VectorXd forcing(double t) const;  // Q(t) + FK(t) + FC(t), without the state-dependent part
};

}  // namespace framedyn::rigid
