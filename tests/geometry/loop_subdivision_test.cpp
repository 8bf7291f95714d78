// pbrt-v4's "loopsubdiv" through OpenSubdiv: the refined triangle count, the limit surface of a
// closed mesh (inside the control hull, shrinking towards the sphere a regular mesh
// approximates), outward limit normals for outward winding, and bad input as errors.
#include "geometry/loop_subdivision.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace caustica {
namespace {

const SourceLocation kLoc{"scene.pbrt", 4, 9};

// An octahedron with outward (counter-clockwise seen from outside) winding.
const std::vector<Vec3f> kOctahedron = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
const std::vector<int> kOctahedronFaces = {0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4,
                                           2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5};

TEST(LoopSubdivision, RefinesFourfoldPerLevelOntoTheLimitSurface) {
    for (int levels : {0, 1, 3}) {
        MeshData m = loop_subdivide(kOctahedronFaces, kOctahedron, levels, kLoc);
        EXPECT_EQ(m.indices.size(), kOctahedronFaces.size() * size_t(std::pow(4, levels)));
        ASSERT_EQ(m.n.size(), m.p.size());
        for (size_t i = 0; i < m.p.size(); ++i) {
            float r = length(m.p[i]);
            // Inside the hull: Loop surfaces shrink towards the hull's centre.
            EXPECT_LT(r, 1.f);
            EXPECT_GT(r, 0.4f);
            // Outward normals, nearly radial on this symmetric surface.
            EXPECT_GT(dot(m.n[i], m.p[i] / r), 0.9f);
        }
    }
    // Loop's limit mask at a vertex of valence n: weight chi = 1 / (n + 3 / (8 beta)) on each
    // neighbour, beta = (5/8 - (3/8 + cos(2 pi / n) / 4)^2) / n. At the octahedron's vertex
    // (1, 0, 0), n = 4 and its neighbours sum to zero: the limit point is (1 - 4 chi, 0, 0).
    const double beta = (5.0 / 8 - std::pow(3.0 / 8 + std::cos(2 * M_PI / 4) / 4, 2)) / 4;
    const double chi = 1 / (4 + 3 / (8 * beta));
    MeshData coarse = loop_subdivide(kOctahedronFaces, kOctahedron, 0, kLoc);
    EXPECT_NEAR(coarse.p[0].x, 1 - 4 * chi, 1e-6);
    // The surface does not depend on the level: the refined mesh reaches the same extreme.
    MeshData fine = loop_subdivide(kOctahedronFaces, kOctahedron, 3, kLoc);
    float largest_x = 0;
    for (const Vec3f &p : fine.p) largest_x = std::max(largest_x, p.x);
    EXPECT_NEAR(largest_x, 1 - 4 * chi, 1e-6);
}

TEST(LoopSubdivision, OpenMeshesKeepTheirBoundary) {
    // A flat square of two triangles stays in its plane, inside the square.
    std::vector<Vec3f> square = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    MeshData m = loop_subdivide({0, 1, 2, 0, 2, 3}, square, 2, kLoc);
    EXPECT_EQ(m.indices.size(), 6u * 16u);
    for (const Vec3f &p : m.p) {
        EXPECT_NEAR(p.z, 0, 1e-6f);
        EXPECT_GE(p.x, -1e-6f);
        EXPECT_LE(p.x, 1 + 1e-6f);
    }
    for (const Vec3f &n : m.n) EXPECT_NEAR(std::abs(n.z), 1, 1e-5f);
}

TEST(LoopSubdivision, BadInputIsAnErrorAtTheShape) {
    EXPECT_THROW(loop_subdivide({0, 1}, kOctahedron, 1, kLoc), InputError);
    EXPECT_THROW(loop_subdivide({0, 1, 6}, kOctahedron, 1, kLoc), InputError);
    EXPECT_THROW(loop_subdivide({0, 1, -1}, kOctahedron, 1, kLoc), InputError);
    EXPECT_THROW(loop_subdivide(kOctahedronFaces, kOctahedron, 9, kLoc), InputError);
    EXPECT_THROW(loop_subdivide(kOctahedronFaces, kOctahedron, -1, kLoc), InputError);
    EXPECT_THROW(loop_subdivide({0, 0, 1}, kOctahedron, 1, kLoc), InputError); // nothing left
    std::vector<Vec3f> nan = kOctahedron;
    nan[2].y = std::nanf("");
    EXPECT_THROW(loop_subdivide(kOctahedronFaces, nan, 1, kLoc), InputError);
    try {
        loop_subdivide({0, 1, 6}, kOctahedron, 1, kLoc);
    } catch (const InputError &e) {
        EXPECT_EQ(e.location().line, 4);
        EXPECT_EQ(e.location().column, 9);
    }
}

} // namespace
} // namespace caustica
