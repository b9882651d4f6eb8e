// Sturm sequence count for the generalised symmetric problem K phi = lambda M
// phi (M positive definite): the number of eigenvalues below s equals the
// number of negative pivots of K - s M = P^T L D L^T P (Sylvester's law of
// inertia; docs/theory/fem.md Eq. 7.3). The modal solver uses it to certify
// that the set it returns is the complete set of the lowest eigenvalues.
#pragma once

#include "fem/assembly.h"

namespace framedyn::fem {

struct SturmCount {
  long below = 0;            // eigenvalues below `shift`
  double shift = 0.0;        // the s actually used (moved on a breakdown)
  int factorizations = 0;    // LDL^T factorisations done
};

// K and M as lower triangles. A zero pivot (s on an eigenvalue to round-off,
// or a breakdown of the unpivoted factorisation) moves s up by `step` and
// factorises again, at most four times; then throws core::NumericalError.
SturmCount count_eigenvalues_below(const SparseMatrix& stiffness, const SparseMatrix& mass, double shift, double step);

}  // namespace framedyn::fem
