// A per-thread bump allocator for objects that live for one path sample (BxDFs, BSDF records).
// Resetting after each sample avoids heap traffic on the hot path.
#pragma once

#include <cstddef>
#include <cstdlib>
#include <memory>
#include <new>
#include <type_traits>
#include <vector>

namespace caustica {

// Cache-line aligned for the reason Sampler is (sampler/sampler.h): its offset changes with every
// allocation.
class alignas(64) ScratchBuffer {
  public:
    explicit ScratchBuffer(size_t size = 64 * 1024) : size_(size) { block_ = allocate_block(size_); }
    ScratchBuffer(const ScratchBuffer &) = delete;
    ScratchBuffer &operator=(const ScratchBuffer &) = delete;
    ~ScratchBuffer() {
        reset();
        std::free(block_);
    }

    void *allocate(size_t bytes, size_t align) {
        offset_ = (offset_ + align - 1) & ~(align - 1);
        if (offset_ + bytes > size_) {
            // Keep the full block alive until reset, then grow to the larger size.
            retired_.push_back(block_);
            size_ = std::max(2 * size_, bytes + align);
            block_ = allocate_block(size_);
            offset_ = 0;
        }
        void *p = block_ + offset_;
        offset_ += bytes;
        return p;
    }

    // Objects must be trivially destructible: reset() never runs destructors.
    template <typename T, typename... Args> T *make(Args &&...args) {
        static_assert(std::is_trivially_destructible_v<T>, "scratch objects are never destroyed");
        return new (allocate(sizeof(T), alignof(T))) T(std::forward<Args>(args)...);
    }

    void reset() {
        for (char *b : retired_) std::free(b);
        retired_.clear();
        offset_ = 0;
    }

  private:
    static char *allocate_block(size_t size) {
        auto *p = static_cast<char *>(std::aligned_alloc(64, (size + 63) & ~size_t(63)));
        if (!p) throw std::bad_alloc();
        return p;
    }
    char *block_ = nullptr;
    size_t size_ = 0, offset_ = 0;
    std::vector<char *> retired_;
};

} // namespace caustica
