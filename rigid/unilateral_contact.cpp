// Contacts that only push: see unilateral_contact.h and docs/theory/rigid.md,
// section 4a (Eqs. 4a.1-4a.4).
#include "rigid/unilateral_contact.h"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

namespace framedyn::rigid {

namespace {
// Offset of the event functions (4a.3), N: a root located to the integrator's
// accuracy leaves |g| of order 1e-9 N (force slopes of 1e5 N/s times 1e-14 s).
constexpr double kEventOffset = 1e-6;
}  // namespace

void UnilateralContacts::configure(const Multibody& model, const std::vector<ContactDefinition>& contacts,
                                   const std::vector<double>& static_forces, const std::vector<GroundInput>& inputs, ContactLaw law) {
  const std::size_t ne = model.elements().size();
  if (static_forces.size() != ne || inputs.size() != ne)
    throw std::invalid_argument("UnilateralContacts: one static force and one ground input per element are needed");
  law_ = law;
  static_forces_ = static_forces;
  inputs_ = inputs;
  maps_.clear();
  stiffness_.clear();
  damping_.clear();
  for (std::size_t e = 0; e < ne; ++e) {
    maps_.push_back(model.elongation_map(static_cast<int>(e)));
    stiffness_.push_back(model.elements()[e].stiffness);
    damping_.push_back(model.elements()[e].damping);
  }
  contacts_.clear();
  for (const ContactDefinition& c : contacts) {
    if (c.normal < 0 || static_cast<std::size_t>(c.normal) >= ne) throw std::invalid_argument("UnilateralContacts: bad normal element");
    if (stiffness_[static_cast<std::size_t>(c.normal)] == 0.0 && damping_[static_cast<std::size_t>(c.normal)] == 0.0) continue;
    contacts_.push_back(c);
  }
  touching_.assign(contacts_.size(), true);
  initial_ = touching_;
  log_.clear();
}

double UnilateralContacts::spring_force(int element, double t, const Eigen::VectorXd& q) const {
  const auto e = static_cast<std::size_t>(element);
  const GroundInput& in = inputs_[e];
  const double xr = in.kind == GroundInput::Kind::none ? 0.0 : in.displacement(t);
  return static_forces_[e] - stiffness_[e] * (maps_[e].dot(q) - xr);  // (4a.1)
}

double UnilateralContacts::linear_force(int element, double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v) const {
  const auto e = static_cast<std::size_t>(element);
  const GroundInput& in = inputs_[e];
  const double vr = in.kind == GroundInput::Kind::none ? 0.0 : in.velocity(t);
  return spring_force(element, t, q) - damping_[e] * (maps_[e].dot(v) - vr);  // (4a.2)
}

void UnilateralContacts::reset(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v) {
  log_.clear();
  for (std::size_t i = 0; i < contacts_.size(); ++i) {
    const int e = contacts_[i].normal;
    touching_[i] = law_ == ContactLaw::linear || std::min(spring_force(e, t, q), linear_force(e, t, q, v)) > 0.0;
  }
  initial_ = touching_;
}

void UnilateralContacts::events(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v, double* g) const {
  if (law_ != ContactLaw::unilateral) return;
  for (std::size_t i = 0; i < contacts_.size(); ++i) {
    const int e = contacts_[i].normal;
    const double m = std::min(spring_force(e, t, q), linear_force(e, t, q, v));
    g[i] = touching_[i] ? m + kEventOffset : m - kEventOffset;  // (4a.3)
  }
}

std::string UnilateralContacts::on_events(double t, int soil_events, const std::vector<int>& fired, const std::vector<int>& directions,
                                          const std::function<std::string(int)>& soil_switch) {
  std::string what;
  int soil_direction = 0;
  for (std::size_t k = 0; k < fired.size(); ++k) {
    const int contact = fired[k] - soil_events;
    if (contact < 0) {
      soil_direction = directions[k];
      continue;
    }
    const std::string s = on_event(t, contact, directions[k]);
    if (!s.empty()) what += (what.empty() ? "" : "; ") + s;
  }
  if (soil_direction == 0) return what;
  const std::string soil = soil_switch(soil_direction);
  return soil.empty() ? what : (what.empty() ? soil : what + "; " + soil);
}

std::string UnilateralContacts::on_event(double t, int contact, int direction) {
  const auto i = static_cast<std::size_t>(contact);
  if (touching_[i] && direction < 0) {
    touching_[i] = false;
    log_.push_back({t, contact, false});
    return fmt::format("{} loses contact", contacts_[i].name);
  }
  if (!touching_[i] && direction > 0) {
    touching_[i] = true;
    log_.push_back({t, contact, true});
    return fmt::format("{} touches again", contacts_[i].name);
  }
  return {};
}

void UnilateralContacts::add_lost_contacts(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v, Eigen::VectorXd& f) const {
  for (std::size_t i = 0; i < contacts_.size(); ++i) {
    if (touching_[i]) continue;
    // (4a.4): take out the force the linear element would apply (static part included).
    f -= maps_[static_cast<std::size_t>(contacts_[i].normal)].transpose() * linear_force(contacts_[i].normal, t, q, v);
    for (int e : contacts_[i].tangential) f -= maps_[static_cast<std::size_t>(e)].transpose() * linear_force(e, t, q, v);
  }
}

bool UnilateralContacts::touching_at(int contact, double t) const {
  bool state = initial_.at(static_cast<std::size_t>(contact));
  for (const Change& c : log_) {
    if (c.time > t) break;
    if (c.contact == contact) state = c.touching;
  }
  return state;
}

int UnilateralContacts::contact_of(int element) const {
  for (std::size_t i = 0; i < contacts_.size(); ++i) {
    if (contacts_[i].normal == element) return static_cast<int>(i);
    if (std::find(contacts_[i].tangential.begin(), contacts_[i].tangential.end(), element) != contacts_[i].tangential.end())
      return static_cast<int>(i);
  }
  return -1;
}

double UnilateralContacts::transmitted_force(int element, double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v) const {
  const int c = contact_of(element);
  if (c >= 0 && !touching_at(c, t)) return 0.0;
  return linear_force(element, t, q, v);
}

}  // namespace framedyn::rigid
