// Progress lines on stderr for work that takes more than a second: a stage
// is announced only once the run has been going for a second (or at once
// with --verbose), so quick runs stay quiet and long ones show where they are.
#pragma once

#include <CLI/CLI.hpp>

#include <chrono>
#include <functional>
#include <string>

namespace framedyn::apps {

// The --verbose and --quiet flags every command has.
struct ProgressFlags {
  bool verbose = false, quiet = false;
  void add_to(CLI::App& cmd);
};

class Progress {
 public:
  explicit Progress(bool verbose = false, bool quiet = false);
  explicit Progress(const ProgressFlags& f) : Progress(f.verbose, f.quiet) {}
  void stage(const std::string& what);
  void done();
  std::function<void(const std::string&)> callback();

 private:
  std::chrono::steady_clock::time_point start_;
  std::string pending_;
  bool verbose_, quiet_, announced_ = false;
  double elapsed() const;
};

}  // namespace framedyn::apps
