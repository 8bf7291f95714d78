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
// Photons may carry identities (WithIds): a caller that must find particular photons again after
// build() has reordered them (vcm finds the photons of one light path, to connect to them) takes
// consecutive identities for them when it adds them, and looks each up by identity (by_id). The
// identity lives in the photon beside its point, and build() turns the identities into a table
// in place: after sorting, photon i holds the identity of the photon that stands at i, a
// permutation, which is inverted so that photon k holds where the photon of identity k now
// stands. It costs 4 bytes a photon, and the search order ignores it.
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
#include <atomic>
#include <cstddef>
#include <bit>
#include <cstdint>
#include <cstring>
#include <memory>
#include <span>
#include <stdexcept>
#include <type_traits>
#include <vector>

namespace caustica {

enum class PhotonSearch { HashGrid, FlannKdTree };

template <class Record> struct PlacedRecord {
    Vec3f p;
    Record record;
};
template <class Record> struct IdentifiedRecord {
    Vec3f p;
    uint32_t id; // see above: an identity while photons are added, a position after build()
    Record record;
};

template <class Record, bool WithIds = false> class PhotonMap {
  public:
    using Photon = std::conditional_t<WithIds, IdentifiedRecord<Record>, PlacedRecord<Record>>;
    // Photons are compared word for word, which orders them by value only if they hold no
    // padding. (Records are expected to be packed as well: see each record's own assertion.)
    static_assert(sizeof(Photon) == sizeof(Vec3f) + (WithIds ? sizeof(uint32_t) : 0) + sizeof(Record),
                  "a photon must not hold padding");
    static_assert(sizeof(Photon) % sizeof(uint32_t) == 0, "photons are compared as 32-bit words");

    // Maps filled in the same passes share their blocks' pool (block_storage.h) to peak lower.
    using Pool = typename BlockStorage<Photon>::Pool;
    explicit PhotonMap(PhotonSearch search = PhotonSearch::HashGrid, std::shared_ptr<Pool> pool = nullptr)
        : search_(search), storage_(std::move(pool)) {}

    // Empties the map for the next pass, keeping its memory.
    void clear() {
        storage_.clear();
        next_id_ = 0;
    }
    // Safe from any number of threads at once, between clear() and build().
    void add(Vec3f p, const Record &record)
        requires(!WithIds)
    {
        storage_.push_back(Photon{p, record});
    }
    // Identities for the next `count` photons: [first, first + count), the returned first. Every
    // identity taken must be given to one photon (add) before build(). Safe from any number of
    // threads at once.
    uint32_t take_ids(uint32_t count)
        requires WithIds
    {
        const uint64_t first = next_id_.fetch_add(count);
        if (first + count >= uint64_t(1) << 31) throw std::length_error("PhotonMap: more than 2^31 - 1 photons");
        return uint32_t(first);
    }
    void add(Vec3f p, uint32_t id, const Record &record)
        requires WithIds
    {
        storage_.push_back(Photon{p, id, record});
    }
    // The photon given identity id, after build().
    const Photon &by_id(uint32_t id) const
        requires WithIds
    {
        return storage_[storage_[id].id];
    }
    // A distributed render: replaces the photons this rank added to each map since clear() with
    // those every rank added to it (RenderShare::gather_all, one exchange for all the maps;
    // collective: every rank passes its maps in the same order), so that each rank's maps hold
    // them all, and their queries see the same photons in the same order as one process's maps.
    // (Identities would collide across ranks: maps with them are not gathered.)
    static void gather(std::span<PhotonMap *const> maps, const RenderShare &share)
        requires(!WithIds)
    {
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
        } else {
            std::sort(storage_.begin(), storage_.end(), value_less);
            std::vector<Vec3f> positions(storage_.size());
            for (size_t i = 0; i < positions.size(); ++i) positions[i] = storage_[i].p;
            tree_.build(positions, max_radius); // the tree keeps a copy
        }
        // take_ids() has kept the identities, one per photon, below 2^31.
        if constexpr (WithIds) invert_ids();
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
    // memcmp, which made the sort twice as slow; the first word, x, nearly always decides). An
    // identity is not a value (it depends on the order threads added photons in), so it is
    // skipped: photons equal in all else are interchangeable.
    static bool value_less(const Photon &a, const Photon &b) {
        using Words = std::array<uint32_t, sizeof(Photon) / sizeof(uint32_t)>;
        const Words wa = std::bit_cast<Words>(a), wb = std::bit_cast<Words>(b);
        constexpr size_t id_word = WithIds ? offsetof(IdentifiedRecord<Record>, id) / sizeof(uint32_t) : wa.size();
        for (size_t i = 0; i < wa.size(); ++i) {
            if (i == id_word || wa[i] == wb[i]) continue;
            return wa[i] < wb[i];
        }
        return false;
    }

    // After sorting, photon i holds the identity of the photon standing at i: a permutation of
    // [0, size()), inverted here in place, cycle by cycle (marking each entry done by setting
    // its top bit, which identities below 2^31 leave clear), so that photon k holds the
    // position of the photon of identity k.
    void invert_ids() {
        constexpr uint32_t done = 1u << 31;
        const uint32_t n = uint32_t(storage_.size());
        for (uint32_t start = 0; start < n; ++start) {
            if (storage_[start].id & done) continue;
            // Along the cycle start -> id(start) -> ...: the photon at `at` has identity `next`,
            // so the entry of identity `next` becomes `at`.
            uint32_t at = start, next = storage_[start].id;
            while (next != start) {
                const uint32_t following = storage_[next].id;
                storage_[next].id = at | done;
                at = next;
                next = following;
            }
            storage_[start].id = at | done;
        }
        for (uint32_t i = 0; i < n; ++i) storage_[i].id &= ~done;
    }

    PhotonSearch search_;
    BlockStorage<Photon> storage_;
    std::atomic<uint64_t> next_id_{0};
    HashGrid grid_;
    FlannKdTree tree_;
    // Each querying thread's indices from the tree.
    mutable tbb::enumerable_thread_specific<std::vector<uint32_t>> found_;
};

} // namespace caustica
