// CalculiX (ccx) as a peer code for tests and benchmarks: writes a one-step
// deck around the caller's model, runs ccx in a child process (fork/exec,
// wall time and peak RSS from wait4) and parses the .dat file.
// See calculix.h for the interface and docs/calculix_peer.md for what the
// results mean.

#include "calculix.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <system_error>

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

namespace framedyn::testing {

namespace {

namespace fs = std::filesystem;

constexpr const char* kJobName = "job";
constexpr const char* kLogName = "ccx.log";
constexpr const char* kOutputSet = "FRAMEDYN_PEER_OUT";
// Longest file name CalculiX 2.20 accepts after INPUT= (longer ones stop it
// with "file name too long").
constexpr std::size_t kMaxIncludeName = 132;
// Lines of the log quoted in error messages.
constexpr std::size_t kLogMessageLines = 30;
constexpr std::size_t kLogTailLines = 12;

std::string find_ccx() {
  const char* path = std::getenv("PATH");
  if (path == nullptr) return {};
  std::stringstream dirs(path);
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    if (dir.empty()) dir = ".";
    const std::string candidate = dir + "/ccx";
    std::error_code ec;
    if (::access(candidate.c_str(), X_OK) == 0 && !fs::is_directory(candidate, ec)) {
      return candidate;
    }
  }
  return {};
}

std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return {};
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// The *ERROR and *WARNING messages of the log (each with the two lines that
// continue it), then its last lines.
std::string log_excerpt(const fs::path& log_path) {
  std::ifstream in(log_path);
  if (!in) return "(no log file " + log_path.string() + ")\n";
  std::vector<std::string> messages;
  std::deque<std::string> tail;
  std::string line;
  int continuation = 0;
  while (std::getline(in, line)) {
    const bool message = line.find("*ERROR") != std::string::npos ||
                         line.find("*WARNING") != std::string::npos;
    if (message) continuation = 3;
    if (continuation > 0 && messages.size() < kLogMessageLines) {
      messages.push_back(line);
      --continuation;
    }
    // Skip blank lines and the progress chatter that ccx repeats per mode.
    if (line.find("for the stress calculation") != std::string::npos ||
        line.find_first_not_of(' ') == std::string::npos) {
      continue;
    }
    tail.push_back(line);
    if (tail.size() > kLogTailLines) tail.pop_front();
  }
  std::string text;
  if (!messages.empty()) {
    text += "--- messages in " + log_path.string() + " ---\n";
    for (const auto& l : messages) text += l + "\n";
  }
  text += "--- last lines of " + log_path.string() + " ---\n";
  for (const auto& l : tail) text += l + "\n";
  return text;
}

[[noreturn]] void fail(const std::string& what, const fs::path& workdir) {
  throw std::runtime_error("CalculiX peer run in " + workdir.string() + ": " + what + "\n" +
                           log_excerpt(workdir / kLogName));
}

// Parses one number as ccx prints it. Fortran drops the 'E' when the exponent
// has three digits ("1.234567-100"); accept that and 'D' exponents too.
bool parse_number(std::string token, double& value) {
  for (char& c : token) {
    if (c == 'D' || c == 'd') c = 'E';
  }
  for (std::size_t i = 1; i < token.size(); ++i) {
    const char c = token[i];
    const char before = token[i - 1];
    if ((c == '+' || c == '-') && before != 'E' && before != 'e') {
      token.insert(i, 1, 'E');
      break;
    }
  }
  const char* begin = token.c_str();
  char* end = nullptr;
  errno = 0;
  value = std::strtod(begin, &end);
  // Underflow (a denormal such as 1.0-320) is fine; overflow is not.
  const bool overflow = errno == ERANGE && std::abs(value) > 1.0;
  return end != begin && *end == '\0' && !overflow;
}

std::vector<std::string> split_ws(const std::string& line) {
  std::vector<std::string> tokens;
  std::istringstream in(line);
  std::string t;
  while (in >> t) tokens.push_back(t);
  return tokens;
}

bool parse_int(const std::string& token, int& value) {
  const char* begin = token.c_str();
  char* end = nullptr;
  errno = 0;
  const long v = std::strtol(begin, &end, 10);
  if (end == begin || *end != '\0' || errno == ERANGE) return false;
  value = static_cast<int>(v);
  return true;
}

// The INPUT= text for the model. ccx removes blanks from keyword lines, splits
// parameters at commas and rejects long names, so a path with any of these is
// reached through a symbolic link in the working directory instead.
std::string include_name(const fs::path& model, const fs::path& workdir) {
  const std::string text = model.string();
  const bool usable = text.size() <= kMaxIncludeName &&
                      text.find_first_of(" \t,") == std::string::npos;
  if (usable) return text;
  const fs::path link = workdir / "framedyn_peer_model.inp";
  std::error_code ec;
  if (!fs::equivalent(link, model, ec)) {
    fs::remove(link, ec);
    fs::create_symlink(model, link, ec);
    if (ec) {
      throw std::runtime_error("CalculiX peer: cannot link " + link.string() + " to " + text +
                               ": " + ec.message());
    }
  }
  return link.filename().string();
}

// Checks the inputs, creates the working directory and writes job.inp.
// `step` is the text between *STEP and *END STEP; `model_extra` goes between
// the *INCLUDE and *STEP (model data such as an output node set).
fs::path write_deck(const std::string& model_inp_path, const std::string& workdir_text,
                    const std::string& model_extra, const std::string& step,
                    const std::string& step_keyword = "*STEP") {
  if (!fs::is_regular_file(model_inp_path)) {
    throw std::invalid_argument("CalculiX peer: model file '" + model_inp_path +
                                "' does not exist or is not a regular file");
  }
  const fs::path model = fs::absolute(model_inp_path).lexically_normal();
  const fs::path workdir = fs::absolute(workdir_text).lexically_normal();
  fs::create_directories(workdir);
  // A failed run must not leave an older job.dat to be read as its result.
  for (const char* ext : {".dat", ".frd", ".sta", ".cvg", ".12d"}) {
    std::error_code ec;
    fs::remove(workdir / (std::string(kJobName) + ext), ec);
  }
  std::ofstream deck(workdir / (std::string(kJobName) + ".inp"));
  deck << "** framedyn peer run, written by tests/support/calculix.cpp\n"
       << "*INCLUDE, INPUT=" << include_name(model, workdir) << "\n"
       << model_extra << step_keyword << "\n"
       << step << "*END STEP\n";
  deck.close();
  if (!deck) throw std::runtime_error("CalculiX peer: cannot write job.inp in " + workdir.string());
  return workdir;
}

// Runs `ccx -i job` in workdir with stdout and stderr going to the log, and
// fills the timing fields. Throws if ccx is missing, dies, exits non-zero or
// reports an *ERROR (some input errors end with exit status 0).
void run_ccx(const fs::path& workdir, CalculixResult& result) {
  const std::string ccx = find_ccx();
  if (ccx.empty()) throw std::runtime_error("CalculiX peer: no 'ccx' executable on PATH");

  // Everything the child needs is prepared before fork: after fork only
  // async-signal-safe calls are allowed (the test process may be threaded).
  const std::string dir = workdir.string();
  const std::string log = (workdir / kLogName).string();
  const char* const argv[] = {"ccx", "-i", kJobName, nullptr};

  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = ::fork();
  if (pid < 0) {
    throw std::runtime_error(std::string("CalculiX peer: fork failed: ") + std::strerror(errno));
  }
  if (pid == 0) {
    if (::chdir(dir.c_str()) != 0) ::_exit(126);
    const int out = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int in = ::open("/dev/null", O_RDONLY);
    if (out < 0 || in < 0) ::_exit(126);
    ::dup2(in, STDIN_FILENO);
    ::dup2(out, STDOUT_FILENO);
    ::dup2(out, STDERR_FILENO);
    ::execv(ccx.c_str(), const_cast<char* const*>(argv));
    static const char msg[] = "exec of ccx failed\n";
    ssize_t ignored = ::write(STDERR_FILENO, msg, sizeof msg - 1);
    (void)ignored;
    ::_exit(127);
  }

  int status = 0;
  struct rusage usage {};
  pid_t waited;
  do {
    waited = ::wait4(pid, &status, 0, &usage);
  } while (waited < 0 && errno == EINTR);
  const auto stop = std::chrono::steady_clock::now();
  if (waited < 0) {
    throw std::runtime_error(std::string("CalculiX peer: wait4 failed: ") + std::strerror(errno));
  }
  result.wall_seconds = std::chrono::duration<double>(stop - start).count();
  result.peak_rss_kib = usage.ru_maxrss;  // Linux reports KiB

  if (WIFSIGNALED(status)) {
    fail("ccx was killed by signal " + std::to_string(WTERMSIG(status)), workdir);
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    fail("ccx exited with status " + std::to_string(WEXITSTATUS(status)), workdir);
  }
  const std::string log_text = read_file(log);
  if (log_text.find("*ERROR") != std::string::npos) {
    fail("ccx reported an *ERROR (exit status was 0)", workdir);
  }
  result.dat_text = read_file(workdir / (std::string(kJobName) + ".dat"));
}

// Reads the eigenvalue table. Rows are
//   mode  eigenvalue  omega(rad/time)  f(cycles/time)  imaginary(rad/time)
// Returns (eigenvalue, frequency) pairs; empty if the table is missing.
std::vector<std::pair<double, double>> parse_eigenvalues(const std::string& dat) {
  std::vector<std::pair<double, double>> rows;
  const std::size_t header = dat.find("E I G E N V A L U E   O U T P U T");
  if (header == std::string::npos) return rows;
  std::istringstream in(dat.substr(header));
  std::string line;
  std::getline(in, line);  // the title itself
  while (std::getline(in, line)) {
    const auto t = split_ws(line);
    if (t.empty()) {
      if (!rows.empty()) break;
      continue;
    }
    int mode = 0;
    double lambda = 0.0, omega = 0.0, freq = 0.0, imag = 0.0;
    const bool is_row = t.size() == 5 && parse_int(t[0], mode) && parse_number(t[1], lambda) &&
                        parse_number(t[2], omega) && parse_number(t[3], freq) &&
                        parse_number(t[4], imag);
    if (is_row) {
      rows.emplace_back(lambda, freq);
    } else if (!rows.empty()) {
      break;  // first line after the table
    }
    // Before the first row: column headings, skipped.
  }
  return rows;
}

// Reads every "displacements (vx,vy,vz) for set <set>" block; a later block
// (a later increment) overwrites an earlier one.
std::map<int, std::array<double, 3>> parse_displacements(const std::string& dat,
                                                         const std::string& set) {
  std::map<int, std::array<double, 3>> u;
  const std::string title = "displacements (vx,vy,vz) for set " + set + " ";
  std::istringstream in(dat);
  std::string line;
  bool in_block = false;
  bool seen_row = false;
  while (std::getline(in, line)) {
    if (line.find(title) != std::string::npos) {
      in_block = true;
      seen_row = false;
      continue;
    }
    if (!in_block) continue;
    const auto t = split_ws(line);
    if (t.empty()) {
      if (seen_row) in_block = false;
      continue;
    }
    int node = 0;
    std::array<double, 3> v{};
    if (t.size() == 4 && parse_int(t[0], node) && parse_number(t[1], v[0]) &&
        parse_number(t[2], v[1]) && parse_number(t[3], v[2])) {
      u[node] = v;
      seen_row = true;
    } else {
      in_block = false;
    }
  }
  return u;
}

// Every "displacements (vx,vy,vz) for set <set>" block, in the order of the
// file (one per increment; a linear static step has one).
std::vector<std::map<int, std::array<double, 3>>> parse_displacement_blocks(const std::string& dat, const std::string& set) {
  std::vector<std::map<int, std::array<double, 3>>> blocks;
  const std::string title = "displacements (vx,vy,vz) for set " + set + " ";
  std::size_t at = dat.find(title);
  while (at != std::string::npos) {
    const std::size_t next = dat.find(title, at + title.size());
    blocks.push_back(parse_displacements(dat.substr(at, next == std::string::npos ? std::string::npos : next - at), set));
    at = next;
  }
  return blocks;
}

// Every "displacements (vx,vy,vz) for set <set> and time <t>" block of a
// transient step, in the order of the file, with its time.
std::pair<std::vector<double>, std::vector<std::map<int, std::array<double, 3>>>> parse_displacement_history(const std::string& dat,
                                                                                                          const std::string& set) {
  std::pair<std::vector<double>, std::vector<std::map<int, std::array<double, 3>>>> history;
  const std::string title = "displacements (vx,vy,vz) for set " + set + " and time";
  std::size_t at = dat.find(title);
  while (at != std::string::npos) {
    const std::size_t next = dat.find(title, at + title.size());
    const std::size_t eol = dat.find('\n', at);
    const auto words = split_ws(dat.substr(at + title.size(), eol - at - title.size()));
    double time = 0.0;
    if (words.size() != 1 || !parse_number(words[0], time)) break;
    history.first.push_back(time);
    history.second.push_back(parse_displacements(dat.substr(at, next == std::string::npos ? std::string::npos : next - at), set));
    at = next;
  }
  return history;
}

}  // namespace

