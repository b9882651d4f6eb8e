// Frame loads and frame stress resultants of the 2-D machine (thesis
// Chapter II, "Frame Loads" and "Stress Resultants", Eqs. 2.43-2.47):
// the forces every attached part puts on the frame over time — tires, cab
// mounts and the cab's horizontal tie, added masses (their inertia,
// Eqs. 2.45-2.46), the plow linkage's pins and lift cylinder, or the chain
// boom — each from Newton's laws on the part with its own inertia taken out;
// and from them the axial, shear and bending resultants SRX, SRZ, SRMY at
// output points along the frame, with the uniform section's distributed
// inertia (Eq. 2.47). Dynamic parts only, as in the thesis (the static weight
// distribution is left out). docs/theory/coupling.md.
#pragma once

#include <Eigen/Dense>

#include <string>
#include <vector>

#include "rigid/machine_2d.h"
#include "rigid/time_integration.h"
#include "rigid/vehicle_model.h"
#include "rigid/vehicle_run.h"

namespace framedyn::coupling {

// One load on the frame: a force (X, Z) and a moment about +Y at `point`, per sample.
struct FrameLoad2D {
  std::string name;
  Eigen::Vector2d point{0, 0};     // where it acts on the frame, m
  std::vector<Eigen::Vector2d> force;  // N, on the frame
  std::vector<double> moment;          // N m, about +Y
};

// The names of the loads frame_loads_2d gives for the machine's own parts
// (tires, cab mounts and tie, plow pins and cylinder, chain boom). An added
// mass's load carries the mass's name, so it may not take one of these.
const std::vector<std::string>& part_load_names_2d();

// The loads of a run: `model` built from `parameters` (rigid::build_vehicle_model),
// `run` the state that run left (its soil and tooth logs), `trajectory` its samples.
std::vector<FrameLoad2D> frame_loads_2d(const rigid::VehicleModel& model, const rigid::Machine2DParameters& parameters,
                                        const rigid::VehicleRunState& run, const rigid::Trajectory& trajectory);

// The distributed inertia of the uniform section in front of `x_cut`, as a
// force (X, Z) and its moment about (x_cut, z_cut), at one sample.
struct SectionLoad {
  Eigen::Vector2d force{0, 0};
  double moment = 0.0;
};
SectionLoad tube_inertia_in_front(const rigid::VehicleModel& model, const rigid::Frame2D& frame, const Eigen::VectorXd& acceleration, double x_cut,
                                  double z_cut);

// Stress resultants (Eq. 2.47) for the whole frame (both rails together):
//   SRX  = -sum FCX_j + SRXD     (axial force on the front part's rear face)
//   SRZ  = -sum FCZ_j + SRZD     (shear force, Z)
//   SRMY = sum [FCM_j + FCX_j (Z_j - Z_op) + FCZ_j (X_op - X_j)] + SRMYD
// summed over the loads in front of the output point (X_j < X_op); the D terms
// are the uniform section's inertia in front. SRMY is the moment of the loads
// in front about the output point, so the internal bending moment on the
// front part's face is -SRMY. Indexed [sample][output point].
struct StressResultants {
  std::vector<double> output_x;                  // m
  double output_z = 0.0;                         // m
  std::vector<std::vector<double>> srx, srz, srmy;  // N, N, N m
};
StressResultants frame_stress_resultants(const rigid::VehicleModel& model, const rigid::Frame2D& frame, const rigid::Trajectory& trajectory,
                                         const std::vector<FrameLoad2D>& loads, const std::vector<double>& output_x,
                                         double output_z = 0.0);

}  // namespace framedyn::coupling
