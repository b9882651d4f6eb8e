// Counters of the expensive steps of a linear solve: assemblies of the
// frame's K and M (the element loop), mass-only assemblies (rigid-body mass
// bookkeeping) and sparse factorisations (Cholesky LL^T and the LDL^T of the
// Sturm counts). They count calls, never time: a test runs a study and checks
// how often it assembled and factorised the frame (issue 17, "one assembly and
// one factorisation per pipeline run"). Process-wide and atomic (the mass is
// assembled and factorised on a second thread); read them as the difference
// of two snapshots around the work, with no other solve running in between.
#pragma once

namespace framedyn::fem {

struct SolverCounts {
  long system_assemblies = 0;  // fem::assemble: K and M together
  long mass_assemblies = 0;    // fem::assemble_mass: M alone
  long factorisations = 0;     // SparseCholesky::factorize and ldlt_inertia
  SolverCounts operator-(const SolverCounts& before) const {
    return {system_assemblies - before.system_assemblies, mass_assemblies - before.mass_assemblies, factorisations - before.factorisations};
  }
};

// A snapshot of the counters since the process started.
SolverCounts solver_counts();

namespace internal {
void count_system_assembly();
void count_mass_assembly();
void count_factorisation();
}  // namespace internal

}  // namespace framedyn::fem
