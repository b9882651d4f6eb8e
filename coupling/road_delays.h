// The road inputs' delays behind the front axle (docs/theory/fatigue.md section 11, F.30-F.31), one
// implementation for the 2-D and the 3-D machines (issue 15: every feature in both models): a tire's
// road input (kind: road) runs `behind` behind the front axle and sees the front's profile
// delay = behind / speed later. The study readers fill GroundInput::behind (derived from the tire
// positions, x_tire - x_front with X growing rearward, or the study's `behind`); these functions
// list what they filled, for summary.json's rigid.road_inputs.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "rigid/ground_input.h"

namespace framedyn::rigid {
struct Machine2DParameters;
struct Machine3DParameters;
}  // namespace framedyn::rigid

namespace framedyn::coupling {

struct RoadDelay {
  std::string tire;       // 3-D: "front left", ..., with " (longitudinal)" for a longitudinal input;
                          // 2-D: "front", "rear", with " (tractive)" for a tractive input
  double behind = 0.0;    // m
  double delay = 0.0;     // s
  bool given = false;     // from the study's `behind`, else derived
};

// F.31 for each named input of kind road, in the order given (the others are skipped).
std::vector<RoadDelay> road_delays(const std::vector<std::pair<std::string, const rigid::GroundInput*>>& inputs);
// Every road input of the machine's tires: 3-D front left, front right, rear left, rear right (each
// vertical, then longitudinal); 2-D front, rear (each normal, then tractive).
std::vector<RoadDelay> road_delays(const rigid::Machine3DParameters& machine);
std::vector<RoadDelay> road_delays(const rigid::Machine2DParameters& machine);

}  // namespace framedyn::coupling
