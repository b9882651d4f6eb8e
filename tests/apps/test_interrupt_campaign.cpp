// Interrupts at many moments leave nothing behind (issue 14, item 2). The run
// is the straight-plowing pipeline (examples/straight_plowing.yaml, cut to
// 0.2 s) with --figures: 3-D machine, frame response, a ParaView series of
// 201 VTU files (paraview: vtu) and figures drawn by gnuplot children. It is interrupted 32
// times, with SIGINT and SIGTERM in turn, at moments spread over the run:
//   - 10 after a delay, from 0 to about the length of an uninterrupted run;
//   - 14 once the partial results folder holds k files (k spread from 1 to
//     the whole series), i.e. while the VTU series is written;
//   - 8 once a gnuplot child or a /tmp/framedyn_plot_* folder of the run
//     exists, i.e. while a figure is drawn.
// After each: the exit status is 128 + signal (or 0 if the run finished
// first); the results folder holds exactly the earlier results, byte for
// byte, or (exit 0, or a signal that came after the commit, which the
// message says) exactly a complete new set; no DIR.partial-* or DIR.old-*;
// no /tmp/framedyn_plot_<pid>_* of the run; no process left in the run's
// process group (the gnuplot children).
// A second campaign interrupts the XDMF series' one .h5 file while it grows.
// A third kills runs into existing results with SIGKILL, which nothing can
// catch, at random moments and at the commit: the results folder is there
// after every kill, holding the earlier run or the new one, whole.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "tests/support/temp_dir.h"

extern char** environ;

namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;

const std::string kBinary = FRAMEDYN_BINARY;
const fs::path kSource = FRAMEDYN_SOURCE_DIR;

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Every file below `folder` (relative path -> content).
std::map<std::string, std::string> contents(const fs::path& folder) {
  std::map<std::string, std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(folder))
    if (!e.is_directory()) files[fs::relative(e.path(), folder).generic_string()] = read_text(e.path());
  return files;
}

std::set<std::string> names(const fs::path& folder) {
  std::set<std::string> n;
  for (const auto& e : fs::recursive_directory_iterator(folder))
    if (!e.is_directory()) n.insert(fs::relative(e.path(), folder).generic_string());
  return n;
}

std::size_t count_files(const fs::path& folder) {
  std::error_code ec;
  std::size_t n = 0;
  for (auto it = fs::directory_iterator(folder, ec); !ec && it != fs::directory_iterator(); it.increment(ec)) ++n;
  return n;
}

std::vector<fs::path> entries_containing(const fs::path& dir, const std::string& part) {
  std::vector<fs::path> found;
  std::error_code ec;
  for (auto it = fs::directory_iterator(dir, ec); !ec && it != fs::directory_iterator(); it.increment(ec))
    if (it->path().filename().string().find(part) != std::string::npos) found.push_back(it->path());
  return found;
}

// The study, shortened, with its mesh found from the test's folder.
std::string study_text(bool xdmf = false) {
  std::string s = read_text(kSource / "examples" / "straight_plowing.yaml");
  auto replace = [&s](const std::string& from, const std::string& to) {
    const std::size_t at = s.find(from);
    if (at == std::string::npos) throw std::runtime_error("examples/straight_plowing.yaml has no '" + from + "'");
    s.replace(at, from.size(), to);
  };
  replace("duration: 20.0", "duration: 0.2");
  if (!xdmf) replace("paraview: xdmf", "paraview: vtu");  // the series as many files: many moments to interrupt at
  replace("mesh: ../meshes/r100_frame.inp", "mesh: " + (kSource / "meshes" / "r100_frame.inp").string());
  return s;
}

