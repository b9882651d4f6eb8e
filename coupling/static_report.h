// What a rigid-body run reports about the state its response starts from
// (docs/theory/rigid.md section 11; docs/user-guide.md, rigid.static and
// rigid.modes_by_state), the same in 2-D and 3-D:
//   - the static force of every contact in the contact-consistent equilibrium
//     (Eqs. 11.1-11.3), compression positive, and whether it is engaged;
//   - the rigid-body modes in each contact state of the soil, each with the
//     stiffness the response sees in it (Eq. 11.7): `cutting` (the soil law's
//     cutting factor on K5: 1, or 0 in the cut-face reading), `backing_off`
//     (REK K5) and `contact_lost` (no soil spring); tires and bounce tire
//     lifted in the statics are left out of all three.
#pragma once

#include <string>
#include <vector>

#include "rigid/vehicle_model.h"
#include "rigid/rigid_modes.h"

namespace framedyn::coupling {

struct StaticContact {
  std::string name;
  double force = 0.0;   // N, compression positive (negative for a lifted contact: k times its gap)
  bool engaged = true;
};

struct StateModes {
  std::string state;   // cutting, backing_off, contact_lost
  std::string label;   // what the response sees in it
  std::vector<rigid::RigidMode> modes;
};

// The static force of every contact of `model` in its equilibrium.
std::vector<StaticContact> static_contacts(const rigid::VehicleModel& model);

// The state a ModalSoil stands for, and its label.
std::string contact_state_name(rigid::ModalSoil soil);
std::string contact_state_label(rigid::ModalSoil soil, const rigid::SoilLaw& law);

// The modes of `model` in each contact state, `fixed` coordinates held.
std::vector<StateModes> modes_by_contact_state(const rigid::VehicleModel& model, const std::vector<std::string>& fixed);

}  // namespace framedyn::coupling
