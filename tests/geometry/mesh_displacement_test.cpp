// pbrt-v4's plymesh displacement (src/geometry/mesh_displacement.h) against closed forms: how
// far refinement splits a mesh, that the triangles on either side of an edge share its
// midpoint, that vertices move along their normals by the texture's value at their object-space
// point and uv, and the errors.
#include "core/error.h"
#include "geometry/mesh_displacement.h"
#include "textures/texture.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

using namespace caustica;

namespace {

// Height u + 2 v: a plane displaced by it stays a plane, tilted.
class RampHeight final : public FloatTexture {
  public:
    float evaluate(const TextureEvalContext &ctx) const override { return ctx.uv.x + 2 * ctx.uv.y; }
};

// Height x in object space.
class ObjectX final : public FloatTexture {
  public:
    float evaluate(const TextureEvalContext &ctx) const override { return ctx.p.x; }
};

// The unit square in the xy plane as two triangles, normals up (z) by their winding, uv = (x, y).
MeshData unit_square() {
    MeshData m;
    m.p = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    m.uv = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    m.indices = {0, 1, 2, 0, 2, 3};
    return m;
}

const SourceLocation kLoc{"scene.pbrt", 3, 7}, kEdgeLoc{"scene.pbrt", 3, 40};

// With edges under 0.3, refinement halves longest edges until every edge of the flat mesh is
// shorter than 0.3; area and winding are kept, and no two vertices coincide (the triangles on
// either side of a split edge share its midpoint). Every vertex moves up by u + 2 v, so the
// recomputed normals are those of the tilted plane.
TEST(MeshDisplacement, RefinesUntilEdgesAreShortAndSharesMidpoints) {
    const MeshData m = displace_mesh(unit_square(), RampHeight(), 0.3f, Transform(), kLoc, kEdgeLoc);
    double area = 0;
    for (size_t i = 0; i < m.indices.size(); i += 3) {
        const Vec3f a = m.p[m.indices[i]], b = m.p[m.indices[i + 1]], c = m.p[m.indices[i + 2]];
        // Undo the displacement (z = u + 2 v, along the original normal +z) to measure the flat mesh.
        const Vec3f fa{a.x, a.y, 0}, fb{b.x, b.y, 0}, fc{c.x, c.y, 0};
        EXPECT_LT(distance(fa, fb), 0.3f);
        EXPECT_LT(distance(fb, fc), 0.3f);
        EXPECT_LT(distance(fc, fa), 0.3f);
        area += 0.5 * length(cross(fb - fa, fc - fa));
        EXPECT_GT(cross(fb - fa, fc - fa).z, 0) << "winding kept";
    }
    EXPECT_NEAR(area, 1.0, 1e-5);
    // No two vertices at one place: midpoints are shared.
    std::set<std::pair<float, float>> positions;
    for (const Vec3f &p : m.p) EXPECT_TRUE(positions.insert({p.x, p.y}).second) << p.x << " " << p.y;
    // Every vertex moved up by u + 2 v; the tilted plane's normal is (-1, -2, 1) / sqrt(6).
    for (size_t i = 0; i < m.p.size(); ++i) EXPECT_NEAR(m.p[i].z, m.uv[i].x + 2 * m.uv[i].y, 1e-5f);
    const Vec3f tilted = normalize(Vec3f{-1, -2, 1});
    for (const Vec3f &n : m.n) EXPECT_NEAR(dot(n, tilted), 1, 1e-4f);
}

// Edge lengths are measured in render space, and the displacement happens in object space at
// the object-space point: scaled by 4, edges under 1 need the object-space refinement of 0.25,
// and a vertex at object x moves by x (not 4 x) in object space.
TEST(MeshDisplacement, MeasuresEdgesInRenderSpaceAndMovesInObjectSpace) {
    const Transform scale = Transform::scale(4, 4, 4);
    const MeshData scaled = displace_mesh(unit_square(), ObjectX(), 1.f, scale, kLoc, kEdgeLoc);
    const MeshData plain = displace_mesh(unit_square(), ObjectX(), 0.25f, Transform(), kLoc, kEdgeLoc);
    EXPECT_EQ(scaled.indices.size(), plain.indices.size());
    for (size_t i = 0; i < scaled.p.size(); ++i) EXPECT_NEAR(scaled.p[i].z, scaled.p[i].x, 1e-6f);
}

TEST(MeshDisplacement, BadInputIsAnErrorAtItsParameter) {
    MeshData no_uv = unit_square();
    no_uv.uv.clear();
    try {
        displace_mesh(no_uv, RampHeight(), 0.3f, Transform(), kLoc, kEdgeLoc);
        FAIL() << "no error";
    } catch (const InputError &e) {
        EXPECT_NE(std::string(e.what()).find("scene.pbrt:3:7"), std::string::npos) << e.what();
    }
    for (const float bad : {0.f, -1.f, NAN, 1e-6f}) {
        try {
            displace_mesh(unit_square(), RampHeight(), bad, Transform(), kLoc, kEdgeLoc);
            FAIL() << "no error for " << bad;
        } catch (const InputError &e) {
            EXPECT_NE(std::string(e.what()).find("scene.pbrt:3:40"), std::string::npos) << e.what();
        }
    }
}

} // namespace
