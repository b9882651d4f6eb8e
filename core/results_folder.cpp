// Whole-or-absent results folders: write beside the target, rename into place.
#include "core/results_folder.h"

#include <pthread.h>
#include <signal.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <mutex>
#include <set>
#include <stdexcept>
#include <system_error>
#include <thread>

#include "core/finite_output.h"

namespace framedyn::core {

namespace fs = std::filesystem;

namespace {

// The partial folders of this process, for the interrupt clean-up.
std::mutex& registry_mutex() {
  static std::mutex m;
  return m;
}
std::set<fs::path>& partial_folders() {
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
      if (sigwait(&signals, &signal_number) != 0) return;
      std::lock_guard<std::mutex> lock(registry_mutex());  // lets a commit in progress finish
      for (const fs::path& folder : partial_folders()) {
        std::error_code ec;
        fs::remove_all(folder, ec);
      }
      std::fprintf(stderr, "framedyn: interrupted by %s; no results written (earlier results left as they were)\n",
                   signal_name(signal_number));
      std::fflush(stderr);
      std::_Exit(128 + signal_number);
    }).detach();
  });
}

ResultsFolder::ResultsFolder(fs::path target) : target_(std::move(target)) {
  if (target_.empty()) throw std::runtime_error("results folder: empty path");
  if (target_.filename().empty()) target_ = target_.parent_path();  // "out/" -> "out"
  partial_ = target_;
  partial_ += ".partial-" + std::to_string(::getpid());
  std::error_code ec;
  fs::remove_all(partial_, ec);
  {
    std::lock_guard<std::mutex> lock(registry_mutex());
    partial_folders().insert(partial_);
  }
  fs::create_directories(partial_, ec);
  if (ec) throw std::runtime_error("cannot create results folder " + partial_.string() + ": " + ec.message());
}

ResultsFolder::~ResultsFolder() {
  std::lock_guard<std::mutex> lock(registry_mutex());
  if (!committed_) {
    std::error_code ec;
    fs::remove_all(partial_, ec);
  }
  partial_folders().erase(partial_);
}

fs::path ResultsFolder::path_of(const std::string& file_name) const { return partial_ / file_name; }

void ResultsFolder::write_text(const std::string& file_name, const std::string& content) const {
  check_finite_output((target_ / file_name).string(), content);  // no NaN or Inf in any results file
  const fs::path p = path_of(file_name);
  std::ofstream out(p, std::ios::binary);
  out << content;
  out.close();
  if (!out) throw std::runtime_error("cannot write " + p.string());
}

void ResultsFolder::commit() {
  std::lock_guard<std::mutex> lock(registry_mutex());
  std::error_code ec;
  fs::path old;
  if (fs::exists(target_, ec)) {
    old = target_;
    old += ".old-" + std::to_string(::getpid());
    fs::remove_all(old, ec);
    fs::rename(target_, old, ec);
    if (ec) throw std::runtime_error("cannot move old results " + target_.string() + " aside: " + ec.message());
  }
  fs::rename(partial_, target_, ec);
  if (ec) {
    if (!old.empty()) fs::rename(old, target_, ec);
    throw std::runtime_error("cannot move results into " + target_.string() + ": " + ec.message());
  }
  committed_ = true;
  partial_folders().erase(partial_);
  if (!old.empty()) fs::remove_all(old, ec);
}

}  // namespace framedyn::core
