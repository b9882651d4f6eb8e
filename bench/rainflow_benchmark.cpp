// Rainflow throughput (issue 18): fatigue::count_cycles with a Miner damage sink (IIW FAT90)
// over N samples held in memory, against one pass summing the same samples in the same run
// (the memory-bandwidth floor: no counting can read its data faster). Printed as a markdown
// table (docs/benchmarks.md). Two histories, both seeded and deterministic:
//   random  independent uniform samples in [-100, 100] MPa: 2/3 of the samples are turning
//           points, the worst case for the counter;
//   narrow  a 10 Hz sine of 50 MPa amplitude plus 5 % uniform noise at 400 samples a second:
//           few turning points a sample, a strain-gauge-like record.
//
//   rainflow_benchmark [--samples N]   (default 4e7: 320 MB of doubles; 1e8 needs 800 MB)
//                      [--repeats R]   (best of R timings of each pass; default 3)
#include <fmt/format.h>
#include <time.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "fatigue/miner_damage.h"
#include "fatigue/rainflow.h"
#include "fatigue/sn_curve.h"

namespace {

using namespace framedyn::fatigue;

double now() {
  timespec t{};
  clock_gettime(CLOCK_MONOTONIC, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

double uniform(std::mt19937_64& g) { return static_cast<double>(g() >> 11) * 0x1.0p-53; }

// Counting alone: sums the counts and ranges (what a histogram costs, without the S-N curve's pow).
class CountSink : public CycleSink {
 public:
  void add(double range, double, double count) override {
    cycles += count;
    ranges += range * count;
  }
  double cycles = 0.0, ranges = 0.0;
};

struct Timing {
  double sum_s = 1e300, count_s = 1e300, rainflow_s = 1e300;
  double checksum = 0.0, damage = 0.0, cycles = 0.0;
  std::size_t turning_points = 0;
};

Timing measure(const std::vector<double>& x, int repeats) {
  Timing t;
  for (int r = 0; r < repeats; ++r) {
    double t0 = now();
    double s = 0.0;
    for (double v : x) s += v;  // the floor: one read of every sample
    t.sum_s = std::min(t.sum_s, now() - t0);
    t.checksum = s;
    CountSink c;
    t0 = now();
    count_cycles(x, Residue::half_cycles, c);
    t.count_s = std::min(t.count_s, now() - t0);
    MinerDamage d(iiw_normal_stress(90), 1e6);
    t0 = now();
    const RainflowSummary rs = count_cycles(x, Residue::half_cycles, d);
    t.rainflow_s = std::min(t.rainflow_s, now() - t0);
    t.damage = d.damage();
    t.cycles = rs.cycles;
    t.turning_points = rs.turning_points;
  }
  return t;
}

}  // namespace

int main(int argc, char** argv) {
  std::size_t n = 40'000'000;
  int repeats = 3;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string a = argv[i];
    if (a == "--samples") n = static_cast<std::size_t>(std::atof(argv[i + 1]));
    else if (a == "--repeats") repeats = std::atoi(argv[i + 1]);
  }
  fmt::print("| history | samples | turning points | cycles | sum pass (s) | rainflow, counting only (s) | ratio | rainflow + Miner (s) | ns/sample | ratio to the floor |\n");
  fmt::print("|---|---|---|---|---|---|---|---|---|---|\n");
  std::vector<double> x(n);
  for (const char* kind : {"random", "narrow"}) {
    std::mt19937_64 g(20261203);
    if (std::string(kind) == "random")
      for (double& v : x) v = 200.0 * uniform(g) - 100.0;
    else
      for (std::size_t i = 0; i < n; ++i) x[i] = 50.0 * std::sin(2.0 * 3.141592653589793 * 10.0 * static_cast<double>(i) / 400.0) + 5.0 * (uniform(g) - 0.5);
    const Timing t = measure(x, repeats);
    fmt::print("| {} | {:.3g} | {:.3g} | {:.4g} | {:.3f} | {:.3f} | {:.1f} | {:.3f} | {:.2f} | {:.1f} |\n", kind, static_cast<double>(n),
               static_cast<double>(t.turning_points), t.cycles, t.sum_s, t.count_s, t.count_s / t.sum_s, t.rainflow_s,
               1e9 * t.rainflow_s / static_cast<double>(n), t.rainflow_s / t.sum_s);
    fmt::print(stderr, "{}: checksum {:.6g}, damage {:.6g}\n", kind, t.checksum, t.damage);
  }
  return 0;
}
