// A results folder that is whole or absent. Files are written into a sibling
// folder "<target>.partial-<pid>"; commit() moves it into place in one rename,
// so a run that stops half-way (an error, an exception, Ctrl-C or SIGTERM)
// leaves any previous results untouched and no partial folder behind.
#pragma once

#include <filesystem>
#include <string>

namespace framedyn::core {

// Makes SIGINT, SIGTERM and SIGHUP remove every results folder still being
// written, print one line, and exit with status 128 + signal. Call it first in
// main, before any thread starts: it blocks those signals in the calling
// thread (threads started later inherit that) and waits for them in a thread
// of its own, so the clean-up runs as ordinary code, not in a signal handler,
// and never races a commit (both hold one lock).
void install_interrupt_cleanup();

class ResultsFolder {
 public:
  explicit ResultsFolder(std::filesystem::path target);
  ~ResultsFolder();  // removes the partial folder unless committed
  ResultsFolder(const ResultsFolder&) = delete;
  ResultsFolder& operator=(const ResultsFolder&) = delete;

  // Path of a file inside the (still partial) folder, for writers that open files themselves.
  std::filesystem::path path_of(const std::string& file_name) const;
  // Throws NumericalError, writing nothing, if the content holds a NaN or an
  // infinity (check_finite_output, core/finite_output.h).
  void write_text(const std::string& file_name, const std::string& content) const;
  // Replace the target by the partial folder. Throws std::runtime_error on failure.
  void commit();
  const std::filesystem::path& target() const { return target_; }

 private:
  std::filesystem::path target_;
  std::filesystem::path partial_;
  bool committed_ = false;
};

}  // namespace framedyn::core
