// `framedyn rainflow SERIES.csv [--column NAME] [--sn CURVE | --curve SPEC] [--mean-stress none|goodman
// --ultimate S] [--thickness T [--thickness-exponent n]] [--repeat] --out DIR`: rainflow counting
// (ASTM E1049-85) of one stress history from a CSV file and, with an S-N curve, its Palmgren-Miner
// damage and equivalent range at 2e6 cycles (fatigue/, docs/theory/fatigue.md sections 1-5): a code's
// curve by name (--sn) or a user curve (--curve points:N:S,N:S,... or basquin:C:m, S in MPa), the
// code's thickness correction (F.9), Goodman's mean-stress correction (F.10) with S_u in the series' unit.
// Reads with fatigue::read_stress_series (the unit from the column's header), counts, writes
// DIR/cycles.csv and DIR/summary.json with report/rainflow_outputs, prints the totals.
#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>
#include <stdexcept>

#include "apps/command_line.h"
#include "apps/commands.h"
#include "apps/progress.h"
#include "core/error.h"
#include "core/number_text.h"
#include "core/results_folder.h"
#include "fatigue/mean_stress.h"
#include "fatigue/miner_damage.h"
#include "fatigue/rainflow.h"
#include "coupling/sn_curve_file.h"
#include "fatigue/sn_curve.h"
#include "fatigue/stress_series.h"
#include "report/rainflow_outputs.h"

namespace framedyn::apps {

namespace {

struct RainflowOptions {
  std::string series, column, sn, curve, mean_stress, ultimate, thickness, thickness_exponent, out;
  bool repeat = false;
  ProgressFlags progress;
};

const char* const kCurveSpec = "points:N1:S1,N2:S2,... (N rising, S falling, S in MPa, at least two) or basquin:C:m (N = C S^-m, S in MPa)";

// A positive finite number from an option's text (nullopt otherwise).
std::optional<double> positive_number(const std::string& text) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || !(v > 0.0) || !std::isfinite(v)) return std::nullopt;
  return v;
}

// --curve: a user curve (F.4, F.8). Throws core::InputError (CLI-67).
fatigue::SnCurve user_curve_from_spec(const std::string& spec) {
  const auto bad = [&](const std::string& why) { return core::InputError(command_line("--curve"), kCurveSpec, "'" + spec + "'" + why); };
  const auto fields = [](const std::string& text, char sep) {
    std::vector<std::string> out;
    std::size_t from = 0;
    for (std::size_t at; (at = text.find(sep, from)) != std::string::npos; from = at + 1) out.push_back(text.substr(from, at - from));
    out.push_back(text.substr(from));
    return out;
  };
  try {
    if (spec.rfind("basquin:", 0) == 0) {
      const std::vector<std::string> f = fields(spec.substr(8), ':');
      const std::optional<double> c = f.size() == 2 ? positive_number(f[0]) : std::nullopt, m = f.size() == 2 ? positive_number(f[1]) : std::nullopt;
      if (!c || !m) throw bad(", not two positive numbers C:m");
      return fatigue::basquin_curve(*c, *m, "user curve (--curve)");
    }
    if (spec.rfind("points:", 0) == 0) {
      std::vector<std::pair<double, double>> points;
      for (const std::string& p : fields(spec.substr(7), ',')) {
        const std::vector<std::string> f = fields(p, ':');
        const std::optional<double> n = f.size() == 2 ? positive_number(f[0]) : std::nullopt, sr = f.size() == 2 ? positive_number(f[1]) : std::nullopt;
        if (!n || !sr) throw bad(", point '" + p + "' is not N:S with positive numbers");
        points.emplace_back(*n, *sr);
      }
      return fatigue::user_curve(points, "user curve (--curve)");
    }
  } catch (const std::invalid_argument&) {
    throw bad(", not a falling curve (at least two points, N rising and S falling)");
  }
  throw bad("");
}

