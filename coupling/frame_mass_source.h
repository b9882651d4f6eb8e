// One source of truth for the frame structure's mass (docs/theory/coupling.md,
// section 9.3, Eq. 9.4). When a 3-D study has a frame mesh (frame_response.mesh),
// the vehicle model's frame structure takes its mass, c.g. and inertia about the
// c.g. from the mesh's assembled mass matrix (T^T M T, Eq. C.9), so the vehicle
// model, the frame model and inertia relief carry the same mass; a user who changes
// a section changes both. The structure is the frame part with `from: frame_mesh`,
// else the part named `frame_structure`. A study part whose name is an element set
// of the mesh holding point masses (*MASS) is already in the mesh's mass: it is
// neither counted again by the vehicle model nor added again to the frame model.
// Every other frame part is mounted on the frame model (coupling/frame_parts.h).
//
// A structure part that also gives its own values is checked against the mesh's:
// the study is refused (STUDY-98) when its mass differs by more than 1 %, its c.g.
// by more than 1 % of the mesh's largest extent, or its inertia tensor about the
// c.g. by more than 10 % (Frobenius norm of the difference over the mesh's). An
// error, not a warning: two sources that disagree mean one of them is stale, and
// the run would silently use a number the user did not write.
#pragma once

#include <string>
#include <vector>

#include "core/error.h"
#include "coupling/frame_parts.h"
#include "fem/frame_model.h"
#include "rigid/machine_3d.h"

namespace framedyn::coupling {

// A frame part as the study gave it.
struct StudyFramePart {
  rigid::RigidPart3D part;      // SI; unset (zero mass) for `from: frame_mesh` without values
  bool from_mesh = false;       // `from: frame_mesh`
  bool has_values = true;       // mass, position and inertia given in the study
  core::InputLocation where;    // the part's entry, for messages
  std::vector<PartMount> mounts;     // where the frame model joins it (coupling/frame_parts.h); empty: its nearest frame node
  core::InputLocation mounts_where;  // the `mounts` key
};

struct FrameMassSources {
  std::vector<rigid::RigidPart3D> vehicle_parts;    // the vehicle model's frame.parts, the structure's values from the mesh
  std::vector<FramePart> mounted;                   // the parts the frame model adds (all but the structure and the carried), with their mounts
  std::vector<std::string> carried_by_mesh;         // parts the mesh's own *MASS elements already hold
  std::string structure_part;                       // the part the mesh models
  rigid::RigidPart3D structure;                     // its values from the mesh
};

struct FrameMassTolerance {
  double mass = 0.01;      // relative
  double cg = 0.01;        // of the mesh's largest extent
  double inertia = 0.10;   // relative, Frobenius norm
};

// `mesh` as read (SI; supports are ignored), `mesh_file` and `parts_at` (the
// study's frame.parts) for messages. Throws core::InputError: no structure part
// (STUDY-97), a structure part whose values disagree with the mesh (STUDY-98).
FrameMassSources frame_mass_from_mesh(const std::vector<StudyFramePart>& parts, const fem::FrameModel& mesh, const std::string& mesh_file,
                                      const core::InputLocation& parts_at, const core::UnitSystem& units, const FrameMassTolerance& tolerance = {});

}  // namespace framedyn::coupling
