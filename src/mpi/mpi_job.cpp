#include "mpi/mpi_job.h"

#include "core/error.h"
#include "film/film.h"

#include <mpi.h>

#include <algorithm>
#include <climits>
#include <cstdio>
#include <sstream>
#include <stdexcept>

namespace caustica {

namespace {

// The largest piece of one message: MPI counts are ints.
constexpr size_t kPiece = size_t(1) << 30;

void check(int result, const char *what) {
    if (result != MPI_SUCCESS) {
        char text[MPI_MAX_ERROR_STRING];
        int length = 0;
        MPI_Error_string(result, text, &length);
        throw std::runtime_error(std::string("MPI ") + what + " failed: " + std::string(text, size_t(length)));
    }
}

void send_bytes(const std::string &bytes, int to) {
    const uint64_t size = bytes.size();
    check(MPI_Send(&size, 1, MPI_UINT64_T, to, 0, MPI_COMM_WORLD), "send");
    for (size_t offset = 0; offset < bytes.size(); offset += kPiece)
        check(MPI_Send(bytes.data() + offset, int(std::min(kPiece, bytes.size() - offset)), MPI_BYTE, to, 0,
                       MPI_COMM_WORLD),
              "send");
}

std::string receive_bytes(int from) {
    uint64_t size = 0;
    check(MPI_Recv(&size, 1, MPI_UINT64_T, from, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE), "receive");
    std::string bytes(size, '\0');
    for (size_t offset = 0; offset < bytes.size(); offset += kPiece)
        check(MPI_Recv(bytes.data() + offset, int(std::min(kPiece, bytes.size() - offset)), MPI_BYTE, from, 0,
                       MPI_COMM_WORLD, MPI_STATUS_IGNORE),
              "receive");
    return bytes;
}

class MpiJob final : public ProcessGroup {
  public:
    MpiJob(int *argc, char ***argv) {
        int provided = 0;
        check(MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided), "initialisation");
        // Errors are returned, not fatal, so that they become exceptions with a message; a
        // rank that dies is reported by the launcher, which ends the job.
        MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN);
        MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
        MPI_Comm_size(MPI_COMM_WORLD, &ranks_);
        if (provided < MPI_THREAD_FUNNELED) {
            MPI_Finalize();
            throw std::runtime_error("the MPI library does not support MPI_THREAD_FUNNELED");
        }
        if (rank_ != 0) set_warnings_enabled(false);
    }
    ~MpiJob() override { MPI_Finalize(); }

    int rank() const override { return rank_; }
    int ranks() const override { return ranks_; }

    int64_t agree(int64_t value) const override {
        check(MPI_Bcast(&value, 1, MPI_INT64_T, 0, MPI_COMM_WORLD), "broadcast");
        return value;
    }

    int64_t sum(int64_t value) const override {
        int64_t total = 0;
        check(MPI_Allreduce(&value, &total, 1, MPI_INT64_T, MPI_SUM, MPI_COMM_WORLD), "sum");
        return total;
    }

    std::vector<char> gather_all(std::vector<char> bytes) const override {
        // Sizes first; the whole exchange must fit MPI's int counts (2 GiB), which an
        // iteration's photons do for any image a rank can hold.
        const long long size = (long long)bytes.size();
        std::vector<long long> sizes(static_cast<size_t>(ranks_));
        check(MPI_Allgather(&size, 1, MPI_LONG_LONG, sizes.data(), 1, MPI_LONG_LONG, MPI_COMM_WORLD), "gather");
        std::vector<int> counts(static_cast<size_t>(ranks_)), offsets(static_cast<size_t>(ranks_));
        long long total = 0;
        for (int r = 0; r < ranks_; ++r) {
            if (total + sizes[r] > INT_MAX)
                throw std::runtime_error("an exchange between the MPI ranks exceeds 2 GiB");
            counts[r] = int(sizes[r]);
            offsets[r] = int(total);
            total += sizes[r];
        }
        std::vector<char> all(static_cast<size_t>(total));
        check(MPI_Allgatherv(bytes.data(), int(size), MPI_BYTE, all.data(), counts.data(), offsets.data(), MPI_BYTE,
                             MPI_COMM_WORLD),
              "gather");
        return all;
    }

    // A binary tree: at step s, each rank r with r mod 2s == s sends its sums to r - s, which
    // adds them to its own. Integer sums make the order irrelevant.
    void reduce(Film &film, RenderStats &stats) const override {
        for (int step = 1; step < ranks_; step *= 2) {
            if (rank_ % (2 * step) == step) {
                std::ostringstream out;
                film.save_state(out);
                send_bytes(std::move(out).str(), rank_ - step);
                break;
            }
            if (rank_ + step < ranks_) {
                std::istringstream in(receive_bytes(rank_ + step));
                film.add_state(in);
            }
        }
        stats.rays = uint64_t(sum(int64_t(stats.rays.load())));
        stats.non_finite_samples = uint64_t(sum(int64_t(stats.non_finite_samples.load())));
        stats.pixel_samples = uint64_t(sum(int64_t(stats.pixel_samples.load())));
        uint64_t stored = stats.stored_light_vertices, most = 0;
        check(MPI_Allreduce(&stored, &most, 1, MPI_UINT64_T, MPI_MAX, MPI_COMM_WORLD), "maximum");
        stats.stored_light_vertices = most;
    }

    std::vector<std::string> gather_to_root(std::string bytes) const override {
        if (rank_ != 0) {
            send_bytes(bytes, 0);
            return {};
        }
        std::vector<std::string> all{std::move(bytes)};
        for (int r = 1; r < ranks_; ++r) all.push_back(receive_bytes(r));
        return all;
    }

    std::string scatter_from_root(std::vector<std::string> per_rank) const override {
        if (rank_ != 0) return receive_bytes(0);
        if (per_rank.size() != size_t(ranks_)) throw std::logic_error("scatter_from_root: one element per rank");
        for (int r = 1; r < ranks_; ++r) send_bytes(per_rank[r], r);
        return std::move(per_rank[0]);
    }

    [[noreturn]] void abort(int status) const override {
        std::fflush(stderr);
        MPI_Abort(MPI_COMM_WORLD, status);
        std::_Exit(status);
    }

  private:
    int rank_ = 0, ranks_ = 1;
};

} // namespace

std::unique_ptr<ProcessGroup> join_mpi_job(int *argc, char ***argv) { return std::make_unique<MpiJob>(argc, argv); }

} // namespace caustica
