// The photon map with both searches against brute force: the expected neighbours of every query
// are computed here by testing every point with the documented convention (float squared
// distance strictly below radius * radius), independently of either structure. Each photon's
// record is its index among the points.
#include "core/rng.h"
#include "spatial/photon_map.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>
#include <thread>

namespace caustica {
namespace {

std::vector<uint32_t> brute_force(std::span<const Vec3f> points, Vec3f center, float radius) {
    std::vector<uint32_t> within;
    for (size_t i = 0; i < points.size(); ++i)
        if (distance_squared(points[i], center) < radius * radius) within.push_back(uint32_t(i));
    return within;
}

using IndexMap = PhotonMap<uint32_t>;

std::vector<uint32_t> visited(const IndexMap &map, Vec3f center, float radius) {
    std::vector<uint32_t> found;
    map.for_each_within(center, radius, [&](uint32_t index) { found.push_back(index); });
    return found;
}

std::vector<uint32_t> sorted_query(const IndexMap &map, Vec3f center, float radius) {
    std::vector<uint32_t> found = visited(map, center, radius);
    std::sort(found.begin(), found.end());
    return found;
}

void build(IndexMap &map, std::span<const Vec3f> points, float max_radius) {
    map.clear();
    for (size_t i = 0; i < points.size(); ++i) map.add(points[i], uint32_t(i));
    map.build(max_radius);
}

Vec3f uniform_in_box(Rng &rng, Vec3f lo, Vec3f hi) {
    return {lerp(rng.uniform(), lo.x, hi.x), lerp(rng.uniform(), lo.y, hi.y),
            lerp(rng.uniform(), lo.z, hi.z)};
}

// Queries at random points of the data's bounds grown by the radius (so some balls straddle the
// border and some miss everything) and at data points themselves, each with the full radius and
// with a third of it. Returns the total number of neighbours found, so callers can make sure a
// test is not vacuous.
size_t expect_matches_brute_force(IndexMap &map, std::span<const Vec3f> points, float max_radius,
                                  uint64_t seed) {
    build(map, points, max_radius);
    Bounds3f bounds;
    for (Vec3f p : points) bounds.expand(p);
    Vec3f margin(max_radius, max_radius, max_radius);
    Rng rng(seed, 1);
    size_t found = 0;
    for (int q = 0; q < 400; ++q) {
        Vec3f center = q % 2 == 0 ? uniform_in_box(rng, bounds.lo - margin, bounds.hi + margin)
                                  : points[rng.next_uint32() % points.size()];
        for (float radius : {max_radius, max_radius / 3}) {
            std::vector<uint32_t> expected = brute_force(points, center, radius);
            EXPECT_EQ(sorted_query(map, center, radius), expected)
                << "query " << q << " at (" << center.x << ", " << center.y << ", " << center.z
                << ") radius " << radius;
            found += expected.size();
        }
    }
    return found;
}

class PhotonMapTest : public testing::TestWithParam<PhotonSearch> {
  protected:
    IndexMap map{GetParam()};
};

TEST_P(PhotonMapTest, UniformCloud) {
    Rng rng(1, 2);
    std::vector<Vec3f> points(20000);
    for (Vec3f &p : points) p = uniform_in_box(rng, {-1, -1, -1}, {1, 1, 1});
    // 20000 points in a volume of 8: a ball of radius 0.1 holds about 10 on average.
    EXPECT_GT(expect_matches_brute_force(map, points, 0.1f, 3), 2000u);
}

TEST_P(PhotonMapTest, ClusteredCloud) {
    // Dense clusters (thousands of points per grid cell) over a sparse background.
    Rng rng(4, 5);
    std::vector<Vec3f> points;
    for (int cluster = 0; cluster < 5; ++cluster) {
        Vec3f c = uniform_in_box(rng, {-10, -10, -10}, {10, 10, 10});
        for (int i = 0; i < 3000; ++i)
            points.push_back(c +
                             uniform_in_box(rng, {-0.02f, -0.02f, -0.02f}, {0.02f, 0.02f, 0.02f}));
    }
    for (int i = 0; i < 2000; ++i)
        points.push_back(uniform_in_box(rng, {-10, -10, -10}, {10, 10, 10}));
    EXPECT_GT(expect_matches_brute_force(map, points, 0.05f, 6), 10000u);
}

TEST_P(PhotonMapTest, PointsOnAPlane) {
    // Photons on a floor: no extent at all along z.
    Rng rng(7, 8);
    std::vector<Vec3f> points(20000);
    for (Vec3f &p : points) p = uniform_in_box(rng, {-3, -2, 0.5f}, {5, 2, 0.5f});
    EXPECT_GT(expect_matches_brute_force(map, points, 0.1f, 9), 2000u);
}

TEST_P(PhotonMapTest, NegativeAndLargeCoordinates) {
    // A dense cloud near (-1e5, 1e5, -1e5) plus outliers at the corners of [-1e5, 1e5]^3.
    Rng rng(10, 11);
    std::vector<Vec3f> points;
    for (int i = 0; i < 20000; ++i)
        points.push_back(
            uniform_in_box(rng, {-1e5f, 1e5f - 20, -1e5f}, {-1e5f + 20, 1e5f, -1e5f + 20}));
    for (float x : {-1e5f, 1e5f})
        for (float y : {-1e5f, 1e5f})
            for (float z : {-1e5f, 1e5f}) points.push_back({x, y, z});
    EXPECT_GT(expect_matches_brute_force(map, points, 1.f, 12), 2000u);
}

TEST_P(PhotonMapTest, TinyRadiusInHugeScene) {
    // The radius is far below the float spacing of the outliers' coordinates: the grid must cap
    // its cell count and still find everything near the origin.
    Rng rng(13, 14);
    std::vector<Vec3f> points;
    for (int i = 0; i < 20000; ++i)
        points.push_back(uniform_in_box(rng, {-0.01f, -0.01f, -0.01f}, {0.01f, 0.01f, 0.01f}));
    points.push_back({-1e5f, -1e5f, -1e5f});
    points.push_back({1e5f, 1e5f, 1e5f});
    // About 10 neighbours within 1e-3 of a data point; the random queries mostly find nothing.
    EXPECT_GT(expect_matches_brute_force(map, points, 1e-3f, 15), 1000u);
}

TEST_P(PhotonMapTest, PointsExactlyAtTheRadiusAreExcluded) {
    // Dyadic values keep every coordinate, difference and squared distance exact (or, for the
    // inner points, rounded to a float still below radius^2), so the expected sets follow from
    // the geometry: the center and points 2^-20 inside the sphere are found, points exactly on
    // it are not.
    Vec3f center(0.25f, -0.5f, 1);
    float radius = 0.5f;
    std::vector<Vec3f> points = {center};
    std::vector<uint32_t> expected = {0};
    for (int axis = 0; axis < 3; ++axis)
        for (float sign : {-1.f, 1.f}) {
            Vec3f on = center, inside = center, outside = center;
            on[axis] += sign * radius;
            inside[axis] = on[axis] - sign * 0x1p-20f;
            outside[axis] += sign * 2 * radius;
            expected.push_back(uint32_t(points.size() + 1));
            points.insert(points.end(), {on, inside, outside});
        }
    build(map, points, radius);
    EXPECT_EQ(sorted_query(map, center, radius), expected);
    // Radius 0 finds nothing, not even a point at the center.
    EXPECT_TRUE(sorted_query(map, center, 0).empty());
    // Around a point on the sphere: itself and its neighbour 2^-20 inward, nothing else (the
    // center and the other points are half a radius or more away).
    EXPECT_EQ(sorted_query(map, points[1], radius / 4), (std::vector<uint32_t>{1, 2}));
}

TEST_P(PhotonMapTest, EmptySet) {
    build(map, {}, 1);
    EXPECT_TRUE(sorted_query(map, {0, 0, 0}, 1).empty());
    EXPECT_EQ(map.memory_bytes(), 0u);
}

TEST_P(PhotonMapTest, IdenticalPoints) {
    std::vector<Vec3f> points(1000, Vec3f(1, -2, 3));
    std::vector<uint32_t> all(points.size());
    for (size_t i = 0; i < all.size(); ++i) all[i] = uint32_t(i);
    build(map, points, 0.1f);
    EXPECT_EQ(sorted_query(map, {1, -2, 3}, 0.1f), all);
    EXPECT_EQ(sorted_query(map, {1.05f, -2, 3}, 0.1f), all);
    EXPECT_TRUE(sorted_query(map, {1.2f, -2, 3}, 0.1f).empty());
    // A zero maximum radius is legal and finds nothing.
    build(map, points, 0);
    EXPECT_TRUE(sorted_query(map, {1, -2, 3}, 0).empty());
}

TEST_P(PhotonMapTest, RepeatedBuildsWithDifferentRadii) {
    Rng rng(16, 17);
    std::vector<Vec3f> first(5000), second(12000);
    for (Vec3f &p : first) p = uniform_in_box(rng, {0, 0, 0}, {1, 1, 1});
    for (Vec3f &p : second) p = uniform_in_box(rng, {-4, 2, -1}, {-2, 3, 0});
    EXPECT_GT(expect_matches_brute_force(map, first, 0.1f, 18), 1000u);
    EXPECT_GT(expect_matches_brute_force(map, second, 0.2f, 19), 1000u);
    EXPECT_GT(expect_matches_brute_force(map, first, 0.05f, 20), 100u);
}

TEST_P(PhotonMapTest, RejectsRadiusAboveMaximum) {
    std::vector<Vec3f> points = {{0, 0, 0}};
    build(map, points, 0.5f);
    EXPECT_THROW(visited(map, {0, 0, 0}, 0.6f), std::invalid_argument);
    EXPECT_THROW(visited(map, {0, 0, 0}, -0.1f), std::invalid_argument);
}

TEST_P(PhotonMapTest, ConcurrentQueriesAgree) {
    Rng rng(21, 22);
    std::vector<Vec3f> points(50000);
    for (Vec3f &p : points) p = uniform_in_box(rng, {-1, -1, -1}, {1, 1, 1});
    float radius = 0.08f;
    build(map, points, radius);
    std::vector<Vec3f> centers(2000);
    for (Vec3f &c : centers) c = uniform_in_box(rng, {-1, -1, -1}, {1, 1, 1});

    // Every thread runs all queries, starting at a different offset so that different threads
    // work on different queries at the same moment.
    constexpr int thread_count = 4;
    std::vector<std::vector<std::vector<uint32_t>>> results(thread_count);
    std::vector<std::thread> threads;
    for (int t = 0; t < thread_count; ++t)
        threads.emplace_back([&, t] {
            results[t].resize(centers.size());
            for (size_t i = 0; i < centers.size(); ++i) {
                size_t q = (i + t * centers.size() / thread_count) % centers.size();
                results[t][q] = sorted_query(map, centers[q], radius);
            }
        });
    for (std::thread &thread : threads) thread.join();
    for (size_t q = 0; q < centers.size(); ++q) {
        std::vector<uint32_t> expected = brute_force(points, centers[q], radius);
        for (int t = 0; t < thread_count; ++t) ASSERT_EQ(results[t][q], expected) << "thread " << t;
    }
}

// Photons added from several threads at once, in an order that differs from run to run, and
// with counts that leave blocks partly filled: every query must still visit the same photons in
// the same order as after adding them one by one in reverse, and find what brute force finds.
TEST_P(PhotonMapTest, QueriesDoNotDependOnWhoAddedWhat) {
    Rng rng(23, 24);
    std::vector<Vec3f> points(30011);
    // Clustered, so that buckets hold many photons whose order matters.
    for (Vec3f &p : points) p = uniform_in_box(rng, {0, 0, 0}, {0.3f, 0.3f, 0.3f});
    const float radius = 0.02f;
    IndexMap serial{GetParam()};
    serial.clear();
    for (size_t i = points.size(); i-- > 0;) serial.add(points[i], uint32_t(i));
    serial.build(radius);

    constexpr int thread_count = 3;
    for (int round = 0; round < 2; ++round) {
        map.clear();
        std::vector<std::thread> threads;
        for (int t = 0; t < thread_count; ++t)
            threads.emplace_back([&, t] {
                // Interleaved, each round dealing the points out differently.
                for (size_t i = 0; i < points.size(); ++i)
                    if ((i + size_t(round)) % thread_count == size_t(t)) map.add(points[i], uint32_t(i));
            });
        for (std::thread &thread : threads) thread.join();
        map.build(radius);
        ASSERT_EQ(map.size(), points.size());
        size_t found = 0;
        for (int q = 0; q < 300; ++q) {
            Vec3f center = points[rng.next_uint32() % points.size()];
            std::vector<uint32_t> order = visited(map, center, radius);
            ASSERT_EQ(order, visited(serial, center, radius)) << "round " << round << " query " << q;
            std::sort(order.begin(), order.end());
            ASSERT_EQ(order, brute_force(points, center, radius));
            found += order.size();
        }
        EXPECT_GT(found, 300u * 20); // about 37 a query
    }
}

// Photons with identities (vcm's kept light vertices): threads take identities in runs of
// random length and add their photons, each record holding the point's index. After build(),
// by_id must find every photon by the identity it was given, and queries must visit the records
// in the same order as a map without identities filled one by one: the identity, which depends
// on which thread came first, is not part of the order. Many photons share a point, so that the
// order among them rests on their records alone. Negative controls (one run each, then undone):
// leaving the identities uninverted fails the look-ups; ordering by the identity too fails the
// visiting order.
TEST_P(PhotonMapTest, IdentitiesFindTheirPhotonsWhoeverAddedThem) {
    Rng rng(31, 32);
    std::vector<Vec3f> spots(97);
    for (Vec3f &p : spots) p = uniform_in_box(rng, {0, 0, 0}, {0.3f, 0.3f, 0.3f});
    std::vector<Vec3f> points(20011);
    for (size_t i = 0; i < points.size(); ++i) points[i] = spots[i % spots.size()];
    const float radius = 0.05f;
    IndexMap serial{GetParam()};
    for (size_t i = 0; i < points.size(); ++i) serial.add(points[i], uint32_t(i));
    serial.build(radius);

    PhotonMap<uint32_t, true> identified{GetParam()};
    constexpr int thread_count = 3;
    for (int round = 0; round < 2; ++round) {
        identified.clear();
        std::vector<uint32_t> point_of_id(points.size(), ~0u);
        std::vector<std::thread> threads;
        for (int t = 0; t < thread_count; ++t)
            threads.emplace_back([&, t] {
                Rng own{uint64_t(round), uint64_t(t)};
                std::vector<uint32_t> mine;
                for (size_t i = 0; i < points.size(); ++i)
                    if ((i + size_t(round)) % thread_count == size_t(t)) mine.push_back(uint32_t(i));
                for (size_t next = 0; next < mine.size();) {
                    const uint32_t run = std::min<uint32_t>(1 + own.next_uint32() % 9, uint32_t(mine.size() - next));
                    const uint32_t first = identified.take_ids(run);
                    for (uint32_t k = 0; k < run; ++k, ++next) {
                        point_of_id[first + k] = mine[next];
                        identified.add(points[mine[next]], first + k, mine[next]);
                    }
                }
            });
        for (std::thread &thread : threads) thread.join();
        identified.build(radius);
        ASSERT_EQ(identified.size(), points.size());
        for (uint32_t id = 0; id < points.size(); ++id) {
            const auto &photon = identified.by_id(id);
            ASSERT_EQ(photon.record, point_of_id[id]) << "round " << round << " identity " << id;
            ASSERT_EQ(photon.p, points[point_of_id[id]]);
        }
        size_t found = 0;
        for (const Vec3f &center : spots) {
            std::vector<uint32_t> order;
            identified.for_each_within(center, radius, [&](uint32_t index) { order.push_back(index); });
            ASSERT_EQ(order, visited(serial, center, radius)) << "round " << round;
            found += order.size();
        }
        EXPECT_GT(found, points.size());
    }
}

INSTANTIATE_TEST_SUITE_P(Searches, PhotonMapTest, testing::Values(PhotonSearch::HashGrid, PhotonSearch::FlannKdTree),
                         [](const testing::TestParamInfo<PhotonSearch> &info) {
                             return info.param == PhotonSearch::HashGrid ? "hashgrid" : "flann";
                         });

} // namespace
} // namespace caustica
