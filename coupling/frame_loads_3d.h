// Frame loads of the 3-D machine (thesis Chapter III, "Frame Loads"): three
// forces and three moments over time at the eight load points — 24 reel and
// reel carrier, 25 front axle pin (no TX), 26 rear axle pin (no TX), 27
// leveling cylinder (vertical FZ27), 28-31 cab mounts — each from Newton's
// laws on the attached body with its own inertia taken out (reel, front axle,
// rear axle) or from the mount elements (Eqs. 3.13-3.15). Loads are ON the
// frame, in the fixed vehicle axes, moments about the load point. Dynamic
// parts (the motion about the static equilibrium), as in the 2-D frame loads;
// the static parts at the same points are static_frame_loads_3d (below). The plow's or chain's loads on the frame at point 19 are
// returned too (`direct`), so that the frame's free body can be checked.
// docs/theory/coupling.md, "3-D frame loads".
#pragma once

#include <Eigen/Dense>

#include <string>
#include <vector>

#include "coupling/load_history.h"
#include "rigid/machine_3d.h"
#include "rigid/time_integration.h"
#include "rigid/vehicle_model.h"
#include "rigid/vehicle_run.h"

namespace framedyn::coupling {

struct FrameLoads3D {
  LoadHistory points;  // P24_REEL, P25_FRONT_AXLE_PIN, P26_REAR_AXLE_PIN, P27_LEVELING_CYLINDER, P28..P31 cab mounts
  // Other loads acting directly on the frame: the plow assembly at its swing
  // pin (point 19), or the chain (RCH, RMCH at point 19) and the soil on the
  // boom; same layout as `points`.
  LoadHistory direct;
};

// Names of the load points, in file order (the node sets of meshes/r100_frame.inp).
std::vector<std::string> frame_load_point_names();

// The loads of a run: `model` built from `parameters` (rigid::build_vehicle_model),
// `run` the state that run left (its soil and tooth logs), `trajectory` its samples.
FrameLoads3D frame_loads_3d(const rigid::VehicleModel& model, const rigid::Machine3DParameters& parameters, const rigid::VehicleRunState& run,
                            const rigid::Trajectory& trajectory);

// The static frame loads: the same load points at the vehicle model's static
// equilibrium under gravity (rigid/contact_statics.h, Eqs. 11.1-11.4), one
// sample at t = 0. Each attached body's weight (reel, axles, plow), the static
// contact forces SF_e (zero for a contact the statics released and for the soil,
// which carries nothing statically under unilateral contacts) and the cab
// mounts' static forces; no acceleration, shaker or chain force (their mean is
// in the dynamic loads, which are measured from this equilibrium). With the
// frame assembly's own weight these loads balance (docs/theory/coupling.md,
// section 11).
FrameLoads3D static_frame_loads_3d(const rigid::VehicleModel& model, const rigid::Machine3DParameters& parameters);

// Every load the vehicle model puts on the frame, as one history: points
// 24-31, then the attachment's (`direct`: P19_PLOW_SWING_PIN, or
// P19_CHAIN_PIN and BOOM_SOIL). This is what the frame model is loaded with
// and what frame_loads.csv holds; with the frame's own inertia these loads
// balance at every sample (docs/theory/coupling.md, section 6).
LoadHistory all_frame_loads(const FrameLoads3D& loads);
// The same, taking the histories over (no copy of a long record's rows).
LoadHistory all_frame_loads(FrameLoads3D&& loads);
// The same points in the same order, without a copy.
std::vector<const LoadPointHistory*> frame_load_points(const FrameLoads3D& loads);

}  // namespace framedyn::coupling
