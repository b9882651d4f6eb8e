// The summary's description of the frame assembly's parts on the beam model
// (docs/theory/coupling.md section 9): each part's mass, c.g., inertia and how it
// is joined to the frame, the assembly's total mass and where the frame
// structure's own mass came from. The reporting layer's half of
// coupling/frame_parts.h, which builds the parts into the model.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/units.h"
#include "coupling/frame_parts.h"
#include "fem/frame_model.h"

namespace framedyn::report {

// The summary's frame.parts (each part: mass, c.g., the frame node and how it
// is joined), frame.total_mass {value, unit, cg} and frame.structure (where the
// frame structure's mass came from), in `units`.
struct FramePartsSummary {
  nlohmann::ordered_json parts, total_mass, structure;
};
FramePartsSummary frame_parts_summary(const fem::FrameModel& model, const std::vector<coupling::MountedPart>& parts,
                                      const coupling::RigidBodyMass& body,
                                      const std::string& structure_part, const std::string& structure_source,
                                      const std::vector<std::string>& carried_by_mesh, const core::UnitSystem& units);

}  // namespace framedyn::report
