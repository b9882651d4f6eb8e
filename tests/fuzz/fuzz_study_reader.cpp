// libFuzzer harness for the YAML study readers: the 2-D and 3-D rigid-body
// studies (coupling/rigid_study.h, both models) and the frame transient
// study (coupling/frame_study.h), which share coupling/yaml_input. The input
// goes to the reader of the `model` it names (a reader refuses another
// model at `model` before it reads any other key). Any input must either read
// into a study whose machine assembles to finite M, K, C with a positive
// definite M (rigid-body studies), or be refused with core::InputError naming
// file, line and key path. Anything else — a crash, a sanitizer report,
// another exception — is a finding. Seeds: examples/**/*.yaml.
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <Eigen/Cholesky>

#include "core/error.h"
#include "coupling/frame_study.h"
#include "coupling/rigid_study.h"
#include "rigid/machine_2d.h"
#include "rigid/machine_3d.h"
#include "rigid/vehicle_model.h"

namespace {

namespace fc = framedyn::coupling;

[[noreturn]] void finding(const char* what) {
  std::fprintf(stderr, "study reader: %s\n", what);
  std::abort();
}

// What a rigid-body reader accepted assembles: finite M, K, C and a positive definite M.
void check_machine(const framedyn::rigid::VehicleModel& model) {
  if (!model.m.allFinite()) finding("accepted a study whose mass matrix is not finite");
  if (!model.k_full.allFinite()) finding("accepted a study whose stiffness matrix is not finite");
  if (!model.c_full.allFinite()) finding("accepted a study whose damping matrix is not finite");
  if (model.m.llt().info() != Eigen::Success) finding("accepted a study whose mass matrix is not positive definite");
}

bool refused_at_model(const framedyn::core::InputError& e) { return e.where().key == "model"; }

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 20000) return -1;
  // The readers take a file: write the input to one per process, unlinked as
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
    try {
      check_machine(fc::build_vehicle_model(fc::read_rigid_study(file).machine));  // rigid_2d and rigid_3d
      return 0;
    } catch (const framedyn::core::InputError& e) {
      if (!refused_at_model(e)) throw;
    }
    (void)fc::read_frame_study(file);
  } catch (const framedyn::core::InputError&) {
    // the expected outcome for bad input
  }
  return 0;
}
