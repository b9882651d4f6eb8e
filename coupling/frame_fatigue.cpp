// Fatigue life of the frame and of a duty cycle; see frame_fatigue.h and docs/theory/fatigue.md sections 7-9.
#include "coupling/frame_fatigue.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>
#include <tuple>

#include "coupling/sn_curve_file.h"
#include "fatigue/miner_damage.h"
#include "fatigue/rainflow.h"
#include "fem/section_stress.h"

namespace framedyn::coupling {

namespace {

constexpr double kTie = 1e-6;  // relative: values this close count as equal (round-off differs between CPUs)
constexpr double kSecondsPerHour = 3600.0;

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

// "FAT71", "EN71" or 71: the class in MPa; nullopt otherwise.
std::optional<double> parse_class(const YAML::Node& n) {
  if (!n.IsScalar()) return std::nullopt;
  std::string s = n.Scalar();
  for (const char* prefix : {"FAT", "EN"})
    if (upper(s).rfind(prefix, 0) == 0) {
      s = s.substr(std::string(prefix).size());
      break;
    }
  if (s.empty() || s.find_first_not_of("0123456789.") != std::string::npos) return std::nullopt;
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (end != s.c_str() + s.size() || !(v > 0.0) || !std::isfinite(v)) return std::nullopt;
  return v;
}

double read_class(const YamlMap& m, const std::string& key) {
  const std::optional<double> c = parse_class(m.node()[key]);
  if (!c) throw m.error(key, "a FAT class or detail category in MPa (e.g. FAT71 or 71)", describe(m.node()[key]));
  return *c;
}

// One history's repeated-block damage and its largest counted range.
struct BlockDamage {
  double damage = 0.0;
  double max_range = 0.0;
};
BlockDamage block_damage(const std::vector<double>& stress_pa, const fatigue::SnCurve& curve, const fatigue::MeanStressCorrection& mean_stress) {
  fatigue::MinerDamage damage(curve, 1.0, mean_stress);
  const fatigue::RainflowSummary summary = fatigue::count_cycles(stress_pa, fatigue::Residue::repeated_block, damage);
  return {damage.damage(), summary.max_range};
}

// table[s][p], else fallback[s][p] (a map built by hand with the combined damage only), else 0.
double damage_or_zero(const std::vector<std::vector<double>>& table, const std::vector<std::vector<double>>& fallback, std::size_t s, std::size_t p) {
  if (s < table.size() && p < table[s].size()) return table[s][p];
  if (s < fallback.size() && p < fallback[s].size()) return fallback[s][p];
  return 0.0;
}

}  // namespace

std::string fatigue_code_name(FatigueCode code) {
  return code == FatigueCode::iiw ? "IIW 2016 (Hobbacher, IIW-2259-15)" : "EN 1993-1-9:2005";
}

FatigueRequest read_fatigue_block(const YamlMap& f) {
  f.allow_only({"code", "default", "shear_default", "details", "mean_stress", "ultimate_strength", "thickness", "thickness_exponent", "hours"});
  FatigueRequest r;
  r.where = f.location("");
  r.where.key = f.path();
  const std::string code = f.text_or("code", "IIW");
  if (code == "IIW") r.code = FatigueCode::iiw;
  else if (code == "EN1993") r.code = FatigueCode::en1993;
  else throw f.error("code", "IIW (IIW 2016 FAT classes) or EN1993 (EN 1993-1-9 detail categories)", "'" + code + "'");
  if (f.has("default")) r.default_class_mpa = read_class(f, "default");
  if (f.has("shear_default")) r.shear_default_class_mpa = read_class(f, "shear_default");
  const std::vector<YamlMap> details = f.list_of_maps("details");
  for (const YamlMap& d : details) {
    d.allow_only({"element_set", "class", "shear_class", "curve"});
    FatigueDetail detail;
    detail.element_set = d.text("element_set");
    if (d.has("curve")) {
      if (d.has("class")) throw d.error("curve", "class (a FAT class) or curve (an S-N curve file), not both", "both");  // STUDY-165
      const std::filesystem::path file = std::filesystem::path(d.file()).parent_path() / d.text("curve");
      detail.curve = read_sn_curve_file(file.lexically_normal().string());
    } else {
      detail.class_mpa = read_class(d, "class");
    }
    if (d.has("shear_class")) detail.shear_class_mpa = read_class(d, "shear_class");
    detail.where = d.location("element_set");
    detail.where.key = d.path() + ".element_set";
    r.details.push_back(detail);
  }
  const std::string mean = f.text_or("mean_stress", "none");
  if (mean == "goodman") {
    if (!f.has("ultimate_strength"))
      throw f.error("mean_stress", "mean_stress: goodman with ultimate_strength (the base metal's tensile strength)", "no ultimate_strength");
    r.mean_stress = fatigue::MeanStressCorrection::goodman(f.positive("ultimate_strength", core::Quantity::stress));
  } else if (mean == "none") {
    if (f.has("ultimate_strength"))
      throw f.error("ultimate_strength", "ultimate_strength only with mean_stress: goodman (as-welded details take no mean stress)", "mean_stress: none");
  } else {
    throw f.error("mean_stress", "none (as-welded details) or goodman (base metal)", "'" + mean + "'");
  }
  if (f.has("thickness")) r.thickness = f.positive("thickness", core::Quantity::length);
  if (f.has("thickness_exponent")) {
    if (r.code != FatigueCode::iiw) throw f.error("thickness_exponent", "no thickness_exponent with code: EN1993 (its k_s takes n = 0.2)", "thickness_exponent");
    r.thickness_exponent = f.non_negative("thickness_exponent", core::Quantity::dimensionless);
  }
  if (f.has("hours")) r.hours = f.positive("hours", core::Quantity::dimensionless);
  return r;
}

fatigue::SnCurve fatigue_curve(const FatigueRequest& q, double class_mpa) {
  fatigue::SnCurve c = q.code == FatigueCode::iiw ? fatigue::iiw_normal_stress(class_mpa) : fatigue::en1993_normal_stress(class_mpa);
  if (q.thickness) c = q.code == FatigueCode::iiw ? fatigue::iiw_thickness_correction(c, *q.thickness, q.thickness_exponent) : fatigue::en1993_size_effect(c, *q.thickness);
  return c;
}

fatigue::SnCurve fatigue_shear_curve(const FatigueRequest& q, double class_mpa) {
  return q.code == FatigueCode::iiw ? fatigue::iiw_shear_stress(class_mpa) : fatigue::en1993_shear_stress(class_mpa);
}

std::string combination_rule(FatigueCode code) {
  if (code == FatigueCode::iiw)
    return fmt::format("IIW Gough-Pollard on damage sums, (D_sigma)^(2/3) + (D_tau)^(2/5) <= CV, CV = {:g} where sigma and tau are proportional, "
                       "{:g} where not; a stress whose largest range is under {:g} % of the other's is neglected",
                       kIiwProportionalComparisonValue, kIiwNonProportionalComparisonValue, 100.0 * kIiwNeglectFraction);
  return "EN 1993-1-9 Eq. 8.3 (exponents 3 and 5 = the curves' slopes): D_sigma + D_tau <= 1";
}

std::string proportionality_rule(FatigueCode code) {
  const std::string measure = fmt::format(
      "the correlation r of sigma(t) and tau(t) over the steady window at each section point; proportional where |r| >= {:g} "
      "(a sine pair out of phase by phi has r = cos phi)",
      kProportionalCorrelation);
  if (code == FatigueCode::iiw) return measure + "; a duty cycle is proportional where every scenario doing damage there is";
  return measure + "; reported only: EN 1993-1-9 Eq. 8.3 has no CV";
}

double stress_correlation(const std::vector<double>& sigma, const std::vector<double>& tau) {
  const std::size_t n = std::min(sigma.size(), tau.size());
  if (n < 2) return 1.0;
  double ms = 0.0, mt = 0.0;
  for (std::size_t k = 0; k < n; ++k) ms += sigma[k], mt += tau[k];
  ms /= static_cast<double>(n);
  mt /= static_cast<double>(n);
  double ss = 0.0, tt = 0.0, st = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    const double a = sigma[k] - ms, b = tau[k] - mt;
    ss += a * a, tt += b * b, st += a * b;
  }
  if (!(ss > 0.0) || !(tt > 0.0)) return 1.0;
  return std::clamp(st / std::sqrt(ss * tt), -1.0, 1.0);
}

