// Which media lie on the two sides of a surface (pbrt-v4's MediumInterface): "inside" is the side
// the geometric normal points away from. Only surfaces whose two sides differ are transitions;
// any other surface leaves a ray in the medium it was already in, so a glass sphere inside fog
// needs no interface of its own.
#pragma once

#include "geometry/interaction.h"
#include "media/medium.h"

namespace caustica {

struct MediumInterface {
    const Medium *inside = nullptr;
    const Medium *outside = nullptr;
    bool is_transition() const { return inside != outside; }
};

// The medium a ray leaving surface point si in direction w travels through, given the medium
// the path was in before reaching si.
inline const Medium *medium_after(const SurfaceInteraction &si, Vec3f w, const Medium *current) {
    if (!si.medium_interface) return current;
    return dot(w, si.n) > 0 ? si.medium_interface->outside : si.medium_interface->inside;
}

} // namespace caustica
