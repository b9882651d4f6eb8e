// The MPI engine of `framedyn batch` (`mpirun -n N framedyn batch ...`): rank 0,
// the manager, hands out runs one at a time to the workers (ranks 1..N-1) as
// each finishes (dynamic load balancing: runs differ in cost), gathers their
// rows and alone writes the results folder (no shared file system assumed
// beyond rank 0's output folder). Built with FRAMEDYN_MPI (Debian's Open MPI);
// without it, or outside mpirun, the world is one process and run_batch_mpi
// is never called.
#pragma once

#include "batch/engine.h"

namespace framedyn::batch {

// The number of MPI processes (1 without MPI or outside mpirun); initialises
// MPI on first call when launched by mpirun.
int mpi_world_size();
bool mpi_is_manager();  // rank 0 (true without MPI)

// Runs the design across the MPI world; the counts are the manager's (zeros on workers).
BatchCounts run_batch_mpi(const BatchDesign& design, const BatchOptions& options);

}  // namespace framedyn::batch
