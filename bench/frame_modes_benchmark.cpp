// Benchmark: the lowest 10 and 50 modes of refined R-100-like frames from
// about 10^3 to 10^6 DOF, wall time and peak memory, with two baselines run
// in the same invocation on the same deck: CalculiX (ccx, the peer FE code)
// and framedyn with Eigen's SimplicialLDLT in place of CHOLMOD; and the cost
// of the Sturm-count certification (docs/theory/fem.md Eq. 7.3): framedyn
// with the check off, same deck, same run, as a ratio (--sturm-off-max-dofs).
//
// Each case runs in a child process (fork), so its peak resident memory is
// its own (wait4's ru_maxrss); framedyn's time covers reading the .inp,
// assembly, factorisation and the Lanczos iteration.
//
//   frame_modes_benchmark [--sizes 1e3,1e4,1e5,1e6] [--modes 10,50]
//                         [--calculix-max-dofs 1e5] [--ldlt-max-dofs 1e6]
//                         [--sturm-off-max-dofs 1e6] [--out DIR]
#include <fmt/format.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "fem/inp_reader.h"
#include "fem/modal_analysis.h"
#include "tests/support/calculix.h"
#include "tests/support/refined_frame.h"

namespace fs = std::filesystem;
using namespace framedyn;

namespace {

struct Measurement {
  bool ok = false;
  std::string note;
  double seconds = 0.0;
  double peak_mib = 0.0;
  std::vector<double> frequencies;
  double sturm_seconds = 0.0;  // the Sturm counts' share of `seconds`
  bool certified = false;
};

std::vector<double> parse_list(const std::string& s) {
  std::vector<double> v;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, ',')) v.push_back(std::stod(item));
  return v;
}

// Runs framedyn's modal analysis of `deck` in a child process.
Measurement run_framedyn(const std::string& deck, int modes, fem::Factorization factorization, bool certify = true) {
  int fd[2];
  if (pipe(fd) != 0) throw std::runtime_error("pipe failed");
  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = fork();
  if (pid == 0) {
    close(fd[0]);
    std::string out;
    try {
      const fem::FrameModel model = fem::read_inp(deck);
      fem::ModalOptions o;
      o.mode_count = modes;
      o.factorization = factorization;
      o.certify = certify;
      const fem::ModalResult r = fem::compute_modes(model, o);
      out += fmt::format("{:.6f} {}\n", r.sturm_seconds, r.certified ? 1 : 0);
      for (const fem::Mode& m : r.modes) out += fmt::format("{:.12g}\n", m.frequency_hz);
    } catch (const std::exception& e) {
      out = std::string("error: ") + e.what() + "\n";
    }
    if (write(fd[1], out.data(), out.size()) < 0) _exit(2);
    close(fd[1]);
    _exit(0);
  }
  close(fd[1]);
  std::string text;
  char buf[4096];
  ssize_t n;
  while ((n = read(fd[0], buf, sizeof buf)) > 0) text.append(buf, static_cast<std::size_t>(n));
  close(fd[0]);
  int status = 0;
  rusage ru{};
  wait4(pid, &status, 0, &ru);
  Measurement m;
  m.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  m.peak_mib = static_cast<double>(ru.ru_maxrss) / 1024.0;
  if (text.rfind("error:", 0) == 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    m.note = text.empty() ? "crashed" : text.substr(0, text.find('\n'));
    return m;
  }
  std::stringstream ss(text);
  int certified = 0;
  ss >> m.sturm_seconds >> certified;
  m.certified = certified != 0;
  double f;
  while (ss >> f) m.frequencies.push_back(f);
  m.ok = true;
  return m;
}

Measurement run_ccx(const std::string& deck, int modes, const fs::path& workdir) {
  Measurement m;
  try {
    const testing::CalculixResult r = testing::run_calculix_frequency(deck, modes, workdir.string());
    m.ok = true;
    m.seconds = r.wall_seconds;
    m.peak_mib = static_cast<double>(r.peak_rss_kib) / 1024.0;
    m.frequencies = r.frequencies_hz;
  } catch (const std::exception& e) {
    m.note = std::string(e.what()).substr(0, 120);
  }
  return m;
}

// Largest relative difference over the first `count` modes (both lists ascending).
double max_relative_difference(const std::vector<double>& a, const std::vector<double>& b, std::size_t count) {
  double worst = 0.0;
  for (std::size_t i = 0; i < std::min({a.size(), b.size(), count}); ++i)
    if (a[i] > 0.0) worst = std::max(worst, std::abs(b[i] - a[i]) / a[i]);
  return worst;
}

// Relative difference of each of framedyn's first `count` frequencies to the
// nearest CalculiX frequency. Finely subdivided B31 models grow spurious
// section-distortion modes in CalculiX (docs/calculix_peer.md); matching by
// nearest value rather than by index leaves those out of the comparison.
std::vector<double> nearest_match_differences(const std::vector<double>& framedyn, const std::vector<double>& calculix, std::size_t count) {
  std::vector<double> out;
  for (std::size_t i = 0; i < std::min(framedyn.size(), count); ++i) {
    if (!(framedyn[i] > 0.0) || calculix.empty()) continue;
    double best = 1e300;
    for (double c : calculix) best = std::min(best, std::abs(c - framedyn[i]) / framedyn[i]);
    out.push_back(best);
  }
  return out;
}

std::string median_and_max(std::vector<double> v) {
  if (v.empty()) return "-";
  std::sort(v.begin(), v.end());
  return fmt::format("{:.2f} % / {:.2f} %", 100 * v[v.size() / 2], 100 * v.back());
}

