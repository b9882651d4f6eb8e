// `framedyn sweep` as a design study over one parameter (issue 19): the study
// run once per value of one of its numeric keys, named by key path as in a
// design file (batch/key_path.h: soil.damping, plow.shaker.frequency_hz,
// frame.added_masses[engine].weight), on threads, every run in memory through
// report::run_study_document as the batch engine runs a sample. Any vehicle
// model with a forced response (rigid_2d; rigid_3d, with or without the frame
// pipeline). The runs' typed results give coupling's SweepResult, from which
// report/sweep_outputs.h writes the tables and figures.
// docs/user-guide.md, "framedyn sweep".
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "core/units.h"
#include "coupling/parameter_sweep.h"

namespace framedyn::batch {

struct OneParameterSweep {
  std::string study_file;          // as given
  std::string key;                 // the key path of the number varied
  std::vector<double> values;      // in the study's units
  int threads = 1;
  // Called (one call at a time, from any thread) as each run starts.
  std::function<void(const std::string&)> progress;
};

struct OneParameterSweepResult {
  coupling::SweepResult result;  // the parameter's values in SI when its quantity is known
  core::UnitSystem units;        // the study's
  std::string study_name;
  std::string parameter_unit;    // the parameter's unit label; the unit system's name when the key has no known quantity
};

// Runs the values, then the study file's own value of the key if it is not
// among them (the reference of the relative changes). Throws core::InputError
// for a study that is not a vehicle model with analysis.response, a key the
// study does not have or that does not hold a number, a key the study
// calibrates; a failed run's error (the first, in the order of the values) passes through.
OneParameterSweepResult run_one_parameter_sweep(const OneParameterSweep& request);

}  // namespace framedyn::batch
