// S-N curves; see sn_curve.h and docs/theory/fatigue.md section 3.
#include "fatigue/sn_curve.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <stdexcept>

namespace framedyn::fatigue {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
const char* const kIiw = "IIW 2016 (Hobbacher, IIW-2259-15)";
const char* const kEn1993 = "EN 1993-1-9:2005";
constexpr double kThicknessReference = 0.025;  // m, t_ref of both codes

std::string number(double v) { return fmt::format("{:g}", v); }

SnCurve iiw(double fat_mpa, double m, double knee_cycles, IiwVariant variant, const std::string& stress) {
  if (!(fat_mpa > 0.0) || !std::isfinite(fat_mpa)) throw std::invalid_argument("IIW curve: FAT class must be positive");
  const double s0 = fat_mpa * kPascalsPerMegapascal;
  const double knee = s0 * std::pow(kReferenceCycles / knee_cycles, 1.0 / m);  // F.5
  const bool va = variant == IiwVariant::variable_amplitude;
  const std::string name = fmt::format("IIW FAT{}, {} stress, m = {}, knee at 1e{} cycles, {}", number(fat_mpa), stress, number(m), std::lround(std::log10(knee_cycles)),
                                       va ? "m = 22 beyond (variable amplitude)" : "no damage beyond (constant amplitude)");
  return SnCurve(name, kIiw, {{s0, kReferenceCycles}, {knee, knee_cycles}}, m, va ? std::optional<double>(22.0) : std::nullopt);
}

}  // namespace

SnCurve::SnCurve(std::string name, std::string code, std::vector<Knot> knots, double slope_above, std::optional<double> slope_below)
    : name_(std::move(name)), code_(std::move(code)), knots_(std::move(knots)), slope_above_(slope_above), slope_below_(slope_below) {
  if (knots_.empty()) throw std::invalid_argument("S-N curve " + name_ + ": at least one point is needed");
  if (!(slope_above_ > 0.0) || (slope_below_ && !(*slope_below_ > 0.0)))
    throw std::invalid_argument("S-N curve " + name_ + ": slopes must be positive");
  for (std::size_t i = 0; i < knots_.size(); ++i) {
    const Knot& k = knots_[i];
    if (!(k.range_pa > 0.0 && k.cycles > 0.0) || !std::isfinite(k.range_pa) || !std::isfinite(k.cycles))
      throw std::invalid_argument("S-N curve " + name_ + ": points need positive finite ranges and cycles");
    if (i > 0) {
      const Knot& p = knots_[i - 1];
      if (!(k.range_pa < p.range_pa && k.cycles > p.cycles))
        throw std::invalid_argument("S-N curve " + name_ + ": ranges must fall and cycles rise from point to point");
      slopes_.push_back(std::log(k.cycles / p.cycles) / std::log(p.range_pa / k.range_pa));  // F.4 between knots
    }
  }
}

double SnCurve::cycles_to_failure(double s) const {
  if (!(s > 0.0)) return kInfinity;
  if (s >= knots_.front().range_pa) return knots_.front().cycles * std::pow(knots_.front().range_pa / s, slope_above_);
  for (std::size_t i = 0; i + 1 < knots_.size(); ++i)
    if (s >= knots_[i + 1].range_pa) return knots_[i].cycles * std::pow(knots_[i].range_pa / s, slopes_[i]);
  if (!slope_below_) return kInfinity;  // below the cut-off
  return knots_.back().cycles * std::pow(knots_.back().range_pa / s, *slope_below_);
}

std::optional<double> SnCurve::range_at(double n) const {
  if (!(n > 0.0)) return std::nullopt;
  if (n <= knots_.front().cycles) return knots_.front().range_pa * std::pow(knots_.front().cycles / n, 1.0 / slope_above_);
  for (std::size_t i = 0; i + 1 < knots_.size(); ++i)
    if (n <= knots_[i + 1].cycles) return knots_[i].range_pa * std::pow(knots_[i].cycles / n, 1.0 / slopes_[i]);
  if (!slope_below_ || !std::isfinite(n)) return std::nullopt;
  return knots_.back().range_pa * std::pow(knots_.back().cycles / n, 1.0 / *slope_below_);
}

std::optional<double> SnCurve::single_slope() const {
  if (!slope_below_ || *slope_below_ != slope_above_) return std::nullopt;
  for (double m : slopes_)
    if (std::abs(m - slope_above_) > 1e-12 * slope_above_) return std::nullopt;
  return slope_above_;
}

SnCurve SnCurve::scaled(double f, const std::string& note) const {
  std::vector<Knot> k = knots_;
  for (Knot& x : k) x.range_pa *= f;
  return SnCurve(name_ + ", " + note, code_, k, slope_above_, slope_below_);
}

SnCurve iiw_normal_stress(double fat_mpa, IiwVariant variant) { return iiw(fat_mpa, 3.0, 1e7, variant, "normal"); }
SnCurve iiw_shear_stress(double fat_mpa, IiwVariant variant) { return iiw(fat_mpa, 5.0, 1e8, variant, "shear"); }