double combined_damage(FatigueCode code, double ds, double dt, double normal_range, double shear_range, double cv) {
  if (code == FatigueCode::en1993) return ds + dt;  // F.29
  // F.28: the smaller stress neglected.
  if (!(dt > 0.0) || shear_range < kIiwNeglectFraction * normal_range) return ds;
  if (!(ds > 0.0) || normal_range < kIiwNeglectFraction * shear_range) return dt;
  // F.27: g(k) = (ds k)^(2/3) + (dt k)^(2/5) rises from 0; find g(k) = CV by bisection in log k
  // between k where each term is CV / 2 at most and k where one term alone is CV.
  const auto g = [&](double k) { return std::pow(ds * k, 2.0 / 3.0) + std::pow(dt * k, 2.0 / 5.0); };
  double lo = std::log(std::min(std::pow(cv / 2, 1.5) / ds, std::pow(cv / 2, 2.5) / dt));
  double hi = std::log(std::min(std::pow(cv, 1.5) / ds, std::pow(cv, 2.5) / dt));
  for (int i = 0; i < 200 && hi - lo > 1e-15 * std::max(1.0, std::abs(hi)); ++i) {
    const double mid = 0.5 * (lo + hi);
    (g(std::exp(mid)) < cv ? lo : hi) = mid;
  }
  return std::exp(-0.5 * (lo + hi));
}

