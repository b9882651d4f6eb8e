// A run of a vehicle model (docs/theory/rigid.md, section 1a): the per-run
// state (the soil law's switching state and log, the chain's tooth count, the
// one-sided contacts' states and log), the one switched-system right-hand
// side over (const VehicleModel, state) for both the 2-D and the 3-D model
// (Eqs. 1.1-1.6, 2.23, 2.36, 4a.1-4a.4, 11.4), and force recovery as
// functions of (model, the state a run left, t, q, v). The model is never
// changed by a run, so one model serves any number of runs (run_vehicle).
#pragma once

#include <Eigen/Dense>

#include <string>
#include <vector>

#include "rigid/switched_system.h"
#include "rigid/time_integration.h"
#include "rigid/vehicle_model.h"

namespace framedyn::rigid {

// The soil law's state in a run: anchor in machine axes (X, Y, Z; Y = 0 in 2-D).
using SoilState = SoilContactState<Eigen::Vector3d>;

struct VehicleRunState {
  SoilContact<Eigen::Vector3d> soil;
  ToothCount teeth;
  UnilateralContacts contacts;
  SwitchedSystem::EventLength last_event_length;  // of the last event
};

// The state of a run starting at t with displacements q (velocities zero for
// the contacts' initial state): blade cutting, soil line at the blade, the
// contacts touching where they press.
VehicleRunState start_run(const VehicleModel& model, double t, const Eigen::VectorXd& q);

// The switched system (rigid/switched_system.h) of a model in a run state.
// Holds references: both must outlive it.
class VehicleDynamics : public SwitchedSystem {
 public:
  VehicleDynamics(const VehicleModel& model, VehicleRunState& state) : model_(model), state_(state) {}
  int size() const override { return model_.size(); }
  void acceleration(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v, Eigen::VectorXd& a) const override;
  int event_count() const override;
  void events(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v, double* g) const override;
  std::string on_event(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v, const std::vector<int>& fired,
                       const std::vector<int>& directions) override;
  EventLength last_event_length() const override { return state_.last_event_length; }
  double next_scheduled_change(double t) const override;
  std::string on_scheduled_change(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v) override;

 private:
  const VehicleModel& model_;
  VehicleRunState& state_;
};

// One run: a fresh state at options.start_time from (q0, v0), integrated with
// event location (rigid/time_integration.h); the state is returned for force recovery.
struct VehicleRun {
  VehicleRunState state;
  Trajectory trajectory;
};
VehicleRun run_vehicle(const VehicleModel& model, const Eigen::VectorXd& q0, const Eigen::VectorXd& v0, const IntegrationOptions& options);

// --- force recovery over (model, state of the run, t, q, v) ----------------------
// The soil law's state in force at t (after a switch at exactly t).
SoilState soil_state_at(const VehicleRunState& state, double t);
// The anchor of the soil springs at t: fixed in the machine, or (2-D and 3-D,
// spring_from_contact with contact_moves_with_soil) carried rearward with the
// soil at model.soil_flow from the instant it was set.
Eigen::Vector3d soil_anchor_at(const VehicleModel& model, const Eigen::Vector3d& anchor, double anchor_time, double t);
// Tension k (G q - xr) + c (G v - vr) in element e, N (positive stretched), with
// the soil law in force at t; for an element of a contact lost at t, the static
// force SF_e (the total force SF_e - tension is zero).
double element_tension(const VehicleModel& model, const VehicleRunState& state, int element, double t, const Eigen::VectorXd& q,
                       const Eigen::VectorXd& v);
// The shaker's force vector at t (machine axes, N); zero without a plow.
Eigen::Vector3d shaker_force(const VehicleModel& model, double t);
// The soil's force on the blade or boom reversed (RPF, Eq. 2.37), N, machine axes.
Eigen::Vector3d plow_force(const VehicleModel& model, const VehicleRunState& state, double t, const Eigen::VectorXd& q,
                           const Eigen::VectorXd& v);
// RCH (N) with the tooth count and soil law the run had at t; zero without a chain.
double chain_force(const VehicleModel& model, const VehicleRunState& state, double t);

}  // namespace framedyn::rigid
