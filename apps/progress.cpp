// Stage reporting on stderr; see progress.h.
#include "apps/progress.h"

#include <fmt/format.h>

#include <cstdio>

namespace framedyn::apps {

void ProgressFlags::add_to(CLI::App& cmd) {
  cmd.add_flag("--verbose,-v", verbose, "Report every stage on stderr");
  cmd.add_flag("--quiet,-q", quiet, "No progress lines");
}

Progress::Progress(bool verbose, bool quiet) : start_(std::chrono::steady_clock::now()), verbose_(verbose), quiet_(quiet) {}

double Progress::elapsed() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void Progress::stage(const std::string& what) {
  if (quiet_) return;
  pending_ = what;
  if (verbose_ || elapsed() > 1.0) {
    fmt::print(stderr, "framedyn [{:7.2f} s] {}\n", elapsed(), what);
    std::fflush(stderr);
    announced_ = true;
  }
}

void Progress::done() {
  if (!quiet_ && (announced_ || verbose_)) fmt::print(stderr, "framedyn [{:7.2f} s] done\n", elapsed());
}

std::function<void(const std::string&)> Progress::callback() {
  return [this](const std::string& s) { stage(s); };
}

}  // namespace framedyn::apps
