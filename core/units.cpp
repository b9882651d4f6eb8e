// Conversion factors between the supported unit systems and SI.
#include "core/units.h"

#include <cctype>
#include <cmath>

#include <stdexcept>

namespace framedyn::core {

namespace {
constexpr double kInch = 0.0254;                 // m, exact
constexpr double kPoundForce = 4.4482216152605;  // N, exact by definition of lbf
constexpr double kDegree = 3.14159265358979323846 / 180.0;  // rad
}  // namespace

std::vector<std::string> UnitSystem::known_names() { return {"in-lbf-s", "m-N-s", "SI", "mm-N-s"}; }

UnitSystem UnitSystem::from_name(const std::string& given) {
  // Any letter case ("IN-LBF-S", "si"): the three names differ in more than
  // case, so no name can be taken for another.
  std::string name = given;
  for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  UnitSystem u;
  if (name == "in-lbf-s") {
    u.name_ = name;
    u.length_ = kInch;
    u.force_ = kPoundForce;
    u.length_label_ = "in";
    u.force_label_ = "lbf";
    u.mass_label_ = "lbf*s^2/in";
    u.stress_label_ = "psi";
  } else if (name == "m-n-s" || name == "si") {
    u.name_ = "m-N-s";
    u.length_label_ = "m";
    u.force_label_ = "N";
    u.mass_label_ = "kg";
    u.stress_label_ = "Pa";
  } else if (name == "mm-n-s") {
    u.name_ = "mm-N-s";
    u.length_ = 1e-3;
    u.length_label_ = "mm";
    u.force_label_ = "N";
    u.mass_label_ = "t";
    u.stress_label_ = "MPa";
  } else {
    throw std::invalid_argument("unknown unit system '" + given + "' (known: in-lbf-s, m-N-s or SI, mm-N-s)");
  }
  return u;
}

double UnitSystem::to_si_factor(Quantity q) const {
  const double L = length_, F = force_;
  const double M = F / L;  // mass unit = force * s^2 / length
  switch (q) {
    case Quantity::dimensionless: return 1.0;
    case Quantity::length: return L;
    case Quantity::area: return L * L;
    case Quantity::second_moment_of_area: return L * L * L * L;
    case Quantity::force: return F;
    case Quantity::moment: return F * L;
    case Quantity::stress: return F / (L * L);
    case Quantity::mass: return M;
    case Quantity::rotary_inertia: return M * L * L;
    case Quantity::density: return M / (L * L * L);
    case Quantity::translational_stiffness: return F / L;
    case Quantity::rotational_stiffness: return F * L;
    case Quantity::translational_damping: return F / L;
    case Quantity::velocity: return L;
    case Quantity::mass_per_length: return M / L;
    case Quantity::force_per_length: return F / L;
    case Quantity::angle: return 1.0;
    case Quantity::frequency: return 1.0;
    case Quantity::time: return 1.0;
    case Quantity::angle_degrees: return kDegree;
    case Quantity::acceleration: return L;
    case Quantity::angular_velocity: return 1.0;
    case Quantity::angular_acceleration: return 1.0;
    case Quantity::mass_normalised_translation: return L / std::sqrt(M);
    case Quantity::mass_normalised_rotation: return 1.0 / std::sqrt(M);
    case Quantity::participation_translation: return std::sqrt(M);
    case Quantity::participation_rotation: return std::sqrt(M) * L;
    case Quantity::per_frequency: return 1.0;
    case Quantity::translation_psd: return L * L;
    case Quantity::rotation_psd: return 1.0;
    case Quantity::stress_psd: return (F / (L * L)) * (F / (L * L));
    case Quantity::percent: return 0.01;
  }
  return 1.0;
}

std::string UnitSystem::label(Quantity q) const {
  const std::string& L = length_label_;
  const std::string& F = force_label_;
  switch (q) {
    case Quantity::dimensionless: return "1";
    case Quantity::length: return L;
    case Quantity::area: return L + "^2";
    case Quantity::second_moment_of_area: return L + "^4";
    case Quantity::force: return F;
    case Quantity::moment: return F + "*" + L;
    case Quantity::stress: return stress_label_;
    case Quantity::mass: return mass_label_;
    case Quantity::rotary_inertia: return mass_label_ + "*" + L + "^2";
    case Quantity::density: return mass_label_ + "/" + L + "^3";
    case Quantity::translational_stiffness: return F + "/" + L;
    case Quantity::rotational_stiffness: return F + "*" + L + "/rad";
    case Quantity::translational_damping: return F + "*s/" + L;
    case Quantity::velocity: return L + "/s";
    case Quantity::mass_per_length: return mass_label_ + "/" + L;
    case Quantity::force_per_length: return F + "/" + L;
    case Quantity::angle: return "rad";
    case Quantity::frequency: return "Hz";
    case Quantity::time: return "s";
    case Quantity::angle_degrees: return "deg";
    case Quantity::acceleration: return L + "/s^2";
    case Quantity::angular_velocity: return "rad/s";
    case Quantity::angular_acceleration: return "rad/s^2";
    case Quantity::mass_normalised_translation: return L + "/sqrt(" + mass_label_ + ")";
    case Quantity::mass_normalised_rotation: return "rad/sqrt(" + mass_label_ + ")";
    case Quantity::participation_translation: return "sqrt(" + mass_label_ + ")";
    case Quantity::participation_rotation: return "sqrt(" + mass_label_ + "*" + L + "^2)";
    case Quantity::per_frequency: return "1/Hz";
    case Quantity::translation_psd: return L + "^2/Hz";
    case Quantity::rotation_psd: return "rad^2/Hz";
    case Quantity::stress_psd: return stress_label_ + "^2/Hz";
    case Quantity::percent: return "%";
  }
  return "?";
}

const std::vector<Quantity>& all_quantities() {
  static const std::vector<Quantity> all = [] {
    std::vector<Quantity> q;
    for (int i = 0; i <= static_cast<int>(Quantity::percent); ++i) q.push_back(static_cast<Quantity>(i));
    return q;
  }();
  return all;
}

std::vector<std::string> UnitSystem::labels() const {
  std::vector<std::string> out;
  for (Quantity q : all_quantities()) out.push_back(label(q));
  return out;
}

}  // namespace framedyn::core
