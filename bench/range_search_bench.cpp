// Build and query cost of the photon range searches (src/spatial) on photon-like data: points
// spread uniformly over the faces of a unit cube, as light vertices lie on surfaces. The radius
// gives about 30 neighbours per query, the middle of the 10-50 that photon mapping uses, and
// queries sit near data points, as the camera vertices that query them lie on the same surfaces.
//   caustica_bench --benchmark_filter=RangeSearch
#include "core/rng.h"
#include "spatial/range_search.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <map>

namespace caustica {
namespace {

constexpr float MeanNeighbours = 30;

struct PhotonSet {
    std::vector<Vec3f> points;
    std::vector<Vec3f> queries;
    float radius = 0;
};

const PhotonSet &photon_set(size_t count) {
    static std::map<size_t, PhotonSet> sets;
    auto [it, inserted] = sets.try_emplace(count);
    PhotonSet &set = it->second;
    if (!inserted) return set;
    Rng rng(count, 3);
    set.points.resize(count);
    for (Vec3f &p : set.points) {
        int face = int(rng.next_uint32() % 6);
        int axis = face / 2;
        p = {rng.uniform(), rng.uniform(), rng.uniform()};
        p[axis] = float(face % 2);
    }
    // count / 6 points per unit area, so a disc of radius r holds pi r^2 count / 6 of them.
    set.radius = std::sqrt(MeanNeighbours * 6 / (Pi * count));
    set.queries.resize(1 << 16);
    for (Vec3f &q : set.queries) {
        Vec3f offset(rng.uniform() - 0.5f, rng.uniform() - 0.5f, rng.uniform() - 0.5f);
        q = set.points[rng.next_uint32() % count] + offset * set.radius;
    }
    return set;
}

void BM_RangeSearchBuild(benchmark::State &state, const char *name) {
    const PhotonSet &set = photon_set(size_t(state.range(0)));
    std::unique_ptr<RangeSearch> search = create_range_search(name);
    for (auto _ : state) search->build(set.points, set.radius);
    state.counters["bytes_per_point"] = double(search->memory_bytes()) / set.points.size();
}

void BM_RangeSearchQuery(benchmark::State &state, const char *name) {
    const PhotonSet &set = photon_set(size_t(state.range(0)));
    std::unique_ptr<RangeSearch> search = create_range_search(name);
    search->build(set.points, set.radius);
    std::vector<uint32_t> found;
    size_t query = 0, neighbours = 0;
    for (auto _ : state) {
        search->find_within(set.queries[query++ % set.queries.size()], set.radius, found);
        neighbours += found.size();
        benchmark::DoNotOptimize(found.data());
    }
    state.counters["neighbours"] = double(neighbours) / state.iterations();
}

BENCHMARK_CAPTURE(BM_RangeSearchBuild, hashgrid, "hashgrid")
    ->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_RangeSearchBuild, flann, "flann")
    ->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_RangeSearchQuery, hashgrid, "hashgrid")->Arg(100000)->Arg(1000000);
BENCHMARK_CAPTURE(BM_RangeSearchQuery, flann, "flann")->Arg(100000)->Arg(1000000);

} // namespace
} // namespace caustica
