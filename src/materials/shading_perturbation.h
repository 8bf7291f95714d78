// Bump and normal mapping: pbrt-v4's "displacement" (a float texture, on every material) and
// "normalmap" (an image file) material parameters. Either one tilts the shading frame before the
// BSDF is made (shade() in material.h); the geometry stays where it is.
//
// Bump mapping (Blinn 1978, pbrt-v4 section 10.5.2): the surface displaced along its shading
// normal by d(u, v) has tangents dp/du + (dd/du) n and dp/dv + (dd/dv) n, the derivatives taken
// by forward differences. pbrt-v4 steps by half the pixel footprint in (u, v) from its ray
// differentials; Caustica has none and steps by pbrt-v4's fallback, 0.0005. pbrt-v4 also adds
// d times the normal's own derivatives dn/du and dn/dv, which Caustica's surfaces do not carry:
// a term of relative size d / (radius of curvature), negligible for bump heights well below the
// curvature radius.
//
// Normal mapping: the image's RGB at (u, v) (repeat wrap, bilinear, linear values) is 2 rgb - 1,
// a tangent-space normal in the frame of dp/du (x) and the shading normal (z).
#pragma once

#include "textures/image_texture.h"
#include "textures/texture.h"

#include <memory>

namespace caustica {

struct SurfaceInteraction;

class ShadingPerturbation {
  public:
    static std::shared_ptr<const ShadingPerturbation> bump(FloatTexturePtr displacement);
    static std::shared_ptr<const ShadingPerturbation> normal_map(std::shared_ptr<const TexelImage> image);

    // Replaces si's shading frame by the perturbed one; leaves it alone where the perturbed
    // frame is degenerate (a zero tangent, a normal-map texel of (0.5, 0.5, 0.5)).
    void apply(SurfaceInteraction &si) const;

  private:
    FloatTexturePtr displacement_;
    std::shared_ptr<const TexelImage> normal_map_;
};

} // namespace caustica
