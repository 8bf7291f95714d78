// Object-space triangle mesh arrays as read from a scene or mesh file, before a TriangleMesh
// validates them and moves them to render space.
#pragma once

#include "core/vecmath.h"

#include <vector>

namespace caustica {

struct MeshData {
    std::vector<int> indices; // three per triangle
    std::vector<Vec3f> p;
    std::vector<Vec3f> n;     // per vertex, or empty
    std::vector<Vec2f> uv;    // per vertex, or empty
};

} // namespace caustica
