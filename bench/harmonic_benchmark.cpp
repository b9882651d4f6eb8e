// Benchmark: the harmonic sweep of a refined R-100-like frame (about 10^4
// DOF) over 1,000 frequencies, `framedyn harmonic` against CalculiX 2.20's
// *FREQUENCY + *STEADY STATE DYNAMICS on the same deck and loads, as ratios
// in one run; and a peer check of the amplitudes (framedyn's library at
// CalculiX's own frequencies, the same modes and damping, no static
// correction, so that both compute the same modal series).
//
// Each code runs as a child process: wall time from fork to wait4, peak
// memory from wait4's ru_maxrss. framedyn's time covers reading the deck,
// assembly, the modes, the sweep and writing every output (no figures);
// CalculiX's its whole job (its .dat output of the output node).
//
// CalculiX needs a *CLOAD (zero) on the loaded beam nodes already in the
// *FREQUENCY step: without it the load of the later steady-state step does
// not reach the beam's expanded brick nodes as a force and the response is
// wrong by orders of magnitude (found here; docs/benchmarks.md).
//
//   harmonic_benchmark [--dofs 1e4] [--frequencies 1000] [--modes 20] [--zeta 0.02] [--node 11] [--out DIR]
#include <fmt/format.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#include <fcntl.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "fem/harmonic_response.h"
#include "fem/inp_reader.h"
#include "fem/modal_analysis.h"
#include "fem/static_analysis.h"
#include "tests/support/refined_frame.h"

namespace fs = std::filesystem;
using namespace framedyn;