SnCurve en1993_normal_stress(double c_mpa) {
  if (!(c_mpa > 0.0) || !std::isfinite(c_mpa)) throw std::invalid_argument("EN 1993-1-9 curve: detail category must be positive");
  const double c = c_mpa * kPascalsPerMegapascal;
  const double d = c * std::cbrt(2.0 / 5.0);        // F.6, constant amplitude fatigue limit at 5e6
  const double l = d * std::pow(5.0 / 100.0, 0.2);  // F.6, cut-off limit at 1e8
  return SnCurve(fmt::format("EN 1993-1-9 detail category {}, normal stress, m = 3 to 5e6 cycles, m = 5 to the cut-off at 1e8", number(c_mpa)),
                 kEn1993, {{c, 2e6}, {d, 5e6}, {l, 1e8}}, 3.0, std::nullopt);
}

SnCurve en1993_shear_stress(double c_mpa) {
  if (!(c_mpa > 0.0) || !std::isfinite(c_mpa)) throw std::invalid_argument("EN 1993-1-9 curve: detail category must be positive");
  const double c = c_mpa * kPascalsPerMegapascal;
  const double l = c * std::pow(2.0 / 100.0, 0.2);  // F.7, cut-off at 1e8
  return SnCurve(fmt::format("EN 1993-1-9 detail category {}, shear stress, m = 5 to the cut-off at 1e8", number(c_mpa)), kEn1993,
                 {{c, 2e6}, {l, 1e8}}, 5.0, std::nullopt);
}

SnCurve user_curve(const std::vector<std::pair<double, double>>& points, const std::string& name) {
  if (points.size() < 2) throw std::invalid_argument("S-N curve " + name + ": at least two points (N, S) are needed");
  std::vector<SnCurve::Knot> knots;
  for (const auto& [n, s] : points) knots.push_back({s * kPascalsPerMegapascal, n});
  const double m0 = std::log(knots[1].cycles / knots[0].cycles) / std::log(knots[0].range_pa / knots[1].range_pa);
  return SnCurve(name + ", points interpolated log-log, no damage below the last point", "user", knots, m0, std::nullopt);
}

SnCurve basquin_curve(double c, double m, const std::string& name) {
  if (!(c > 0.0 && m > 0.0) || !std::isfinite(c) || !std::isfinite(m)) throw std::invalid_argument("Basquin curve " + name + ": C and m must be positive");
  const double s_ref = std::pow(c / kReferenceCycles, 1.0 / m) * kPascalsPerMegapascal;  // F.8 at 2e6 cycles
  return SnCurve(fmt::format("{}, Basquin N = C S^-m, m = {}", name, number(m)), "user", {{s_ref, kReferenceCycles}}, m, m);
}

SnCurve iiw_thickness_correction(const SnCurve& curve, double t, double n) {
  if (!(t > 0.0) || !(n >= 0.0)) throw std::invalid_argument("thickness correction: t > 0 and n >= 0 are needed");
  if (t <= kThicknessReference) return curve;
  const double f = std::pow(kThicknessReference / t, n);  // F.9
  return curve.scaled(f, fmt::format("IIW thickness correction f(t) = (25/{:g})^{} = {:.4g}", t * 1e3, number(n), f));
}

SnCurve en1993_size_effect(const SnCurve& curve, double t) {
  if (!(t > 0.0)) throw std::invalid_argument("size effect: t > 0 is needed");
  if (t <= kThicknessReference) return curve;
  const double k = std::pow(kThicknessReference / t, 0.2);  // F.9 with n = 0.2
  return curve.scaled(k, fmt::format("EN 1993-1-9 size effect k_s = (25/{:g})^0.2 = {:.4g}", t * 1e3, k));
}

std::string sn_curve_names() {
  return "FAT<class> (IIW normal stress), FAT<class>:shear, FAT<class>:ca or FAT<class>:shear:ca (IIW constant amplitude), EN<category> "
         "or EN<category>:shear (EN 1993-1-9), class and category in MPa";
}

SnCurve sn_curve_from_name(const std::string& text) {
  auto bad = [&]() { return std::invalid_argument("unknown S-N curve '" + text + "'; expected " + sn_curve_names()); };
  std::string head = text, rest;
  if (const std::size_t colon = text.find(':'); colon != std::string::npos) {
    head = text.substr(0, colon);
    rest = text.substr(colon);
  }
  std::string prefix;
  for (const char* p : {"FAT", "EN"})
    if (head.rfind(p, 0) == 0) prefix = p;
  if (prefix.empty()) throw bad();
  const std::string digits = head.substr(prefix.size());
  if (digits.empty() || digits.find_first_not_of("0123456789.") != std::string::npos) throw bad();
  char* end = nullptr;
  const double value = std::strtod(digits.c_str(), &end);
  if (end != digits.c_str() + digits.size() || !(value > 0.0) || !std::isfinite(value)) throw bad();
  if (prefix == "FAT") {
    if (rest.empty()) return iiw_normal_stress(value);
    if (rest == ":shear") return iiw_shear_stress(value);
    if (rest == ":ca") return iiw_normal_stress(value, IiwVariant::constant_amplitude);
    if (rest == ":shear:ca") return iiw_shear_stress(value, IiwVariant::constant_amplitude);
    throw bad();
  }
  if (rest.empty()) return en1993_normal_stress(value);
  if (rest == ":shear") return en1993_shear_stress(value);
  throw bad();
}

}  // namespace framedyn::fatigue