// Starts `framedyn run study.yaml --figures --out results -q` in `dir`, in a
// process group of its own (so that its children can be found afterwards).
pid_t start_run(const fs::path& dir, bool figures = true) {
  std::vector<std::string> all = {kBinary, "run", "study.yaml", "--out", "results", "-q"};
  if (figures) all.push_back("--figures");
  std::vector<char*> argv;
  for (std::string& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, (dir / "stderr.txt").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  posix_spawnattr_setpgroup(&attributes, 0);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP);
  const fs::path here = fs::current_path();
  fs::current_path(dir);
  pid_t pid = 0;
  const int rc = posix_spawn(&pid, kBinary.c_str(), &actions, &attributes, argv.data(), environ);
  fs::current_path(here);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  if (rc != 0) throw std::runtime_error("cannot start " + kBinary);
  return pid;
}

bool signals_blocked(pid_t pid) {
  std::ifstream status("/proc/" + std::to_string(pid) + "/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind("SigBlk:", 0) == 0) return (std::stoull(line.substr(7), nullptr, 16) & (1ULL << (SIGINT - 1))) != 0;
  return false;
}

// True if a process other than `pid` is in the process group `pid`.
bool has_child_in_group(pid_t pid) {
  for (const auto& e : fs::directory_iterator("/proc")) {
    const std::string name = e.path().filename().string();
    if (name.find_first_not_of("0123456789") != std::string::npos || std::stoi(name) == pid) continue;
    const std::string stat = read_text(e.path() / "stat");
    const std::size_t close = stat.rfind(')');
    if (close == std::string::npos) continue;
    std::istringstream rest(stat.substr(close + 2));
    std::string state;
    long ppid = 0, pgrp = 0;
    rest >> state >> ppid >> pgrp;
    if (pgrp == pid) return true;
  }
  return false;
}

std::uintmax_t size_of(const fs::path& p) {
  std::error_code ec;
  const std::uintmax_t n = fs::file_size(p, ec);
  return ec ? 0 : n;
}

// Returns the exit status (or -signal) once the run has ended, or -1000 if it
// is still running.
int poll_exit(pid_t pid) {
  int raw = 0;
  if (::waitpid(pid, &raw, WNOHANG) != pid) return -1000;
  return WIFEXITED(raw) ? WEXITSTATUS(raw) : -WTERMSIG(raw);
}

struct Trigger {
  enum Kind { delay, files, figure } kind;
  double seconds = 0;      // delay
  std::size_t count = 0;   // files in the partial folder
};

class InterruptCampaign : public ::testing::Test {
 protected:
  framedyn::testing::TempDir dir_{"framedyn_test_interrupt_campaign"};
};

TEST_F(InterruptCampaign, ThirtyTwoInterruptsLeaveEarlierResultsOrCompleteNewOnesAndNoLitter) {
  dir_.write("study.yaml", study_text());
  // The earlier results: an uninterrupted run, timed for the delays below.
  const auto start = Clock::now();
  const pid_t first = start_run(dir_.path());
  int status = -1000;
  while ((status = poll_exit(first)) == -1000) std::this_thread::sleep_for(1ms);
  const double run_seconds = std::chrono::duration<double>(Clock::now() - start).count();
  ASSERT_EQ(status, 0) << read_text(dir_ / "stderr.txt");
  const fs::path results = dir_ / "results";
  const std::map<std::string, std::string> earlier = contents(results);
  const std::set<std::string> all_names = names(results);
  ASSERT_TRUE(all_names.count(".framedyn-manifest"));
  ASSERT_TRUE(all_names.count("frame_response_00200.vtu"));
  ASSERT_TRUE(all_names.count("fig25_rail_bending_moment.png"));
  ASSERT_TRUE(all_names.count("frame_mode_shapes.png"));
  ASSERT_TRUE(all_names.count("frame_hot_spots.png"));
  const std::size_t total_files = all_names.size();

  std::vector<Trigger> triggers;
  for (int i = 0; i < 10; ++i) triggers.push_back({Trigger::delay, run_seconds * (i + 0.5) / 10.0, 0});
  for (int i = 0; i < 14; ++i) triggers.push_back({Trigger::files, 0, 1 + i * (total_files - 2) / 13});
  for (int i = 0; i < 8; ++i) triggers.push_back({Trigger::figure, 0, static_cast<std::size_t>(i)});

  int interrupted = 0, finished = 0, after_commit = 0;
  for (std::size_t t = 0; t < triggers.size(); ++t) {
    const int sig = t % 2 == 0 ? SIGINT : SIGTERM;
    const Trigger& trigger = triggers[t];
    SCOPED_TRACE("interrupt " + std::to_string(t + 1) + (sig == SIGINT ? " SIGINT" : " SIGTERM") +
                 (trigger.kind == Trigger::delay ? " after " + std::to_string(trigger.seconds) + " s"
                  : trigger.kind == Trigger::files ? " at " + std::to_string(trigger.count) + " files written"
                                                    : " while figure " + std::to_string(trigger.count + 1) + " is drawn"));
    const pid_t pid = start_run(dir_.path());
    while (!signals_blocked(pid) && (status = poll_exit(pid)) == -1000) std::this_thread::sleep_for(200us);
    const auto begin = Clock::now();
    const std::string plot_prefix = "framedyn_plot_" + std::to_string(pid) + "_";
    int figures_seen = 0;
    bool in_figure = false;
    status = -1000;
    for (;;) {
      if ((status = poll_exit(pid)) != -1000) break;  // finished before the moment came
      bool now = false;
      if (trigger.kind == Trigger::delay) {
        now = std::chrono::duration<double>(Clock::now() - begin).count() >= trigger.seconds;
      } else if (trigger.kind == Trigger::files) {
        const std::vector<fs::path> partial = entries_containing(dir_.path(), "results.partial-");
        now = !partial.empty() && count_files(partial.front()) >= trigger.count;
      } else {
        const bool drawing = !entries_containing(fs::temp_directory_path(), plot_prefix).empty() || has_child_in_group(pid);
        if (drawing && !in_figure) ++figures_seen;
        in_figure = drawing;
        now = drawing && figures_seen > static_cast<int>(trigger.count);
      }
      if (now) {
        ::kill(pid, sig);
        while ((status = poll_exit(pid)) == -1000) std::this_thread::sleep_for(1ms);
        break;
      }
      std::this_thread::sleep_for(trigger.kind == Trigger::figure ? 200us : 1ms);
    }
    const std::string err = read_text(dir_ / "stderr.txt");
    if (status == 0) {
      ++finished;
    } else {
      EXPECT_EQ(status, 128 + sig) << err;
      ++interrupted;
    }
    const bool kept_new = status != 0 && err.find("were complete (they are kept)") != std::string::npos;
    after_commit += kept_new;
    if (status == 0 || kept_new) {
      // A complete new set: the same files as the earlier run, listed in its manifest.
      EXPECT_EQ(names(results), all_names);
    } else {
      EXPECT_NE(err.find("no results written (earlier results left as they were)"), std::string::npos) << err;
      EXPECT_TRUE(contents(results) == earlier) << "the earlier results changed";
    }
    EXPECT_TRUE(entries_containing(dir_.path(), ".partial-").empty());
    EXPECT_TRUE(entries_containing(dir_.path(), ".old-").empty());
    const std::vector<fs::path> litter = entries_containing(fs::temp_directory_path(), plot_prefix);
    EXPECT_TRUE(litter.empty()) << litter.front();
    const bool orphans = has_child_in_group(pid);
    EXPECT_FALSE(orphans) << "a child of the run (gnuplot) is still alive";
    if (orphans) ::kill(-pid, SIGKILL);
    for (const fs::path& p : litter) fs::remove_all(p);
    if (status == 0 || kept_new) {  // back to the earlier results for the next interrupt
      fs::remove_all(results);
      for (const auto& [name, text] : earlier) dir_.write("results/" + name, text);
    }
  }
  std::printf("[ campaign ] uninterrupted run %.2f s; %d interrupted (%d after the commit), %d finished first\n", run_seconds, interrupted,
              after_commit, finished);
  EXPECT_GE(interrupted, 16) << "most moments fall inside the run (the file and figure moments always do)";
}


// The XDMF series (paraview: xdmf, the default) is one .h5 that grows by one
// time step at a time, then one .xdmf: interrupts while the .h5 is being
// written (at 12 sizes spread from its first bytes to its full size) leave the
// earlier results byte for byte and no partial folder, as for the VTU series.
TEST_F(InterruptCampaign, InterruptsWhileTheHdf5FileGrowsLeaveEarlierResultsAndNoHalfWrittenFile) {
  dir_.write("study.yaml", study_text(true));
  const pid_t first = start_run(dir_.path(), false);
  int status = -1000;
  while ((status = poll_exit(first)) == -1000) std::this_thread::sleep_for(1ms);
  ASSERT_EQ(status, 0) << read_text(dir_ / "stderr.txt");
  const fs::path results = dir_ / "results";
  const std::map<std::string, std::string> earlier = contents(results);
  const std::set<std::string> all_names = names(results);
  ASSERT_TRUE(all_names.count("frame_response.h5"));
  ASSERT_TRUE(all_names.count("frame_response.xdmf"));
  const std::uintmax_t full = size_of(results / "frame_response.h5");
  ASSERT_GT(full, 0u);

  int interrupted = 0, finished = 0;
  for (int t = 0; t < 12; ++t) {
    const int sig = t % 2 == 0 ? SIGINT : SIGTERM;
    const std::uintmax_t at = 1 + full * t / 12;  // the .h5 in the partial folder has reached this size
    SCOPED_TRACE("interrupt " + std::to_string(t + 1) + " at " + std::to_string(at) + " bytes of " + std::to_string(full));
    const pid_t pid = start_run(dir_.path(), false);
    while (!signals_blocked(pid) && (status = poll_exit(pid)) == -1000) std::this_thread::sleep_for(200us);
    for (;;) {
      if ((status = poll_exit(pid)) != -1000) break;
      const std::vector<fs::path> partial = entries_containing(dir_.path(), "results.partial-");
      if (!partial.empty() && size_of(partial.front() / "frame_response.h5") >= at) {
        ::kill(pid, sig);
        while ((status = poll_exit(pid)) == -1000) std::this_thread::sleep_for(1ms);
        break;
      }
      std::this_thread::sleep_for(100us);
    }
    const std::string err = read_text(dir_ / "stderr.txt");
    const bool kept_new = status != 0 && err.find("were complete (they are kept)") != std::string::npos;
    if (status == 0 || kept_new) {
      ++finished;
      EXPECT_EQ(names(results), all_names);
      fs::remove_all(results);
      for (const auto& [name, text] : earlier) dir_.write("results/" + name, text);
    } else {
      ++interrupted;
      EXPECT_EQ(status, 128 + sig) << err;
      EXPECT_NE(err.find("no results written (earlier results left as they were)"), std::string::npos) << err;
      EXPECT_TRUE(contents(results) == earlier) << "the earlier results changed";
    }
    EXPECT_TRUE(entries_containing(dir_.path(), ".partial-").empty());
    EXPECT_TRUE(entries_containing(dir_.path(), ".old-").empty());
  }
  std::printf("[ campaign ] .h5 of %ju bytes; %d interrupted while it grew, %d finished first\n", full, interrupted, finished);
  EXPECT_GE(interrupted, 6) << "the .h5 grows over most of the writing: most of these moments fall inside it";
}

// SIGKILL (no clean-up can run) at 18 moments of runs into existing results
// (the VTU series: 200 files, so the swap's old folder takes a while to delete):
//   - 6 at random delays over the length of an uninterrupted run (seeded);
//   - 6 once the new folder's manifest exists (the commit has begun: the swap is next);
//   - 6 once `results` is another folder (just after the swap, while the old one is deleted).
// After each kill `results` exists and holds either the earlier results or the
// new run, whole: byte for byte the files of an uninterrupted run (the same study
// gives the same files); its inode says which; no `results.old-*` (the swap is one step); a
// `results.partial-<pid>` may be left (SIGKILL). At the end a plain re-run into
// `results` succeeds beside that litter.
TEST_F(InterruptCampaign, SigkillAtAnyMomentLeavesTheEarlierOrTheNewResultsWhole) {
  dir_.write("study.yaml", study_text());
  const auto start = Clock::now();
  const pid_t first = start_run(dir_.path(), false);
  int status = -1000;
  while ((status = poll_exit(first)) == -1000) std::this_thread::sleep_for(1ms);
  const double run_seconds = std::chrono::duration<double>(Clock::now() - start).count();
  ASSERT_EQ(status, 0) << read_text(dir_ / "stderr.txt");
  const fs::path results = dir_ / "results";
  const std::map<std::string, std::string> whole = contents(results);
  const std::set<std::string> all_names = names(results);
  ASSERT_TRUE(all_names.count("frame_response_00200.vtu"));
  const auto inode = [&results]() -> long long {
    struct stat st {};
    return ::stat(results.c_str(), &st) == 0 ? static_cast<long long>(st.st_ino) : -1;
  };
  std::mt19937 random(20261204);
  std::uniform_real_distribution<double> moment(0.0, run_seconds);
  int kept_old = 0, kept_new = 0, finished = 0;
  for (int t = 0; t < 18; ++t) {
    const int kind = t % 3;  // 0 random delay, 1 commit begun, 2 just swapped
    const double delay = moment(random);
    SCOPED_TRACE("kill " + std::to_string(t + 1) + (kind == 0 ? " after " + std::to_string(delay) + " s" : kind == 1 ? " at the commit" : " after the swap"));
    const long long before = inode();
    ASSERT_GE(before, 0);
    const pid_t pid = start_run(dir_.path(), false);
    const auto begin = Clock::now();
    for (;;) {
      if ((status = poll_exit(pid)) != -1000) break;  // finished before the moment came
      bool now = false;
      if (kind == 0) {
        now = std::chrono::duration<double>(Clock::now() - begin).count() >= delay;
      } else if (kind == 1) {
        std::error_code ec;
        now = fs::exists(dir_ / ("results.partial-" + std::to_string(pid)) / ".framedyn-manifest", ec);
      } else {
        now = inode() != before;
      }
      if (now) {
        ::kill(pid, SIGKILL);
        while ((status = poll_exit(pid)) == -1000) std::this_thread::sleep_for(1ms);
        break;
      }
      std::this_thread::sleep_for(kind == 0 ? 1ms : 50us);
    }
    ASSERT_TRUE(fs::is_directory(results)) << "the results folder is absent after the kill";
    if (status == 0) {
      ++finished;
    } else {
      EXPECT_EQ(status, -SIGKILL);
    }
    // The same study gives the same files byte for byte (same input, same output), so the
    // earlier results and a new run's are both exactly `whole`; which one is there, the
    // folder's inode tells (the swap puts another folder at the path).
    EXPECT_TRUE(contents(results) == whole) << "the results folder is not a whole run";
    if (inode() == before) ++kept_old;
    else ++kept_new;
    EXPECT_TRUE(entries_containing(dir_.path(), ".old-").empty());
  }
  const std::size_t litter = entries_containing(dir_.path(), "results.partial-").size();
  // The way on after any of them: run again into the same folder.
  const pid_t again = start_run(dir_.path(), false);
  while ((status = poll_exit(again)) == -1000) std::this_thread::sleep_for(1ms);
  EXPECT_EQ(status, 0) << read_text(dir_ / "stderr.txt");
  EXPECT_TRUE(contents(results) == whole);
  std::printf("[ campaign ] SIGKILL 18 times (run %.2f s): %d left the earlier results, %d the new ones whole, %d finished first; "
              "%zu partial folders left by the kills; results never absent\n",
              run_seconds, kept_old, kept_new, finished, litter);
  EXPECT_GE(kept_old, 1);
  EXPECT_GE(kept_new, 1);
}

}  // namespace
