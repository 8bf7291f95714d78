// Helpers shared by the geometry tests.
#pragma once

#include "core/error.h"
#include "core/rng.h"
#include "geometry/embree_scene.h"
#include "geometry/shape_factory.h"
#include "geometry/shape_group.h"
#include "geometry/triangle_mesh.h"
#include "params/parameters.h"

#include <gtest/gtest.h>

#include <memory>

namespace caustica::test {

inline std::shared_ptr<ShapeGroup> mesh_group(const Transform &render_from_object,
                                              bool reverse_orientation, std::vector<int> indices,
                                              std::vector<Vec3f> p, std::vector<Vec3f> n = {},
                                              std::vector<Vec2f> uv = {}) {
    auto group = std::make_shared<ShapeGroup>();
    group->type = "trianglemesh";
    group->mesh = std::make_shared<TriangleMesh>(render_from_object, reverse_orientation,
                                                 std::move(indices), std::move(p), std::move(n),
                                                 std::move(uv));
    return group;
}

inline std::shared_ptr<ShapeGroup> analytic_group(std::shared_ptr<AnalyticShape> shape) {
    auto group = std::make_shared<ShapeGroup>();
    group->type = "analytic";
    group->analytic = std::move(shape);
    return group;
}

// The one group a Shape directive makes (null for none); the directives the tests use make at
// most one.
inline std::shared_ptr<ShapeGroup> create_shape(const std::string &type, const Transform &render_from_object,
                                                bool reverse_orientation, const ParameterDictionary &params,
                                                const SourceLocation &loc) {
    auto groups = create_shapes(type, render_from_object, reverse_orientation, params, loc);
    EXPECT_LE(groups.size(), 1u);
    return groups.empty() ? nullptr : groups.front();
}

// A scene holding just the given groups, committed.
inline std::unique_ptr<GeometryScene>
scene_of(std::initializer_list<std::shared_ptr<ShapeGroup>> groups) {
    auto scene = std::make_unique<GeometryScene>();
    for (const auto &g : groups) scene->add(g, {});
    scene->commit();
    return scene;
}

// 12 triangles of the box [lo, hi] with outward winding, mapped by render_from_object.
inline std::shared_ptr<ShapeGroup> box_group(const Transform &render_from_object, Vec3f lo,
                                             Vec3f hi) {
    std::vector<Vec3f> p;
    for (int i = 0; i < 8; ++i)
        p.push_back({i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z});
    // Each face as a quad a, b, c, d counterclockwise seen from outside.
    const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                             {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    std::vector<int> indices;
    for (const auto &f : faces) indices.insert(indices.end(), {f[0], f[1], f[2], f[0], f[2], f[3]});
    return mesh_group(render_from_object, false, indices, p);
}

inline ParsedParameter numbers(const std::string &type, const std::string &name,
                               std::vector<double> values) {
    ParsedParameter p;
    p.type = type;
    p.name = name;
    p.numbers = std::move(values);
    p.loc = {"test.pbrt", 1, 1};
    return p;
}

inline ParsedParameter strings(const std::string &type, const std::string &name,
                               std::vector<std::string> values) {
    ParsedParameter p;
    p.type = type;
    p.name = name;
    p.strings = std::move(values);
    p.loc = {"test.pbrt", 1, 1};
    return p;
}

inline ParameterDictionary dictionary(std::vector<ParsedParameter> params,
                                      std::string base_directory = "") {
    return ParameterDictionary(std::move(params), {"test.pbrt", 1, 1}, nullptr,
                               std::move(base_directory));
}

inline void expect_near_vec(Vec3f a, Vec3f b, float tolerance) {
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

// Silences warnings for the duration of a test.
struct QuietWarnings {
    QuietWarnings() { set_warnings_enabled(false); }
    ~QuietWarnings() { set_warnings_enabled(true); }
};

} // namespace caustica::test
