// The soil law and the digging chain's tooth law shared by the 2-D and the
// 3-D machine (rigid::VehicleModel, rigid/vehicle_run.h):
//
// - SoilContact: the cutting/backing switching law of the soil at the blade
//   or boom point (thesis Eq. 2.36, with the soil streaming past the machine
//   at VS, Eq. 2.23). While the blade cuts, the soil springs and dampers act
//   at full value (K5, C5); the blade backs off when it moves rearward
//   faster than the soil flows past, and from then on moves in soil already
//   cut (REK K5, REC C5) until it reaches the unpenetrated soil line again,
//   which streams rearward at VS cos theta_g. The state (cutting, soil line,
//   where the soil springs are unstretched) is logged at every switch so that
//   forces can be recovered at any sample time afterwards.
// - ChainTeeth, ToothCount: the tooth force of Appendix D, FTH = FTG REH +
//   VCH CCH RED, with NTD = MTIG - 1 + XNN teeth digging (Eq. D.3, XNN
//   = 1 for the first ATCH of every tooth period TPCH), RCH = NTD FTH with a
//   linear start-up (Eq. 2.41), and the schedule of the tooth-count changes.
//   The tooth count in force is logged at every change, so that a sample
//   taken a hair before a scheduled change sees the count the equations of
//   motion saw, not the one the clock arithmetic gives at that time.
//
// Positions and velocities along the cutting direction in m and m/s, forces
// in N, times in s. docs/theory/rigid.md.
#pragma once

#include <Eigen/Dense>

#include <string>
#include <utility>
#include <vector>

namespace framedyn::rigid {

struct SoilLaw {
  double stiffness = 0.0;            // K5, N/m (both X and Z at the blade point)
  double damping = 0.0;              // C5, N s/m
  double stiffness_reduction = 0.0;  // REK, 0..1, while the blade moves in soil already cut
  double damping_reduction = 1.0;    // REC, 0..1
  // Where the soil springs are unstretched: at the blade's equilibrium
  // position (Eq. 2.37 as printed, the default), or where the blade was when
  // the current cut began ("soil in compression only": the soil is pushed
  // from the point of contact on).
  bool spring_from_contact = false;
  // With spring_from_contact: the springs' ground end is fixed in the soil,
  // which streams rearward past the machine at VS (Eq. 2.23), so the
  // unstretched position moves with the unpenetrated soil line at
  // (VS cos theta_g, -VS sin theta_g) from the instant the cut began; the
  // spring then acts on the blade's penetration into the soil it is cutting,
  // as the damper acts on its velocity relative to that soil (2-D and 3-D:
  // the anchor moves at VehicleModel::soil_flow).
  bool contact_moves_with_soil = false;
  // The cut-face reading: the cutting blade fails the soil it pushes, so the
  // springs' ground end stays at the blade while it cuts (they carry
  // nothing: the soil resists a cutting blade by its damping alone); when it
  // backs off, the springs (REK K5) act from the cut face it left, where the
  // unpenetrated soil begins, carried rearward with the soil (with
  // contact_moves_with_soil, which the study reader sets with it). The
  // modes still see K5 at full value (analysis.modal_soil): a blade at rest
  // in the soil is held by its elasticity. docs/theory/rigid.md section 4.
  bool cut_face = false;

  // The factors on K5 and C5 in the state `cutting` (1, or REK and REC; 0 on
  // K5 while cutting in the cut-face reading).
  double stiffness_factor(bool cutting) const { return cutting ? (cut_face ? 0.0 : 1.0) : stiffness_reduction; }
  double damping_factor(bool cutting) const { return cutting ? 1.0 : damping_reduction; }
};

// One state of the soil law, from `time` on. Anchor: the blade displacement
// at which the soil springs are unstretched (Eigen::Vector2d (X, Z) in 2-D,
// Eigen::Vector3d in 3-D).
template <class Anchor>
struct SoilContactState {
  double time = 0.0;             // when it began, s
  bool cutting = true;
  double line = 0.0;             // blade position along the cut where the soil is unpenetrated, at `time`, m
  Anchor anchor = Anchor::Zero();
  double anchor_time = 0.0;      // when the anchor was set, s
};

// The switching law of Eq. 2.36 and its log; the machine supplies the
// blade's position and velocity along the cutting direction.
template <class Anchor>
class SoilContact {
 public:
  using State = SoilContactState<Anchor>;
  enum class Switch { none, backs_off, cuts_again };

