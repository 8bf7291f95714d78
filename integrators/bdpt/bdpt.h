// Bidirectional path tracing (Veach 1997, ch. 10; pbrt-v4 section 16.3). For every pixel sample
// a camera subpath and a light subpath are traced, and every prefix pair (s light vertices, t
// camera vertices) is joined into a complete path: s = 0 when the camera subpath itself hits an
// emitter, t = 1 by connecting a light vertex to a sampled lens point (splatted where it lands),
// s = 1 by sampling a point on a light from the camera vertex, and otherwise by a shadow ray
// between the two subpaths' ends. The strategies are combined with the power heuristic, their
// weights computed from per-vertex area densities (Veach 1997, section 10.2.1).
//
// Participating media (pbrt-v4's BDPT with media): both subpaths sample free-flight distances
// along their segments (the shared SubpathWalk) and may scatter inside a medium, making medium
// vertices, which connect like surface vertices with the phase function in place of the BSDF and
// no cosine. Every connection, to the lens and to a sampled light point included, is weighted by
// the transmittance of the media it crosses, and is zero when a surface blocks it. Emissive
// media are light sources here too: light subpaths start in them, chosen with the lights by
// power, and the camera subpaths' collision estimate of their emission is one strategy among
// the others (docs/media.md).
//
// One set of hero wavelengths serves both subpaths of a sample; a dispersive refraction on
// either keeps only the hero wavelength for every contribution of that sample. Beer-Lambert
// absorption inside dielectrics multiplies the throughput of the subpath segments that cross
// them; connection segments are not attenuated by it (a connection from inside a closed
// dielectric to a point outside it is blocked by its boundary anyway). There is no Russian
// roulette (as in pbrt-v4): subpath lengths are bounded by "maxdepth" alone.
#pragma once

#include "integrators/integrator.h"
#include "params/parameters.h"

namespace caustica {

class BDPT final : public Integrator {
  public:
    // Parameters (pbrt-v4 names): "maxdepth" (5), the most scattering events (bounces) of a
    // connected path; "regularize" (false): each subpath widens the microfacet lobes it meets
    // after a non-specular bounce (SubpathWalk::regularize_after_non_specular_bounces), as
    // pbrt-v4's RandomWalk does. "visualizestrategies" and "visualizeweights" are not
    // supported (reported as unused). Throws InputError if the camera does not model
    // importance (orthographic), since light subpaths must be connected to the lens.
    BDPT(const ParameterDictionary &params, const Scene &scene);
    // Deterministic for a seed: each sample's random numbers depend only on (pixel, sample
    // index, seed), and splats are summed in fixed point.
    void render(const Scene &scene, const RenderBudget &budget, RenderStats &stats,
                const ProgressCallback &progress) override;
    double splat_scale(const Scene &scene, const RenderStats &stats) const override;
    int max_depth() const { return max_depth_; }

  private:
    int max_depth_;
    bool regularize_;
};

} // namespace caustica
