#include "mpi/mpi_job.h"

#include "core/error.h"
#include "film/film.h"

#include <mpi.h>

#include <algorithm>
#include <climits>
#include <cstdio>
#include <exception>
#include <functional>
#include <span>
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
        MPI_Type_contiguous(int(sizeof(fixed_point::Wide)), MPI_BYTE, &wide_type_);
        MPI_Type_commit(&wide_type_);
        MPI_Op_create(&add_checked<int64_t>, 1, &narrow_sum_);
        MPI_Op_create(&add_checked<fixed_point::Wide>, 1, &wide_sum_);
    }
    ~MpiJob() override {
        MPI_Op_free(&narrow_sum_);
        MPI_Op_free(&wide_sum_);
        MPI_Type_free(&wide_type_);
        MPI_Finalize();
    }

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

    // MPI_Reduce onto rank 0, in place there, of the film's integer sums: integer addition
    // makes the order of the ranks' terms irrelevant. The operations add with overflow checks,
    // as the film does.
    void reduce(Film &film, RenderStats &stats) const override {
        uint32_t held = film.stores(), stores = 0;
        check(MPI_Allreduce(&held, &stores, 1, MPI_UINT32_T, MPI_BOR, MPI_COMM_WORLD), "reduction");
        Film::Sums sums = film.sums(stores);
        sum_overflowed = false;
        for (std::span<int64_t> array : sums.narrow)
            reduce_to_root(array.data(), array.size(), sizeof(int64_t), MPI_INT64_T, narrow_sum_);
        reduce_to_root(sums.wide.data(), sums.wide.size(), sizeof(fixed_point::Wide), wide_type_, wide_sum_);
        uint32_t overflow = sums.overflow | (sum_overflowed ? ~0u : 0u), any_overflow = 0;
        check(MPI_Reduce(&overflow, &any_overflow, 1, MPI_UINT32_T, MPI_BOR, 0, MPI_COMM_WORLD), "reduction");
        if (rank_ == 0) film.set_overflow(any_overflow);

        stats.rays = uint64_t(sum(int64_t(stats.rays.load())));
        stats.non_finite_samples = uint64_t(sum(int64_t(stats.non_finite_samples.load())));
        stats.pixel_samples = uint64_t(sum(int64_t(stats.pixel_samples.load())));
        uint64_t stored = stats.stored_light_vertices, most = 0;
        check(MPI_Allreduce(&stored, &most, 1, MPI_UINT64_T, MPI_MAX, MPI_COMM_WORLD), "maximum");
        stats.stored_light_vertices = most;
    }

    void gather_to_root(std::string bytes, const std::function<void(const std::string &)> &take) const override {
        if (rank_ != 0) {
            send_bytes(bytes, 0);
            return;
        }
        std::exception_ptr failure;
        for (int r = 0; r < ranks_; ++r) {
            if (r > 0) bytes = receive_bytes(r);
            try {
                if (!failure) take(bytes);
            } catch (...) {
                failure = std::current_exception();
            }
        }
        if (failure) std::rethrow_exception(failure);
    }

    std::string scatter_from_root(const std::function<std::string(int)> &make) const override {
        if (rank_ != 0) return receive_bytes(0);
        std::string mine = make(0);
        for (int r = 1; r < ranks_; ++r) send_bytes(make(r), r);
        return mine;
    }

    [[noreturn]] void abort(int status) const override {
        std::fflush(stderr);
        MPI_Abort(MPI_COMM_WORLD, status);
        std::_Exit(status);
    }

  private:
    // Sums `count` elements of `size` bytes into rank 0's, in pieces that MPI's int counts allow.
    void reduce_to_root(void *data, size_t count, size_t size, MPI_Datatype type, MPI_Op op) const {
        const size_t piece = kPiece / size;
        for (size_t offset = 0; offset < count; offset += piece) {
            char *first = static_cast<char *>(data) + offset * size;
            const int n = int(std::min(piece, count - offset));
            check(MPI_Reduce(rank_ == 0 ? MPI_IN_PLACE : first, first, n, type, op, 0, MPI_COMM_WORLD), "reduction");
        }
    }

    // Whether an addition of the reduction left the integers' range (in the process that made it).
    static inline bool sum_overflowed = false;

    template <typename T> static void add_checked(void *in, void *inout, int *count, MPI_Datatype *) {
        const T *a = static_cast<const T *>(in);
        T *b = static_cast<T *>(inout);
        for (int i = 0; i < *count; ++i)
            if (__builtin_add_overflow(b[i], a[i], &b[i])) sum_overflowed = true;
    }

    int rank_ = 0, ranks_ = 1;
    MPI_Datatype wide_type_ = MPI_DATATYPE_NULL; // a 128-bit integer
    MPI_Op narrow_sum_ = MPI_OP_NULL, wide_sum_ = MPI_OP_NULL;
};

} // namespace

std::unique_ptr<ProcessGroup> join_mpi_job(int *argc, char ***argv) { return std::make_unique<MpiJob>(argc, argv); }

} // namespace caustica
