// BlockStorage: what several threads append comes out as one sequence holding exactly those
// records, packed into as few blocks as they need, and cleared storages hand their blocks on
// through a shared pool.
#include "spatial/block_storage.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <thread>
#include <vector>

namespace caustica {
namespace {

using Storage = BlockStorage<uint64_t>;
constexpr size_t Block = Storage::BlockSize;

// Appends [0, count) from thread_count threads, record i from thread i % thread_count, and
// returns the sequence after close().
std::vector<uint64_t> fill_from_threads(Storage &storage, size_t count, int thread_count) {
    storage.clear();
    std::vector<std::thread> threads;
    for (int t = 0; t < thread_count; ++t)
        threads.emplace_back([&, t] {
            for (size_t i = size_t(t); i < count; i += size_t(thread_count)) storage.push_back(i);
        });
    for (std::thread &thread : threads) thread.join();
    storage.close();
    return std::vector<uint64_t>(storage.begin(), storage.end());
}

TEST(BlockStorage, ThreadsRecordsFormOnePackedSequence) {
    Storage storage;
    // Counts that leave each thread's last block partly filled, and one that fills them all.
    for (size_t count : {size_t(0), size_t(1), Block - 1, 3 * Block + 7, size_t(10000), 4 * Block}) {
        std::vector<uint64_t> records = fill_from_threads(storage, count, 3);
        ASSERT_EQ(storage.size(), count);
        std::sort(records.begin(), records.end());
        for (size_t i = 0; i < count; ++i) ASSERT_EQ(records[i], i) << "count " << count;
        // Packed: the partly filled blocks' records were moved together at the end.
        EXPECT_EQ(storage.memory_bytes(), (count + Block - 1) / Block * Block * sizeof(uint64_t)) << count;
        // Indexing and iterators address the same records.
        for (size_t i = 0; i < count; i += 97) EXPECT_EQ(&storage[i], &*(storage.begin() + std::ptrdiff_t(i)));
    }
}

TEST(BlockStorage, TheSequenceCanBeSortedInPlace) {
    Storage storage;
    fill_from_threads(storage, 5000, 2);
    std::sort(storage.begin(), storage.end(), std::greater<>());
    for (size_t i = 0; i < storage.size(); ++i) ASSERT_EQ(storage[i], 4999 - i);
}

TEST(BlockStorage, ClearedBlocksAreReusedThroughASharedPool) {
    auto pool = std::make_shared<Storage::Pool>();
    Storage first(pool), second(pool);
    fill_from_threads(first, 4 * Block, 1);
    std::set<const uint64_t *> first_blocks;
    for (size_t i = 0; i < first.size(); i += Block) first_blocks.insert(&first[i]);
    first.clear();
    fill_from_threads(second, 4 * Block, 1);
    for (size_t i = 0; i < second.size(); i += Block) EXPECT_TRUE(first_blocks.count(&second[i])) << i;
}

} // namespace
} // namespace caustica
