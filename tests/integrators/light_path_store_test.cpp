// LightPathStore (integrators/vcm/light_path_store.h): every path comes back whole and in order,
// including the paths that cross from one chunk into the next and paths longer than a chunk, and
// the spans handed out stay valid while later paths are added, until clear().
#include "integrators/vcm/light_path_store.h"

#include <gtest/gtest.h>

#include <vector>

namespace caustica {
namespace {

// A vertex that names its path and its place on it.
StoredLightVertex vertex(int path, int index) {
    StoredLightVertex v{};
    v.d_vcm = float(path);
    v.d_vc = float(index);
    return v;
}

// Adds paths of the given lengths, keeping the span of each.
std::vector<std::span<const StoredLightVertex>> add_paths(LightPathStore &store, const std::vector<int> &lengths) {
    std::vector<std::span<const StoredLightVertex>> spans;
    for (size_t p = 0; p < lengths.size(); ++p) {
        store.start_path();
        for (int i = 0; i < lengths[p]; ++i) store.push_back(vertex(int(p), i));
        spans.push_back(store.path());
    }
    return spans;
}

void expect_paths(const std::vector<std::span<const StoredLightVertex>> &spans, const std::vector<int> &lengths) {
    ASSERT_EQ(spans.size(), lengths.size());
    for (size_t p = 0; p < spans.size(); ++p) {
        ASSERT_EQ(spans[p].size(), size_t(lengths[p])) << "path " << p;
        for (int i = 0; i < lengths[p]; ++i) {
            EXPECT_EQ(spans[p][i].d_vcm, float(p)) << "path " << p << " vertex " << i;
            EXPECT_EQ(spans[p][i].d_vc, float(i)) << "path " << p << " vertex " << i;
        }
    }
}

TEST(LightPathStore, PathsStayWholeAcrossChunks) {
    // Lengths 0 to 6 over many chunks: some paths fill a chunk exactly, others straddle its end.
    std::vector<int> lengths;
    size_t total = 0;
    for (int p = 0; total < 5 * LightPathStore::ChunkCapacity; ++p) {
        lengths.push_back(p % 7);
        total += size_t(p % 7);
    }
    LightPathStore store;
    const auto spans = add_paths(store, lengths);
    EXPECT_EQ(store.size(), total);
    expect_paths(spans, lengths);
}

TEST(LightPathStore, APathLongerThanAChunkIsKeptWhole) {
    const int long_path = int(3 * LightPathStore::ChunkCapacity + 5);
    const std::vector<int> lengths{3, long_path, 2, long_path, 1};
    LightPathStore store;
    const auto spans = add_paths(store, lengths);
    expect_paths(spans, lengths);
}

TEST(LightPathStore, ClearForgetsThePathsAndReusesTheChunks) {
    const std::vector<int> first(3000, 5), second(2000, 4);
    LightPathStore store;
    const auto old_spans = add_paths(store, first);
    const StoredLightVertex *first_vertex = old_spans.front().data();
    store.clear();
    EXPECT_EQ(store.size(), 0u);
    EXPECT_TRUE(store.path().empty());
    const auto spans = add_paths(store, second);
    EXPECT_EQ(store.size(), 2000u * 4u);
    EXPECT_EQ(spans.front().data(), first_vertex); // the same memory, written again
    expect_paths(spans, second);
}

TEST(LightPathStore, AnEmptyPathIsEmpty) {
    LightPathStore store;
    store.start_path();
    EXPECT_TRUE(store.path().empty());
    add_paths(store, {4});
    store.start_path();
    EXPECT_TRUE(store.path().empty());
}

} // namespace
} // namespace caustica
