// Which media lie on the two sides of a surface (pbrt-v4's MediumInterface): "inside" is the side
// the geometric normal points away from. Only surfaces whose two sides differ are transitions;
// any other surface leaves a ray in the medium it was already in, so a glass sphere inside fog
// needs no interface of its own.
#pragma once

#include "geometry/interaction.h"
#include "materials/material.h"
#include "media/medium.h"

namespace caustica {

struct MediumInterface {
    const Medium *inside = nullptr;
    const Medium *outside = nullptr;
    bool is_transition() const { return inside != outside; }
};

// The medium a ray leaving surface point si in direction w travels through, given the medium
// the path was in before reaching si. A material's own interior medium (si.interior, set by
// shade()) takes precedence inside its surface; leaving it, a path returns to the shape's outside
// medium (vacuum without a MediumInterface). A path already inside keeps its medium, which may be
// one the material made for the point where the path entered (material.h).
inline const Medium *medium_after(const SurfaceInteraction &si, Vec3f w, const Medium *current) {
    const bool outwards = dot(w, si.n) > 0;
    if (si.interior) {
        const bool inside = current && (current == si.interior || current->interior_of() == si.material);
        if (!outwards) return inside ? current : si.interior;
        if (!inside) return current;
        return si.medium_interface ? si.medium_interface->outside : nullptr;
    }
    if (!si.medium_interface) return current;
    return outwards ? si.medium_interface->outside : si.medium_interface->inside;
}

} // namespace caustica
