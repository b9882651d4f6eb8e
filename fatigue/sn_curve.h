// S-N curves of welded details and base metal (docs/theory/fatigue.md, section 3,
// Eqs. F.4-F.9): cycles to failure N against the stress range S in Pa, piecewise
// straight in log-log (N = N_i (S_i / S)^m_i between knots), each curve named after
// the code it comes from:
//   IIW (Hobbacher, IIW-2259-15, 2016): FAT = S at 2e6 cycles; normal stress m = 3 to the
//     knee at 1e7 cycles, shear m = 5 to the knee at 1e8; beyond the knee, for variable
//     amplitude loading, m = 22 (IIW 2016 §3.7.2: the default variant here) or, for
//     constant amplitude, no damage (a horizontal curve, the CAFL);
//   EN 1993-1-9:2005: detail category S_C at 2e6; normal stress m = 3 to S_D at 5e6, m = 5
//     to the cut-off S_L at 1e8 (S_D = (2/5)^(1/3) S_C, S_L = (5/100)^(1/5) S_D); shear m = 5
//     from S_C at 2e6 to the cut-off S_L at 1e8; no damage below S_L;
//   user curves: points (N, S) interpolated log-log, no damage below the last point; or
//     Basquin constants N = C S^-m with S in MPa, one slope throughout.
// Thickness correction multiplies every S of the curve by f(t) = (t_ref / t)^n for plates
// thicker than t_ref = 25 mm (IIW, n from the joint's table; EN 1993-1-9 k_s, n = 0.2).
// FAT classes and detail categories are in MPa (N/mm^2); the curve holds Pa.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace framedyn::fatigue {

// The reference number of cycles of FAT classes, detail categories and equivalent ranges.
inline constexpr double kReferenceCycles = 2e6;
inline constexpr double kPascalsPerMegapascal = 1e6;

enum class IiwVariant {
  variable_amplitude,  // m = 22 beyond the knee (IIW 2016 §3.7.2), the default
  constant_amplitude,  // no damage beyond the knee (the constant amplitude fatigue limit)
};

class SnCurve {
 public:
  struct Knot {
    double range_pa;  // S_i
    double cycles;    // N_i
  };

  // knots with S strictly decreasing and N strictly increasing; slope_above: m above the
  // first knot; slope_below: m below the last, or nullopt for a cut-off (no damage below).
  // Throws std::invalid_argument on knots that do not form a falling curve.
  SnCurve(std::string name, std::string code, std::vector<Knot> knots, double slope_above, std::optional<double> slope_below);

  // Cycles to failure at range S (Pa): +infinity at S <= 0 and below a cut-off.
  double cycles_to_failure(double range_pa) const;
  // The range whose cycles to failure are N (the inverse of cycles_to_failure): nullopt
  // where no range has that life (beyond a cut-off's last finite life).
  std::optional<double> range_at(double cycles) const;
  // m if the curve is one straight line in log-log (same slope everywhere, no cut-off).
  std::optional<double> single_slope() const;
  // The range at 2e6 cycles (FAT class, detail category), Pa.
  double reference_range() const { return *range_at(kReferenceCycles); }

  const std::string& name() const { return name_; }  // e.g. "IIW FAT90, normal stress, m = 3/22"
  const std::string& code() const { return code_; }  // e.g. "IIW 2016 (Hobbacher, IIW-2259-15)"
  const std::vector<Knot>& knots() const { return knots_; }
  double slope_above() const { return slope_above_; }
  const std::vector<double>& slopes() const { return slopes_; }  // between knots i and i+1
  std::optional<double> slope_below() const { return slope_below_; }

  // Every S times f (thickness correction); `note` is appended to the name.
  SnCurve scaled(double f, const std::string& note) const;

 private:
  std::string name_, code_;
  std::vector<Knot> knots_;
  std::vector<double> slopes_;
  double slope_above_;
  std::optional<double> slope_below_;
};

// IIW 2016 curves: FAT in MPa.
SnCurve iiw_normal_stress(double fat_mpa, IiwVariant variant = IiwVariant::variable_amplitude);
SnCurve iiw_shear_stress(double fat_mpa, IiwVariant variant = IiwVariant::variable_amplitude);
// EN 1993-1-9 curves: detail category in MPa.
SnCurve en1993_normal_stress(double category_mpa);
SnCurve en1993_shear_stress(double category_mpa);
// User curves: points (N, S in MPa), N increasing and S decreasing, at least two.
SnCurve user_curve(const std::vector<std::pair<double, double>>& cycles_and_range_mpa, const std::string& name);
// N = C S^-m, S in MPa (C in MPa^m).
SnCurve basquin_curve(double c_mpa_m, double m, const std::string& name);

// Thickness corrections (t in m; no correction at t <= 25 mm).
SnCurve iiw_thickness_correction(const SnCurve& curve, double thickness_m, double exponent_n);
SnCurve en1993_size_effect(const SnCurve& curve, double thickness_m);  // k_s = (25/t)^0.2

// A curve by its short name: FAT<class> (IIW normal stress), FAT<class>:shear,
// FAT<class>:ca (constant amplitude variant), FAT<class>:shear:ca, EN<category>,
// EN<category>:shear; class and category in MPa. Throws std::invalid_argument.
SnCurve sn_curve_from_name(const std::string& short_name);
// What sn_curve_from_name reads, for messages.
std::string sn_curve_names();

}  // namespace framedyn::fatigue
