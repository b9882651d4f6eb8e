// Runs per second of `framedyn batch` on the offset-plowing pipeline
// (examples/offset_plowing.yaml, 1 s of plowing into the beam frame; summary
// outputs only): a Monte Carlo design over the soil's damping, on 1 and 2
// threads through the library, and on 2 and 3 MPI ranks through mpirun (rank 0
// manages only). Usage: batch_benchmark [RUNS] (default 16). Issue 19's target:
// 1,000 pipeline runs in 30 s on 2 cores (33 runs/s).
#include <fmt/format.h>

#include <chrono>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "batch/design.h"
#include "batch/engine.h"

namespace fs = std::filesystem;

int main(int argc, char** argv) {
  const int runs = argc > 1 ? std::atoi(argv[1]) : 16;
  const fs::path dir = fs::temp_directory_path() / fmt::format("framedyn_batch_benchmark_{}", ::getpid());
  fs::create_directories(dir);
  const fs::path design = dir / "design.yaml";
  std::ofstream(design) << "framedyn_batch: 1\nstudy: " << (fs::path(FRAMEDYN_SOURCE_DIR) / "examples" / "offset_plowing.yaml").string()
                        << "\nsampling: {method: monte_carlo, samples: " << runs << ", seed: 1}\nparameters:\n"
                        << "  - {key: soil.damping, distribution: uniform, low: 150, high: 450}\noutputs:\n"
                        << "  - frame.peak_normal_stress\n  - rigid.response.peak_cutting_force\n";
  // An absolute study path: the design file's folder is joined with it (an absolute path stays itself).
  const framedyn::batch::BatchDesign d = framedyn::batch::read_batch_design(design.string());
  double one = 0.0;
  for (int threads : {1, 2}) {
    framedyn::batch::BatchOptions o;
    o.out = dir / fmt::format("threads_{}", threads);
    o.threads = threads;
    const auto t0 = std::chrono::steady_clock::now();
    const framedyn::batch::BatchCounts c = framedyn::batch::run_batch(d, o);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (threads == 1) one = s;
    fmt::print("{} thread(s): {} runs ({} failed) in {:.2f} s: {:.2f} runs/s, parallel efficiency {:.0f} %\n", threads, c.total, c.failed, s, c.total / s,
               100.0 * one / (s * threads));
  }
  for (int ranks : {2, 3}) {
    const std::string cmd = fmt::format("cd {} && OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 mpirun -n {} --oversubscribe {} batch design.yaml --out mpi_{} -q > /dev/null",
                                        dir.string(), ranks, FRAMEDYN_BINARY, ranks);
    const auto t0 = std::chrono::steady_clock::now();
    const int rc = std::system(cmd.c_str());
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    fmt::print("{} MPI ranks ({} worker(s)): {} in {:.2f} s: {:.2f} runs/s (mpirun start-up included)\n", ranks, ranks - 1, rc == 0 ? "done" : "FAILED", s,
               runs / s);
  }
  fs::remove_all(dir);
  return 0;
}
