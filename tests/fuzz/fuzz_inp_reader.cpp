// libFuzzer harness for the .inp mesh reader (fem/inp_reader.h). Any input
// must either read into a model that assembles to finite K, M and load vector, or be
// refused with core::InputError naming file, line and keyword. Anything else
// — a crash, a sanitizer report, another exception, a NaN in K or M — is a
// finding. Seeds: meshes/*.inp and the hand-made decks of the tests.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "core/error.h"
#include "fem/assembly.h"
#include "fem/distributed_loads.h"
#include "fem/inp_reader.h"

namespace {

void require_finite(const framedyn::fem::SparseMatrix& matrix, const char* what) {
  for (int k = 0; k < matrix.outerSize(); ++k)
    for (framedyn::fem::SparseMatrix::InnerIterator it(matrix, k); it; ++it)
      if (!std::isfinite(it.value())) {
        std::fprintf(stderr, "accepted mesh gives a non-finite %s entry\n", what);
        std::abort();
      }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 20000) return -1;  // keep models small: the reader's logic, not its speed
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    // *INCLUDE resolves against a folder that does not exist: includes fail as input errors.
    const framedyn::fem::FrameModel model = framedyn::fem::read_inp_text(text, "fuzz.inp", "/nonexistent-framedyn-fuzz");
    if (model.dof_count() > 6000) return 0;
    const framedyn::fem::DofMap dofs = framedyn::fem::make_dof_map(model);
    const framedyn::fem::FreeSystem system = framedyn::fem::assemble(model, dofs);
    require_finite(system.stiffness, "stiffness");
    require_finite(system.mass, "mass");
    if (!framedyn::fem::applied_load_vector(model).allFinite()) {
      std::fprintf(stderr, "accepted mesh gives a non-finite load vector entry\n");
      std::abort();
    }
  } catch (const framedyn::core::InputError&) {
    // the expected outcome for bad input
  }
  return 0;
}
