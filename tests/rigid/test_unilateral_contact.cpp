// Contacts that only push (rigid/unilateral_contact.h, docs/theory/rigid.md
// section 4a) against closed forms, on a mass m on a grounded one-sided
// spring-damper k, c (coordinate z up, measured from the static equilibrium
// under gravity g, static force SF = m g; the spring touches at z = SF / k):
//   - without gravity, a mass that meets the spring stays on it for half the
//     spring-mass period, pi sqrt(m/k), and leaves with the speed it came in;
//   - dropped from h under gravity, it stays in contact for
//     (pi + 2 asin(d_s / A)) / omega, d_s = m g / k, A = sqrt(d_s^2 + (V/omega)^2),
//     V = sqrt(2 g h), and rebounds to the height it was dropped from (energy);
//   - on a base moving as a sin(Omega t + phi), in its steady state
//     z = X sin(.), X = a omega^2 / (omega^2 - Omega^2), the contact force is
//     m g - m a Omega^2 omega^2 / (omega^2 - Omega^2) sin(.), so the mass lifts
//     off exactly when the base acceleration amplitude a Omega^2 exceeds
//     g (1 - Omega^2 / omega^2), 1 g for a stiff spring: just below never,
//     just above at sin(.) = threshold / amplitude;
//   - the event-located response against the fixed-step RK4 (which switches
//     only at step ends): within the bound a switch at most one step late gives.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "rigid/multibody.h"
#include "rigid/switched_system.h"
#include "rigid/time_integration.h"
#include "rigid/unilateral_contact.h"

namespace {

using namespace framedyn;
using Eigen::VectorXd;
constexpr double kPi = 3.14159265358979323846;

// A mass on a one-sided spring-damper, as the vehicle models build their tires.
class Bouncer : public rigid::SwitchedSystem {
 public:
  Bouncer(double m, double k, double c, double g, rigid::GroundInput base = {}) : mass_(m), model_({"z"}, {core::Quantity::length}) {
    rigid::Body b;
    b.name = "mass";
    b.mass = m;
    b.translation = rigid::Jacobian::Zero(3, 1);
    b.translation(2, 0) = 1.0;
    b.rotation = rigid::Jacobian::Zero(3, 1);
    model_.add_body(b);
    const int foot = model_.add_point({"foot", b.translation});
    model_.add_element({"spring", foot, -1, Eigen::Vector3d::UnitZ(), k, c});
    base_ = base;
    contacts_.configure(model_, {{"spring", 0, {}}}, {m * g}, {base}, rigid::ContactLaw::unilateral);
  }
  int size() const override { return 1; }
  void acceleration(double t, const VectorXd& q, const VectorXd& v, VectorXd& a) const override {
    const rigid::SpringDamper& e = model_.elements()[0];
    const double xr = base_.kind == rigid::GroundInput::Kind::none ? 0.0 : base_.displacement(t);
    const double vr = base_.kind == rigid::GroundInput::Kind::none ? 0.0 : base_.velocity(t);
    VectorXd f(1);
    f(0) = -e.stiffness * (q(0) - xr) - e.damping * (v(0) - vr);  // the linear element about equilibrium
    contacts_.add_lost_contacts(t, q, v, f);
    a = f / mass_;
  }
  int event_count() const override { return contacts_.event_count(); }
  void events(double t, const VectorXd& q, const VectorXd& v, double* g) const override { contacts_.events(t, q, v, g); }
  std::string on_event(double t, const VectorXd&, const VectorXd&, const std::vector<int>& fired, const std::vector<int>& dirs) override {
    std::string what;
    for (std::size_t i = 0; i < fired.size(); ++i) what += contacts_.on_event(t, fired[i], dirs[i]);
    return what;
  }
  void reset(double t, const VectorXd& q, const VectorXd& v) { contacts_.reset(t, q, v); }
  const rigid::UnilateralContacts& contacts() const { return contacts_; }

