// Validity warnings of a vehicle response (docs/theory/coupling.md, section 8;
// docs/user-guide.md, "Warnings"): each a core::Warning with its code, message
// and figures.
//   rotation_beyond_linear_range  a body rotated so far that the linearised
//       kinematics (sin x ~ x, cos x ~ 1) err by more than 1 %: the neglected
//       1 - cos x ~ x^2/2 of the arm (Eq. 8.1) at the largest rotation.
//   switching_law_chattering      a switching law (the soil's, a contact's)
//       switches more than 10 times in one shaker period with a median
//       interval under 1 % of it: a sliding regime (Eq. 8.2), and how the
//       integrator treated it.
//   shaker_near_mode              the shaker frequency within 10 % of a
//       natural frequency of the vehicle (Eq. 8.3).
//   steady_not_reached            the run ended before steady operation
//       (rigid/steady_operation.h), with the remaining cycle-to-cycle change.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/warnings.h"
#include "rigid/multibody.h"
#include "rigid/rigid_modes.h"
#include "rigid/steady_operation.h"
#include "rigid/time_integration.h"

namespace framedyn::coupling {

// Eq. 8.1: the largest rotation over the samples: of any body (|R_b q|) or
// angle coordinate (theta*, psi, eta, alpha: psi turns the plow linkage's
// massless arms); named "body <name>" or "coordinate <name>", the first (bodies
// in order, then coordinates) among those within 1e-6 relative of the largest.
struct LargestRotation {
  double angle = 0.0;  // rad
  std::string body;    // what rotates: "body plow", "coordinate psi"
  double time = 0.0;   // s
};
constexpr double kLinearisationErrorLimit = 0.01;  // x^2/2 at the largest rotation
LargestRotation largest_body_rotation(const rigid::Multibody& model, const rigid::Trajectory& tr);
std::optional<core::Warning> rotation_warning(const LargestRotation& r);

// Eq. 8.2: one switching law's activity over shaker periods of length `window`.
constexpr int kChatterSwitchesPerPeriod = 10;   // more than this in one period ...
constexpr double kChatterIntervalFraction = 0.01;  // ... with a median interval under this fraction of it
struct SwitchingActivity {
  std::string law;                 // "soil" or the contact's name
  int switches = 0;                // over the run
  int chattering_periods = 0;      // periods meeting both limits
  int switches_in_chattering = 0;  // switches in those periods
  int most_in_one_period = 0;
  double median_interval = 0.0;    // s, between the switches of the chattering periods (else of the whole run)
  double first = 0.0, last = 0.0;  // s: the first and last switch of the chattering periods
};
// Switching laws in order of their first switch. The soil's law is named by
// "blade backs off" / "blade cuts again", a contact's by "<name> loses contact"
// / "<name> touches again"; scheduled changes (teeth) are not switches of a law.
std::vector<SwitchingActivity> switching_activity(const std::vector<rigid::Trajectory::Event>& events, double window);
// `event_located`: how the switches were integrated (else RK4 with `rk4_step`);
// `shaker`: the window is a shaker period (else the 0.1 s of switching_window).
std::vector<core::Warning> chattering_warnings(const std::vector<SwitchingActivity>& activity, double window, bool event_located,
                                               double rk4_step, bool shaker = true);

// Eq. 8.3: one warning per mode with |f_shaker - f_mode| <= 0.1 f_mode.
constexpr double kResonanceBand = 0.10;
std::vector<core::Warning> resonance_warnings(double shaker_hz, const std::vector<rigid::RigidMode>& modes, const std::string& modes_label);
// The same band on the elastic modes of the frame's beam model (the pipeline,
// `frame_modes_hz` ascending): one shaker_near_frame_mode per such mode, where
// the frame's stresses are set by its modal damping (a free-free frame model
// whose part hangs from one node can put a local mode there).
std::vector<core::Warning> frame_resonance_warnings(double shaker_hz, const std::vector<double>& frame_modes_hz, const std::string& mesh_name);

// steady_not_reached, when `s` has no reached_at; `duration` the run's length (s).
std::optional<core::Warning> steady_warning(const rigid::SteadyOperation& s, const rigid::SteadyCriterion& c, double duration);

// The window of Eq. 8.2 for a machine: its shaker period, or 0.1 s without a shaker.
double switching_window(double shaker_hz);

}  // namespace framedyn::coupling
