// Unidirectional path tracing with next-event estimation and multiple importance sampling
// (Veach 1997, ch. 9: power heuristic between light sampling and BSDF sampling), Russian
// roulette, and hero-wavelength termination at dispersive refraction. Subsurface scattering by a
// profile (the Disney material's diffusion and dipole models) is rendered here only: a path that
// enters such a surface continues from an exit point sampled with probe rays.
#pragma once

#include "integrators/integrator.h"
#include "params/parameters.h"

namespace caustica {

class PathTracer final : public Integrator {
  public:
    // Parameters (pbrt-v4 names): "maxdepth" (5); "regularize" (false): widen the microfacet
    // lobes met after a non-specular bounce (SubpathWalk::regularize_after_non_specular_bounces).
    explicit PathTracer(const ParameterDictionary &params);
    void render(const Scene &scene, const RenderBudget &budget, RenderStats &stats,
                const ProgressCallback &progress) override;
    int max_depth() const { return max_depth_; }

  private:
    int max_depth_;
    bool regularize_;
};

} // namespace caustica