std::string cell(const Measurement& m) {
  if (!m.ok) return m.note.empty() ? "not run" : "failed";
  return fmt::format("{:.3g} s, {:.0f} MiB", m.seconds, m.peak_mib);
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<double> sizes = {1e3, 1e4, 1e5, 1e6};
  std::vector<double> mode_counts = {10, 50};
  double calculix_max = 1e5, ldlt_max = 1e6, sturm_off_max = 1e6;
  fs::path out = "bench_results";
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string k = argv[i], v = argv[i + 1];
    if (k == "--sizes") sizes = parse_list(v);
    else if (k == "--modes") mode_counts = parse_list(v);
    else if (k == "--calculix-max-dofs") calculix_max = std::stod(v);
    else if (k == "--ldlt-max-dofs") ldlt_max = std::stod(v);
    else if (k == "--sturm-off-max-dofs") sturm_off_max = std::stod(v);
    else if (k == "--out") out = v;
    else {
      std::cerr << "unknown option " << k << "\n";
      return 1;
    }
  }
  fs::create_directories(out);
  const fem::FrameModel base = fem::read_inp(std::string(FRAMEDYN_SOURCE_DIR) + "/meshes/r100_frame.inp");
  const bool have_ccx = testing::calculix_available();

  std::ofstream csv(out / "frame_modes_benchmark.csv");
  csv << "target_dofs,subdivisions,modes,code,ok,wall [s],peak_memory [MiB],f1 [Hz],f_last [Hz],max_rel_diff_vs_framedyn\n";
  fmt::print("| DOF | modes | framedyn (CHOLMOD) | of which Sturm counts | Sturm check off | on / off time | Eigen SimplicialLDLT | CalculiX | LDLT / CHOLMOD time | CalculiX / framedyn time | max freq. diff. LDLT | CalculiX nearest-match diff., first 10 modes (median / max) |\n");
  fmt::print("|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (double target : sizes) {
    const int k = testing::subdivisions_for(base, static_cast<long>(target));
    const fs::path deck = out / fmt::format("frame_{:.0e}.inp", target);
    {
      std::ofstream f(deck);
      f << testing::refined_frame_inp(base, k, "REAR_END");
    }
    const long dofs = 6L * (static_cast<long>(base.nodes.size()) + static_cast<long>(base.beams.size()) * (k - 1)) - 6L * 3;
    for (double mc : mode_counts) {
      const int modes = static_cast<int>(mc);
      const Measurement fd = run_framedyn(deck.string(), modes, fem::Factorization::cholmod);
      Measurement ld, cx, off;
      if (target <= sturm_off_max) off = run_framedyn(deck.string(), modes, fem::Factorization::cholmod, false);
      if (target <= ldlt_max) ld = run_framedyn(deck.string(), modes, fem::Factorization::eigen_simplicial_ldlt);
      if (have_ccx && target <= calculix_max) cx = run_ccx(fs::absolute(deck).string(), modes, out / fmt::format("ccx_{:.0e}_{}", target, modes));
      const std::string ld_ratio = (fd.ok && ld.ok) ? fmt::format("{:.2f}", ld.seconds / fd.seconds) : "-";
      const std::string cx_ratio = (fd.ok && cx.ok) ? fmt::format("{:.1f}", cx.seconds / fd.seconds) : "-";
      const std::string ld_diff = (fd.ok && ld.ok) ? fmt::format("{:.1e}", max_relative_difference(fd.frequencies, ld.frequencies, 1000)) : "-";
      const std::string cx_diff = (fd.ok && cx.ok) ? median_and_max(nearest_match_differences(fd.frequencies, cx.frequencies, 10)) : "-";
      const std::string sturm = fd.ok ? fmt::format("{:.3g} s{}", fd.sturm_seconds, fd.certified ? "" : " (not certified)") : "-";
      const std::string off_ratio = (fd.ok && off.ok) ? fmt::format("{:.2f}", fd.seconds / off.seconds) : "-";
      fmt::print("| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n", dofs, modes, cell(fd), sturm, cell(off), off_ratio, cell(ld),
                 cell(cx), ld_ratio, cx_ratio, ld_diff, cx_diff);
      std::cout.flush();
      for (const auto& [name, m] : {std::pair<std::string, const Measurement*>{"framedyn_cholmod", &fd}, {"framedyn_simplicial_ldlt", &ld}, {"framedyn_sturm_off", &off}, {"calculix", &cx}}) {
        csv << fmt::format("{:.0f},{},{},{},{},{:.4f},{:.1f},{},{},{}\n", target, k, modes, name, m->ok ? 1 : 0, m->seconds, m->peak_mib,
                           m->frequencies.empty() ? 0.0 : m->frequencies.front(), m->frequencies.empty() ? 0.0 : m->frequencies.back(),
                           (fd.ok && m->ok) ? max_relative_difference(fd.frequencies, m->frequencies, name == "calculix" ? 10 : 1000) : -1.0);
      }
      if (fd.ok && cx.ok) {
        std::ofstream pair(out / fmt::format("frequencies_{:.0e}_{}.csv", target, modes));
        pair << "mode,framedyn [Hz],calculix [Hz],ratio\n";
        for (std::size_t i = 0; i < std::min(fd.frequencies.size(), cx.frequencies.size()); ++i)
          pair << fmt::format("{},{:.8g},{:.8g},{:.6f}\n", i + 1, fd.frequencies[i], cx.frequencies[i], cx.frequencies[i] / fd.frequencies[i]);
      }
    }
  }
  return 0;
}
