// The soil law (Eq. 2.36) and the chain tooth law (Appendix D) shared by
// the 2-D and 3-D machines; see soil_contact.h.
#include "rigid/soil_contact.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>

namespace framedyn::rigid {

// --- the soil law (Eq. 2.36) ---------------------------------------------------

template <class Anchor>
void SoilContact<Anchor>::configure(double soil_velocity, bool spring_from_contact, bool anchor_at_back_off) {
  soil_velocity_ = soil_velocity;
  spring_from_contact_ = spring_from_contact;
  anchor_at_back_off_ = anchor_at_back_off;
}

template <class Anchor>
void SoilContact<Anchor>::reset(double t, double position, const Anchor& anchor) {
  cutting_ = true;
  line_ = position;
  line_time_ = t;
  anchor_ = spring_from_contact_ ? anchor : Anchor::Zero();
  anchor_time_ = t;
  history_.assign(1, {t, true, line_, anchor_, anchor_time_});
}

template <class Anchor>
double SoilContact<Anchor>::line_at(double t) const {
  return cutting_ ? line_ : line_ + soil_velocity_ * (t - line_time_);
}

template <class Anchor>
double SoilContact<Anchor>::event_value(double t, double position, double velocity) const {
  constexpr double kHair = 1e-10;
  // Cutting ends when the blade moves rearward faster than the soil flows past;
  // it resumes when the blade reaches the unpenetrated soil line again.
  if (cutting_) return velocity - soil_velocity_ - kHair;
  return position - line_at(t) + kHair;
}

template <class Anchor>
typename SoilContact<Anchor>::Switch SoilContact<Anchor>::on_event(double t, int direction, double position, const Anchor& anchor) {
  if (cutting_ && direction > 0) {
    cutting_ = false;
    line_ = position;
    line_time_ = t;
    if (anchor_at_back_off_) {
      anchor_ = anchor;
      anchor_time_ = t;
    }
    history_.push_back({t, false, position, anchor_, anchor_time_});
    return Switch::backs_off;
  }
  if (!cutting_ && direction < 0) {
    cutting_ = true;
    line_ = position;
    line_time_ = t;
    if (spring_from_contact_ && !anchor_at_back_off_) {
      anchor_ = anchor;
      anchor_time_ = t;
    }
    history_.push_back({t, true, position, anchor_, anchor_time_});
    return Switch::cuts_again;
  }
  return Switch::none;
}

template <class Anchor>
typename SoilContact<Anchor>::State SoilContact<Anchor>::state_at(double t) const {
  if (history_.empty()) return State{};
  // The last switch at or before t (the first entry for t before it). The log is
  // in time order (the integrator locates the switches going forward), so a binary
  // search finds it: force recovery asks once per output sample, and a 20-s run
  // logs thousands of switches.
  if (!(t >= history_.front().time)) return history_.front();
  const auto after = std::upper_bound(history_.begin(), history_.end(), t, [](double time, const State& h) { return time < h.time; });
  return *std::prev(after);
}

template class SoilContact<Eigen::Vector2d>;
template class SoilContact<Eigen::Vector3d>;

// --- the chain's tooth law (Appendix D) ------------------------------------------

bool ChainTeeth::full_teeth_at(double t) const {
  if (!(chain_speed > 0) || !(tooth_spacing > 0)) return true;
  // Within each tooth period TPCH, MTIG teeth dig for the first ATCH.
  const double period = tooth_spacing / chain_speed;
  const double mtig = std::floor(length_in_ground / tooth_spacing);
  const double atch = (length_in_ground - tooth_spacing * mtig) / tooth_spacing * period;
  const double tau = t - std::floor(t / period + 1e-9) * period;
  return tau < atch - 1e-12 * period;
}

double ChainTeeth::teeth_digging(bool full_teeth) const {
  const double mtig = std::floor(length_in_ground / tooth_spacing);
  return mtig - 1.0 + (full_teeth ? 1.0 : 0.0);  // NTD = MTIG - 1 + XNN (Eq. D.3)
}

double ChainTeeth::tooth_force(bool cutting) const {
  const double reh = cutting ? 1.0 : static_reduction, red = cutting ? 1.0 : damping_reduction;
  return tooth_static_force * reh + chain_speed * tooth_damping * red;  // FTH
}

double ChainTeeth::chain_force(double t, bool cutting, bool full_teeth) const {
  const double ramp = ramp_time > 0.0 ? std::min(1.0, std::max(0.0, t / ramp_time)) : 1.0;
  return ramp * tooth_force(cutting) * teeth_digging(full_teeth);  // RCH (Eq. 2.41)
}

double ChainTeeth::next_change(double t) const {
  const double next = next_tooth_change(t);
  return ramp_time > t ? std::min(ramp_time, next) : next;
}

double ChainTeeth::next_tooth_change(double t) const {
  double next = std::numeric_limits<double>::infinity();
  if (chain_speed > 0 && tooth_spacing > 0) {
    const double period = tooth_spacing / chain_speed;
    const double mtig = std::floor(length_in_ground / tooth_spacing);
    const double atch = (length_in_ground - tooth_spacing * mtig) / tooth_spacing * period;
    const double k = std::floor(t / period);
    for (double candidate : {k * period + atch, (k + 1) * period, (k + 1) * period + atch})
      if (candidate > t * (1 + 1e-14) + 1e-15) next = std::min(next, candidate);
  }
  return next;
}

void ToothCount::reset(double t) {
  full_ = law_.full_teeth_at(t);
  history_.assign(1, {t, full_});
}

std::string ToothCount::on_scheduled_change(double t) {
  const bool full = law_.full_teeth_at(t);
  if (full == full_) return {};
  full_ = full;
  history_.push_back({t, full});
  return fmt::format("{} teeth digging", static_cast<int>(law_.teeth_digging(full)));
}

bool ToothCount::full_at(double t) const {
  if (history_.empty()) return law_.full_teeth_at(t);
  // The last change logged at or before t (the first entry for t before the log).
  // (The log is in time order: a binary search, as SoilContact::state_at.)
  auto entry = history_.begin();
  if (t >= history_.front().first)
    entry = std::prev(std::upper_bound(history_.begin(), history_.end(), t, [](double time, const std::pair<double, bool>& h) { return time < h.first; }));
  // It holds until the next scheduled change after it, computed as the
  // integrator computes the change times, so that a sample a hair before a
  // change sees the count in force then.
  if (t < law_.next_tooth_change(entry->first)) return entry->second;
  return law_.full_teeth_at(t);
}

}  // namespace framedyn::rigid
