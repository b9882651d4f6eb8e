// rigid.modes and rigid_modes.csv for every rigid-body study (report/rigid_modes_output.h).
#include "report/rigid_modes_output.h"

#include "core/units.h"
#include "report/csv_writer.h"
#include "report/json_quantity.h"

namespace framedyn::report {

nlohmann::ordered_json write_rigid_modes(const std::vector<std::string>& coordinates, const std::vector<rigid::RigidMode>& modes,
                                         const core::ResultsFolder& folder) {
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  std::vector<std::string> header = {"mode", report::column("frequency", core::UnitSystem::si().label(core::Quantity::frequency)), "dominant"};
  for (const std::string& c : coordinates) header.push_back("energy_share_" + c);
  report::CsvTable csv(header);
  for (std::size_t i = 0; i < modes.size(); ++i) {
    const rigid::RigidMode& m = modes[i];
    nlohmann::ordered_json share;
    for (std::size_t c = 0; c < coordinates.size(); ++c) share[coordinates[c]] = m.energy_share(static_cast<Eigen::Index>(c));
    list.push_back({{"mode", i + 1}, {"frequency", report::quantity(m.frequency_hz, core::UnitSystem::si().label(core::Quantity::frequency))}, {"dominant", m.dominant}, {"energy_share", share}});
    csv.row().add(static_cast<int>(i + 1)).add(m.frequency_hz).add(m.dominant);
    for (std::size_t c = 0; c < coordinates.size(); ++c) csv.add(m.energy_share(static_cast<Eigen::Index>(c)));
  }
  folder.write_text("rigid_modes.csv", csv.str());
  return list;
}

}  // namespace framedyn::report
