// A design file (`framedyn batch DESIGN.yaml`): the base study, the sampling,
// the parameters varied by key path and the outputs collected by key path from
// each run's summary. Reading checks every key (errors BATCH-01 .. BATCH-20,
// docs/errors.md), including that each parameter names a number the study has.
// docs/user-guide.md, "framedyn batch".
#pragma once

#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <string>
#include <vector>

#include "batch/sampling.h"

namespace framedyn::batch {

struct BatchDesign {
  std::string file;                  // the design file, as given
  std::filesystem::path study_file;  // relative to the design file's folder
  YAML::Node study;                  // the study, parsed once (to check the parameters' keys)
  std::string study_text;            // its text: each run parses its own copy (YAML::Clone would lose the lines errors name)
  std::string study_units;           // the study's `units:` (parameters are in them)
  Sampling sampling;
  std::vector<ParameterSpec> parameters;
  std::vector<int> parameter_lines;  // each parameter's line in the design file
  std::vector<std::string> outputs;
};

// Throws core::InputError naming the design file, its line and key.
BatchDesign read_batch_design(const std::string& file);

// The design as summary.json records it (study, sampling, parameters, outputs).
std::string sampling_name(SamplingMethod m);
std::string distribution_name(Distribution d);

}  // namespace framedyn::batch
