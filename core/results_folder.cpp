// Whole-or-absent results folders: write beside the target, rename into place.
#include "core/results_folder.h"

#include <unistd.h>

#include <fstream>
#include <stdexcept>
#include <system_error>

namespace framedyn::core {

namespace fs = std::filesystem;

ResultsFolder::ResultsFolder(fs::path target) : target_(std::move(target)) {
  if (target_.empty()) throw std::runtime_error("results folder: empty path");
  if (target_.filename().empty()) target_ = target_.parent_path();  // "out/" -> "out"
  partial_ = target_;
  partial_ += ".partial-" + std::to_string(::getpid());
  std::error_code ec;
  fs::remove_all(partial_, ec);
  fs::create_directories(partial_, ec);
  if (ec) throw std::runtime_error("cannot create results folder " + partial_.string() + ": " + ec.message());
}

ResultsFolder::~ResultsFolder() {
  if (!committed_) {
    std::error_code ec;
    fs::remove_all(partial_, ec);
  }
}

fs::path ResultsFolder::path_of(const std::string& file_name) const { return partial_ / file_name; }

void ResultsFolder::write_text(const std::string& file_name, const std::string& content) const {
  const fs::path p = path_of(file_name);
  std::ofstream out(p, std::ios::binary);
  out << content;
  out.close();
  if (!out) throw std::runtime_error("cannot write " + p.string());
}

void ResultsFolder::commit() {
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
  if (!old.empty()) fs::remove_all(old, ec);
}

}  // namespace framedyn::core
