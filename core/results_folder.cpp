// Whole-or-absent results folders that replace only what framedyn wrote:
// write beside the target, list the files in a manifest, swap it with the old
// folder in one step (or rename into place), then delete the old folder's
// listed files (and the folder once empty).
#include "core/results_folder.h"

#include <fcntl.h>
#include <unistd.h>

#include <stdio.h>  // renameat2, RENAME_EXCHANGE (glibc >= 2.28, with _GNU_SOURCE)

#include <cerrno>

#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <set>
#include <stdexcept>
#include <system_error>

#include "core/error.h"
#include "core/finite_output.h"

namespace framedyn::core {

namespace fs = std::filesystem;

namespace {

constexpr const char* kManifestHeader = "# framedyn results manifest 1: the files framedyn wrote here; it replaces this folder only while it holds nothing else";

const InputLocation kOut{"command line", 0, "--out"};

std::string display(const fs::path& p) { return "'" + p.string() + "'"; }

// The files a manifest lists (relative paths), or false if `folder` has none
// (no file, or not a framedyn manifest).
bool read_manifest(const fs::path& folder, std::set<std::string>& files) {
  std::ifstream in(folder / kManifestName, std::ios::binary);
  if (!in) return false;
  std::string line;
  if (!std::getline(in, line) || line.rfind("# framedyn results manifest", 0) != 0) return false;
  while (std::getline(in, line))
    if (!line.empty() && line[0] != '#') files.insert(line);
  return true;
}

// Every entry under `folder` that is not a listed file or a folder on the way
// to one, as relative paths (at most `limit`).
std::vector<std::string> unlisted_entries(const fs::path& folder, const std::set<std::string>& listed, std::size_t limit) {
  std::set<std::string> listed_dirs;
  for (const std::string& f : listed)
    for (fs::path d = fs::path(f).parent_path(); !d.empty(); d = d.parent_path()) listed_dirs.insert(d.generic_string());
  std::vector<std::string> extra;
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(folder, ec); !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
    const std::string rel = fs::relative(it->path(), folder, ec).generic_string();
    if (rel == kManifestName) continue;
    const bool is_dir = it->is_directory(ec) && !it->is_symlink(ec);
    if (is_dir ? listed_dirs.count(rel) != 0 : listed.count(rel) != 0) continue;
    extra.push_back(rel + (is_dir ? "/" : ""));
    if (is_dir) it.disable_recursion_pending();
    if (extra.size() >= limit) break;
  }
  if (ec) extra.push_back("(cannot list the folder: " + ec.message() + ")");
  return extra;
}

// True if `inner` is `outer` or lies inside it (both made absolute, with
// symbolic links and "..", resolved as far as they exist).
bool is_within(const fs::path& inner, const fs::path& outer) {
  std::error_code ec;
  const fs::path a = fs::weakly_canonical(fs::absolute(inner), ec), b = fs::weakly_canonical(fs::absolute(outer), ec);
  auto ia = a.begin(), ib = b.begin();
  for (; ib != b.end(); ++ia, ++ib) {
    if (ib->empty() && std::next(ib) == b.end()) return true;  // trailing "/"
    if (ia == a.end() || *ia != *ib) return false;
  }
  return true;
}

fs::path normalised(fs::path target) {
  if (target.filename().empty() && target.has_parent_path() && target != target.root_path()) target = target.parent_path();  // "out/" -> "out"
  return target;
}

// Deletes the files a manifest listed, the manifest, then each folder once
// empty (deepest first). Returns false if anything is left.
bool remove_listed(const fs::path& folder, const std::set<std::string>& listed) {
  std::error_code ec;
  std::set<fs::path> dirs;
  for (const std::string& f : listed) {
    fs::remove(folder / f, ec);
    for (fs::path d = fs::path(f).parent_path(); !d.empty(); d = d.parent_path()) dirs.insert(d);
  }
  fs::remove(folder / kManifestName, ec);
  std::vector<fs::path> ordered(dirs.begin(), dirs.end());
  std::sort(ordered.begin(), ordered.end(), [](const fs::path& a, const fs::path& b) { return a.string().size() > b.string().size(); });
  for (const fs::path& d : ordered) fs::remove(folder / d, ec);  // removes only an empty folder
  return fs::remove(folder, ec);
}

// Swaps two existing folders in one step (renameat2 RENAME_EXCHANGE, Linux >= 3.15).
// False, changing nothing, where the file system or kernel cannot (EINVAL,
// ENOSYS, EOPNOTSUPP): the caller then falls back to two renames. Throws on
// any other failure (the old results then stay in place).
bool exchange_folders(const fs::path& a, const fs::path& b) {
#ifdef RENAME_EXCHANGE
  if (::renameat2(AT_FDCWD, a.c_str(), AT_FDCWD, b.c_str(), RENAME_EXCHANGE) == 0) return true;
  const int e = errno;
  if (e == EINVAL || e == ENOSYS || e == EOPNOTSUPP) return false;
  throw std::runtime_error("cannot swap the new results into " + b.string() + ": " + std::generic_category().message(e));
#else
  (void)a;
  (void)b;
  return false;
#endif
}

}  // namespace

