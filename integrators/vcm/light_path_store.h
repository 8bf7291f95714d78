// The light vertices one thread keeps through an iteration of vcm, for the camera pass's
// connections: a path's vertices side by side, in chunks that never move.
//
// A growing std::vector copied every vertex each time it doubled, and touched fresh memory for
// every copy in the first iteration; it also left up to half its capacity unused. Here a full
// chunk is followed by the next, and only the path being traced (at most maxdepth vertices, plus
// the exits of jumps) moves into it, so that each path stays contiguous. clear() keeps the
// chunks, so later iterations write into memory already mapped.
#pragma once

#include "integrators/vcm/light_vertex.h"

#include <algorithm>
#include <cstddef>
#include <memory>
#include <span>
#include <vector>

namespace caustica {

class LightPathStore {
  public:
    // Vertices a chunk holds, unless one path needs more.
    static constexpr size_t ChunkCapacity = 4096;

    // Forgets every vertex; the chunks are kept for the next iteration.
    void clear() {
        chunk_ = 0;
        used_ = 0;
        path_begin_ = 0;
        size_ = 0;
    }

    // The vertices added from now on form the next path.
    void start_path() { path_begin_ = used_; }

    void push_back(const StoredLightVertex &v) {
        if (chunks_.empty() || used_ == chunks_[chunk_].capacity) next_chunk();
        chunks_[chunk_].vertices[used_++] = v;
        ++size_;
    }

    // The vertices added since start_path(); valid until clear().
    std::span<const StoredLightVertex> path() const {
        if (chunks_.empty()) return {};
        return {chunks_[chunk_].vertices.get() + path_begin_, used_ - path_begin_};
    }

    // Vertices kept since clear().
    size_t size() const { return size_; }

  private:
    struct Chunk {
        std::unique_ptr<StoredLightVertex[]> vertices;
        size_t capacity = 0;
    };

    // Moves the path being traced to the start of the next chunk (a new one, if none is kept or
    // the kept one is too small for it).
    void next_chunk() {
        const size_t path_length = used_ - path_begin_;
        const size_t needed = std::max(ChunkCapacity, 2 * (path_length + 1));
        const size_t next = chunks_.empty() ? 0 : chunk_ + 1;
        if (next == chunks_.size()) chunks_.push_back(Chunk{});
        Chunk &chunk = chunks_[next];
        if (chunk.capacity < needed) chunk = Chunk{std::make_unique<StoredLightVertex[]>(needed), needed};
        if (path_length > 0) {
            const StoredLightVertex *from = chunks_[chunk_].vertices.get() + path_begin_;
            std::copy(from, from + path_length, chunk.vertices.get());
        }
        chunk_ = next;
        path_begin_ = 0;
        used_ = path_length;
    }

    std::vector<Chunk> chunks_;
    size_t chunk_ = 0;      // the chunk being filled
    size_t used_ = 0;       // vertices in it
    size_t path_begin_ = 0; // where the current path starts in it
    size_t size_ = 0;
};

} // namespace caustica
