// The contact-consistent static equilibrium: see contact_statics.h and
// docs/theory/rigid.md, section 11 (Eqs. 11.1-11.6).
#include "rigid/contact_statics.h"

#include <fmt/format.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace framedyn::rigid {

namespace {

// A null-space eigenvalue of the diagonally scaled K_A (whose diagonal is of
// order 1): a lost restraint leaves round-off, 1e-16; a soft one is far above.
constexpr double kSingular = 1e-10;
// A coordinate takes part in the unrestrained motion if its share is at least
// this fraction of the largest (Eq. 11.6): real shares are of order 1e-3..1,
// round-off 1e-30, so no share sits near the threshold.
constexpr double kShare = 1e-3;

std::string joined(const std::vector<std::string>& names) {
  std::string s;
  for (std::size_t i = 0; i < names.size(); ++i) s += (i ? ", " : "") + names[i];
  return s;
}

}  // namespace

Eigen::VectorXd gravity_force(const Multibody& model, double gravity) {
  Eigen::VectorXd q = Eigen::VectorXd::Zero(model.size());
  for (const Body& b : model.bodies()) q += b.translation.transpose() * Eigen::Vector3d(0, 0, -gravity * b.mass);
  return q;
}

ContactStatics solve_contact_statics(const Multibody& model, const Eigen::VectorXd& gravity, const std::vector<ContactDefinition>& given,
                                     const std::vector<int>& soil, ContactLaw law) {
  // The contacts UnilateralContacts keeps: a normal element with stiffness or damping.
  std::vector<ContactDefinition> all_contacts;
  for (const ContactDefinition& c : given) {
    const SpringDamper& el = model.elements().at(static_cast<std::size_t>(c.normal));
    if (el.stiffness != 0.0 || el.damping != 0.0) all_contacts.push_back(c);
  }
  const int n = model.size();
  const auto ne = model.elements().size();
  const Eigen::MatrixXd k_full = model.stiffness_matrix();
  std::vector<Eigen::RowVectorXd> maps;
  for (std::size_t e = 0; e < ne; ++e) maps.push_back(model.elongation_map(static_cast<int>(e)));
  auto stiffness = [&](int e) { return model.elements()[static_cast<std::size_t>(e)].stiffness; };
  auto element_force = [&](int e, const Eigen::VectorXd& q) { return -stiffness(e) * maps[static_cast<std::size_t>(e)].dot(q); };

  ContactStatics s;
  s.contacts = all_contacts;
  s.engaged.assign(all_contacts.size(), true);
  if (law == ContactLaw::linear) {
    // The thesis's statics: every element bilateral, the soil at full value (Eq. 2.37 as printed).
    s.deflection = k_full.ldlt().solve(gravity);
    for (std::size_t e = 0; e < ne; ++e) s.element_forces.push_back(element_force(static_cast<int>(e), s.deflection));
    s.preload = Eigen::VectorXd::Zero(n);
    return s;
  }

  auto without = [&](Eigen::MatrixXd& k, int e) {
    const Eigen::RowVectorXd& g = maps[static_cast<std::size_t>(e)];
    k -= stiffness(e) * g.transpose() * g;
  };
  Eigen::MatrixXd k_base = k_full;
  for (int e : soil) without(k_base, e);
  // Diagonal scaling for the singularity test: K's own diagonal (m and rad mixed).
  Eigen::VectorXd scale(n);
  for (int i = 0; i < n; ++i) scale(i) = k_full(i, i) > 0.0 ? 1.0 / std::sqrt(k_full(i, i)) : 1.0;

  // A contact force below 1e-9 of the largest gravity load is taken as zero (no flip on round-off).
  const double tolerance = 1e-9 * std::max(gravity.cwiseAbs().maxCoeff(), 1e-300);

  const int max_changes = 4 * static_cast<int>(all_contacts.size()) + 4;
  for (;;) {
    Eigen::MatrixXd k = k_base;
    std::vector<std::string> lifted;
    for (std::size_t i = 0; i < all_contacts.size(); ++i) {
      if (s.engaged[i]) continue;
      lifted.push_back(all_contacts[i].name);
      without(k, all_contacts[i].normal);
      for (int e : all_contacts[i].tangential) without(k, e);
    }
    // Eq. 11.5: K_A singular leaves a rigid motion unrestrained (the machine tips or rolls).
    const Eigen::MatrixXd scaled = scale.asDiagonal() * k * scale.asDiagonal();
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(scaled);
    const Eigen::VectorXd lambda = eig.eigenvalues();
    const double largest = std::max(lambda.cwiseAbs().maxCoeff(), 1e-300);
    Eigen::VectorXd share = Eigen::VectorXd::Zero(n);  // diagonal of the projector on the null space: basis-free
    for (int j = 0; j < n; ++j)
      if (lambda(j) < kSingular * largest) share += eig.eigenvectors().col(j).cwiseAbs2();
    if (share.maxCoeff() > 0.0) {
      std::vector<std::string> motion;
      for (int i = 0; i < n; ++i)
        if (share(i) >= kShare * share.maxCoeff()) motion.push_back(model.coordinate_names()[static_cast<std::size_t>(i)]);
      const std::string which = lifted.empty() ? "with every contact engaged" : "with " + joined(lifted) + " lifted (in tension when engaged)";
      throw StaticsError(fmt::format("{}, a motion of {} that nothing restrains (the machine would tip or roll)", which, joined(motion)),
                         lifted, motion);
    }
    s.deflection = k.ldlt().solve(gravity);

    // The largest violation (Eqs. 11.2-11.3), ties to the lowest index.
    double worst = tolerance;
    std::size_t flip = all_contacts.size();
    for (std::size_t i = 0; i < all_contacts.size(); ++i) {
      const double f = element_force(all_contacts[i].normal, s.deflection);
      const double violation = s.engaged[i] ? -f : f;  // tension while engaged, penetration while released
      if (violation > worst * (1.0 + 1e-9)) {
        worst = violation;
        flip = i;
      }
    }
    if (flip == all_contacts.size()) break;
    if (++s.changes > max_changes)
      throw StaticsError(fmt::format("the engaged set did not settle after {} changes of the engaged contacts (the last: {})",
                                     max_changes, all_contacts[flip].name),
                         {}, {});
    s.engaged[flip] = !s.engaged[flip];
  }

  for (std::size_t e = 0; e < ne; ++e) s.element_forces.push_back(element_force(static_cast<int>(e), s.deflection));
  for (int e : soil) s.element_forces[static_cast<std::size_t>(e)] = 0.0;  // anchored where the blade stands
  // Eq. 11.4: b = Q_g + sum over non-soil elements of G^T SF, which by (11.1)
  // is the released contacts' share alone: summed so, b is exactly zero with
  // every contact engaged (a symmetric machine stays exactly symmetric).
  s.preload = Eigen::VectorXd::Zero(n);
  for (std::size_t i = 0; i < all_contacts.size(); ++i) {
    if (s.engaged[i]) continue;
    std::vector<int> elements = all_contacts[i].tangential;
    elements.push_back(all_contacts[i].normal);
    for (int e : elements) s.preload += maps[static_cast<std::size_t>(e)].transpose() * s.element_forces[static_cast<std::size_t>(e)];
  }
  return s;
}

void remove_lifted_contacts(const Multibody& model, const ContactStatics& statics, Eigen::MatrixXd& k) {
  for (std::size_t i = 0; i < statics.contacts.size(); ++i) {
    if (statics.engaged[i]) continue;
    std::vector<int> elements = statics.contacts[i].tangential;
    elements.push_back(statics.contacts[i].normal);
    for (int e : elements) {
      const Eigen::RowVectorXd g = model.elongation_map(e);
      k -= model.elements()[static_cast<std::size_t>(e)].stiffness * g.transpose() * g;
    }
  }
}

}  // namespace framedyn::rigid
