// The labels of the contact states a run's modes are given in: see static_report.h.
#include "coupling/static_report.h"

namespace framedyn::coupling {

std::string contact_state_name(rigid::Machine2D::ModalSoil soil) {
  switch (soil) {
    case rigid::Machine2D::ModalSoil::cutting: return "cutting";
    case rigid::Machine2D::ModalSoil::backing: return "backing_off";
    case rigid::Machine2D::ModalSoil::none: return "contact_lost";
  }
  return "cutting";
}

std::string contact_state_label(rigid::Machine2D::ModalSoil soil, const rigid::SoilLaw& law) {
  switch (soil) {
    case rigid::Machine2D::ModalSoil::cutting:
      return law.cut_face ? "blade cutting: no soil spring (cut-face reading), soil damping C5"
                          : "blade cutting: soil spring K5 and damping C5 at full value";
    case rigid::Machine2D::ModalSoil::backing: return "blade backing off: soil spring REK K5, damping REC C5";
    case rigid::Machine2D::ModalSoil::none: return "blade out of the soil: no soil spring";
  }
  return {};
}

}  // namespace framedyn::coupling
