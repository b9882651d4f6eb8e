// The road inputs' delays of both machines: see road_delays.h.
#include "coupling/road_delays.h"

#include "rigid/machine_2d.h"
#include "rigid/machine_3d.h"

namespace framedyn::coupling {

std::vector<RoadDelay> road_delays(const std::vector<std::pair<std::string, const rigid::GroundInput*>>& inputs) {
  std::vector<RoadDelay> out;
  for (const auto& [name, input] : inputs)
    if (input->kind == rigid::GroundInput::Kind::road) out.push_back({name, input->behind, input->behind / input->speed, input->behind_given});  // F.31
  return out;
}

std::vector<RoadDelay> road_delays(const rigid::Machine3DParameters& m) {
  std::vector<std::pair<std::string, const rigid::GroundInput*>> inputs;
  for (const auto& [name, tire] : {std::pair("front left", &m.front_tires.left), std::pair("front right", &m.front_tires.right),
                                   std::pair("rear left", &m.rear_tires.left), std::pair("rear right", &m.rear_tires.right)}) {
    inputs.emplace_back(name, &tire->vertical_input);
    inputs.emplace_back(std::string(name) + " (longitudinal)", &tire->longitudinal_input);
  }
  return road_delays(inputs);
}

std::vector<RoadDelay> road_delays(const rigid::Machine2DParameters& m) {
  std::vector<std::pair<std::string, const rigid::GroundInput*>> inputs;
  for (const auto& [name, tire] : {std::pair("front", &m.front_tire), std::pair("rear", &m.rear_tire)}) {
    inputs.emplace_back(name, &tire->normal_input);
    inputs.emplace_back(std::string(name) + " (tractive)", &tire->tractive_input);
  }
  return road_delays(inputs);
}

}  // namespace framedyn::coupling
