// The geometry of one Shape directive: a triangle mesh, bilinear patches, a single analytic shape,
// or curves.
#pragma once

#include "geometry/analytic_shape.h"
#include "geometry/bilinear_patch.h"
#include "geometry/curves.h"
#include "geometry/triangle_mesh.h"

#include <memory>
#include <string>
#include <vector>

namespace caustica {

struct ShapeGroup {
    std::string type;                              // the directive's shape name
    std::shared_ptr<const TriangleMesh> mesh;      // set for meshes
    std::shared_ptr<AnalyticShape> analytic;       // set for spheres and disks
    std::shared_ptr<const CurveSet> curves;        // set for curves
    std::shared_ptr<const BilinearPatchMesh> patches; // set for curved bilinear patches

    bool empty() const { return !mesh && !analytic && !curves && !patches; }
    // One Shape per primitive, in the order the scene's primitives use (a Triangle per mesh
    // triangle, a BilinearPatch per patch), so that an area light can be made for each. Builds new
    // objects on every call for meshes and patches. None for curves, which cannot be sampled (nor can they in pbrt-v4).
    std::vector<std::shared_ptr<Shape>> shapes() const;
    // shapes().size() without building them.
    size_t primitive_count() const;
    size_t triangle_count() const { return mesh ? size_t(mesh->triangle_count()) : 0; }
    Bounds3f bounds() const;
};

} // namespace caustica
