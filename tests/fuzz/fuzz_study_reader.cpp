// libFuzzer harness for the YAML study reader (coupling/rigid_study.h). Any
// input must either read into a study whose machine assembles to finite,
// definite M, K, C, or be refused with core::InputError naming file, line and
// key path. Anything else — a crash, a sanitizer report, another exception —
// is a finding. Seeds: examples/**/*.yaml.
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>

#include "core/error.h"
#include "coupling/rigid_study.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 20000) return -1;
  // The reader takes a file: write the input to one per process.
  static const std::string file = "/tmp/framedyn-fuzz-study-" + std::to_string(::getpid()) + ".yaml";
  {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  try {
    const framedyn::coupling::RigidStudy study = framedyn::coupling::read_rigid_study(file);
    (void)study;
  } catch (const framedyn::core::InputError&) {
    // the expected outcome for bad input
  }
  return 0;
}
