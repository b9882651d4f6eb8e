// A results folder that is whole or absent, and that never costs the user a
// file. Files are written into a sibling folder "<target>.partial-<pid>";
// commit() writes the manifest (kManifestName: the list of the files of the
// run) and moves the folder into place in one rename, or, over earlier
// results, swaps the two folders in one step (renameat2 RENAME_EXCHANGE), so
// the target is never absent; a run that stops half-way (an error, an
// exception, Ctrl-C or SIGTERM: core/interrupt.h) leaves any previous results
// untouched and no partial folder behind, and even SIGKILL, at any moment,
// leaves at the target either the old results or the new ones, whole (and at
// most a "<target>.partial-<pid>" beside it). Where the file system cannot
// swap, the old folder is renamed aside first (a SIGKILL between the two
// renames then leaves it in "<target>.old-<pid>").
//
// framedyn replaces only what it made: a target that does not exist, an empty
// folder, or a folder whose manifest lists every file in it. Anything else at
// the path (a file, a folder of the user's, a results folder the user added
// files to, the working directory or a folder above it, a folder holding an
// input of the run) is refused with an InputError on the key --out. The old
// results go only after the new ones are in place, file by listed file.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/interrupt.h"

namespace framedyn::core {

// The manifest framedyn writes into every results folder.
inline constexpr const char* kManifestName = ".framedyn-manifest";

// Throws InputError (command line: --out: ...) if framedyn may not replace
// `target`; `inputs` are the files the run reads. Commands call it before
// computing, so that a refusal costs no run time; ResultsFolder calls it again.
void check_results_target(const std::filesystem::path& target, const std::vector<std::filesystem::path>& inputs = {});

class ResultsFolder {
 public:
  explicit ResultsFolder(std::filesystem::path target, std::vector<std::filesystem::path> inputs = {});
  // A folder that keeps nothing: write_text checks the text and drops it, commit()
  // does nothing, path_of throws (no figures). For runs whose summary is wanted in
  // memory only (report/study_run.h: design studies run thousands of them).
  struct InMemory {};
  explicit ResultsFolder(InMemory) {}
  bool in_memory() const { return partial_.empty(); }
  ~ResultsFolder();  // removes the partial folder unless committed
  ResultsFolder(const ResultsFolder&) = delete;
  ResultsFolder& operator=(const ResultsFolder&) = delete;

  // Path of a file inside the (still partial) folder, for writers that open
  // files themselves: they must hold the output gate while they create it
  // (report::write_png does; its gnuplot child is registered for the clean-up).
  std::filesystem::path path_of(const std::string& file_name) const;
  // Throws NumericalError, writing nothing, if the content holds a NaN or an
  // infinity (check_finite_output, core/finite_output.h).
  void write_text(const std::string& file_name, const std::string& content) const;
  // Replace the target by the partial folder (an atomic swap over earlier
  // results, see above). Throws InputError if the target
  // changed into something framedyn may not replace since the run began,
  // std::runtime_error on a failed rename (the old results then stay).
  void commit();
  const std::filesystem::path& target() const { return target_; }

 private:
  std::filesystem::path target_;
  std::vector<std::filesystem::path> inputs_;
  std::filesystem::path partial_;
  bool committed_ = false;
};

}  // namespace framedyn::core
