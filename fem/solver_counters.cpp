// Process-wide counters of assemblies and factorisations; see solver_counters.h.
#include "fem/solver_counters.h"

#include <atomic>

namespace framedyn::fem {

namespace {
std::atomic<long> g_system_assemblies{0}, g_mass_assemblies{0}, g_factorisations{0};
}  // namespace

SolverCounts solver_counts() { return {g_system_assemblies.load(), g_mass_assemblies.load(), g_factorisations.load()}; }

namespace internal {
void count_system_assembly() { ++g_system_assemblies; }
void count_mass_assembly() { ++g_mass_assemblies; }
void count_factorisation() { ++g_factorisations; }
}  // namespace internal

}  // namespace framedyn::fem