bool calculix_available() { return !find_ccx().empty(); }

CalculixResult run_calculix_frequency(const std::string& model_inp_path, int n_modes,
                                      const std::string& workdir) {
  if (n_modes < 1) {
    throw std::invalid_argument("CalculiX peer: n_modes must be at least 1, got " +
                                std::to_string(n_modes));
  }
  const fs::path dir = write_deck(model_inp_path, workdir, "",
                                  "*FREQUENCY\n" + std::to_string(n_modes) + "\n");
  CalculixResult result;
  run_ccx(dir, result);

  const auto rows = parse_eigenvalues(result.dat_text);
  if (rows.empty()) fail("no eigenvalue table in job.dat", dir);
  if (rows.size() != static_cast<std::size_t>(n_modes)) {
    fail("asked for " + std::to_string(n_modes) + " modes, job.dat lists " +
             std::to_string(rows.size()),
         dir);
  }
  // Rigid-body modes come out as eigenvalues of about 1e-12 of the largest,
  // either sign. CalculiX 2.20 (ARPACK with 5 * n_modes Lanczos vectors) can
  // instead return large negative eigenvalues, with further spurious positive
  // ones among the true modes, when n_modes is large for a small model.
  double largest = 0.0;
  for (const auto& r : rows) largest = std::max(largest, std::abs(r.first));
  for (const auto& r : rows) {
    if (r.first < -1e-6 * largest) {
      fail("spurious negative eigenvalue " + std::to_string(r.first) +
               " among the " + std::to_string(n_modes) +
               " requested modes; the model has too few mass-carrying degrees of freedom "
               "for this many modes (ask for fewer)",
           dir);
    }
  }
  result.frequencies_hz.reserve(rows.size());
  for (const auto& r : rows) result.frequencies_hz.push_back(r.second);
  return result;
}

