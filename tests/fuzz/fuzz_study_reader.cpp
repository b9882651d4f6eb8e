// libFuzzer harness for the YAML study reader (coupling/rigid_study.h). Any
// input must either read into a study whose machine assembles to finite,
// definite M, K, C, or be refused with core::InputError naming file, line and
// key path. Anything else — a crash, a sanitizer report, another exception —
// is a finding. Seeds: examples/**/*.yaml.
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <Eigen/Cholesky>

#include "core/error.h"
#include "coupling/rigid_study.h"
#include "rigid/machine_2d.h"

namespace {

[[noreturn]] void finding(const char* what) {
  std::fprintf(stderr, "study reader: %s\n", what);
  std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 20000) return -1;
  // The reader takes a file: write the input to one per process, unlinked as
  // soon as it is made (read back through /proc/self/fd), so that no run,
  // however it ends, leaves a file behind.
  static const int fd = [] {
    char name[] = "/tmp/framedyn-fuzz-study-XXXXXX";
    const int d = ::mkstemp(name);
    if (d < 0) finding("cannot create the harness's temporary file");
    ::unlink(name);
    return d;
  }();
  static const std::string file = "/proc/self/fd/" + std::to_string(fd);
  if (::ftruncate(fd, 0) != 0 || ::pwrite(fd, data, size, 0) != static_cast<ssize_t>(size)) finding("cannot write the harness's temporary file");
  try {
    const framedyn::coupling::RigidStudy study = framedyn::coupling::read_rigid_study(file);
    // What was accepted assembles: finite M, K, C and a positive definite M.
    const framedyn::rigid::Machine2D machine(study.machine);
    if (!machine.mass_matrix().allFinite()) finding("accepted a study whose mass matrix is not finite");
    if (!machine.stiffness_matrix().allFinite()) finding("accepted a study whose stiffness matrix is not finite");
    if (!machine.damping_matrix().allFinite()) finding("accepted a study whose damping matrix is not finite");
    if (machine.mass_matrix().llt().info() != Eigen::Success) finding("accepted a study whose mass matrix is not positive definite");
  } catch (const framedyn::core::InputError&) {
    // the expected outcome for bad input
  }
  return 0;
}
