// The two machine builders of the one study reader (coupling/rigid_study.h):
// each reads its model's machine keys of a study file (ground, frame, cab,
// tires, the front axle in 3-D, soil, plow, chain) into its parameters (SI),
// names its calibration parameters, gives a declared body's inertia, and
// reads the one block its model alone has (2-D: frame_output; 3-D:
// frame_response). Everything else of a study (units, attachment, contacts,
// analysis, calibration, body sizes' checks) is read once, for both, by
// read_rigid_study; the runs are run_rigid_study's. Internal to coupling/.
#pragma once

#include <string>
#include <vector>

#include "coupling/frame_mass_source.h"
#include "coupling/rigid_study.h"
#include "coupling/study_blocks.h"
#include "coupling/yaml_input.h"

namespace framedyn::coupling::internal {

// ---- 2-D (model: rigid_2d) ----

// The machine's keys: ground, frame, cab, tires, soil, plow, chain, in this
// order; appends the declared body sizes to `body_sizes`.
rigid::Machine2DParameters read_machine_2d(const YamlMap& root, rigid::Attachment attachment, rigid::ContactLaw contacts,
                                           std::vector<DeclaredBodySize>& body_sizes);
// The frame_output block (X positions on the frame tube, the rail's section).
FrameOutputRequest read_frame_output(const YamlMap& fo, const rigid::Machine2DParameters& p, const core::UnitSystem& units);

std::vector<std::string> calibratable_parameters_2d();
double get_parameter_2d(const rigid::Machine2DParameters& p, const std::string& name);
void set_parameter_2d(rigid::Machine2DParameters& p, const std::string& name, double value);
core::Quantity parameter_quantity_2d(const rigid::Machine2DParameters& p, const std::string& name);
// The mass and pitch inertia (about Y) of a declared body: an added mass of the frame, the cab or the plow.
BodyInertia body_inertia_2d(const rigid::Machine2DParameters& p, const DeclaredBodySize& b);

// ---- 3-D (model: rigid_3d) ----

// The frame's parts as the study lists them: their entries (for messages) and
// where the mesh gives their values (frame_response with `from: frame_mesh`).
struct StudyFrameParts {
  std::vector<StudyFramePart> parts;
  std::vector<YamlMap> entries;  // frame.parts[i]
  core::InputLocation where;     // frame.parts
};

// The machine's keys: tires, ground, frame, front_axle, cab, soil, plow,
// chain, in this order; appends the declared body sizes to `body_sizes` and
// the frame's parts as listed to `parts`.
rigid::Machine3DParameters read_machine_3d(const YamlMap& root, rigid::Attachment attachment, rigid::ContactLaw contacts,
                                           std::vector<DeclaredBodySize>& body_sizes, StudyFrameParts& parts);
// The frame_response block (the pipeline), with the frame parts' values from
// the mesh put into the machine (s.machine_3d().frame.parts); without the
// block, a part `from: frame_mesh` is refused.
void read_frame_response(const YamlMap& root, const std::string& file, const StudyFrameParts& parts, RigidStudy& s);

std::vector<std::string> calibratable_parameters_3d();
double get_parameter_3d(const rigid::Machine3DParameters& p, const std::string& name);
void set_parameter_3d(rigid::Machine3DParameters& p, const std::string& name, double value);
core::Quantity parameter_quantity_3d(const std::string& name);
// The mass and the inertias about its own axes of a declared body.
BodyInertia body_inertia_3d(const rigid::Machine3DParameters& p, const DeclaredBodySize& b);

}  // namespace framedyn::coupling::internal
