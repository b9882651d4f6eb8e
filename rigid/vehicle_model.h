// One vehicle model for the 2-D and the 3-D machine (docs/theory/rigid.md,
// section 1a; docs/design.md, "rigid/"): everything a run reads and never
// changes, apart from the state of a run (rigid/vehicle_run.h). As Pinocchio
// separates Model and Data: the multibody assembly (bodies, points, elements;
// the coordinate table with each coordinate's name and quantity, Eqs. 1.1-1.6),
// each element's role (one-sided contact, soil on the blade or boom, ground
// input as data), the shaker (Eq. 2.28 / 3.12), the chain's tooth law
// (Appendix D), the soil law (Eq. 2.36), the switched system's coefficient
// matrices for each soil state and the contact-consistent statics
// (Eqs. 11.1-11.4). Built by build_vehicle_model from the 2-D parameters
// (Chapter II) or the 3-D parameters (Chapter III); both give this one type.
//
// A model is built once and run many times. Changing data that enters no
// matrix and no static equilibrium (the shaker's amplitude, frequency, phase)
// or only the damping matrices (an element's damping) updates the model in
// place (set_shaker, set_element_damping): the result is identical, bit for
// bit, to a model built afresh with the new value. Every other change (a mass,
// a position, a stiffness, the soil law, the contact law, the attachment, the
// ground inputs) needs a rebuild: it moves the static equilibrium, the
// one-sided contacts' preloads or the Jacobians. All values SI.
#pragma once

#include <Eigen/Dense>

#include <string>
#include <vector>

#include "rigid/contact_statics.h"
#include "rigid/ground_input.h"
#include "rigid/multibody.h"
#include "rigid/soil_contact.h"
#include "rigid/unilateral_contact.h"

namespace framedyn::rigid {

enum class Attachment { none, plow, chain };

// The stiffness the response sees in a contact state (docs/theory/rigid.md
// section 11.3): the blade cutting, backing off, or out of the soil.
enum class ModalSoil { cutting, backing, none };

// Exact positions of the 3-D plow's points after beta and alpha' (machine axes, m; Appendix E).
struct PlowPlacement {
  Eigen::Vector3d pin6, pin11, pin9, pin10, cg, blade, shaker, bounce, cylinder_base, cylinder_arm;
  Eigen::Vector3d pin_axis;           // arm pin axis (horizontal, normal to the boom plane)
  Eigen::Matrix3d inertia;            // [I2] in the fixed axes
};

// The plow's rotating force along the shank (Eq. 2.28, Eq. 3.12).
struct Shaker {
  double amplitude = 0.0;                     // N
  double frequency = 0.0;                     // Hz
  double phase = 0.0;                         // rad
  Eigen::Vector3d direction{0, 0, 0};         // unit, along the shank (zero without a plow)
};

struct VehicleModel {
  int dimensions = 2;                         // 2: the planar model (Chapter II); 3: the spatial one (Chapter III)
  Attachment attachment = Attachment::none;
  Multibody multibody{std::vector<std::string>{}, std::vector<core::Quantity>{}};
  double gravity = 9.80665;                   // m/s^2

  // Element roles. The reference ground input of every element (kind none:
  // fixed ground), and the elements that have one, in order.
  std::vector<GroundInput> ground_inputs;
  std::vector<int> input_elements;
  std::vector<ContactDefinition> contact_definitions;  // the one-sided contacts
  ContactLaw contact_law = ContactLaw::unilateral;
  std::vector<int> soil_elements;             // 2-D: X, Z; 3-D: along, across, vertical

  // The soil law (Eq. 2.36) along cut_direction at the blade (or boom) point;
  // the soil streams past the machine at soil_flow (Eq. 2.23), its line at soil_line_speed.
  SoilLaw soil;
  Eigen::Vector3d cut_direction{1, 0, 0};
  Eigen::Vector3d soil_flow{0, 0, 0};         // m/s
  double soil_line_speed = 0.0;               // VS cos theta_g, m/s

  int blade_point = -1, shaker_point = -1, chain_point = -1;
  // Body indices in multibody.bodies() (-1: the model has no such body).
  int frame_body = 0, cab_body = -1, plow_body = -1;
  int reel_body = -1, rear_axle_body = -1, front_axle_body = -1;  // 3-D only: rigid with the frame (reel) or its own (axles)
  Eigen::Vector3d frame_cg{0, 0, 0};          // c.g. of the frame body (for frame_point_jacobian)
  Eigen::Vector3d reference{0, 0, 0};         // where x, (y,) z are measured

  Shaker shaker;
  ChainTeeth chain;                           // the tooth law; chain_direction, chain_moment_arm where RCH, RMCH act
  Eigen::Vector3d chain_direction{0, 0, 0};
  double chain_moment_arm = 0.0;              // m

  // 3-D plow only (zero otherwise): the placement and the linkage ratio CB.
  PlowPlacement plow_placement{};
  double linkage_ratio = 0.0;

  // The switched system's coefficients: M; K, C with every element at full
  // value; while cutting (k_cut: the cut-face reading drops K5), while backing
  // off (REK K5, REC C5), without the soil springs; the factorised M.
  Eigen::MatrixXd m, k_full, c_full, k_cut, c_cut, k_back, c_back, k_no_soil;
  Eigen::LDLT<Eigen::MatrixXd> m_solver;
  ContactStatics statics;                     // the equilibrium q is measured from
  // The contacts configured at rest (static forces, maps, ground inputs);
  // every run copies them into its own state (rigid/vehicle_run.h).
  UnilateralContacts contacts;

  int size() const { return multibody.size(); }
  int coordinate(const std::string& name) const;  // -1 if absent
};

struct Machine2DParameters;
struct Machine3DParameters;

// The two builders: Chapter II's planar machine and Chapter III's spatial one.
VehicleModel build_vehicle_model(const Machine2DParameters& p);
VehicleModel build_vehicle_model(const Machine3DParameters& p);

// Updates that need no rebuild (see the top of this file).
void set_shaker(VehicleModel& model, double amplitude, double frequency, double phase);
// The damping of element `name` (N s/m); C and the contacts' dampers follow.
// Throws std::invalid_argument for an unknown element or a soil element (use a rebuild).
void set_element_damping(VehicleModel& model, const std::string& name, double damping);

// K in a contact state with the contacts lifted in the statics left out (Eq. 11.7).
Eigen::MatrixXd modal_stiffness(const VehicleModel& model, ModalSoil soil);
// Displacement Jacobian of a point fixed to the frame (machine axes, m).
Jacobian frame_point_jacobian(const VehicleModel& model, const Eigen::Vector3d& point);
// The reference ground input of element e, or nullptr.
const GroundInput* ground_input_of(const VehicleModel& model, int element);

}  // namespace framedyn::rigid
