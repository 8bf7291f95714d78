// Light tracing (pbrt-v4's "lightpath"; Veach 1997 section 10.2, the s >= 1, t = 1 strategies of
// bidirectional path tracing used alone): paths start on the lights, in proportion to their
// power, and every vertex on a non-specular surface, the point on the light included, is
// connected to a sampled point of the camera lens and splatted to the film where that
// connection lands. It renders caustics (light focused by specular surfaces onto diffuse ones)
// that camera paths find only by chance. In participating media the paths also scatter at
// medium vertices, which are connected to the lens like surface vertices (with the phase
// function, and no cosine); every connection is weighted by the transmittance of the media it
// crosses, the camera's own medium included.
//
// Not rendered: environment (infinite) lights seen directly, whose "points" are at infinity and
// cannot be connected to the lens (as in pbrt-v4's lightpath), and anything seen only through
// specular surfaces (mirror images, objects behind glass): their vertices cannot be connected.
#pragma once

#include "integrators/integrator.h"
#include "params/parameters.h"

namespace caustica {

class LightTracer final : public Integrator {
  public:
    // Parameters (pbrt-v4 names): "maxdepth" (5), the most scattering vertices of a light path.
    // Throws InputError if the scene's camera does not model importance (orthographic).
    LightTracer(const ParameterDictionary &params, const Scene &scene);
    // Traces budget.spp iterations (or as many as fit in budget.seconds), each of one light path
    // per pixel of the film's pixel bounds; the path's random numbers depend only on (pixel,
    // iteration, seed), so the image does not depend on the number of threads.
    void render(const Scene &scene, const RenderBudget &budget, RenderStats &stats,
                const ProgressCallback &progress) override;
    double splat_scale(const Scene &scene, const RenderStats &stats) const override;
    int max_depth() const { return max_depth_; }

  private:
    int max_depth_;
};

} // namespace caustica