CalculixResult run_calculix_static(const std::string& model_inp_path,
                                   const std::string& load_lines,
                                   const std::vector<int>& node_ids,
                                   const std::string& workdir) {
  // Own node set rather than NSET=NALL: CalculiX defines no NALL (it warns
  // and prints nothing), and user sets are resolved before the beams are
  // expanded, so the set holds exactly the caller's nodes.
  const std::set<int> wanted(node_ids.begin(), node_ids.end());
  std::string set_text;
  std::string output_text;
  if (!wanted.empty()) {
    set_text = std::string("*NSET, NSET=") + kOutputSet + "\n";
    int on_line = 0;
    for (int id : wanted) {
      set_text += (on_line == 0 ? "" : ", ") + std::to_string(id);
      if (++on_line == 8) {
        set_text += "\n";
        on_line = 0;
      }
    }
    if (on_line != 0) set_text += "\n";
    output_text = std::string("*NODE PRINT, NSET=") + kOutputSet + "\nU\n";
  }
  std::string loads = load_lines;
  if (!loads.empty() && loads.back() != '\n') loads += '\n';

  const fs::path dir =
      write_deck(model_inp_path, workdir, set_text, "*STATIC\n" + loads + output_text);
  CalculixResult result;
  run_ccx(dir, result);
  if (wanted.empty()) return result;

  auto all = parse_displacements(result.dat_text, kOutputSet);
  if (all.empty()) fail("no displacement table for set " + std::string(kOutputSet), dir);
  for (int id : wanted) {
    const auto it = all.find(id);
    if (it == all.end()) {
      fail("node " + std::to_string(id) + " is missing from the displacement output "
               "(is it a node of the model?)",
           dir);
    }
    result.displacements.emplace(id, it->second);
  }
  return result;
}

