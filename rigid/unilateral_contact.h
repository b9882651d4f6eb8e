// Contacts that only push (docs/theory/rigid.md, section 4a): tires and
// bounce tires are one-sided. A contact is a grounded normal spring-damper
// element e (and the tangential elements of the same tire, which act only
// while it touches). With the static force SF_e of the equilibrium under
// gravity, its linear-law compression is
//     S_e = SF_e - k_e (G_e q - xr_e)              (spring part)      (4a.1)
//     F_e = S_e - c_e (G_e q' - vr_e)              (total)            (4a.2)
// and under `unilateral` the force it transmits is F_e while in contact and 0
// after lift-off. Contact is lost where F_e falls through zero and regained
// where min(S_e, F_e) rises through zero (the ground reached again, and the
// damper not pulling); both are events of the switched system
//     g_e = min(S_e, F_e) -/+ eps                                     (4a.3)
// (eps = 1e-6 N on the side of the state just left, so that a located root
// is not found again at the restart). While contact is lost the equations of
// motion (written about the static equilibrium) get back the generalised force
// the linear element applied: f -= G^T F_lin for the normal and tangential
// elements of the contact (4a.4).
// Under `linear` (the thesis's bilateral springs) there are no events and the
// forces may pull; the outputs say how long they did.
#pragma once

#include <Eigen/Dense>

#include <functional>
#include <string>
#include <vector>

#include "rigid/ground_input.h"
#include "rigid/multibody.h"

namespace framedyn::rigid {

enum class ContactLaw { unilateral, linear };

// One contact: its normal element and the tangential elements that act only
// while it touches (indices in the Multibody's elements).
struct ContactDefinition {
  std::string name;                 // e.g. "front_tire", "bounce_tire"
  int normal = -1;
  std::vector<int> tangential;
};

class UnilateralContacts {
 public:
  // static_forces: SF_e for every element of the model (compression positive);
  // inputs: the reference ground input of every element (kind none if none).
  // Contacts whose normal element has neither stiffness nor damping are left out.
  void configure(const Multibody& model, const std::vector<ContactDefinition>& contacts, const std::vector<double>& static_forces,
                 const std::vector<GroundInput>& inputs, ContactLaw law);

  ContactLaw law() const { return law_; }
  const std::vector<ContactDefinition>& contacts() const { return contacts_; }
  int event_count() const { return law_ == ContactLaw::unilateral ? static_cast<int>(contacts_.size()) : 0; }

  // The linear law's compression (4a.2) and spring part (4a.1) of element e, N.
  double linear_force(int element, double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v) const;
  double spring_force(int element, double t, const Eigen::VectorXd& q) const;
  double static_force(int element) const { return static_forces_.at(static_cast<std::size_t>(element)); }

  // Discrete state: every contact touching if min(S, F) > 0 at (t, q, v).
  void reset(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v);
  void events(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v, double* g) const;  // event_count() values
  // Contact i's event crossed in direction (+1 rising, -1 falling): returns a
  // description if its state changed, else empty.
  std::string on_event(double t, int contact, int direction);
  // The events of one instant of a machine whose event functions are its soil
  // law's (the first `soil_events`) followed by these contacts': each contact
  // event through on_event, the soil's through `soil_switch(direction)`.
  // Returns what happened, "; "-joined, the soil's switch last (the event log
  // appends the blade's position to it).
  std::string on_events(double t, int soil_events, const std::vector<int>& fired, const std::vector<int>& directions,
                        const std::function<std::string(int)>& soil_switch);
  // Adds (4a.4) to the generalised force f for every contact lost now.
  void add_lost_contacts(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v, Eigen::VectorXd& f) const;

  bool touching(int contact) const { return touching_.at(static_cast<std::size_t>(contact)); }
  // State at t (after a change at exactly t), from the logged changes.
  bool touching_at(int contact, double t) const;
  // The contact an element belongs to (normal or tangential), or -1.
  int contact_of(int element) const;
  // Compression (positive) transmitted by element e at t: F_lin, or 0 while its contact is lost.
  double transmitted_force(int element, double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v) const;

 private:
  ContactLaw law_ = ContactLaw::unilateral;
  std::vector<ContactDefinition> contacts_;
  std::vector<double> static_forces_;
  std::vector<GroundInput> inputs_;
  std::vector<Eigen::RowVectorXd> maps_;  // G_e of every element (copies: a machine stays copyable)
  std::vector<double> stiffness_, damping_;
  std::vector<bool> touching_;
  struct Change {
    double time;
    int contact;
    bool touching;
  };
  std::vector<Change> log_;
  std::vector<bool> initial_;
};

}  // namespace framedyn::rigid
