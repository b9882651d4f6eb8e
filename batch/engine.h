// Running a design study (`framedyn batch`): every sample's run in memory
// (report::run_study_document on a copy of the study with the sample's values
// set by key path), on threads or (batch/mpi_engine.cpp) MPI ranks, and the
// results folder: runs.csv (one row per run in index order, whatever the
// thread or rank count) and summary.json (the design, counts, sensitivity).
// docs/user-guide.md, "framedyn batch"; docs/theory/coupling.md section 13.
#pragma once

#include <nlohmann/json.hpp>

#include <cstddef>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "batch/design.h"

namespace framedyn::coupling {
class FrameModelCache;
}

namespace framedyn::batch {

// One run's row. Cells are the table's text (10 significant digits); the
// parameters were rounded to that text before the run, so the row says exactly
// what ran, and a resumed batch reads back the same numbers it would have held.
struct RunRecord {
  std::size_t index = 0;
  std::vector<std::string> parameters, outputs;  // outputs: "" when absent
  std::vector<std::string> output_units;         // as the run's summary gives them ("" unknown)
  bool done = false;                             // false: failed
  std::string message;                           // the error of a failed run; notes of a done one
  bool present = false;                          // run (or read back by --resume)
};

// The design's samples with each value rounded to the table's 10 significant digits.
std::vector<std::vector<double>> design_samples(const BatchDesign& design);

// A design's output from a run's summary, by key path (a design's `outputs`, Python's
// batch(outputs=...)): {value, unit} objects give both, a bare number has unit "1",
// true/false are 1/0. False, with `why` (e.g. "the run's summary has no frame.modes[3]"),
// when the summary has no number there. `path` must be a key path (coupling::parse_key_path).
bool summary_value(const nlohmann::ordered_json& summary, const std::string& path, double& value, std::string& unit, std::string& why);

// Runs one sample in memory (with keep_folder: also writes that run's results folder).
// `frame_cache`: the calling worker's frame models (coupling/frame_model_cache.h), built
// once and reused by its later runs; the row is the same with or without it.
RunRecord run_sample(const BatchDesign& design, std::size_t index, const std::vector<double>& values,
                     const std::optional<std::filesystem::path>& keep_folder = std::nullopt, coupling::FrameModelCache* frame_cache = nullptr);

// runs.csv's text: index, parameters [the study's units], outputs [unit], status, message.
std::string runs_csv(const BatchDesign& design, const std::vector<RunRecord>& rows);
// Reads back the rows of an earlier runs.csv of the same design (--resume); throws
// core::InputError (OUT-08) if its header is not this design's.
std::vector<RunRecord> read_runs_csv(const BatchDesign& design, const std::filesystem::path& csv);
// summary.json's content: design, runs {total, done, failed, missing}, sensitivity per output.
nlohmann::ordered_json batch_summary(const BatchDesign& design, const std::vector<RunRecord>& rows);

struct BatchOptions {
  std::filesystem::path out;
  int threads = 1;
  bool resume = false;
  bool keep_runs = false;          // each run's own results folder in <out>_runs/run_NNNNNN
  bool reuse_models = true;        // each worker builds its frame models once (coupling/frame_model_cache.h); false: every run builds its own
  std::size_t checkpoint_runs = 0;  // write the folder every so many runs (0: every 5 % of the runs)
  std::function<void(std::size_t, std::size_t)> progress;  // (runs finished, runs to do)
  std::function<void(const std::string&)> stage;            // called with "writing results" once the runs are done
};

struct BatchCounts {
  std::size_t total = 0, done = 0, failed = 0, skipped = 0;  // skipped: read back by --resume
};

// Keeps the memory a run frees in the process for the next run (glibc: large
// blocks from the heap, not mapped and unmapped per run, and no trimming of it),
// so that a worker's runs do not fault in fresh pages for the same buffers each
// time (about a third of a pipeline run's CPU time). Called by run_on_threads and
// by an MPI worker; the results do not depend on it.
void keep_freed_memory_for_next_runs();

// The engine's threads: calls run(i, models) once for every i in [0, count), on
// `threads` threads (at most count; the calling thread is one of them) taking
// the next index as they finish, each with its own frame models
// (coupling/frame_model_cache.h; null with reuse_models false). `run` must
// leave its result in a slot of its own for i. The first exception a run
// throws is rethrown once every thread has stopped (the others stop taking runs).
// Used by run_batch and by the Python module's framedyn.batch.
void run_on_threads(std::size_t count, int threads, bool reuse_models,
                    const std::function<void(std::size_t, coupling::FrameModelCache*)>& run);

// Runs the design on threads; writes (and checkpoints) the results folder.
BatchCounts run_batch(const BatchDesign& design, const BatchOptions& options);

// The results folder's inputs (never replaced): the design file and the study.
std::vector<std::filesystem::path> batch_inputs(const BatchDesign& design);
// Writes runs.csv and summary.json into options.out (core/results_folder: whole or nothing).
void write_batch_folder(const BatchDesign& design, const std::vector<RunRecord>& rows, const BatchOptions& options);
// The rows --resume starts from (all absent without it).
std::vector<RunRecord> starting_rows(const BatchDesign& design, const BatchOptions& options, std::size_t total);

}  // namespace framedyn::batch
