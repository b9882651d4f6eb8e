// Runs any study document in memory and returns its summary: the one library
// call behind `framedyn run` (model rigid_2d; rigid_3d with and without the
// frame_response block, i.e. the pipeline; duty_cycle) and behind design
// studies (`framedyn batch`) and the Python binding, which need a run's
// summary without a results folder. The summary is the content of
// summary.json (nlohmann ordered JSON, every number {value, unit}; written with
// dump(2) plus a newline it is summary.json byte for byte). With `out` the
// results folder is written as `framedyn run --out` writes it
// (core/results_folder: whole or nothing, never a file framedyn did not write).
// docs/user-guide.md, "summary.json".
#pragma once

#include <nlohmann/json.hpp>

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/warnings.h"

namespace YAML {
class Node;
}

namespace framedyn::coupling {
class FrameModelCache;
}

namespace framedyn::report {

struct StudyRunOptions {
  // A worker's frame models (coupling/frame_model_cache.h), reused by the
  // pipeline's frame side when this run's mesh, supports and parts are those
  // of an earlier run; null: built for this run alone. The summary is the same either way.
  coupling::FrameModelCache* frame_cache = nullptr;
  // Write the results folder here (the files `framedyn run --out` writes); none:
  // the summary only, in memory, and no file is written at all.
  std::optional<std::filesystem::path> out;
  bool figures = false;  // PNG figures (needs `out` and gnuplot)
  // A duty cycle's scenarios run at the same time (coupling::run_duty_cycle; 0: one per
  // core). Other models ignore it. 1 here: a design study's workers already fill the cores.
  int threads = 1;
  // The summary's key paths the caller reads (a design study's outputs,
  // batch/engine), or none: the whole summary. With them and without `out`, a
  // pipeline run computes only what those paths can read: unless one of them
  // lies outside `input`, `rigid` and the frame block's keys from its modes,
  // loads and rails (a hot spot, the von Mises peak, compared supports,
  // fatigue, warnings), the frame's stress histories, hot spots and life map
  // are skipped (coupling::FrameStudyRequest::hot_spots); when every path lies
  // in `input` or `rigid` (a path may name a whole block: "rigid"), the frame
  // is not run at all (no frame block, no frame warnings). Every listed path
  // reads the same value either way; the rest of the summary may be missing.
  std::optional<std::vector<std::string>> summary_outputs;
  // Progress: a stage begins ("reading ...", "modes and forced response", ...); a stage's loop advances.
  std::function<void(const std::string&)> stage;
  std::function<void(int, int)> step;
  // Each warning as it joins the summary's `warnings` list (the console prints it).
  std::function<void(const core::Warning&)> warning;
};

struct StudyRunDetails;  // the typed study and results, for the console (report/study_run_details.h)

struct StudyRun {
  std::string model;               // rigid_2d, rigid_3d or duty_cycle
  nlohmann::ordered_json summary;  // summary.json's content
  std::vector<std::string> figures;  // PNG files written (with figures)
  std::shared_ptr<const StudyRunDetails> details;
};

// Runs the study `doc` (parsed; not modified). `file` names it in messages and
// in summary.input.study and anchors its relative paths (meshes, scenarios).
// Throws core::InputError on a bad study or a refused `out`, core::NumericalError
// on a failed solution.
StudyRun run_study_document(const YAML::Node& doc, const std::filesystem::path& file, const StudyRunOptions& options = {});
// The same for a study file (reads it; a duplicated key or bad YAML is an InputError).
StudyRun run_study_file(const std::filesystem::path& file, const StudyRunOptions& options = {});

}  // namespace framedyn::report
