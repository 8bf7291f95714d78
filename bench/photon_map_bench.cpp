// Build and query cost of the photon map (src/spatial/photon_map.h) with each search, on
// photon-like data: points spread uniformly over the faces of a unit cube, as light vertices lie
// on surfaces, each carrying a 32-byte record like vcm's. The radius gives about 30 neighbours
// per query, the middle of the 10-50 that photon mapping uses, and queries sit near data points,
// as the camera vertices that query them lie on the same surfaces. A query reads every record
// it finds, as a merge does.
//   caustica_bench --benchmark_filter=PhotonMap
#include "core/rng.h"
#include "spatial/photon_map.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <map>

namespace caustica {
namespace {

constexpr float MeanNeighbours = 30;

// The size of vcm's merge record (integrators/vcm/light_vertex.h).
struct Record {
    float values[8];
};

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

void fill(PhotonMap<Record> &map, const PhotonSet &set) {
    map.clear();
    for (size_t i = 0; i < set.points.size(); ++i) map.add(set.points[i], Record{{float(i)}});
}

// Adding the photons (from one thread) and building the search; bytes_per_photon is the map's
// memory, photons included, over their count.
void BM_PhotonMapBuild(benchmark::State &state, PhotonSearch search) {
    const PhotonSet &set = photon_set(size_t(state.range(0)));
    PhotonMap<Record> map(search);
    for (auto _ : state) {
        fill(map, set);
        map.build(set.radius);
    }
    state.counters["bytes_per_photon"] = double(map.memory_bytes()) / set.points.size();
}

void BM_PhotonMapQuery(benchmark::State &state, PhotonSearch search) {
    const PhotonSet &set = photon_set(size_t(state.range(0)));
    PhotonMap<Record> map(search);
    fill(map, set);
    map.build(set.radius);
    size_t query = 0, neighbours = 0;
    for (auto _ : state) {
        float sum = 0;
        map.for_each_within(set.queries[query++ % set.queries.size()], set.radius, [&](const Record &record) {
            sum += record.values[0];
            ++neighbours;
        });
        benchmark::DoNotOptimize(sum);
    }
    state.counters["neighbours"] = double(neighbours) / state.iterations();
}

BENCHMARK_CAPTURE(BM_PhotonMapBuild, hashgrid, PhotonSearch::HashGrid)
    ->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_PhotonMapBuild, flann, PhotonSearch::FlannKdTree)
    ->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_PhotonMapQuery, hashgrid, PhotonSearch::HashGrid)->Arg(100000)->Arg(1000000);
BENCHMARK_CAPTURE(BM_PhotonMapQuery, flann, PhotonSearch::FlannKdTree)->Arg(100000)->Arg(1000000);

} // namespace
} // namespace caustica