std::vector<std::map<int, std::array<double, 3>>> run_calculix_static_steps(const std::string& model_inp_path,
                                                                            const std::vector<std::string>& step_bodies,
                                                                            const std::vector<int>& node_ids,
                                                                            const std::string& workdir) {
  if (step_bodies.empty()) throw std::invalid_argument("CalculiX peer: no steps");
  std::string set_text = std::string("*NSET, NSET=") + kOutputSet + "\n";
  for (std::size_t i = 0; i < node_ids.size(); ++i) set_text += (i ? ", " : "") + std::to_string(node_ids[i]);
  set_text += "\n";
  const std::string output_text = std::string("*NODE PRINT, NSET=") + kOutputSet + "\nU\n";
  // write_deck wraps the text in one *STEP ... *END STEP: the steps between are closed and opened here.
  std::string steps;
  for (std::size_t k = 0; k < step_bodies.size(); ++k) {
    if (k > 0) steps += "*END STEP\n*STEP\n";
    steps += step_bodies[k];
    if (!steps.empty() && steps.back() != '\n') steps += '\n';
    steps += output_text;
  }
  const fs::path dir = write_deck(model_inp_path, workdir, set_text, steps);
  CalculixResult result;
  run_ccx(dir, result);
  auto blocks = parse_displacement_blocks(result.dat_text, kOutputSet);
  if (blocks.size() != step_bodies.size())
    fail("expected one displacement table per step (" + std::to_string(step_bodies.size()) + "), found " + std::to_string(blocks.size()), dir);
  for (const auto& b : blocks)
    for (int id : node_ids)
      if (!b.count(id)) fail("node " + std::to_string(id) + " is missing from a step's displacement output", dir);
  return blocks;
}

