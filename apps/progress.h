// Progress and verbosity, the same on every command (docs/user-guide.md,
// "Progress and verbosity"):
//   default  a progress line on stderr for work over a second: a stage is
//            announced once the run has been going for a second, and a
//            percentage at most once a second where a stage is a loop
//            (e.g. "writing results (frame) 45 %");
//   -v       every stage at once, and at the end each stage with its time and
//            its share of the run;
//   -q       errors only: nothing on stderr for a successful run, and on
//            stdout only the line naming the results folder (no tables).
#pragma once

#include <CLI/CLI.hpp>

#include <chrono>
#include <functional>
#include <string>
#include <vector>

#include "core/warnings.h"

namespace framedyn::apps {

// The --verbose and --quiet flags every command has (they exclude each other).
struct ProgressFlags {
  bool verbose = false, quiet = false;
  void add_to(CLI::App& cmd);
};

// Whether the command runs with -q: the console prints only errors and the
// results line (set by a Progress for the whole process; read by main's
// closing "run time" line and the warnings' printer).
bool quiet_console();

// Prints a run's warning on stderr as "framedyn: warning [code]: message" (nothing with -q).
void print_warning(const core::Warning& w);

class Progress {
 public:
  explicit Progress(bool verbose = false, bool quiet = false);
  explicit Progress(const ProgressFlags& f) : Progress(f.verbose, f.quiet) {}
  void stage(const std::string& what);
  // `done` of `total` steps of the current stage's loop: a percentage line at most once a second.
  void step(long long done, long long total);
  void done();
  bool quiet() const { return quiet_; }
  std::function<void(const std::string&)> callback();
  std::function<void(int, int)> step_callback();

 private:
  struct Stage {
    std::string what;
    double started = 0.0;
  };
  std::chrono::steady_clock::time_point start_;
  std::vector<Stage> stages_;
  double last_line_ = -1.0;
  bool verbose_, quiet_, announced_ = false;
  double elapsed() const;
  void line(const std::string& text);
};

}  // namespace framedyn::apps
