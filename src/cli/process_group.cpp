#include "cli/process_group.h"

#include "core/error.h"

#ifdef CAUSTICA_HAVE_MPI
#include "mpi/mpi_job.h"
#endif

#include <cstdlib>

namespace caustica {

void ProcessGroup::abort(int status) const { std::_Exit(status); }

namespace {

// Whether an MPI launcher started this process, and the size of its job if it says (Open MPI's
// and MPICH's variables; under Slurm with PMIx only the rank is named, and the size is 0).
bool launched_by_mpi(int *size) {
    for (const char *name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"})
        if (const char *value = std::getenv(name)) {
            *size = std::atoi(value);
            return true;
        }
    *size = 0;
    return std::getenv("PMIX_RANK") != nullptr;
}

} // namespace

std::unique_ptr<ProcessGroup> join_process_group(int *argc, char ***argv) {
    int size = 0;
    const bool launched = launched_by_mpi(&size);
#ifdef CAUSTICA_HAVE_MPI
    if (launched) return join_mpi_job(argc, argv);
#else
    (void)argc;
    (void)argv;
    if (launched && size != 1)
        throw InputError("this process was started by an MPI launcher, but this caustica was built without MPI "
                         "(install libopenmpi-dev, as scripts/setup.sh does, and build again)");
#endif
    return std::make_unique<ProcessGroup>();
}

} // namespace caustica
