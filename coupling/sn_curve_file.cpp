// A user-defined S-N curve from a YAML file; see sn_curve_file.h.
#include "coupling/sn_curve_file.h"

#include <fmt/format.h>

#include <cmath>
#include <optional>
#include <stdexcept>
#include <vector>

#include "core/stress_unit.h"
#include "coupling/yaml_input.h"

namespace framedyn::coupling {

namespace {

// An error at a list item (its own line; YamlMap::error knows only the map's keys).
core::InputError item_error(const YamlMap& m, const YAML::Node& n, const std::string& key, const std::string& expected, const std::string& found) {
  return core::InputError({m.file(), n.Mark().line >= 0 ? n.Mark().line + 1 : m.location("points").line, key}, expected, found);
}

// A positive finite number at node n of a list item.
double positive_at(const YamlMap& m, const YAML::Node& item, const YAML::Node& n, const std::string& key) {
  double v = 0.0;
  if (!parse_number(n, v) || !(v > 0.0)) throw item_error(m, item, key, "a positive number", describe(n));
  return v;
}

}  // namespace

fatigue::SnCurve read_sn_curve_file(const std::string& file) {
  static const core::UnitSystem si = core::UnitSystem::si();
  const YamlMap m(load_yaml_file(file), "", file, &si);
  m.allow_only({"name", "units", "points", "slope_below", "basquin", "reference", "slopes", "knees", "cut_off"});
  const std::string name = m.text("name");
  const std::string units = m.text_or("units", "MPa");
  const double pa = core::pascals_per_stress_unit(units);
  if (!(pa > 0.0)) {
    std::string known;
    for (const std::string& l : core::stress_unit_labels()) known += (known.empty() ? "" : ", ") + l;
    throw m.error("units", "a stress unit (" + known + ")", "'" + units + "'");  // STUDY-162
  }
  const double mpa = pa / fatigue::kPascalsPerMegapascal;  // MPa per unit
  const int forms = int(m.has("points")) + int(m.has("basquin")) + int(m.has("reference"));
  if (forms != 1)
    throw m.error("", "exactly one of points, basquin or reference (with slopes)", forms == 0 ? "none" : "more than one");  // STUDY-161
  const std::string label = name + " (" + file + ")";
  if (m.has("points")) {
    const YAML::Node list = m.node()["points"];
    if (!list.IsSequence() || list.size() < 2) throw m.error("points", "a list of at least two points [N, S]", describe(list));
    std::vector<std::pair<double, double>> points;
    for (std::size_t i = 0; i < list.size(); ++i) {
      const std::string key = fmt::format("points[{}]", i);
      if (!list[i].IsSequence() || list[i].size() != 2) throw item_error(m, list[i], key, "a point [N, S]", describe(list[i]));
      const double n = positive_at(m, list[i], list[i][0], key), s = positive_at(m, list[i], list[i][1], key);
      if (!points.empty() && !(n > points.back().first && s * mpa < points.back().second))  // STUDY-163
        throw item_error(m, list[i], key, "N rising and S falling from the point before", fmt::format("[{:g}, {:g}] after [{:g}, {:g}]", n, s, points.back().first, points.back().second / mpa));
      points.emplace_back(n, s * mpa);
    }
    fatigue::SnCurve c = fatigue::user_curve(points, label);
    if (!m.has("slope_below")) return c;
    const double below = m.positive("slope_below", core::Quantity::dimensionless);
    return fatigue::SnCurve(label + fmt::format(", points interpolated log-log, m = {:g} below the last point", below), "user", c.knots(), c.slope_above(), below);
  }
  if (m.has("slope_below")) throw m.error("slope_below", "slope_below only with points (slopes and cut_off with reference)", "slope_below");
  if (m.has("basquin")) {
    const YamlMap b = m.map("basquin");
    b.allow_only({"C", "m"});
    const double c = b.positive("C", core::Quantity::dimensionless), slope = b.positive("m", core::Quantity::dimensionless);
    return fatigue::basquin_curve(c * std::pow(mpa, slope), slope, label);  // N = C S_u^-m = C mpa^m S_MPa^-m
  }
  // reference + slopes [+ knees] [+ cut_off]
  const YamlMap r = m.map("reference");
  r.allow_only({"range", "cycles"});
  const double s_ref = r.positive("range", core::Quantity::dimensionless) * mpa * fatigue::kPascalsPerMegapascal;
  const double n_ref = r.has("cycles") ? r.positive("cycles", core::Quantity::dimensionless) : fatigue::kReferenceCycles;
  const std::vector<double> slopes = m.numbers("slopes", core::Quantity::dimensionless);
  const std::vector<double> knees = m.numbers("knees", core::Quantity::dimensionless);
  if (slopes.empty()) throw m.error("slopes", "a list of slopes m (one more than knees) with reference", "none");
  for (double s : slopes)
    if (!(s > 0.0)) throw m.error("slopes", "positive slopes", fmt::format("{:g}", s));
  if (knees.size() + 1 != slopes.size())  // STUDY-164
    throw m.error("knees", fmt::format("{} knee cycles for {} slopes (one fewer)", slopes.size() - 1, slopes.size()), fmt::format("{}", knees.size()));
  std::vector<fatigue::SnCurve::Knot> knots = {{s_ref, n_ref}};
  for (std::size_t i = 0; i < knees.size(); ++i) {
    if (!(knees[i] > knots.back().cycles))
      throw m.error("knees", "knee cycles rising, beyond the reference's", fmt::format("{:g} after {:g}", knees[i], knots.back().cycles));
    knots.push_back({knots.back().range_pa * std::pow(knots.back().cycles / knees[i], 1.0 / slopes[i]), knees[i]});
  }
  std::optional<double> below = slopes.back();
  std::string text = fmt::format("{}, m = ", label);
  for (std::size_t i = 0; i < slopes.size(); ++i) text += fmt::format("{}{:g}", i ? "/" : "", slopes[i]);
  if (m.has("cut_off")) {
    const double n_c = m.positive("cut_off", core::Quantity::dimensionless);
    if (!(n_c > knots.back().cycles)) throw m.error("cut_off", "cut-off cycles beyond the reference and the knees", fmt::format("{:g}", n_c));
    knots.push_back({knots.back().range_pa * std::pow(knots.back().cycles / n_c, 1.0 / slopes.back()), n_c});
    below.reset();
    text += fmt::format(", cut-off at {:g} cycles", n_c);
  }
  return fatigue::SnCurve(text, "user", knots, slopes.front(), below);
}

}  // namespace framedyn::coupling
