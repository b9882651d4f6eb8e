// 3-D rigid-body studies (the thesis's CMW3D runs, `model: rigid_3d`): read a
// YAML study into rigid::Machine3DParameters (SI), and run it — natural
// frequencies with dominant coordinates, a forced response, the frame loads
// at the eight load points (coupling/frame_loads_3d.h). Reading is strict in
// the way of coupling/rigid_study.h (file, line, key path, expected, found).
// The keys: docs/user-guide.md, "3-D rigid-body studies".
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/units.h"
#include "coupling/contact_report.h"
#include "coupling/static_report.h"
#include "coupling/frame_loads_3d.h"
#include "coupling/frame_study.h"
#include "coupling/rigid_study.h"
#include "coupling/road_delays.h"
#include "coupling/steady_report.h"
#include "rigid/calibration.h"
#include "rigid/machine_3d.h"
#include "rigid/rigid_modes.h"
#include "rigid/time_integration.h"

namespace framedyn::coupling {

// The `model:` key of a study file ("rigid_2d", "rigid_3d", ...); throws
// core::InputError if the file cannot be read or has no such key.
std::string study_model(const std::string& file);
std::string study_model(const YAML::Node& doc, const std::string& file);  // of a parsed document

struct RigidStudy3D {
  std::string file;
  std::string name;
  core::UnitSystem units;
  rigid::Machine3DParameters machine;
  bool modes = true;
  std::vector<std::string> fixed_coordinates;
  // The soil's contact state the modes and a calibration see (analysis.modal_soil, as in 2-D):
  // cutting, the default, is the state the response starts in (Eq. 11.7).
  rigid::ModalSoil modal_soil = rigid::ModalSoil::cutting;
  std::optional<ResponseRequest> response;
  std::optional<CalibrationRequest> calibration;  // parameter names of calibratable_parameters_3d()
  // The pipeline (issue 5): the `frame_response:` block sends this run's
  // frame loads at points 24-31 into the beam model of the frame
  // (coupling/frame_study.h). Needs analysis.response; takes no `loads` key.
  std::optional<FrameStudyRequest> frame_response;
  std::vector<DeclaredBodySize> body_sizes;  // bodies with declared dimensions (docs/theory/rigid.md, section 15)
};

RigidStudy3D read_rigid_study_3d(const std::string& file);
// The same from a parsed document; `file` names it in messages and anchors relative paths.
RigidStudy3D read_rigid_study_3d(const YAML::Node& doc, const std::string& file);

// The rear tires' delay (docs/theory/fatigue.md section 11, F.30-F.31): a tire's road input
// (kind: road) without `behind` runs behind = x_tire - x_front behind the front axle, x_front
// the mean X of the front tires' contacts (X grows rearward); `behind` in the study overrides the
// derived value. The reader fills GroundInput::behind so; a tire ahead of the front axle is refused
// (STUDY-141). coupling::road_delays (coupling/road_delays.h, shared with 2-D) lists them.

// Parameters a 3-D calibration may adjust (SI values). Names:
//   tires.<front|rear>.<vertical|longitudinal|lateral>.stiffness  (both tires of the axle)
//   tires.contact_depth (all four contacts), cab.<mounts|front_mounts|rear_mounts>.<x|y|z>.stiffness
//   (all four, the two ahead of or behind the mounts' mean X), cab.mass, cab.inertia.<xx|yy|zz>
//   frame.parts.mass_scale, frame.parts.inertia_scale.<xx|yy|zz> (the parts' total; setting it scales every part alike)
//   front_axle.inertia.xx, plow.swing_spring.stiffness, soil.stiffness, soil.lateral.stiffness,
//   plow.bounce_tire.stiffness, plow.lift_cylinder.stiffness, plow.mass
std::vector<std::string> calibratable_parameters_3d();
double get_parameter_3d(const rigid::Machine3DParameters& p, const std::string& name);
void set_parameter_3d(rigid::Machine3DParameters& p, const std::string& name, double value);
core::Quantity parameter_quantity_3d(const std::string& name);

// The 3-D model's results: the common ones (coupling/rigid_study.h,
// VehicleResults) and its parameters as analysed and frame loads.
struct RigidResults3D : VehicleResults {
  rigid::Machine3DParameters machine;  // as analysed (after any calibration)
  std::optional<FrameLoads3D> frame_loads;           // with a response
  std::optional<FrameLoads3D> static_frame_loads;    // with a response: the same points at the static equilibrium (static_frame_loads_3d)
};

RigidResults3D run_rigid_study_3d(const RigidStudy3D& study);

}  // namespace framedyn::coupling