 private:
  double mass_;
  rigid::Multibody model_;
  rigid::GroundInput base_;
  rigid::UnilateralContacts contacts_;
};

VectorXd scalar(double x) { return VectorXd::Constant(1, x); }

rigid::IntegrationOptions tight(double end, double interval = 1e-3) {
  rigid::IntegrationOptions o;
  o.end_time = end;
  o.output_interval = interval;
  o.relative_tolerance = 1e-11;
  o.absolute_tolerance = 1e-13;
  return o;
}

std::vector<double> event_times(const rigid::Trajectory& tr, const std::string& word) {
  std::vector<double> t;
  for (const auto& e : tr.events)
    if (e.what.find(word) != std::string::npos) t.push_back(e.time);
  return t;
}

TEST(UnilateralContact, MassMeetingAOneSidedSpringStaysOnItForHalfTheSpringMassPeriod) {
  const double m = 100.0, k = 4e5, V = 0.3, d = 0.01;  // no gravity: touches at z = 0
  Bouncer b(m, k, 0.0, 0.0);
  b.reset(0.0, scalar(d), scalar(-V));
  EXPECT_FALSE(b.contacts().touching(0));
  const rigid::Trajectory tr = rigid::integrate_event_located(b, scalar(d), scalar(-V), tight(0.2));
  const std::vector<double> on = event_times(tr, "touches again"), off = event_times(tr, "loses contact");
  ASSERT_EQ(on.size(), 1u);
  ASSERT_EQ(off.size(), 1u);
  const double half_period = kPi * std::sqrt(m / k);
  std::printf("touch at %.12f s (exact %.12f), contact %.12f s (exact %.12f)\n", on[0], d / V, off[0] - on[0], half_period);
  // Located to CVODE's root tolerance (~1e-14 s) on a state accurate to ~1e-10 relative.
  EXPECT_NEAR(on[0], d / V, 1e-9);
  EXPECT_NEAR(off[0] - on[0], half_period, 1e-9);
  // Leaves with the speed it came in with, then flies freely: z = (t - t_off) V.
  const double t_end = tr.time.back();
  EXPECT_NEAR(tr.v.back()(0), V, 1e-8 * V);
  EXPECT_NEAR(tr.q.back()(0), (t_end - off[0]) * V, 1e-8);
}

TEST(UnilateralContact, DroppedMassStaysInContactForTheGravityOffsetArcAndReboundsToItsDropHeight) {
  const double m = 50.0, k = 2e5, g = 9.80665, h = 0.02;
  const double ds = m * g / k, omega = std::sqrt(k / m), V = std::sqrt(2 * g * h);
  const double A = std::hypot(ds, V / omega);
  const double fall = std::sqrt(2 * h / g), contact = (kPi + 2 * std::asin(ds / A)) / omega;
  const double z0 = ds + h;
  Bouncer b(m, k, 0.0, g);
  b.reset(0.0, scalar(z0), scalar(0.0));
  const double apex = 2 * fall + contact;  // back at the top
  const rigid::Trajectory tr = rigid::integrate_event_located(b, scalar(z0), scalar(0.0), tight(apex, apex / 100));
  const std::vector<double> on = event_times(tr, "touches again"), off = event_times(tr, "loses contact");
  ASSERT_EQ(on.size(), 1u);
  ASSERT_EQ(off.size(), 1u);
  std::printf("fall %.12f s (exact %.12f), contact %.12f s (exact %.12f), apex z %.12f (dropped from %.12f)\n", on[0], fall,
              off[0] - on[0], contact, tr.q.back()(0), z0);
  EXPECT_NEAR(on[0], fall, 1e-9);
  EXPECT_NEAR(off[0] - on[0], contact, 1e-9);
  // Energy across the two contact events: the rebound reaches the drop height, at rest.
  EXPECT_NEAR(tr.q.back()(0), z0, 1e-9);
  EXPECT_NEAR(tr.v.back()(0), 0.0, 1e-8);
}

// Base excitation in the steady state of the linear solution (no transient).
struct BaseRun {
  std::vector<double> lift_offs;
  double phase = 0.0, omega_base = 0.0;
};
BaseRun base_excited(double ratio_to_threshold) {
  const double m = 20.0, k = 8e5, g = 9.80665;
  const double omega = std::sqrt(k / m), Omega = 0.1 * omega;
  const double threshold = g * (1 - Omega * Omega / (omega * omega));  // base acceleration amplitude
  const double a = ratio_to_threshold * threshold / (Omega * Omega);
  rigid::GroundInput base;
  base.kind = rigid::GroundInput::Kind::sine;
  base.amplitude = a;
  base.frequency = Omega / (2 * kPi);
  base.phase = 0.0;
  Bouncer b(m, k, 0.0, g, base);
  const double X = a * omega * omega / (omega * omega - Omega * Omega);
  const VectorXd z0 = scalar(0.0), v0 = scalar(X * Omega);  // z = X sin(Omega t)
  b.reset(0.0, z0, v0);
  EXPECT_TRUE(b.contacts().touching(0));
  const rigid::Trajectory tr = rigid::integrate_event_located(b, z0, v0, tight(10 * 2 * kPi / Omega));
  return {event_times(tr, "loses contact"), 0.0, Omega};
}

TEST(UnilateralContact, BaseExcitedMassLosesContactOnlyAboveOneGOfBaseAcceleration) {
  const BaseRun below = base_excited(0.999);
  EXPECT_TRUE(below.lift_offs.empty()) << "lifted off at " << below.lift_offs.front() << " s";
  const BaseRun above = base_excited(1.001);
  ASSERT_FALSE(above.lift_offs.empty());
  // First lift-off where m g = m a Omega^2 omega^2/(omega^2 - Omega^2) sin(Omega t): sin = 1 / 1.001.
  const double t_exact = std::asin(1 / 1.001) / above.omega_base;
  std::printf("first lift-off %.12f s (exact %.12f)\n", above.lift_offs.front(), t_exact);
  EXPECT_NEAR(above.lift_offs.front(), t_exact, 1e-7);
}

TEST(UnilateralContact, EventLocatedBounceAgreesWithRk4AtSmallStepsWithinTheLateSwitchBound) {
  // A damped bounce: at touch-down the damper's force jumps by c V (V the approach speed), so the
  // acceleration jumps by c V / m; lift-off is where the total force is zero (no jump). RK4 switches
  // at the end of the step in which the event falls, at most one step h late, which leaves a velocity
  // error of at most (c V / m) h and a position error growing at most as (c V / m) h (T - t_i) after
  // touch-down i (the contact arcs, being oscillations, do not amplify it). V <= sqrt(2 g h_drop):
  // the damper only takes energy out.
  const double m = 50.0, k = 2e5, c = 400.0, g = 9.80665, drop = 0.02, z0 = drop + m * g / k, T = 0.3;
  auto run = [&](double step) {
    Bouncer b(m, k, c, g);
    b.reset(0.0, scalar(z0), scalar(0.0));
    rigid::IntegrationOptions o = tight(T, 1e-3);
    return step > 0 ? rigid::integrate_rk4(b, scalar(z0), scalar(0.0), step, o) : rigid::integrate_event_located(b, scalar(z0), scalar(0.0), o);
  };
  const rigid::Trajectory ref = run(0.0);
  const std::vector<double> touch = event_times(ref, "touches again");
  ASSERT_GE(touch.size(), 2u);  // bounces more than once
  ASSERT_GE(event_times(ref, "loses contact").size(), 1u);
  const double jump = c * std::sqrt(2 * g * drop) / m;
  for (double step : {2e-5, 1e-5}) {
    const rigid::Trajectory tr = run(step);
    ASSERT_EQ(tr.time.size(), ref.time.size());
    double bound = 0.0;
    for (double t : touch) bound += jump * step * (T - t);
    double err = 0.0;
    for (std::size_t i = 0; i < tr.time.size(); ++i) err = std::max(err, std::abs(tr.q[i](0) - ref.q[i](0)));
    std::printf("RK4 h = %.0e s against event-located: max |dz| %.3e m, late-switch bound %.3e m (%zu touch-downs)\n", step, err, bound,
                touch.size());
    EXPECT_LT(err, bound);
  }
}

}  // namespace