CalculixResult run_calculix_dynamic(const std::string& model_inp_path, const std::string& procedure_lines,
                                    const std::string& load_lines, const std::vector<int>& node_ids,
                                    const std::string& workdir) {
  if (node_ids.empty()) throw std::invalid_argument("CalculiX peer: no output nodes for the transient step");
  std::string set_text = std::string("*NSET, NSET=") + kOutputSet + "\n";
  for (std::size_t i = 0; i < node_ids.size(); ++i) set_text += (i ? ", " : "") + std::to_string(node_ids[i]);
  set_text += "\n";
  std::string step = procedure_lines;
  if (!step.empty() && step.back() != '\n') step += '\n';
  step += load_lines;
  if (!step.empty() && step.back() != '\n') step += '\n';
  step += std::string("*NODE PRINT, NSET=") + kOutputSet + "\nU\n";
  // INC: ccx stops a step after 100 increments by default ("max. # of
  // increments reached"); a fixed-increment (DIRECT) step needs period / increment.
  const fs::path dir = write_deck(model_inp_path, workdir, set_text, step, "*STEP, INC=1000000");
  CalculixResult result;
  run_ccx(dir, result);
  auto history = parse_displacement_history(result.dat_text, kOutputSet);
  if (history.first.empty()) fail("no displacement history for set " + std::string(kOutputSet), dir);
  for (const auto& b : history.second)
    for (int id : node_ids)
      if (!b.count(id)) fail("node " + std::to_string(id) + " is missing from an increment's displacement output", dir);
  result.history_times = std::move(history.first);
  result.history = std::move(history.second);
  return result;
}

}  // namespace framedyn::testing
