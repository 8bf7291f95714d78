#include "geometry/mesh_file.h"
#include "geometry/shape_factory.h"
#include "geometry/sphere.h"
#include "geometry_test_util.h"

#include <filesystem>

namespace caustica {
namespace {

using test::create_shape;
using test::dictionary;
using test::numbers;
using test::strings;

const SourceLocation loc{"test.pbrt", 3, 1};
const std::string data_dir = std::string(CAUSTICA_TEST_DATA) + "/geometry";

double total_area(const ShapeGroup &group) {
    double area = 0;
    for (const auto &shape : group.shapes()) area += shape->area();
    return area;
}

TEST(CreateShape, TriangleMesh) {
    auto params = dictionary({numbers("integer", "indices", {0, 1, 2, 0, 2, 3}),
                              numbers("point3", "P", {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}),
                              numbers("point2", "uv", {0, 0, 1, 0, 1, 1, 0, 1})});
    auto group = create_shape("trianglemesh", Transform::scale(2, 2, 2), false, params, loc);
    ASSERT_TRUE(group && group->mesh);
    EXPECT_EQ(group->triangle_count(), 2u);
    EXPECT_EQ(group->primitive_count(), 2u);
    EXPECT_EQ(group->shapes().size(), 2u);
    EXPECT_NEAR(total_area(*group), 4, 1e-6);
    EXPECT_EQ(group->mesh->uvs().size(), 4u);

    // Three vertices need no indices.
    auto single = create_shape(
        "trianglemesh", {}, false,
        dictionary({numbers("point3", "P", {0, 0, 0, 1, 0, 0, 0, 1, 0})}), loc);
    ASSERT_TRUE(single);
    EXPECT_EQ(single->triangle_count(), 1u);

    // pbrt-v3 files give uv as a flat float array.
    auto flat_uv = create_shape("trianglemesh", {}, false,
                                dictionary({numbers("point3", "P", {0, 0, 0, 1, 0, 0, 0, 1, 0}),
                                            numbers("float", "uv", {0, 0, 1, 0, 0, 1})}),
                                loc);
    ASSERT_TRUE(flat_uv);
    EXPECT_EQ(flat_uv->mesh->uvs()[2].y, 1);
}

TEST(CreateShape, TriangleMeshErrors) {
    test::QuietWarnings quiet;
    auto four_points = numbers("point3", "P", {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0});
    EXPECT_THROW(create_shape("trianglemesh", {}, false, dictionary({four_points}), loc),
                 InputError);
    EXPECT_THROW(create_shape("trianglemesh", {}, false,
                              dictionary({four_points, numbers("integer", "indices", {0, 1, 7})}),
                              loc),
                 InputError);
    EXPECT_THROW(create_shape("trianglemesh", {}, false,
                              dictionary({numbers("integer", "indices", {0, 1, 2})}), loc),
                 InputError);
    // Wrongly sized uv are dropped (pbrt-v4 reports them and carries on).
    auto group = create_shape(
        "trianglemesh", {}, false,
        dictionary({four_points, numbers("integer", "indices", {0, 1, 2}),
                    numbers("point2", "uv", {0, 0, 1, 0})}),
        loc);
    ASSERT_TRUE(group);
    EXPECT_TRUE(group->mesh->uvs().empty());
}

TEST(CreateShape, AnalyticShapes) {
    auto sphere_group = create_shape("sphere", {}, true,
                                     dictionary({numbers("float", "radius", {2.5})}), loc);
    ASSERT_TRUE(sphere_group && sphere_group->analytic);
    auto *sphere = dynamic_cast<const Sphere *>(sphere_group->analytic.get());
    ASSERT_TRUE(sphere);
    EXPECT_EQ(sphere->radius(), 2.5f);
    EXPECT_TRUE(sphere->is_full());
    EXPECT_TRUE(sphere->reverse_orientation());
    EXPECT_EQ(sphere_group->shapes().size(), 1u);
    EXPECT_EQ(sphere_group->triangle_count(), 0u);

    auto disk = create_shape("disk", {}, false,
                             dictionary({numbers("float", "radius", {2}),
                                         numbers("float", "innerradius", {1}),
                                         numbers("float", "height", {0.5})}),
                             loc);
    ASSERT_TRUE(disk && disk->analytic);
    EXPECT_NEAR(disk->analytic->area(), Pi * 3, 1e-5);
    EXPECT_NEAR(disk->bounds().lo.z, 0.5f, 1e-6);
}

TEST(CreateShape, UnsupportedAndUnknownShapes) {
    test::QuietWarnings quiet;
    for (const char *name : {"cone", "paraboloid", "hyperboloid"})
        EXPECT_EQ(create_shape(name, {}, false, dictionary({}), loc), nullptr) << name;
    EXPECT_THROW(create_shape("teapot", {}, false, dictionary({}), loc), InputError);
    // loopsubdiv needs its control mesh and a curve its control points, as in pbrt-v4; a
    // cylinder has pbrt-v4's defaults.
    EXPECT_THROW(create_shape("loopsubdiv", {}, false, dictionary({}), loc), InputError);
    EXPECT_THROW(create_shape("curve", {}, false, dictionary({}), loc), InputError);
    EXPECT_NE(create_shape("cylinder", {}, false, dictionary({}), loc), nullptr);
}

TEST(CreateShape, BilinearMeshAsTriangles) {
    // One planar patch p00, p10, p01, p11 (a parallelogram) and its default uv.
    auto params = dictionary({numbers("point3", "P", {0, 0, 0, 2, 0, 0, 1, 1, 0, 3, 1, 0})});
    auto group = create_shape("bilinearmesh", {}, false, params, loc);
    ASSERT_TRUE(group && group->mesh);
    EXPECT_EQ(group->triangle_count(), 2u);
    EXPECT_NEAR(total_area(*group), 2, 1e-6);
    auto scene = test::scene_of({std::const_pointer_cast<ShapeGroup>(group)});
    // The bilinear map p(u, v) = (2u + v, v, 0) is linear here, so triangles reproduce it.
    for (Vec2f uv : {Vec2f{0.25f, 0.75f}, Vec2f{0.8f, 0.1f}}) {
        SurfaceInteraction si;
        ASSERT_TRUE(scene->intersect({{2 * uv.x + uv.y, uv.y, 1}, {0, 0, -1}}, &si));
        EXPECT_NEAR(si.uv.x, uv.x, 1e-6);
        EXPECT_NEAR(si.uv.y, uv.y, 1e-6);
        // The patch normal dp/du x dp/dv = (2, 0, 0) x (1, 1, 0) = +z.
        EXPECT_EQ(si.n.z, 1);
    }
    test::QuietWarnings quiet;
    EXPECT_THROW(create_shape("bilinearmesh", {}, false,
                              dictionary({numbers("point3", "P", {0, 0, 0, 1, 0, 0, 0, 1, 0}),
                                          numbers("integer", "indices", {0, 1, 2})}),
                              loc),
                 InputError);
    // A curved patch is an exact bilinear patch (bilinear_patch_test.cpp), not triangles; so is
    // a planar one whose uv are not affine over it.
    auto curved = create_shape(
        "bilinearmesh", {}, false,
        dictionary({numbers("point3", "P", {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 1})}), loc);
    ASSERT_TRUE(curved && curved->patches);
    EXPECT_EQ(curved->triangle_count(), 0u);
    EXPECT_EQ(curved->primitive_count(), 1u);
    auto warped_uv = create_shape("bilinearmesh", {}, false,
                                  dictionary({numbers("point3", "P", {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0}),
                                              numbers("point2", "uv", {0, 0, 1, 0, 0, 1, 2, 2})}),
                                  loc);
    ASSERT_TRUE(warped_uv && warped_uv->patches);
}

void expect_quad_ply(const ShapeGroup &group) {
    ASSERT_TRUE(group.mesh);
    // The quad splits into two triangles; with the triangle above it, area 1 + 2.
    EXPECT_EQ(group.triangle_count(), 3u);
    EXPECT_NEAR(total_area(group), 3, 1e-5);
    EXPECT_FALSE(group.mesh->normals().empty());
    EXPECT_FALSE(group.mesh->uvs().empty());
    GeometryScene scene;
    scene.add(std::make_shared<ShapeGroup>(group), {});
    scene.commit();
    SurfaceInteraction si;
    // Under the upper triangle's overhang only the quad is hit from below.
    ASSERT_TRUE(scene.intersect({{0.3f, 0.6f, -1}, {0, 0, 1}}, &si));
    EXPECT_NEAR(si.t, 1, 1e-6);
    EXPECT_NEAR(si.uv.x, 0.3f, 1e-6);
    EXPECT_NEAR(si.uv.y, 0.6f, 1e-6);
    test::expect_near_vec(si.n, {0, 0, 1}, 0);
    ASSERT_TRUE(scene.intersect({{0.3f, 0.6f, 3}, {0, 0, -1}}, &si));
    EXPECT_NEAR(si.t, 2, 1e-6);
    EXPECT_NEAR(si.uv.x, 0.15f, 1e-6);
}

TEST(CreateShape, PlyMesh) {
    auto params = dictionary({strings("string", "filename", {"quad.ply"})}, data_dir);
    auto group = create_shape("plymesh", {}, false, params, loc);
    ASSERT_TRUE(group);
    expect_quad_ply(*group);
}

TEST(CreateShape, GzippedPlyMesh) {
    auto params = dictionary({strings("string", "filename", {"quad.ply.gz"})}, data_dir);
    auto group = create_shape("plymesh", {}, false, params, loc);
    ASSERT_TRUE(group);
    expect_quad_ply(*group);
}

// A curved quad of a PLY file is pbrt-v4's bilinear patch (v0, v1, v3, v2), here z = u v, and
// is rendered as one: a ray up through (0.3, 0.6) meets it at z = 0.18 (split into two triangles
// along v1-v3, at z = 0).
TEST(CreateShape, PlyMeshWithACurvedQuad) {
    auto params = dictionary({strings("string", "filename", {"saddle-quad.ply"})}, data_dir);
    auto group = create_shape("plymesh", {}, false, params, loc);
    ASSERT_TRUE(group && group->patches);
    EXPECT_EQ(group->primitive_count(), 1u);
    auto scene = test::scene_of({group});
    SurfaceInteraction si;
    ASSERT_TRUE(scene->intersect({{0.3f, 0.6f, -1}, {0, 0, 1}}, &si));
    EXPECT_NEAR(si.p.z, 0.18f, 1e-6);
    EXPECT_NEAR(si.uv.x, 0.3f, 1e-6);
    EXPECT_NEAR(si.uv.y, 0.6f, 1e-6);
}

// pbrt-v4 makes a triangle mesh and bilinear patches of a file that holds both.
TEST(CreateShape, PlyMeshWithTrianglesAndACurvedQuad) {
    auto params = dictionary({strings("string", "filename", {"saddle-quad-and-triangle.ply"})}, data_dir);
    auto groups = create_shapes("plymesh", {}, false, params, loc);
    ASSERT_EQ(groups.size(), 2u);
    ASSERT_TRUE(groups[0]->mesh && !groups[0]->patches);
    ASSERT_TRUE(groups[1]->patches && !groups[1]->mesh);
    EXPECT_EQ(groups[0]->triangle_count(), 1u);
    EXPECT_NEAR(total_area(*groups[0]), 0.5, 1e-6);
    EXPECT_EQ(groups[1]->primitive_count(), 1u);
    auto scene = test::scene_of({groups[0], groups[1]});
    SurfaceInteraction si;
    ASSERT_TRUE(scene->intersect({{0.3f, 0.6f, -1}, {0, 0, 1}}, &si));
    EXPECT_NEAR(si.p.z, 0.18f, 1e-6); // on the saddle, not on a split quad's flat triangle
    ASSERT_TRUE(scene->intersect({{2.2f, 0.3f, -1}, {0, 0, 1}}, &si));
    EXPECT_NEAR(si.p.z, 0.f, 1e-6);
}

// The binary PLY of pbrt-v4's scene collection that made Assimp abort: its body starts with a
// line-end byte.
TEST(CreateShape, PlyMeshWhoseBodyStartsWithALineEnd) {
    auto params = dictionary({strings("string", "filename", {"body_starts_with_newline.ply"})}, data_dir);
    auto group = create_shape("plymesh", {}, false, params, loc);
    ASSERT_TRUE(group);
    EXPECT_EQ(group->triangle_count(), 1u);
    EXPECT_NEAR(total_area(*group), 0.5, 1e-5);
}

TEST(CreateShape, PlyMeshErrors) {
    auto missing = dictionary({strings("string", "filename", {"no_such.ply"})}, data_dir);
    EXPECT_THROW(create_shape("plymesh", {}, false, missing, loc), InputError);
    EXPECT_THROW(create_shape("plymesh", {}, false, dictionary({}, data_dir), loc), InputError);
    // A file that is not a mesh.
    std::filesystem::path bad = std::filesystem::temp_directory_path() / "caustica_not_a_mesh.ply";
    { FILE *f = std::fopen(bad.c_str(), "w"); std::fputs("ply\nnonsense\n", f); std::fclose(f); }
    EXPECT_THROW(read_mesh_file(bad.string(), loc), InputError);
    std::filesystem::remove(bad);
}

} // namespace
} // namespace caustica
