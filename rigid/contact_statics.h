// Static equilibrium under gravity with the contact laws the response starts
// in (docs/theory/rigid.md, section 11, Eqs. 11.1-11.6). Under `unilateral`
// the tires and bounce tire can only push: the engaged set A is found by an
// active-set iteration (a contact in tension is released, a released one that
// penetrates the ground is engaged, one change at a time, the largest
// violation first) until
//     K_A q_s = Q_g,   F_e = -k_e G_e q_s >= 0 (e in A),   -k_e G_e q_s <= 0 (e not in A)   (11.1-11.3)
// The soil springs carry nothing statically: their ground end is where the
// blade stands when the run starts (Eq. 2.37's "unstretched at the blade's
// equilibrium position"; the cut-face reading has none while cutting), so
// they are left out of K_A. The equations of motion, written about q_s, get
// the constant generalised force
//     b = Q_g + sum_{e not soil} G_e^T SF_e = sum_{e of released contacts} G_e^T SF_e (by 11.1)   (11.4)
// (summed in the second form: exactly zero with every contact engaged), which balances the lost-contact
// correction (4a.4) of the released ones, so that q = 0, v = 0 is a rest
// state of the response. Under `linear` (the thesis's bilateral springs) the
// statics is the thesis's: every element, soil included, in K; b = 0.
// If K_A is singular (the machine would tip or roll on the contacts left),
// StaticsError names the released contacts and the coordinates the
// unrestrained motion moves (a stable rule, not a near-tie: every coordinate
// whose share of the null space, D^(-1/2)-scaled, is at least 1e-3 of the
// largest share, in the coordinate table's order; Eq. 11.6).
#pragma once

#include <Eigen/Dense>

#include <string>
#include <utility>
#include <vector>

#include "core/error.h"
#include "rigid/multibody.h"
#include "rigid/unilateral_contact.h"

namespace framedyn::rigid {

struct ContactStatics {
  Eigen::VectorXd deflection;           // q_s from the unloaded springs, SI
  std::vector<double> element_forces;   // SF_e, N, compression positive (a released contact: -k G q_s < 0, its gap times k)
  std::vector<ContactDefinition> contacts;  // those given whose normal element has stiffness or damping, in order
  std::vector<bool> engaged;            // per contact of `contacts`
  Eigen::VectorXd preload;              // b of Eq. 11.4, generalised force (SI)
  int changes = 0;                      // contact state changes the iteration made
};

// No static equilibrium on the contacts left engaged.
class StaticsError : public core::NumericalError {
 public:
  // detail: what was found, after "no static equilibrium under gravity on contacts that only push: ".
  StaticsError(const std::string& detail, std::vector<std::string> lifted, std::vector<std::string> motion)
      : core::NumericalError("no static equilibrium under gravity on contacts that only push: " + detail),
        detail_(detail), lifted_(std::move(lifted)), motion_(std::move(motion)) {}
  const std::string& detail() const { return detail_; }
  const std::vector<std::string>& lifted() const { return lifted_; }  // contact names
  const std::vector<std::string>& motion() const { return motion_; }  // coordinate names, table order
 private:
  std::string detail_;
  std::vector<std::string> lifted_, motion_;
};

// gravity: Q_g, the generalised gravity force; contacts: as for
// UnilateralContacts (contacts whose normal element has neither stiffness nor
// damping are ignored, as there); soil: elements that carry no static force.
ContactStatics solve_contact_statics(const Multibody& model, const Eigen::VectorXd& gravity, const std::vector<ContactDefinition>& contacts,
                                     const std::vector<int>& soil, ContactLaw law);

// Eq. 11.7: K less the normal and tangential elements of the contacts the
// statics released (the stiffness a modal analysis about q_s sees).
void remove_lifted_contacts(const Multibody& model, const ContactStatics& statics, Eigen::MatrixXd& k);

// Q_g = sum over bodies of T^T (0, 0, -g m).
Eigen::VectorXd gravity_force(const Multibody& model, double gravity);

}  // namespace framedyn::rigid
