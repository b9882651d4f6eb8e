// Reading a design file; see design.h.
#include "batch/design.h"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include "core/error.h"
#include "core/units.h"
#include "coupling/study_key_path.h"
#include "coupling/yaml_input.h"

namespace framedyn::batch {

using coupling::YamlMap;

std::string sampling_name(SamplingMethod m) {
  switch (m) {
    case SamplingMethod::grid: return "grid";
    case SamplingMethod::latin_hypercube: return "latin_hypercube";
    case SamplingMethod::monte_carlo: return "monte_carlo";
  }
  return "";
}

std::string distribution_name(Distribution d) {
  switch (d) {
    case Distribution::uniform: return "uniform";
    case Distribution::normal: return "normal";
    case Distribution::lognormal: return "lognormal";
    case Distribution::truncated_normal: return "truncated_normal";
  }
  return "";
}

namespace {

ParameterSpec read_parameter(const YamlMap& p, SamplingMethod method) {
  p.allow_only({"key", "values", "distribution", "low", "high", "mean", "std_dev", "median", "log_std"});
  ParameterSpec s;
  s.key = p.text("key");
  constexpr core::Quantity one = core::Quantity::dimensionless;
  if (method == SamplingMethod::grid) {
    if (p.has("distribution")) throw p.error("distribution", "values: [...] (sampling.method grid takes each parameter's values)", "a distribution");
    s.values = p.numbers("values", one);
    if (s.values.empty()) throw p.error("values", "a list of one or more numbers (sampling.method grid)", p.has("values") ? "an empty list" : "no values");
    return s;
  }
  if (p.has("values"))
    throw p.error("values", fmt::format("a distribution (sampling.method {} draws the values)", sampling_name(method)), "values");
  const std::string d = p.text_or("distribution", "uniform");
  const auto need_range = [&] {
    s.low = p.number("low", one);
    s.high = p.number("high", one);
    if (!(s.high > s.low)) throw p.error("high", fmt::format("a number above low ({:g})", s.low), fmt::format("{:g}", s.high));
  };
  if (d == "uniform") {
    s.distribution = Distribution::uniform;
    need_range();
  } else if (d == "normal" || d == "truncated_normal") {
    s.distribution = d == "normal" ? Distribution::normal : Distribution::truncated_normal;
    s.mean = p.number("mean", one);
    s.std_dev = p.positive("std_dev", one);
    if (s.distribution == Distribution::truncated_normal) need_range();
  } else if (d == "lognormal") {
    s.distribution = Distribution::lognormal;
    s.median = p.positive("median", one);
    s.log_std = p.positive("log_std", one);
  } else {
    throw p.error("distribution", "uniform, normal, lognormal or truncated_normal", "'" + d + "'");
  }
  return s;
}

}  // namespace

BatchDesign read_batch_design(const std::string& file) {
  const YAML::Node doc = coupling::load_yaml_file(file);
  const core::UnitSystem si = core::UnitSystem::si();
  const YamlMap top(doc, "", file, &si);
  top.allow_only({"framedyn_batch", "name", "study", "sampling", "parameters", "outputs"});
  if (top.integer("framedyn_batch") != 1) throw top.error("framedyn_batch", "1 (the design format this framedyn reads)", top.text("framedyn_batch"));
  BatchDesign d;
  d.file = file;
  d.study_file = std::filesystem::path(file).parent_path() / top.text("study");
  // The study is read once, here; its own errors name the study file.
  d.study = coupling::load_yaml_file(d.study_file.string());
  {
    std::ifstream in(d.study_file, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    d.study_text = text.str();
  }
  if (d.study.IsMap() && d.study["units"] && d.study["units"].IsScalar()) d.study_units = d.study["units"].Scalar();

  const YamlMap s = top.map("sampling");
  s.allow_only({"method", "samples", "seed"});
  const std::string method = s.text("method");
  if (method == "grid") d.sampling.method = SamplingMethod::grid;
  else if (method == "latin_hypercube") d.sampling.method = SamplingMethod::latin_hypercube;
  else if (method == "monte_carlo") d.sampling.method = SamplingMethod::monte_carlo;
  else throw s.error("method", "grid, latin_hypercube or monte_carlo", "'" + method + "'");
  if (d.sampling.method != SamplingMethod::grid) {
    const int n = s.integer("samples");
    if (n < 2 || n > 10000000) throw s.error("samples", "an integer from 2 to 10000000", std::to_string(n));
    d.sampling.samples = static_cast<std::size_t>(n);
    const int seed = s.has("seed") ? s.integer("seed") : 1;
    if (seed < 0) throw s.error("seed", "an integer >= 0", std::to_string(seed));
    d.sampling.seed = static_cast<std::uint64_t>(seed);
  } else if (s.has("samples")) {
    throw s.error("samples", "no samples with method grid (every combination of the parameters' values is run)", s.text("samples"));
  }

  const std::vector<YamlMap> params = top.list_of_maps("parameters");
  if (params.empty()) throw top.error("parameters", "a list of parameters {key, ...}", top.has("parameters") ? "an empty list" : "no parameters");
  std::set<std::string> keys;
  for (const YamlMap& p : params) {
    ParameterSpec spec = read_parameter(p, d.sampling.method);
    // The key path's own errors (docs/errors.md PY-01 to PY-04) name the study, its line and the path.
    coupling::study_number(d.study, spec.key, d.study_file.string());
    if (!keys.insert(spec.key).second) throw p.error("key", "each key once", "'" + spec.key + "' again");
    d.parameter_lines.push_back(p.location("key").line);
    d.parameters.push_back(spec);
  }
  std::size_t runs = 1;
  if (d.sampling.method == SamplingMethod::grid) {
    for (const ParameterSpec& p : d.parameters) runs *= p.values.size();
    if (runs > 10000000) throw top.error("parameters", "a grid of at most 10000000 runs", fmt::format("{} runs", runs));
  }

  d.outputs = top.strings("outputs");
  if (d.outputs.empty()) throw top.error("outputs", "a list of key paths into a run's summary (e.g. rigid.response.peak_cutting_force)",
                                         top.has("outputs") ? "an empty list" : "no outputs");
  std::set<std::string> outs;
  for (const std::string& o : d.outputs) {
    if (!coupling::parse_key_path(o)) throw top.error("outputs", std::string(coupling::kKeyPathForm) + " into a run's summary", "'" + o + "'");
    if (!outs.insert(o).second) throw top.error("outputs", "each output once", "'" + o + "' again");
  }
  return d;
}

}  // namespace framedyn::batch
