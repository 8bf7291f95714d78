#include "geometry/shape_group.h"

#include "geometry/triangle.h"

namespace caustica {

std::vector<std::shared_ptr<Shape>> ShapeGroup::shapes() const {
    std::vector<std::shared_ptr<Shape>> result;
    if (analytic) result.push_back(analytic);
    if (mesh) {
        result.reserve(mesh->triangle_count());
        for (int i = 0; i < mesh->triangle_count(); ++i)
            result.push_back(std::make_shared<Triangle>(mesh, i));
    }
    if (patches) {
        result.reserve(patches->patch_count());
        for (int i = 0; i < patches->patch_count(); ++i)
            result.push_back(std::make_shared<BilinearPatch>(patches, i));
    }
    return result;
}

size_t ShapeGroup::primitive_count() const {
    return (analytic ? 1 : 0) + triangle_count() + (patches ? size_t(patches->patch_count()) : 0);
}

Bounds3f ShapeGroup::bounds() const {
    Bounds3f b;
    if (analytic) b.expand(analytic->bounds());
    if (mesh) b.expand(mesh->bounds());
    if (curves) b.expand(curves->bounds());
    if (patches) b.expand(patches->bounds());
    return b;
}

} // namespace caustica
