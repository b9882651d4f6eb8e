// The interface between vehicle models and time integrators: a linear
// second-order system whose coefficients switch at events,
//     M q'' + C_s q' + K_s q = f_s(t),
// where s is a discrete state (the soil law in force, the number of chain
// teeth digging, ...) that changes only when an event function crosses zero
// or at a scheduled time. Models implement it; integrators (CVODE with root
// finding, fixed-step RK4) drive it. docs/theory/rigid.md, section 4.
#pragma once

#include <Eigen/Dense>

#include <limits>
#include <string>
#include <vector>

namespace framedyn::rigid {

class SwitchedSystem {
 public:
  virtual ~SwitchedSystem() = default;

  virtual int size() const = 0;  // n, the number of generalised coordinates

  // q'' for the current discrete state.
  virtual void acceleration(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v, Eigen::VectorXd& a) const = 0;

  // Event functions g_i(t, q, v); the discrete state changes where one crosses zero.
  virtual int event_count() const { return 0; }
  virtual void events(double /*t*/, const Eigen::VectorXd& /*q*/, const Eigen::VectorXd& /*v*/, double* /*g*/) const {}
  // Called at a located root of the events listed in `fired` (indices), with
  // the direction of each crossing (+1 rising, -1 falling); updates the
  // discrete state. Returns a short description for the event log.
  virtual std::string on_event(double /*t*/, const Eigen::VectorXd& /*q*/, const Eigen::VectorXd& /*v*/,
                               const std::vector<int>& /*fired*/, const std::vector<int>& /*directions*/) {
    return {};
  }
  // A length that goes with the last on_event's description (the blade's
  // position where it backs off), in m, kept apart from the text so that
  // writers give it in the study's units; an empty name: none.
  struct EventLength {
    std::string name;
    double metres = std::numeric_limits<double>::quiet_NaN();
  };
  virtual EventLength last_event_length() const { return {}; }

  // The next time after t at which the discrete state changes on a schedule
  // (a chain tooth entering the ground, the end of a start-up ramp), or +inf.
  virtual double next_scheduled_change(double /*t*/) const { return std::numeric_limits<double>::infinity(); }
  // Called when the integration reaches a scheduled time.
  virtual std::string on_scheduled_change(double /*t*/, const Eigen::VectorXd& /*q*/, const Eigen::VectorXd& /*v*/) { return {}; }
};

}  // namespace framedyn::rigid