void check_results_target(const fs::path& raw_target, const std::vector<fs::path>& inputs) {
  const fs::path target = normalised(raw_target);
  const std::string how = "; choose a new --out (a folder that does not exist yet)";
  if (target.empty()) throw InputError(kOut, "a folder for the results", "an empty path");
  std::error_code ec;
  const fs::path cwd = fs::current_path(ec);
  if (!ec && is_within(cwd, target))
    throw InputError(kOut, "a results folder framedyn may replace",
                     display(raw_target) + ", the working directory" + (fs::equivalent(cwd, target, ec) ? "" : std::string(" or a folder above it")) +
                         " (framedyn never replaces it)" + how);
  for (const fs::path& input : inputs)
    if (!input.empty() && is_within(input, target))
      throw InputError(kOut, "a results folder framedyn may replace",
                       display(raw_target) + ", the folder holding the input file " + display(input) + " (framedyn never replaces it)" + how);
  const fs::file_status status = fs::symlink_status(target, ec);
  if (!fs::exists(status)) return;  // a new folder
  if (fs::is_symlink(status))
    throw InputError(kOut, "a results folder framedyn may replace", display(raw_target) + ", a symbolic link (framedyn replaces only a folder it wrote)" + how);
  if (!fs::is_directory(status))
    throw InputError(kOut, "a results folder framedyn may replace",
                     display(raw_target) + ", a file that is not a folder (framedyn replaces only a folder it wrote)" + how);
  std::set<std::string> listed;
  if (!read_manifest(target, listed)) {
    if (fs::is_empty(target, ec) && !ec) return;  // an empty folder: replacing it loses nothing
    throw InputError(kOut, "a results folder framedyn may replace",
                     display(raw_target) + fmt::format(", a folder framedyn did not write (it has no {} listing framedyn's files)", kManifestName) + how +
                         ", or move that folder away");
  }
  const std::vector<std::string> extra = unlisted_entries(target, listed, 6);
  if (!extra.empty()) {
    std::string names;
    for (std::size_t i = 0; i < extra.size() && i < 5; ++i) names += (i ? ", " : "") + extra[i];
    if (extra.size() > 5) names += ", ...";
    throw InputError(kOut, "a results folder framedyn may replace",
                     display(raw_target) + ", earlier framedyn results with files framedyn did not write (" + names + ")" + how +
                         ", or move those files out");
  }
}

ResultsFolder::ResultsFolder(fs::path target, std::vector<fs::path> inputs) : target_(normalised(std::move(target))), inputs_(std::move(inputs)) {
  check_results_target(target_, inputs_);
  std::error_code ec;
  if (target_.has_parent_path()) fs::create_directories(target_.parent_path(), ec);
  auto gate = hold_output_gate();
  // A fresh name: never reuse (or delete) a folder that is already there.
  for (int attempt = 0;; ++attempt) {
    partial_ = target_;
    partial_ += ".partial-" + std::to_string(::getpid()) + (attempt ? "-" + std::to_string(attempt) : std::string());
    if (fs::create_directory(partial_, ec)) break;
    if (ec || attempt >= 1000) throw std::runtime_error("cannot create results folder " + partial_.string() + ": " + (ec ? ec.message() : "name taken"));
  }
  register_temporary(partial_);
}

