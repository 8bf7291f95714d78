// Storage for the records that the threads of a pass append concurrently (photons, as they are
// traced), read afterwards as one random-access sequence that may be reordered in place.
//
// The records live in fixed-size blocks that a thread claims one at a time and fills alone, so
// an append takes no lock (claiming a block does), nothing is moved to grow, and the storage
// costs at most one partly filled block per appending thread beyond its records: no copy into
// a final array, no doubling slack. close() then moves the records of the partly filled blocks
// into as few blocks as possible at the end, so that the records form the sequence [0, size()).
// The order of the blocks is the order threads claimed them in, which depends on scheduling:
// callers that need a fixed order sort the sequence.
#pragma once

#include <tbb/enumerable_thread_specific.h>

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <memory>
#include <mutex>
#include <type_traits>
#include <vector>

namespace caustica {

// Free blocks, for storages to claim. Storages that take turns growing (one per wavelength group,
// whose shares of a pass vary) share one pool, so that their memory peaks at the most they hold
// together rather than at the sum of what each one ever held. (Returning blocks to the
// allocator instead costs more: glibc's per-thread arenas then grow apart.)
template <class T, size_t BlockSize> class BlockPool {
  public:
    std::unique_ptr<T[]> take() {
        {
            std::lock_guard lock(mutex_);
            if (!free_.empty()) {
                std::unique_ptr<T[]> block = std::move(free_.back());
                free_.pop_back();
                return block;
            }
        }
        return std::make_unique_for_overwrite<T[]>(BlockSize);
    }
    void give(std::unique_ptr<T[]> block) {
        std::lock_guard lock(mutex_);
        free_.push_back(std::move(block));
    }

  private:
    std::mutex mutex_;
    std::vector<std::unique_ptr<T[]>> free_;
};

template <class T> class BlockStorage {
    static_assert(std::is_trivially_copyable_v<T>);

  public:
    // 128 records a block: with 2 threads appending to each of 32 maps (vcm's 16 wavelength
    // groups, on surfaces and in media), the partly filled blocks of a pass stay within 1.5
    // bytes a record at a few hundred thousand records, and claiming a block (a lock) is rare.
    static constexpr size_t BlockSize = 128;
    using Pool = BlockPool<T, BlockSize>;

    // With its own pool, or sharing one.
    explicit BlockStorage(std::shared_ptr<Pool> pool = nullptr) : pool_(pool ? std::move(pool) : std::make_shared<Pool>()) {}

    class iterator {
      public:
        using iterator_category = std::random_access_iterator_tag;
        using value_type = T;
        using difference_type = std::ptrdiff_t;
        using pointer = T *;
        using reference = T &;

        iterator() = default;
        iterator(T *const *blocks, size_t index) : blocks_(blocks), index_(index) {}
        T &operator*() const { return blocks_[index_ / BlockSize][index_ % BlockSize]; }
        T *operator->() const { return &**this; }
        T &operator[](difference_type d) const { return *(*this + d); }
        iterator &operator++() { ++index_; return *this; }
        iterator &operator--() { --index_; return *this; }
        iterator operator++(int) { iterator old = *this; ++index_; return old; }
        iterator operator--(int) { iterator old = *this; --index_; return old; }
        iterator &operator+=(difference_type d) { index_ = size_t(difference_type(index_) + d); return *this; }
        iterator &operator-=(difference_type d) { return *this += -d; }
        friend iterator operator+(iterator it, difference_type d) { return it += d; }
        friend iterator operator+(difference_type d, iterator it) { return it += d; }
        friend iterator operator-(iterator it, difference_type d) { return it -= d; }
        friend difference_type operator-(iterator a, iterator b) { return difference_type(a.index_) - difference_type(b.index_); }
        friend bool operator==(iterator a, iterator b) { return a.index_ == b.index_; }
        friend auto operator<=>(iterator a, iterator b) { return a.index_ <=> b.index_; }

      private:
        T *const *blocks_ = nullptr;
        size_t index_ = 0;
    };

    // Empties the storage, its blocks going back to the pool. Not concurrent with push_back.
    void clear() {
        for (std::unique_ptr<T[]> &block : blocks_) pool_->give(std::move(block));
        blocks_.clear();
        block_pointers_.clear();
        for (OpenBlock &open : open_) open = OpenBlock{};
        size_ = 0;
    }

    // Appends a record; safe from any number of threads at once, between clear() and close().
    void push_back(const T &value) {
        OpenBlock &open = open_.local();
        if (open.block == nullptr || open.count == BlockSize) open = OpenBlock{claim_block(), 0};
        open.block[open.count++] = value;
    }

    // Makes the records appended since clear() the sequence [begin(), end()).
    void close() {
        std::vector<T> partial;
        for (OpenBlock &open : open_) {
            if (open.block == nullptr) continue;
            if (open.count < BlockSize) {
                partial.insert(partial.end(), open.block, open.block + open.count);
                auto it = std::find_if(blocks_.begin(), blocks_.end(),
                                       [&](const std::unique_ptr<T[]> &b) { return b.get() == open.block; });
                pool_->give(std::move(*it));
                blocks_.erase(it);
            }
            open = OpenBlock{};
        }
        size_ = blocks_.size() * BlockSize;
        for (const T &value : partial) {
            if (size_ % BlockSize == 0) blocks_.push_back(pool_->take());
            blocks_.back()[size_++ % BlockSize] = value;
        }
        block_pointers_.clear();
        for (const std::unique_ptr<T[]> &block : blocks_) block_pointers_.push_back(block.get());
    }

    // The sequence, valid from close() to the next clear().
    size_t size() const { return size_; }
    iterator begin() const { return iterator(block_pointers_.data(), 0); }
    iterator end() const { return iterator(block_pointers_.data(), size_); }
    T &operator[](size_t i) const { return block_pointers_[i / BlockSize][i % BlockSize]; }

    size_t memory_bytes() const { return blocks_.size() * BlockSize * sizeof(T); }

  private:
    struct OpenBlock {
        T *block = nullptr;
        size_t count = 0;
    };

    T *claim_block() {
        std::unique_ptr<T[]> block = pool_->take();
        std::lock_guard lock(mutex_);
        return blocks_.emplace_back(std::move(block)).get();
    }

    std::shared_ptr<Pool> pool_;
    std::mutex mutex_;
    std::vector<std::unique_ptr<T[]>> blocks_;
    std::vector<T *> block_pointers_;
    tbb::enumerable_thread_specific<OpenBlock> open_;
    size_t size_ = 0;
};

} // namespace caustica
