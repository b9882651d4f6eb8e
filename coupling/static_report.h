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

#include "rigid/machine_2d.h"
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

// Machine: rigid::Machine2D or Machine3D.
template <class Machine>
std::vector<StaticContact> static_contacts(const Machine& machine) {
  const rigid::ContactStatics& s = machine.statics();
  const std::vector<double> forces = machine.static_element_forces();
  std::vector<StaticContact> out;
  for (std::size_t i = 0; i < s.contacts.size(); ++i)
    out.push_back({s.contacts[i].name, forces.at(static_cast<std::size_t>(s.contacts[i].normal)), static_cast<bool>(s.engaged[i])});
  return out;
}

// The state a ModalSoil stands for, and its label.
std::string contact_state_name(rigid::Machine2D::ModalSoil soil);
std::string contact_state_label(rigid::Machine2D::ModalSoil soil, const rigid::SoilLaw& law);

template <class Machine>
std::vector<StateModes> modes_by_contact_state(const Machine& machine, const std::vector<std::string>& fixed) {
  std::vector<StateModes> out;
  using S = rigid::Machine2D::ModalSoil;
  for (S soil : {S::cutting, S::backing, S::none})
    out.push_back({contact_state_name(soil), contact_state_label(soil, machine.parameters().soil),
                   rigid::rigid_modes(machine.mass_matrix(), machine.stiffness_matrix(soil), machine.model().coordinate_names(), fixed)});
  return out;
}

}  // namespace framedyn::coupling
