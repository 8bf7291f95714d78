// A photon map: records at points, added by the threads of a pass as light paths are traced,
// then indexed once and queried from many threads for the records within a radius. It is the
// photon lookup of photon mapping and the merge of vertex merging.
//
// Two searches sit behind it. The default is the hashed grid of the VCM paper (hash_grid.h),
// which sorts the photons into its bucket order in place. The photons then cost their own
// bytes, plus 1 byte each for the bucket table. The other
// is FLANN's kd-tree (flann_kd_tree.h), which copies the positions into a tree of its own.
//
// Queries see photons in an order that depends only on the set of photons, never on which
// thread traced which path or on the thread count. Rendered images thus do not change with the
// thread count, although floating-point sums depend on their order. Both searches sort the
// photons by value (the grid within each bucket, the tree before it is built), and then
// visit them in an order fixed by the structure.
//
// A point is found when its float squared distance to the center, (dx*dx + dy*dy) + dz*dz, is
// strictly less than radius*radius, so radius 0 finds nothing and points exactly at the radius
// are left out. Points, centers and radii are assumed finite; at most 2^32 - 1 photons.
#pragma once

#include "integrators/integrator.h"
#include "spatial/block_storage.h"
#include "spatial/flann_kd_tree.h"
#include "spatial/hash_grid.h"

#include <tbb/enumerable_thread_specific.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <cstring>
#include <memory>
#include <span>
#include <stdexcept>
#include <vector>

namespace caustica {

enum class PhotonSearch { HashGrid, FlannKdTree };

template <class Record> class PhotonMap {
  public:
    struct Photon {
        Vec3f p;
        Record record;
    };
    // Photons are compared word for word, which orders them by value only if they hold no
    // padding. (Records are expected to be packed as well: see each record's own assertion.)
    static_assert(sizeof(Photon) == sizeof(Vec3f) + sizeof(Record), "a photon must not hold padding");
    static_assert(sizeof(Photon) % sizeof(uint32_t) == 0, "photons are compared as 32-bit words");

    // Maps filled in the same passes share their blocks' pool (block_storage.h) to peak lower.
    using Pool = typename BlockStorage<Photon>::Pool;
    explicit PhotonMap(PhotonSearch search = PhotonSearch::HashGrid, std::shared_ptr<Pool> pool = nullptr)
        : search_(search), storage_(std::move(pool)) {}

    // Empties the map for the next pass, keeping its memory.
    void clear() { storage_.clear(); }
    // Safe from any number of threads at once, between clear() and build().
    void add(Vec3f p, const Record &record) { storage_.push_back(Photon{p, record}); }
    // A distributed render: replaces the photons this rank added to each map since clear() with
    // those every rank added to it (RenderShare::gather_all, one exchange for all the maps;
    // collective: every rank passes its maps in the same order), so that each rank's maps hold
    // them all, and their queries see the same photons in the same order as one process's maps.
    static void gather(std::span<PhotonMap *const> maps, const RenderShare &share) {
        if (share.ranks() == 1) return;
        // Each rank's bytes: per map, its photon count, then its photons.
        std::vector<char> mine;
        auto append = [&](const void *data, size_t bytes) {
            mine.insert(mine.end(), static_cast<const char *>(data), static_cast<const char *>(data) + bytes);
        };
        for (PhotonMap *map : maps) {
            map->storage_.close();
            const uint64_t count = map->storage_.size();
            append(&count, sizeof(count));
            for (size_t i = 0; i < count; ++i) append(&map->storage_[i], sizeof(Photon));
        }
        const std::vector<char> all = share.gather_all(std::move(mine));
        for (PhotonMap *map : maps) map->storage_.clear();
        // The ranks' bytes follow one another in rank order, so each map receives rank 0's photons,
        // then rank 1's, and so on.
        size_t offset = 0;
        auto read = [&](void *data, size_t bytes) {
            if (offset + bytes > all.size()) throw std::runtime_error("PhotonMap::gather: truncated exchange");
            std::memcpy(data, &all[offset], bytes);
            offset += bytes;
        };
        while (offset < all.size())
            for (PhotonMap *map : maps) {
                uint64_t count;
                read(&count, sizeof(count));
                for (uint64_t i = 0; i < count; ++i) {
                    Photon photon;
                    read(&photon, sizeof(Photon));
                    map->storage_.push_back(photon);
                }
            }
    }
    // Indexes the photons added since clear() for queries of radius at most max_radius.
    void build(float max_radius) {
        storage_.close();
        if (search_ == PhotonSearch::HashGrid) {
            grid_.build(storage_.begin(), storage_.end(), max_radius, [](const Photon &photon) { return photon.p; },
                        value_less);
            return;
        }
        std::sort(storage_.begin(), storage_.end(), value_less);
        std::vector<Vec3f> positions(storage_.size());
        for (size_t i = 0; i < positions.size(); ++i) positions[i] = storage_[i].p;
        tree_.build(positions, max_radius); // the tree keeps a copy
    }

    // Calls visit(record) for every photon within radius of center; thread-safe after build().
    // Requires 0 <= radius <= max_radius (std::invalid_argument otherwise).
    template <class Visit> void for_each_within(Vec3f center, float radius, Visit visit) const {
        if (search_ == PhotonSearch::HashGrid) {
            const float radius2 = radius * radius;
            std::array<HashGrid::Range, 27> ranges;
            const int count = grid_.candidate_ranges(center, radius, ranges);
            // Each range's photons are contiguous, but the ranges are far apart: start loading the
            // first photons of all of them before testing any (as for the buckets themselves).
            for (int i = 0; i < count; ++i) __builtin_prefetch(&storage_[ranges[i].begin]);
            for (int i = 0; i < count; ++i)
                for (auto it = storage_.begin() + ranges[i].begin, last = storage_.begin() + ranges[i].end; it != last; ++it)
                    if (distance_squared(it->p, center) < radius2) visit(it->record);
            return;
        }
        std::vector<uint32_t> &found = found_.local();
        tree_.find_within(center, radius, found);
        for (uint32_t index : found) visit(storage_[index].record);
    }

    size_t size() const { return storage_.size(); }
    // The photons' blocks and the search structure.
    size_t memory_bytes() const {
        return storage_.memory_bytes() +
               (search_ == PhotonSearch::HashGrid ? grid_.memory_bytes() : tree_.memory_bytes());
    }

  private:
    // A total order on the photons' values: their 32-bit words compared in turn (inline, unlike
    // memcmp, which made the sort twice as slow; the first word, x, nearly always decides).
    static bool value_less(const Photon &a, const Photon &b) {
        using Words = std::array<uint32_t, sizeof(Photon) / sizeof(uint32_t)>;
        const Words wa = std::bit_cast<Words>(a), wb = std::bit_cast<Words>(b);
        return std::lexicographical_compare(wa.begin(), wa.end(), wb.begin(), wb.end());
    }

    PhotonSearch search_;
    BlockStorage<Photon> storage_;
    HashGrid grid_;
    FlannKdTree tree_;
    // Each querying thread's indices from the tree.
    mutable tbb::enumerable_thread_specific<std::vector<uint32_t>> found_;
};

} // namespace caustica