namespace {

struct Run {
  int status = -1;
  double seconds = 0.0;
  double peak_mib = 0.0;
};

// Runs `argv` in `dir` with stdout and stderr into dir/log.
Run run_process(const std::vector<std::string>& argv, const fs::path& dir, const std::string& log) {
  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = fork();
  if (pid == 0) {
    if (chdir(dir.c_str()) != 0) _exit(126);
    const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0) {
      dup2(fd, 1);
      dup2(fd, 2);
    }
    std::vector<char*> args;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    execvp(args[0], args.data());
    _exit(127);
  }
  int status = 0;
  rusage ru{};
  wait4(pid, &status, 0, &ru);
  Run r;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.peak_mib = static_cast<double>(ru.ru_maxrss) / 1024.0;
  r.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

std::string read_text(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// CalculiX's steady-state output of one node: frequency -> (real, imaginary) displacement.
std::map<double, std::pair<Eigen::Vector3d, Eigen::Vector3d>> parse_steady_state(const std::string& dat, int node) {
  std::map<double, std::pair<Eigen::Vector3d, Eigen::Vector3d>> out;
  std::istringstream in(dat);
  std::string line;
  std::map<double, int> seen;
  while (std::getline(in, line)) {
    const std::size_t at = line.find("displacements (vx,vy,vz) for set");
    if (at == std::string::npos) continue;
    const double f = std::stod(line.substr(line.rfind("time") + 4));
    std::getline(in, line);  // blank
    std::getline(in, line);
    std::istringstream row(line);
    int id = 0;
    Eigen::Vector3d v;
    row >> id >> v.x() >> v.y() >> v.z();
    if (id != node) continue;
    if (seen[f]++ == 0) out[f].first = v;  // the real part comes first, then the imaginary part
    else out[f].second = v;
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  double target_dofs = 1e4, zeta = 0.02;
  int frequencies = 1000, modes = 20, node_id = 11;
  std::string out_dir = "harmonic_benchmark";
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto next = [&]() { return std::string(i + 1 < argc ? argv[++i] : ""); };
    if (a == "--dofs") target_dofs = std::stod(next());
    else if (a == "--frequencies") frequencies = std::stoi(next());
    else if (a == "--modes") modes = std::stoi(next());
    else if (a == "--zeta") zeta = std::stod(next());
    else if (a == "--node") node_id = std::stoi(next());
    else if (a == "--out") out_dir = next();
    else {
      std::cerr << "usage: harmonic_benchmark [--dofs 1e4] [--frequencies 1000] [--modes 20] [--zeta 0.02] [--node 11] [--out DIR]\n";
      return 2;
    }
  }
  const fs::path out = fs::absolute(out_dir);
  fs::create_directories(out);

  // --- The deck: the refined RECT frame, clamped at REAR_END, a vertical and a lateral load.
  const fem::FrameModel base = fem::read_inp(std::string(FRAMEDYN_SOURCE_DIR) + "/meshes/r100_frame.inp");
  const int k = testing::subdivisions_for(base, static_cast<long>(target_dofs));
  const std::string model = testing::refined_frame_inp(base, k, "REAR_END");
  int lateral_node = 0;  // the first base node that is not clamped, other than the output node
  for (const fem::Node& n : base.nodes) {
    const auto& clamped = base.node_sets.at("REAR_END");
    const bool is_clamped = std::find(clamped.begin(), clamped.end(), base.node_index(n.id)) != clamped.end();
    if (!is_clamped && n.id != node_id) {
      lateral_node = n.id;
      break;
    }
  }
  const std::string loads = fmt::format("{}, 3, -1000.\n{}, 2, 500.\n", node_id, lateral_node);  // lbf
  std::ofstream(out / "model.inp") << model << fmt::format("*NSET, NSET=OUT\n{}\n", node_id);
  std::ofstream(out / "frame.inp") << model << fmt::format("*NSET, NSET=OUT\n{}\n", node_id) << "*STEP\n*STATIC\n*CLOAD\n" << loads << "*END STEP\n";

  // The modes (not timed), to choose the band and CalculiX's points per interval.
  const fem::FrameModel frame_model = fem::read_inp((out / "frame.inp").string());
  fem::ModalOptions mo;
  mo.mode_count = modes;
  const fem::ModalResult mr = fem::compute_modes(frame_model, mo);
  const double f_lo = 0.5 * mr.modes.front().frequency_hz;
  const double f_hi = mr.modes[static_cast<std::size_t>(modes / 2)].frequency_hz;  // half the modes in the band, the rest above it
  int in_band = 0;
  for (const fem::Mode& m : mr.modes) in_band += m.frequency_hz > f_lo && m.frequency_hz < f_hi;
  const int per_interval = std::max(2, static_cast<int>(std::lround(static_cast<double>(frequencies) / (in_band + 1))));
  fmt::print("deck: {} elements per member, {} free DOFs; {} modes up to {:.2f} Hz; band {:.3f} to {:.3f} Hz with {} modes; zeta {}\n", k,
             mr.free_dofs, modes, mr.modes.back().frequency_hz, f_lo, f_hi, in_band, zeta);

  // --- framedyn harmonic, with and without the static correction.
  const std::string fargs = fmt::format("{}:{}:{}", f_lo, f_hi, frequencies);
  std::vector<std::string> base_args = {FRAMEDYN_BINARY, "harmonic", "frame.inp", "-f", fargs, "-z", fmt::format("{}", zeta), "--modes",
                                        std::to_string(modes), "--output-set", "OUT", "--no-figures", "-q"};
  std::vector<std::string> with = base_args, without = base_args;
  with.insert(with.end(), {"--out", "fd_corrected"});
  without.insert(without.end(), {"--no-static-correction", "--out", "fd_plain"});
  Run fd_best{}, fd_plain_best{};
  for (int rep = 0; rep < 3; ++rep) {
    const Run a = run_process(with, out, "framedyn.log");
    const Run b = run_process(without, out, "framedyn_plain.log");
    if (a.status != 0 || b.status != 0) {
      std::cerr << "framedyn failed:\n" << read_text(out / "framedyn.log") << read_text(out / "framedyn_plain.log");
      return 1;
    }
    if (rep == 0 || a.seconds < fd_best.seconds) fd_best = a;
    if (rep == 0 || b.seconds < fd_plain_best.seconds) fd_plain_best = b;
  }

  // --- CalculiX: *FREQUENCY (with the zero loads) + *STEADY STATE DYNAMICS.
  std::string zero_loads;
  for (const std::string& l : {fmt::format("{}, 3, 0.\n", node_id), fmt::format("{}, 2, 0.\n", lateral_node)}) zero_loads += l;
  std::ofstream(out / "job.inp") << "*INCLUDE, INPUT=" << (out / "model.inp").string() << "\n*STEP\n*FREQUENCY, STORAGE=YES\n" << modes
                                  << "\n*CLOAD\n" << zero_loads << "*END STEP\n*STEP\n*STEADY STATE DYNAMICS\n"
                                  << fmt::format("{}, {}, {}\n", f_lo, f_hi, per_interval) << "*MODAL DAMPING\n"
                                  << fmt::format("1, {}, {}\n", modes, zeta) << "*CLOAD\n" << loads << "*NODE PRINT, NSET=OUT\nU\n*END STEP\n";
  const Run ccx = run_process({"ccx", "-i", "job"}, out, "ccx.log");
  const auto ccx_result = parse_steady_state(read_text(out / "job.dat"), node_id);
  if (ccx.status != 0 || ccx_result.empty()) {
    std::cerr << "ccx failed (status " << ccx.status << "):\n" << read_text(out / "ccx.log");
    return 1;
  }

  fmt::print("\n| run | frequencies | wall time (s) | peak memory (MiB) | CalculiX / this |\n|---|---:|---:|---:|---:|\n");
  fmt::print("| framedyn harmonic, {} modes + static correction (best of 3) | {} | {:.3f} | {:.1f} | {:.1f} |\n", modes, frequencies, fd_best.seconds,
             fd_best.peak_mib, ccx.seconds / fd_best.seconds);
  fmt::print("| framedyn harmonic, {} modes, no static correction (best of 3) | {} | {:.3f} | {:.1f} | {:.1f} |\n", modes, frequencies,
             fd_plain_best.seconds, fd_plain_best.peak_mib, ccx.seconds / fd_plain_best.seconds);
  fmt::print("| CalculiX 2.20 *FREQUENCY + *STEADY STATE DYNAMICS, {} modes (one run) | {} | {:.3f} | {:.1f} | 1 |\n", modes, ccx_result.size(),
             ccx.seconds, ccx.peak_mib);

  // --- Peer check: framedyn's modal series (same modes, damping, no correction) at CalculiX's frequencies.
  fem::FrameDynamics dyn(frame_model);
  const fem::ModalBasis basis = fem::modal_basis(dyn.dofs(), mr);
  fem::HarmonicOptions ho;
  ho.response.damping = fem::ModalDamping::ratio(zeta);
  ho.response.static_correction = false;
  const int node = frame_model.node_index(node_id);
  ho.output_dofs = {6 * node, 6 * node + 1, 6 * node + 2};
  for (const auto& [f, v] : ccx_result) ho.frequencies_hz.push_back(f);
  const fem::HarmonicResult hr = fem::harmonic_response(dyn, basis, fem::applied_loads(frame_model), ho);
  std::ofstream csv(out / "peer_amplitudes.csv");
  csv << "frequency [Hz],framedyn_uz_amplitude [in],calculix_uz_amplitude [in],framedyn_uz_phase [deg],calculix_uz_phase [deg]\n";
  std::vector<double> diffs;
  double peak_fd = 0.0, peak_ccx = 0.0, peak_fd_f = 0.0, peak_ccx_f = 0.0;
  std::size_t i = 0;
  const double to_length_unit = 1.0 / frame_model.units.to_si_factor(core::Quantity::length);  // framedyn computes in SI
  for (const auto& [f, v] : ccx_result) {
    const std::complex<double> c(v.first.z(), v.second.z());
    const std::complex<double> d = hr.output(2, static_cast<Eigen::Index>(i++)) * to_length_unit;
    csv << fmt::format("{},{},{},{},{}\n", f, std::abs(d), std::abs(c), std::arg(d) * 57.29577951308232, std::arg(c) * 57.29577951308232);
    diffs.push_back(std::abs(std::abs(d) - std::abs(c)) / std::abs(c));
    if (std::abs(d) > peak_fd) peak_fd = std::abs(d), peak_fd_f = f;
    if (std::abs(c) > peak_ccx) peak_ccx = std::abs(c), peak_ccx_f = f;
  }
  std::vector<double> sorted = diffs;
  std::sort(sorted.begin(), sorted.end());
  fmt::print("\npeer check at node {} (uz, {} frequencies of CalculiX's grid): |U| differs by median {:.2f} %, 90th percentile {:.2f} %, max {:.2f} %\n",
             node_id, sorted.size(), 100 * sorted[sorted.size() / 2], 100 * sorted[sorted.size() * 9 / 10], 100 * sorted.back());
  fmt::print("largest |uz|: framedyn {:.6g} in at {:.4f} Hz, CalculiX {:.6g} in at {:.4f} Hz ({:+.2f} %)\n", peak_fd, peak_fd_f, peak_ccx, peak_ccx_f,
             100 * (peak_fd / peak_ccx - 1));
  // Resonance peaks of |uz| in both: CalculiX's on its own grid (clustered at its eigenfrequencies by
  // the bias), framedyn's on a fine even grid (20,000 frequencies, in-process); paired by frequency.
  auto peaks = [](const std::vector<double>& f, const std::vector<double>& a) {
    std::vector<std::pair<double, double>> p;
    const double top = *std::max_element(a.begin(), a.end());
    for (std::size_t j = 1; j + 1 < a.size(); ++j)
      if (a[j] > a[j - 1] && a[j] >= a[j + 1] && a[j] > 0.01 * top) p.push_back({f[j], a[j]});
    return p;
  };
  std::vector<double> cf, ca;
  for (const auto& [f, v] : ccx_result) cf.push_back(f), ca.push_back(std::abs(std::complex<double>(v.first.z(), v.second.z())));
  fem::HarmonicOptions fine = ho;
  fine.frequencies_hz.clear();
  for (int j = 0; j < 20000; ++j) fine.frequencies_hz.push_back(f_lo + (f_hi - f_lo) * j / 19999.0);
  const fem::HarmonicResult hf = fem::harmonic_response(dyn, basis, fem::applied_loads(frame_model), fine);
  std::vector<double> fa;
  for (Eigen::Index j = 0; j < hf.output.cols(); ++j) fa.push_back(std::abs(hf.output(2, j)) * to_length_unit);
  const auto pc = peaks(cf, ca), pf = peaks(fine.frequencies_hz, fa);
  fmt::print("\n| CalculiX peak (Hz) | |uz| (in) | framedyn peak (Hz) | |uz| (in) | frequency | amplitude |\n|---:|---:|---:|---:|---:|---:|\n");
  for (const auto& [f, a] : pc) {
    std::pair<double, double> best{0, 0};
    for (const auto& q : pf)
      if (best.first == 0 || std::abs(q.first - f) < std::abs(best.first - f)) best = q;
    fmt::print("| {:.3f} | {:.5g} | {:.3f} | {:.5g} | {:+.2f} % | {:+.2f} % |\n", f, a, best.first, best.second, 100 * (best.first / f - 1),
               100 * (best.second / a - 1));
  }
  fmt::print("at the band's lower end ({:.3f} Hz, quasi-static): framedyn {:.6g} in, CalculiX {:.6g} in ({:+.2f} %)\n", cf.front(),
             std::abs(hr.output(2, 0)) * to_length_unit, ca.front(), 100 * (std::abs(hr.output(2, 0)) * to_length_unit / ca.front() - 1));
  std::string fd_freqs, ccx_freqs;
  for (std::size_t m = 0; m < 5 && m < mr.modes.size(); ++m) fd_freqs += fmt::format("{}{:.3f}", m ? ", " : "", mr.modes[m].frequency_hz);
  fmt::print("framedyn's first modes {} Hz (CalculiX's are in {}/job.dat)\nper-frequency values in {}/peer_amplitudes.csv\n", fd_freqs, out.string(),
             out.string());
  return 0;
}
