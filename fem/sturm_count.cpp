// Sturm sequence count from the inertia of K - s M (see sturm_count.h).
#include "fem/sturm_count.h"

#include <fmt/format.h>

#include "core/error.h"
#include "fem/sparse_cholesky.h"

namespace framedyn::fem {

SturmCount count_eigenvalues_below(const SparseMatrix& k, const SparseMatrix& m, double shift, double step) {
  SturmCount out;
  out.shift = shift;
  for (int attempt = 0; attempt < 5; ++attempt) {
    const SparseMatrix a = (k - out.shift * m).pruned();
    const Inertia in = ldlt_inertia(a);
    ++out.factorizations;
    if (!in.breakdown) {
      out.below = in.negative;
      return out;
    }
    out.shift += step;
  }
  throw core::NumericalError(fmt::format(
      "the Sturm count of the eigenvalues below {:.6g} rad^2/s^2 failed: the LDL^T factorisation of K - s M met a zero "
      "pivot at {} shifts from {:.6g} to {:.6g} rad^2/s^2 (is the stiffness or mass matrix not finite?)",
      shift, out.factorizations, shift, out.shift - step));
}

}  // namespace framedyn::fem
