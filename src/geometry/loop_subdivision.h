// pbrt-v4's "loopsubdiv" shape: a triangle mesh refined by Loop subdivision (Loop 1987, "Smooth
// Subdivision Surfaces Based on Triangles") `levels` times, every vertex then moved to the limit
// surface and given the limit surface's normal, so that shading is smooth. The refinement is
// OpenSubdiv's (Far::TopologyRefiner with the Loop scheme); boundaries are cubic B-spline
// curves (edges sharp, corners not), as in pbrt-v4. OpenSubdiv uses Loop's original vertex
// weights and exact limit masks where pbrt-v4 uses Warren's simplified weights; the two surfaces
// agree at regular (valence 6) vertices and differ slightly elsewhere.
#pragma once

#include "core/error.h"
#include "geometry/mesh_data.h"

#include <vector>

namespace caustica {

// Throws InputError at loc for indices that are not whole triangles or lie outside `p`, a
// level outside [0, 8], or a refined mesh beyond the triangle limit; faces that repeat a
// vertex are dropped with a warning (OpenSubdiv requires distinct corners).
MeshData loop_subdivide(std::vector<int> indices, const std::vector<Vec3f> &p, int levels,
                        const SourceLocation &loc);

} // namespace caustica