// The curve the options ask for, thickness-corrected; nullopt without --sn or --curve.
std::optional<fatigue::SnCurve> curve_of(const RainflowOptions& opt) {
  if (!opt.sn.empty() && !opt.curve.empty())
    throw core::InputError(command_line("--curve"), "one S-N curve: --sn (a code's curve) or --curve (a user curve)", "both --sn and --curve");  // CLI-68
  std::optional<fatigue::SnCurve> curve;
  if (!opt.sn.empty()) {
    try {
      curve = fatigue::sn_curve_from_name(opt.sn);
    } catch (const std::invalid_argument&) {
      throw core::InputError(command_line("--sn"), fatigue::sn_curve_names(), "'" + opt.sn + "'");
    }
  }
  if (!opt.curve.empty()) {
    const auto ends = [&](const std::string& tail) { return opt.curve.size() > tail.size() && opt.curve.compare(opt.curve.size() - tail.size(), tail.size(), tail) == 0; };
    const bool file = ends(".yaml") || ends(".yml");
    curve = file ? coupling::read_sn_curve_file(opt.curve) : user_curve_from_spec(opt.curve);  // an S-N curve file (STUDY-161..164)
  }
  if (!curve && (!opt.mean_stress.empty() || !opt.thickness.empty()))  // CLI-69
    throw core::InputError(command_line(!opt.mean_stress.empty() ? "--mean-stress" : "--thickness"), "an S-N curve (--sn or --curve) to apply it to",
                           "no curve");
  if (!opt.thickness_exponent.empty() && opt.thickness.empty())
    throw core::InputError(command_line("--thickness-exponent"), "--thickness-exponent only with --thickness", "no --thickness");  // CLI-66
  if (!opt.thickness.empty()) {
    const std::optional<double> t_mm = positive_number(opt.thickness);
    if (!t_mm) throw core::InputError(command_line("--thickness"), "a plate thickness in mm, a positive number", "'" + opt.thickness + "'");  // CLI-65
    const double t = *t_mm * 1e-3;
    if (curve->code() == "EN 1993-1-9:2005") {
      if (!opt.thickness_exponent.empty())
        throw core::InputError(command_line("--thickness-exponent"), "no --thickness-exponent with an EN 1993-1-9 curve (its k_s takes n = 0.2)",
                               "'" + opt.thickness_exponent + "'");  // CLI-66
      curve = fatigue::en1993_size_effect(*curve, t);
    } else if (curve->code() == "user") {
      throw core::InputError(command_line("--thickness"), "a code's curve (--sn) for the thickness correction (a user curve holds its own)",
                             "--curve " + opt.curve);  // CLI-66
    } else {
      double n = 0.3;  // IIW's n for transverse fillet welds (as the study's thickness_exponent)
      if (!opt.thickness_exponent.empty()) {
        const std::optional<double> e = positive_number(opt.thickness_exponent);
        if (!e) throw core::InputError(command_line("--thickness-exponent"), "IIW's thickness exponent n, a positive number", "'" + opt.thickness_exponent + "'");  // CLI-65
        n = *e;
      }
      curve = fatigue::iiw_thickness_correction(*curve, t, n);
    }
  }
  return curve;
}

// --mean-stress and --ultimate (S_u in the series' unit).
fatigue::MeanStressCorrection mean_stress_of(const RainflowOptions& opt, double pascals_per_unit, const std::string& unit) {
  const std::string kind = opt.mean_stress.empty() ? "none" : opt.mean_stress;
  if (kind != "none" && kind != "goodman")
    throw core::InputError(command_line("--mean-stress"), "none (as-welded details) or goodman (base metal, with --ultimate)", "'" + kind + "'");  // CLI-60
  if (kind == "none") {
    if (!opt.ultimate.empty())
      throw core::InputError(command_line("--ultimate"), "--ultimate only with --mean-stress goodman (as-welded details take no mean stress)",
                             "--mean-stress " + kind);  // CLI-64
    return fatigue::MeanStressCorrection::none();
  }
  if (opt.ultimate.empty())
    throw core::InputError(command_line("--mean-stress"), "--mean-stress goodman with --ultimate (the base metal's tensile strength, in the series' unit)",
                           "no --ultimate");  // CLI-62
  const std::optional<double> su = positive_number(opt.ultimate);
  if (!su) throw core::InputError(command_line("--ultimate"), "the tensile strength in the series' unit (" + unit + "), a positive number", "'" + opt.ultimate + "'");  // CLI-63
  return fatigue::MeanStressCorrection::goodman(*su * pascals_per_unit);
}

// Passes each cycle to the list and, with a curve, to the damage sum.
class Tee : public fatigue::CycleSink {
 public:
  Tee(fatigue::CycleSink& a, fatigue::CycleSink* b) : a_(a), b_(b) {}
  void add(double range, double mean, double count) override {
    a_.add(range, mean, count);
    if (b_) b_->add(range, mean, count);
  }

 private:
  fatigue::CycleSink& a_;
  fatigue::CycleSink* b_;
};

