// Interrupt clean-up; see interrupt.h for the design.
#include "core/interrupt.h"

#include <pthread.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <system_error>
#include <thread>

namespace framedyn::core {

namespace fs = std::filesystem;

namespace {

std::recursive_mutex& gate() {
  static std::recursive_mutex m;
  return m;
}
std::set<fs::path>& temporaries() {
  static std::set<fs::path> paths;
  return paths;
}
std::set<pid_t>& children() {
  static std::set<pid_t> pids;
  return pids;
}
std::set<fs::path>& written() {
  static std::set<fs::path> folders;
  return folders;
}

const char* signal_name(int signal_number) {
  switch (signal_number) {
    case SIGINT: return "SIGINT";
    case SIGTERM: return "SIGTERM";
    case SIGHUP: return "SIGHUP";
    default: return "a signal";
  }
}

[[noreturn]] void clean_up_and_exit(int signal_number) {
  // Held until _Exit: a writer waiting for the gate never gets it, so the
  // folders removed below cannot gain a file while (or after) they go.
  gate().lock();
  for (pid_t pid : children()) {
    ::kill(pid, SIGKILL);
    while (::waitpid(pid, nullptr, 0) < 0 && errno == EINTR) {
    }
  }
  for (const fs::path& p : temporaries()) {
    std::error_code ec;
    fs::remove_all(p, ec);
  }
  if (written().empty()) {
    std::fprintf(stderr, "framedyn: interrupted by %s; no results written (earlier results left as they were)\n", signal_name(signal_number));
  } else {
    for (const fs::path& folder : written())
      std::fprintf(stderr, "framedyn: interrupted by %s after the results in %s were complete (they are kept)\n", signal_name(signal_number),
                   folder.string().c_str());
  }
  std::fflush(stderr);
  std::_Exit(128 + signal_number);
}

}  // namespace

void install_interrupt_cleanup() {
  static std::once_flag once;
  std::call_once(once, [] {
    sigset_t signals;
    sigemptyset(&signals);
    sigaddset(&signals, SIGINT);
    sigaddset(&signals, SIGTERM);
    sigaddset(&signals, SIGHUP);
    pthread_sigmask(SIG_BLOCK, &signals, nullptr);
    std::thread([signals] {
      int signal_number = 0;
      while (sigwait(&signals, &signal_number) != 0) {
      }
      clean_up_and_exit(signal_number);
    }).detach();
  });
}

std::unique_lock<std::recursive_mutex> hold_output_gate() { return std::unique_lock<std::recursive_mutex>(gate()); }

void register_temporary(const fs::path& path) {
  std::lock_guard<std::recursive_mutex> lock(gate());
  temporaries().insert(path);
}
void unregister_temporary(const fs::path& path) {
  std::lock_guard<std::recursive_mutex> lock(gate());
  temporaries().erase(path);
}
void register_child(pid_t pid) {
  std::lock_guard<std::recursive_mutex> lock(gate());
  children().insert(pid);
}
void unregister_child(pid_t pid) {
  std::lock_guard<std::recursive_mutex> lock(gate());
  children().erase(pid);
}
void note_results_written(const fs::path& folder) {
  std::lock_guard<std::recursive_mutex> lock(gate());
  written().insert(folder);
}

}  // namespace framedyn::core
