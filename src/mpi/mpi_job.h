// A render shared by the processes of an MPI job (Open MPI from Debian; any MPI-3 library
// would do): `mpirun -np N caustica render SCENE ...`, or Slurm's `srun`. docs/mpi.md says how
// to run it on a cluster.
//
// Only the thread that called main() talks to MPI (MPI_THREAD_FUNNELED): the render's loops make
// their collective calls between parallel sweeps. Messages larger than MPI's int counts allow
// are sent in pieces.
#pragma once

#include "cli/process_group.h"

#include <memory>

namespace caustica {

// Initialises MPI (MPI_Finalize runs when the group is destroyed). Ranks other than 0 print no
// warnings.
std::unique_ptr<ProcessGroup> join_mpi_job(int *argc, char ***argv);

} // namespace caustica