int run_rainflow(const RainflowOptions& opt) {
  Progress progress(opt.progress);
  const std::optional<fatigue::SnCurve> curve = curve_of(opt);
  const std::string out_dir = opt.out.empty() ? std::filesystem::path(opt.series).stem().string() + "_rainflow" : opt.out;
  core::check_results_target(out_dir, {opt.series});  // before the run: a refusal costs no time
  progress.stage("reading " + opt.series);
  const fatigue::StressSeries s = fatigue::read_stress_series(opt.series, opt.column);

  progress.stage("counting cycles");
  report::RainflowRun run;
  run.series_file = opt.series;
  run.column = s.header;
  run.unit = s.unit;
  fatigue::CycleList list;
  std::optional<fatigue::MinerDamage> damage;
  const fatigue::MeanStressCorrection mean_stress = mean_stress_of(opt, s.pascals_per_unit, s.unit);
  if (curve) damage.emplace(*curve, s.pascals_per_unit, mean_stress);
  Tee tee(list, damage ? &*damage : nullptr);
  run.summary = fatigue::count_cycles(s.values, opt.repeat ? fatigue::Residue::repeated_block : fatigue::Residue::half_cycles, tee);
  run.cycles = std::move(list.cycles);
  if (curve) {
    run.curve = curve;
    run.mean_stress = mean_stress.describe();
    run.damage = damage->damage();
    if (const std::optional<double> eq = fatigue::equivalent_range(*curve, run.damage)) run.equivalent_range = *eq / s.pascals_per_unit;
  }

  progress.stage("writing results");
  core::ResultsFolder folder(out_dir, {opt.series});
  report::write_rainflow_results(run, folder);
  folder.commit();
  progress.done();
  if (progress.quiet()) {  // -q: errors only, and the results folder on stdout
    fmt::print("results in {}/\n", out_dir);
    return 0;
  }
  fmt::print("framedyn rainflow: {} column '{}' ({} samples, {} turning points)\n", opt.series, s.header, run.summary.samples, run.summary.turning_points);
  fmt::print("{} cycles, max range {} {}; residue: {}\n", core::format_number(run.summary.cycles), core::format_number(run.summary.max_range), s.unit,
             fatigue::describe(run.summary.residue));
  if (curve) {
    fmt::print("S-N curve {} ({}); mean stress: {}\n", curve->name(), curve->code(), run.mean_stress);
    fmt::print("Miner damage {}; equivalent range at 2e6 cycles {}\n", core::format_number(run.damage),
               run.equivalent_range ? core::format_number(*run.equivalent_range) + " " + s.unit : std::string("none (damage below the cut-off's)"));
  }
  fmt::print("results in {}/ (summary.json, cycles.csv)\n", out_dir);
  return 0;
}

}  // namespace

void add_rainflow_command(CLI::App& app, std::function<int()>& run) {
  auto opt = std::make_shared<RainflowOptions>();
  CLI::App* cmd = app.add_subcommand("rainflow", "Rainflow cycle counting (ASTM E1049-85) and Miner damage of one stress history");
  cmd->add_option("series", opt->series, "Stress history, CSV with a header 'name [unit]' per column (unit: Pa, kPa, MPa, GPa, N/mm^2, psi, ksi; "
                                          "an optional 'time [s]' column must increase)")
      ->required();
  cmd->add_option("--column,-c", opt->column, "The stress column to count, by name or header (default: the only column that is not time)");
  cmd->add_option("--sn", opt->sn, "S-N curve for the damage: " + fatigue::sn_curve_names());
  cmd->add_option("--curve", opt->curve, std::string("A user S-N curve instead of --sn: ") + kCurveSpec + ", or an S-N curve file FILE.yaml (name, units, points | basquin | reference + slopes + knees + cut_off)");
  cmd->add_option("--mean-stress", opt->mean_stress, "Mean-stress correction: none (as-welded details, the default) or goodman (base metal, with --ultimate)");
  cmd->add_option("--ultimate", opt->ultimate, "Goodman's tensile strength S_u, in the series' unit");
  cmd->add_option("--thickness", opt->thickness, "Plate thickness in mm for the code's thickness correction (IIW f(t) = (25/t)^n; EN 1993-1-9 k_s = (25/t)^0.2; none at <= 25 mm)");
  cmd->add_option("--thickness-exponent", opt->thickness_exponent, "IIW's thickness exponent n (default 0.3)");
  cmd->add_flag("--repeat", opt->repeat, "Count the history as a block repeated for ever (closed at its absolute maximum; no half cycles)");
  cmd->add_option("--out,-o", opt->out, "Results folder (default: <series name>_rainflow)");
  opt->progress.add_to(*cmd);
  cmd->callback([opt, &run]() { run = [opt]() { return run_rainflow(*opt); }; });
}

}  // namespace framedyn::apps