double repeated_block_damage(const std::vector<double>& stress_pa, const fatigue::SnCurve& curve, const fatigue::MeanStressCorrection& mean_stress) {
  return block_damage(stress_pa, curve, mean_stress).damage;
}

std::pair<std::size_t, int> worst_location(const std::vector<std::vector<double>>& v) {
  double m = -std::numeric_limits<double>::infinity();
  for (const auto& row : v)
    for (double x : row) m = std::max(m, x);
  const double threshold = m - kTie * std::abs(m);
  for (std::size_t s = 0; s < v.size(); ++s)
    for (std::size_t p = 0; p < v[s].size(); ++p)
      if (v[s][p] >= threshold) return {s, static_cast<int>(p)};
  return {0, 0};
}

double LifeMap::max_damage_per_hour() const {
  if (worst_station >= damage_per_hour.size() || damage_per_hour[worst_station].empty()) return 0.0;
  return damage_per_hour[worst_station][static_cast<std::size_t>(worst_point)];
}

LifeMap frame_life_map(const fem::FrameModel& model, const StressHistories& h, const std::vector<fem::SectionForces>& static_forces,
                       const SteadyWindow& window, const FatigueRequest& q, core::WorkShare* share) {
  LifeMap out;
  out.code = fatigue_code_name(q.code);
  out.code_id = q.code;
  // Each station's curve: the first details entry whose set holds its element, else the default (F.22).
  std::map<int, std::size_t> detail_of_element;
  for (std::size_t d = q.details.size(); d-- > 0;) {  // backwards: the first listed wins
    const auto set = model.element_sets.find(upper(q.details[d].element_set));
    if (set == model.element_sets.end())
      throw core::InputError(q.details[d].where, "an element set of the frame mesh", "'" + q.details[d].element_set + "', not in the mesh");
    for (int id : set->second) detail_of_element[id] = d;
  }
  std::vector<bool> used(q.details.size(), false);
  std::map<std::string, int> curve_index;
  std::vector<fatigue::SnCurve> curves, shear_curves;
  out.curve_of_station.reserve(h.stations.size());
  for (const StressStation& st : h.stations) {
    const auto at = detail_of_element.find(st.element_id);
    const bool listed = at != detail_of_element.end();
    const double cls = listed ? q.details[at->second].class_mpa : q.default_class_mpa;
    const double shear_cls = listed ? q.details[at->second].shear_class_mpa.value_or(q.shear_default_class_mpa) : q.shear_default_class_mpa;
    const std::string who = listed ? fmt::format("{} (details[{}])", q.details[at->second].element_set, at->second) : "default";
    if (listed) used[at->second] = true;
    const fatigue::SnCurve* own = listed && q.details[at->second].curve ? &*q.details[at->second].curve : nullptr;
    const std::string key = fmt::format("{:.10g}|{:.10g}|{}", cls, shear_cls, who);
    auto found = curve_index.find(key);
    if (found == curve_index.end()) {
      found = curve_index.emplace(key, static_cast<int>(curves.size())).first;
      curves.push_back(own ? *own : fatigue_curve(q, cls));
      shear_curves.push_back(fatigue_shear_curve(q, shear_cls));
      out.curves.push_back(curves.back().name());
      out.shear_curves.push_back(shear_curves.back().name());
      out.assignment.push_back(who);
    }
    out.curve_of_station.push_back(found->second);
  }
  for (std::size_t d = 0; d < q.details.size(); ++d)
    if (!used[d])
      throw core::InputError(q.details[d].where, "an element set with elements on the frame's element-set outputs (the stations the life map covers)",
                             "'" + q.details[d].element_set + "', on none of them");
  // The steady window as a repeated block: its n samples at spacing dt repeat with period n dt (F.20).
  const double edge = window.from - 1e-9 * std::max(1.0, std::abs(window.from));
  std::vector<Eigen::Index> steady;
  for (Eigen::Index j = 0; j < h.times.size(); ++j)
    if (h.times(j) >= edge) steady.push_back(j);
  if (steady.size() < 2)
    throw core::InputError(q.where, fmt::format("a steady window with at least two output times (steady from {:g} s, {})", window.from, window.source),
                           fmt::format("{} output times from {:g} s on", steady.size(), window.from));
  const double span = h.times(steady.back()) - h.times(steady.front());
  out.block_samples = steady.size();
  out.block_seconds = span * static_cast<double>(steady.size()) / static_cast<double>(steady.size() - 1);
  const double per_hour = kSecondsPerHour / out.block_seconds;
  const auto tables = {&out.damage_per_hour,  &out.normal_damage_per_hour, &out.shear_damage_per_hour,         &out.normal_max_range,
                       &out.shear_max_range, &out.correlation,            &out.proportional_damage_per_hour, &out.non_proportional_damage_per_hour,
                       &out.comparison_value};
  for (auto* table : tables) table->resize(h.stations.size());
  // Each station's points on their own: any share of the stations gives the same map.
  core::for_ranges(share, h.stations.size(), 4, [&](std::size_t begin, std::size_t end) {
  std::vector<double> sigma(steady.size()), tau(steady.size()), tau_other(steady.size());
  for (std::size_t s = begin; s < end; ++s) {
    const std::size_t sec = static_cast<std::size_t>(h.stations[s].section);
    const fem::SectionForces fs = static_forces.empty() ? fem::SectionForces{} : static_forces.at(s);
    const std::vector<fem::SectionPoint>& points = h.points[sec];
    for (auto* table : tables) (*table)[s].assign(points.size(), 0.0);
    const std::size_t curve = static_cast<std::size_t>(out.curve_of_station[s]);
    for (std::size_t p = 0; p < points.size(); ++p) {
      const bool has_shear = fem::shear_direction(points[p]).norm() > 0.0;
      for (std::size_t k = 0; k < steady.size(); ++k) {
        fem::SectionForces f = h.forces_at(s, steady[k]);
        f.n += fs.n, f.vy += fs.vy, f.vz += fs.vz, f.t += fs.t, f.my += fs.my, f.mz += fs.mz;
        sigma[k] = fem::point_stress(h.sections[sec], points[p], f).normal;
        if (has_shear) {
          const fem::SignedShear t = fem::signed_shear(points[p], f);
          tau[k] = t.face;
          tau_other[k] = t.other_face;
        }
      }
      const BlockDamage normal = block_damage(sigma, curves[curve], q.mean_stress);
      BlockDamage shear;
      double r = 1.0;  // no shear: nothing to be out of phase with
      if (has_shear) {
        shear = block_damage(tau, shear_curves[curve], fatigue::MeanStressCorrection::none());  // shear: no mean-stress effect (both codes)
        r = stress_correlation(sigma, tau);
        if (points[p].open_wall) {  // the worse of an open wall's two faces
          const BlockDamage other = block_damage(tau_other, shear_curves[curve], fatigue::MeanStressCorrection::none());
          if (other.damage > shear.damage) shear = other, r = stress_correlation(sigma, tau_other);
        }
      }
      out.normal_damage_per_hour[s][p] = normal.damage * per_hour;
      out.shear_damage_per_hour[s][p] = shear.damage * per_hour;
      out.normal_max_range[s][p] = normal.max_range;
      out.shear_max_range[s][p] = shear.max_range;
      const auto combine = [&](double cv) { return combined_damage(q.code, normal.damage * per_hour, shear.damage * per_hour, normal.max_range, shear.max_range, cv); };
      out.correlation[s][p] = r;
      out.comparison_value[s][p] = iiw_comparison_value(r);
      out.proportional_damage_per_hour[s][p] = combine(kIiwProportionalComparisonValue);
      out.non_proportional_damage_per_hour[s][p] = combine(kIiwNonProportionalComparisonValue);
      out.damage_per_hour[s][p] = combine(out.comparison_value[s][p]);  // F.33
    }
  }
  });
  std::tie(out.worst_station, out.worst_point) = worst_location(out.damage_per_hour);
  return out;
}

