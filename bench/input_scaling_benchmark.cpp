// Large inputs (issue 6): reading an .inp deck and assembling K and M must
// scale linearly with the model's size. Refined R-100-like frames of about
// 1e4 to 1e6 DOF (tests/support/refined_frame.h) are written to a file once,
// then read (fem::read_inp) and assembled (fem::make_dof_map + fem::assemble)
// several times; the table gives the best time of each, the time per DOF and
// its ratio to the smallest model's (1.0 = exactly linear), and the peak
// resident memory of the process after the largest case.
//
//   input_scaling_benchmark [--repeats N] [--max-dofs N]
#include <fmt/format.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "fem/assembly.h"
#include "fem/inp_reader.h"
#include "tests/support/refined_frame.h"

namespace {

using namespace framedyn;
namespace fs = std::filesystem;

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

int main(int argc, char** argv) {
  int repeats = 3;
  double max_dofs = 1.0e6;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string a = argv[i];
    if (a == "--repeats") repeats = std::max(1, std::atoi(argv[i + 1]));
    else if (a == "--max-dofs") max_dofs = std::atof(argv[i + 1]);
  }
  const fem::FrameModel base = fem::read_inp(fs::path(FRAMEDYN_SOURCE_DIR) / "meshes" / "r100_frame.inp");
  const fs::path deck = fs::temp_directory_path() / ("framedyn_input_scaling_" + std::to_string(::getpid()) + ".inp");

  fmt::print("| DOF | deck size | read (s) | assemble K, M (s) | read per DOF (µs) | assemble per DOF (µs) | read / DOF vs smallest | assemble / DOF vs smallest |\n");
  fmt::print("|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  double read_per_dof_0 = 0.0, assemble_per_dof_0 = 0.0;
  for (double target : {1.0e4, 3.0e4, 1.0e5, 3.0e5, 1.0e6}) {
    if (target > max_dofs * 1.0001) break;
    const int k = testing::subdivisions_for(base, static_cast<long>(target));
    {
      std::ofstream out(deck, std::ios::binary);
      out << testing::refined_frame_inp(base, k, "REAR_END");
    }
    double best_read = 1e300, best_assemble = 1e300;
    long dofs = 0;
    for (int r = 0; r < repeats; ++r) {
      auto t0 = std::chrono::steady_clock::now();
      const fem::FrameModel model = fem::read_inp(deck);
      best_read = std::min(best_read, seconds_since(t0));
      t0 = std::chrono::steady_clock::now();
      const fem::DofMap dofs_map = fem::make_dof_map(model);
      const fem::FreeSystem system = fem::assemble(model, dofs_map);
      best_assemble = std::min(best_assemble, seconds_since(t0));
      dofs = system.stiffness.rows();
    }
    const double read_per_dof = best_read / static_cast<double>(dofs), assemble_per_dof = best_assemble / static_cast<double>(dofs);
    if (read_per_dof_0 == 0.0) {
      read_per_dof_0 = read_per_dof;
      assemble_per_dof_0 = assemble_per_dof;
    }
    fmt::print("| {} | {:.1f} MB | {:.4f} | {:.4f} | {:.3f} | {:.3f} | {:.2f} | {:.2f} |\n", dofs, static_cast<double>(fs::file_size(deck)) / 1e6, best_read,
               best_assemble, 1e6 * read_per_dof, 1e6 * assemble_per_dof, read_per_dof / read_per_dof_0, assemble_per_dof / assemble_per_dof_0);
    std::fflush(stdout);
  }
  fs::remove(deck);
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  fmt::print("\npeak resident memory of the process: {:.0f} MiB\n", usage.ru_maxrss / 1024.0);
  return 0;
}
