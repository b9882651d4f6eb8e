// Unit systems. framedyn computes in SI (m, N, s, kg) inside; every input
// names its unit system and readers convert on the way in; writers convert
// back on the way out and label every column. The thesis works in inch,
// pound-force, second, with mass in lbf*s^2/in.
#pragma once

#include <string>
#include <vector>

namespace framedyn::core {

// Physical quantities that inputs and outputs carry.
enum class Quantity {
  dimensionless,
  length,
  area,
  second_moment_of_area,   // length^4
  force,
  moment,                  // force * length
  stress,                  // force / length^2 (also E and G)
  mass,                    // force * time^2 / length
  rotary_inertia,          // mass * length^2
  density,                 // mass / length^3
  translational_stiffness, // force / length
  rotational_stiffness,    // moment / radian
  translational_damping,   // force * time / length
  velocity,                // length / time
  mass_per_length,         // mass / length
  force_per_length,        // force / length (a weight per length)
  angle,                   // radian, same in every system
  frequency,               // hertz, same in every system
  time,
  // Outputs' quantities (kept after the inputs' so that their numbering stays).
  angle_degrees,           // degree (phases, plotted angles), same in every system
  acceleration,            // length / time^2
  angular_velocity,        // radian / time
  angular_acceleration,    // radian / time^2
  mass_normalised_translation,  // length / sqrt(mass): a mass-normalised mode shape's translation
  mass_normalised_rotation,     // radian / sqrt(mass)
  participation_translation,    // sqrt(mass): a modal participation factor in translation
  participation_rotation,       // sqrt(mass) * length: in rotation (sqrt of rotary inertia)
  per_frequency,                // 1/Hz: the spectral density of a dimensionless load factor
  translation_psd,              // length^2 / Hz
  rotation_psd,                 // radian^2 / Hz
  stress_psd,                   // stress^2 / Hz
  percent,                      // a relative change in %
};

// Every quantity, in the enum's order (the tables a test checks outputs against).
const std::vector<Quantity>& all_quantities();

class UnitSystem {
 public:
  // Known names: "in-lbf-s", "m-N-s" (alias "SI"), "mm-N-s" (mass in tonne), in any letter case.
  static UnitSystem from_name(const std::string& name);  // throws std::invalid_argument
  static std::vector<std::string> known_names();
  static UnitSystem si() { return from_name("m-N-s"); }

  const std::string& name() const { return name_; }
  // Factor that turns a value in this system into SI.
  double to_si_factor(Quantity q) const;
  double to_si(double value, Quantity q) const { return value * to_si_factor(q); }
  double from_si(double value, Quantity q) const { return value / to_si_factor(q); }
  std::string label(Quantity q) const;
  // Every label of this system, all_quantities()' order: what an output of it may carry as a unit.
  std::vector<std::string> labels() const;

 private:
  std::string name_;
  double length_ = 1.0;  // metres per length unit
  double force_ = 1.0;   // newtons per force unit
  std::string length_label_, force_label_, mass_label_, stress_label_;
};

}  // namespace framedyn::core
