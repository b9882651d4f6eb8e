// The static contact forces and the modes by contact state: see static_report.h.
#include "coupling/static_report.h"

namespace framedyn::coupling {

std::string contact_state_name(rigid::ModalSoil soil) {
  switch (soil) {
    case rigid::ModalSoil::cutting: return "cutting";
    case rigid::ModalSoil::backing: return "backing_off";
    case rigid::ModalSoil::none: return "contact_lost";
  }
  return "cutting";
}

std::string contact_state_label(rigid::ModalSoil soil, const rigid::SoilLaw& law) {
  switch (soil) {
    case rigid::ModalSoil::cutting:
      return law.cut_face ? "blade cutting: no soil spring (cut-face reading), soil damping C5"
                          : "blade cutting: soil spring K5 and damping C5 at full value";
    case rigid::ModalSoil::backing: return "blade backing off: soil spring REK K5, damping REC C5";
    case rigid::ModalSoil::none: return "blade out of the soil: no soil spring";
  }
  return {};
}

std::vector<StaticContact> static_contacts(const rigid::VehicleModel& model) {
  const rigid::ContactStatics& s = model.statics;
  std::vector<StaticContact> out;
  for (std::size_t i = 0; i < s.contacts.size(); ++i)
    out.push_back({s.contacts[i].name, s.element_forces.at(static_cast<std::size_t>(s.contacts[i].normal)), static_cast<bool>(s.engaged[i])});
  return out;
}

std::vector<StateModes> modes_by_contact_state(const rigid::VehicleModel& model, const std::vector<std::string>& fixed) {
  std::vector<StateModes> out;
  using S = rigid::ModalSoil;
  for (S soil : {S::cutting, S::backing, S::none})
    out.push_back({contact_state_name(soil), contact_state_label(soil, model.soil),
                   rigid::rigid_modes(model.m, rigid::modal_stiffness(model, soil), model.multibody.coordinate_names(), fixed)});
  return out;
}

}  // namespace framedyn::coupling