  // soil_velocity: VS cos theta_g, the rate at which the soil streams
  // rearward along the cut; spring_from_contact: SoilLaw::spring_from_contact;
  // anchor_at_back_off: the anchor is set where each cut ends (SoilLaw::cut_face).
  void configure(double soil_velocity, bool spring_from_contact, bool anchor_at_back_off = false);

  // A run starting at t with the blade cutting at `position`; `anchor` is the
  // blade displacement then (used with spring_from_contact, else zero).
  void reset(double t, double position, const Anchor& anchor);

  bool cutting() const { return cutting_; }
  const Anchor& anchor() const { return anchor_; }
  double anchor_time() const { return anchor_time_; }
  // The unpenetrated soil line at t (moving with the soil while backing).
  double line_at(double t) const;

  // The event function: zero where the state switches. Each starts a hair
  // (1e-10 m or m/s) on its own side of zero when its state begins, because
  // a switch leaves the other function exactly at zero with zero slope (the
  // soil line is set at the blade, the relative velocity is zero): an exact
  // zero at a restart hides the next crossing from the root finder, as when
  // the blade only grazes free and cuts again at once.
  double event_value(double t, double position, double velocity) const;

  // A located zero of event_value crossed in `direction`: cutting ends when
  // the blade moves rearward faster than the soil flows past (direction > 0),
  // cutting resumes when the blade reaches the soil line again (direction <
  // 0). `anchor` is the blade displacement at t.
  Switch on_event(double t, int direction, double position, const Anchor& anchor);

  const std::vector<State>& history() const { return history_; }
  State state_at(double t) const;  // the state in force at t (after a switch at exactly t)

 private:
  double soil_velocity_ = 0.0;
  bool spring_from_contact_ = false;
  bool anchor_at_back_off_ = false;
  bool cutting_ = true;
  double line_ = 0.0, line_time_ = 0.0;
  Anchor anchor_ = Anchor::Zero();
  double anchor_time_ = 0.0;
  std::vector<State> history_;
};

extern template class SoilContact<Eigen::Vector2d>;
extern template class SoilContact<Eigen::Vector3d>;

// The digging chain's tooth law (Appendix D); the base of Chain2D and Chain3D.
struct ChainTeeth {
  double tooth_static_force = 0.0;  // FTG, N
  double tooth_damping = 0.0;       // CCH, N s/m
  double chain_speed = 0.0;         // VCH, m/s
  double static_reduction = 1.0;    // REH, while the teeth back off
  double damping_reduction = 1.0;   // RED
  double tooth_spacing = 0.0;       // TS, m
  double length_in_ground = 0.0;    // LC, m
  double ramp_time = 0.0;           // linear start-up, s

  // XNN at t from the schedule: within each tooth period TPCH, all MTIG teeth
  // dig for the first ATCH; true without a moving chain.
  bool full_teeth_at(double t) const;
  double teeth_digging(bool full_teeth) const;  // NTD = MTIG - 1 + XNN (Eq. D.3)
  double tooth_force(bool cutting) const;    // FTH (Appendix D)
  double chain_force(double t, bool cutting, bool full_teeth) const;  // RCH (Eq. 2.41) with the start-up ramp
  // The next scheduled change after t (end of the ramp, start or end of
  // ATCH), infinity if none; next_tooth_change: the same without the ramp's end.
  double next_change(double t) const;
  double next_tooth_change(double t) const;
};

// The tooth count in force during a run, and its log.
class ToothCount {
 public:
  explicit ToothCount(const ChainTeeth& law = {}) : law_(law) {}
  const ChainTeeth& law() const { return law_; }
  void reset(double t);  // a run starting at t
  bool full() const { return full_; }
  // At a scheduled change at t: the new count as "N teeth digging", or empty if unchanged.
  std::string on_scheduled_change(double t);
  // XNN in force at t: from the log up to the next scheduled tooth-count
  // change after the last logged one (the span a run has covered), from the
  // schedule beyond it (or where nothing is logged).
  bool full_at(double t) const;

 private:
  ChainTeeth law_;
  bool full_ = true;
  std::vector<std::pair<double, bool>> history_;  // (time, all MTIG teeth digging) from each change on
};

}  // namespace framedyn::rigid