double DutyLife::life_hours(std::size_t station, int point) const {
  const double d = damage_per_cycle.at(station).at(static_cast<std::size_t>(point));
  return d > 0.0 ? cycle_hours / d : std::numeric_limits<double>::infinity();
}

DutyLife combine_duty_cycle(const std::vector<DutyScenario>& scenarios) {
  if (scenarios.empty()) throw std::invalid_argument("a duty cycle needs at least one scenario");
  DutyLife out;
  const LifeMap& first = *scenarios.front().map;
  out.damage_per_cycle.resize(first.damage_per_hour.size());
  out.dominant.resize(first.damage_per_hour.size());
  const auto tables = {&out.damage_per_cycle, &out.normal_damage_per_cycle, &out.shear_damage_per_cycle, &out.correlation,
                       &out.comparison_value, &out.proportional_damage_per_cycle, &out.non_proportional_damage_per_cycle};
  for (auto* table : tables) table->resize(first.damage_per_hour.size());
  for (std::size_t s = 0; s < first.damage_per_hour.size(); ++s) {
    for (auto* table : tables) (*table)[s].assign(first.damage_per_hour[s].size(), 0.0);
    out.dominant[s].assign(first.damage_per_hour[s].size(), 0);
  }
  for (const DutyScenario& sc : scenarios) {
    bool same = sc.map && sc.map->damage_per_hour.size() == first.damage_per_hour.size();
    for (std::size_t s = 0; same && s < first.damage_per_hour.size(); ++s) same = sc.map->damage_per_hour[s].size() == first.damage_per_hour[s].size();
    if (!same) throw std::invalid_argument("scenario " + sc.name + ": its life map has other stations or points than the first scenario's");
    out.cycle_hours += sc.hours;
  }
  for (std::size_t s = 0; s < out.damage_per_cycle.size(); ++s)
    for (std::size_t p = 0; p < out.damage_per_cycle[s].size(); ++p) {
      // F.23 for each stress, then the code's combination of the cycle's sums (F.29); the
      // 15 % rule on the largest ranges over the scenarios.
      // F.34: the cycle is as proportional as its least proportional scenario doing damage there.
      std::vector<double> part;
      double normal = 0.0, shear = 0.0, normal_range = 0.0, shear_range = 0.0, r = 1.0;
      for (const DutyScenario& sc : scenarios) {
        part.push_back(sc.hours * sc.map->damage_per_hour[s][p]);
        const double n_i = sc.hours * damage_or_zero(sc.map->normal_damage_per_hour, sc.map->damage_per_hour, s, p);
        const double t_i = sc.hours * damage_or_zero(sc.map->shear_damage_per_hour, {}, s, p);
        normal += n_i, shear += t_i;
        normal_range = std::max(normal_range, damage_or_zero(sc.map->normal_max_range, {}, s, p));
        shear_range = std::max(shear_range, damage_or_zero(sc.map->shear_max_range, {}, s, p));
        const double r_i = s < sc.map->correlation.size() && p < sc.map->correlation[s].size() ? sc.map->correlation[s][p] : 0.0;  // unmeasured: not proportional
        if (n_i + t_i > 0.0 && std::abs(r_i) < std::abs(r)) r = r_i;
      }
      out.normal_damage_per_cycle[s][p] = normal;
      out.shear_damage_per_cycle[s][p] = shear;
      out.correlation[s][p] = r;
      out.comparison_value[s][p] = iiw_comparison_value(r);
      out.proportional_damage_per_cycle[s][p] = combined_damage(first.code_id, normal, shear, normal_range, shear_range, kIiwProportionalComparisonValue);
      out.non_proportional_damage_per_cycle[s][p] = combined_damage(first.code_id, normal, shear, normal_range, shear_range, kIiwNonProportionalComparisonValue);
      out.damage_per_cycle[s][p] = combined_damage(first.code_id, normal, shear, normal_range, shear_range, out.comparison_value[s][p]);
      out.dominant[s][p] = static_cast<int>(stable_argmax(part));
    }
  std::tie(out.worst_station, out.worst_point) = worst_location(out.damage_per_cycle);
  return out;
}

}  // namespace framedyn::coupling
