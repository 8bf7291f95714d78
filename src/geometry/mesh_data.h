// Object-space triangle mesh arrays as read from a scene or mesh file, before a TriangleMesh
// validates them and moves them to render space.
#pragma once

#include "core/vecmath.h"

#include <vector>

namespace caustica {

struct MeshData {
    std::vector<int> indices; // three per triangle
    // Four per quad of a PLY file, as pbrt-v4's bilinear patch (p00, p10, p01, p11) of the face
    // (v0, v1, v2, v3), that is (v0, v1, v3, v2); empty for other sources.
    std::vector<int> quads;
    std::vector<Vec3f> p;
    std::vector<Vec3f> n;     // per vertex, or empty
    std::vector<Vec2f> uv;    // per vertex, or empty
};

} // namespace caustica
