// The processes that run one `caustica render` together: an MPI job started by mpirun, mpiexec
// or Slurm's srun (mpi/mpi_job.h), or this process on its own.
//
// Every process parses the scene and renders under the same budget; the render's loops share
// the work through the RenderShare interface (integrators/integrator.h). The film's stores are
// fixed-point sums (film/fixed_point.h), so adding up the ranks' films gives, bit for bit, the
// film one process would have filled with the same seed and samples. Rank 0 then writes the
// image; the other ranks write nothing and print no progress.
#pragma once

#include "integrators/integrator.h"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace caustica {

class Film;

class ProcessGroup : public RenderShare {
  public:
    // Adds every rank's film (Film::sums) into rank 0's, and the ranks' counters (rays,
    // samples taken, non-finite samples; the most light vertices kept) into rank 0's stats.
    virtual void reduce(Film &film, RenderStats &stats) const {
        (void)film;
        (void)stats;
    }
    // Rank 0 receives every rank's bytes in rank order, one at a time, and passes each to
    // `take` (called on rank 0 only), so that it never holds more than one. If `take` throws,
    // the rest are still received, and the first exception is thrown afterwards.
    virtual void gather_to_root(std::string bytes, const std::function<void(const std::string &)> &take) const {
        take(bytes);
    }
    // Rank 0 makes each rank's bytes in rank order (`make(rank)`, called on rank 0 only) and
    // sends them; every rank returns its own.
    virtual std::string scatter_from_root(const std::function<std::string(int rank)> &make) const { return make(0); }
    // Ends every process of the job at once with `status`, for a failure on one rank that the
    // others, waiting for it, cannot see.
    [[noreturn]] virtual void abort(int status) const;
};

// Joins the MPI job this process was started in, if it was; otherwise a group of one. Throws
// InputError when an MPI launcher started this process but Caustica was built without MPI.
std::unique_ptr<ProcessGroup> join_process_group(int *argc, char ***argv);

} // namespace caustica
