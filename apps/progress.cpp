// Stage reporting on stderr; see progress.h.
#include "apps/progress.h"

#include <fmt/format.h>

#include <cstdio>

namespace framedyn::apps {

namespace {
bool g_quiet = false;
}  // namespace

bool quiet_console() { return g_quiet; }

void ProgressFlags::add_to(CLI::App& cmd) {
  CLI::Option* v = cmd.add_flag("--verbose,-v", verbose, "Every stage on stderr, and each stage's time at the end");
  CLI::Option* q = cmd.add_flag("--quiet,-q", quiet, "Errors only: no progress, no warnings on stderr, no tables (stdout: the results folder)");
  v->excludes(q);
}

Progress::Progress(bool verbose, bool quiet) : start_(std::chrono::steady_clock::now()), verbose_(verbose), quiet_(quiet) { g_quiet = quiet; }

double Progress::elapsed() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void Progress::line(const std::string& text) {
  fmt::print(stderr, "framedyn [{:7.2f} s] {}\n", elapsed(), text);
  std::fflush(stderr);
  announced_ = true;
  last_line_ = elapsed();
}

void Progress::stage(const std::string& what) {
  if (quiet_) return;
  stages_.push_back({what, elapsed()});
  if (verbose_ || elapsed() > 1.0) line(what);
}

void Progress::step(long long done, long long total) {
  if (quiet_ || stages_.empty() || total <= 0) return;
  // At most once a second, and only once the run has been going for a second.
  if (elapsed() <= 1.0 || elapsed() - last_line_ < 1.0) return;
  line(fmt::format("{} {:.0f} %", stages_.back().what, 100.0 * static_cast<double>(done) / static_cast<double>(total)));
}

void Progress::done() {
  if (quiet_) return;
  const double end = elapsed();
  if (verbose_) {
    fmt::print(stderr, "framedyn stages:\n");
    for (std::size_t i = 0; i < stages_.size(); ++i) {
      const double until = i + 1 < stages_.size() ? stages_[i + 1].started : end;
      fmt::print(stderr, "  {:<60} {:8.3f} s {:5.1f} %\n", stages_[i].what, until - stages_[i].started,
                 end > 0.0 ? 100.0 * (until - stages_[i].started) / end : 0.0);
    }
  }
  if (announced_ || verbose_) fmt::print(stderr, "framedyn [{:7.2f} s] done\n", end);
}

void print_warning(const core::Warning& w) {
  if (!quiet_console()) fmt::print(stderr, "framedyn: warning [{}]: {}\n", w.code, w.message);
}

std::function<void(const std::string&)> Progress::callback() {
  return [this](const std::string& s) { stage(s); };
}

std::function<void(int, int)> Progress::step_callback() {
  return [this](int done, int total) { step(done, total); };
}

}  // namespace framedyn::apps