ResultsFolder::~ResultsFolder() {
  if (in_memory()) return;
  auto gate = hold_output_gate();
  if (!committed_) {
    std::error_code ec;
    fs::remove_all(partial_, ec);
  }
  unregister_temporary(partial_);
}

fs::path ResultsFolder::path_of(const std::string& file_name) const {
  if (in_memory()) throw std::logic_error("a results folder in memory has no path for " + file_name);
  return partial_ / file_name;
}

void ResultsFolder::write_text(const std::string& file_name, const std::string& content) const {
  check_finite_output((target_ / file_name).string(), content);  // no NaN or Inf in any results file
  if (in_memory()) return;
  const fs::path p = path_of(file_name);
  auto gate = hold_output_gate();
  std::ofstream out(p, std::ios::binary);
  out << content;
  out.close();
  if (!out) throw std::runtime_error("cannot write " + p.string());
}

void ResultsFolder::commit() {
  if (in_memory()) return;
  auto gate = hold_output_gate();  // an interrupt waits until the results are in place and the old ones gone
  check_results_target(target_, inputs_);
  std::error_code ec;
  {
    std::vector<std::string> files;
    for (auto it = fs::recursive_directory_iterator(partial_, ec); !ec && it != fs::recursive_directory_iterator(); it.increment(ec))
      if (!it->is_directory()) files.push_back(fs::relative(it->path(), partial_).generic_string());
    if (ec) throw std::runtime_error("cannot list results folder " + partial_.string() + ": " + ec.message());
    std::sort(files.begin(), files.end());
    std::ofstream out(partial_ / kManifestName, std::ios::binary);
    out << kManifestHeader << "\n";
    for (const std::string& f : files) out << f << "\n";
    out.close();
    if (!out) throw std::runtime_error("cannot write " + (partial_ / kManifestName).string());
  }
  std::set<std::string> old_files;
  if (fs::exists(fs::symlink_status(target_, ec))) {
    read_manifest(target_, old_files);  // none: an empty folder (check_results_target)
    // One atomic swap: the target holds the old results, then the new ones, and is
    // never absent, whenever the process stops (SIGKILL included). The old results
    // are then at the partial folder's name, deleted below file by listed file.
    if (exchange_folders(partial_, target_)) {
      committed_ = true;
      unregister_temporary(partial_);
      note_results_written(target_);
      if (!remove_listed(partial_, old_files))
        std::fprintf(stderr, "framedyn: warning: the earlier results were moved to %s and not all of it could be deleted\n", partial_.string().c_str());
      return;
    }
  }
  fs::path old;
  if (fs::exists(fs::symlink_status(target_, ec))) {
    // A file system without the atomic swap: the old folder aside, then the new one in.
    for (int attempt = 0;; ++attempt) {
      old = target_;
      old += ".old-" + std::to_string(::getpid()) + (attempt ? "-" + std::to_string(attempt) : std::string());
      if (!fs::exists(fs::symlink_status(old, ec))) break;
      if (attempt >= 1000) throw std::runtime_error("cannot find a free name to move old results " + target_.string() + " aside");
    }
    fs::rename(target_, old, ec);
    if (ec) throw std::runtime_error("cannot move old results " + target_.string() + " aside: " + ec.message());
  }
  fs::rename(partial_, target_, ec);
  if (ec) {
    const std::string why = ec.message();
    if (!old.empty()) fs::rename(old, target_, ec);
    throw std::runtime_error("cannot move results into " + target_.string() + ": " + why);
  }
  committed_ = true;
  unregister_temporary(partial_);
  note_results_written(target_);
  if (!old.empty() && !remove_listed(old, old_files))
    std::fprintf(stderr, "framedyn: warning: the earlier results were moved to %s and not all of it could be deleted\n", old.string().c_str());
}

}  // namespace framedyn::core
