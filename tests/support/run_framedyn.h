// Running the framedyn program from a test as a user would: in a folder of
// its own, capturing the exit status, stdout and stderr. Header-only: the
// program's path, FRAMEDYN_BINARY, is defined for each test executable
// (tests/CMakeLists.txt), not for the support library.
#pragma once

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/temp_dir.h"

namespace framedyn::testing {

inline std::string read_file(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// A shell word: 'text' (the paths of the tests have no quotes).
inline std::string quote(const std::string& s) { return "'" + s + "'"; }

struct RunResult {
  int status = -1;  // exit status, -1 if the program did not exit normally
  std::string out, err;
};

// Runs `framedyn ARGS` from `dir`, capturing stdout and stderr (in files
// that are removed again, so that the folder holds only what framedyn wrote).
inline RunResult framedyn(const TempDir& dir, const std::string& args) {
  const std::filesystem::path out = dir / "stdout.txt", err = dir / "stderr.txt";
  const std::string cmd = "cd " + quote(dir.path().string()) + " && " + quote(FRAMEDYN_BINARY) + " " + args + " >" + quote(out.string()) + " 2>" +
                          quote(err.string());
  const int rc = std::system(cmd.c_str());
  RunResult r;
  r.status = (rc != -1 && WIFEXITED(rc)) ? WEXITSTATUS(rc) : -1;
  r.out = read_file(out);
  r.err = read_file(err);
  std::filesystem::remove(out);
  std::filesystem::remove(err);
  return r;
}

// Names in `dir` that contain `part`.
inline std::vector<std::string> entries_containing(const std::filesystem::path& dir, const std::string& part) {
  std::vector<std::string> found;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    if (e.path().filename().string().find(part) != std::string::npos) found.push_back(e.path().filename().string());
  return found;
}

}  // namespace framedyn::testing
