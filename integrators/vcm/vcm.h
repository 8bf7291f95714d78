// Vertex connection and merging (Georgiev, Krivanek, Davidovic and Slusallek 2012; the same
// combination is Hachisuka, Pantaleoni and Jensen 2012's unified path sampling), and its
// merging-only special case, bidirectional photon mapping (bpm).
//
// Each iteration traces one light subpath per pixel and stores its non-specular vertices; then
// one camera subpath per pixel is traced, and at each of its non-specular vertices it
//   - samples a light (next-event estimation, a connection),
//   - connects to every stored vertex of the light subpath traced for its pixel,
//   - merges with the stored light vertices (photons) within radius r of it,
// while light subpath vertices are also connected to the lens and splatted (light tracing).
// All strategies are weighted by the power heuristic through the recursive quantities of
// vcm_mis.h. The merge radius shrinks as r_i = r_0 i^((alpha - 1) / 2) over iterations i, so
// that the merging bias vanishes while its variance stays bounded (Knaus and Zwicker 2011).
// bpm keeps only the merges and the camera paths' own light hits.
//
// Participating media: both subpaths scatter inside media (path_segment.h), and their medium
// vertices are connected, light-sampled and splatted like surface ones (phase function in place
// of the BSDF, no cosine), with transmittance along every connection. Light vertices in media
// become photons of their own maps, which camera vertices in media gather within a sphere of
// radius r (volumetric photon mapping, Jensen and Christensen 1998), weighted against the other
// strategies as in Krivanek et al. 2014 (see vcm_mis.h and merge_in_medium in vcm.cpp).
// Emissive media are light sources too: light paths start in them, chosen with the lights by
// power, camera vertices are joined to such a start, and the camera paths' collision estimate of
// their emission is weighed against both (integrators/common/medium_emission.h, docs/media.md).
//
// Spectral: pixels are split into wavelength groups per iteration (wavelength_groups.h); light
// and camera subpaths that are connected or merged always share the group's wavelengths. A
// dispersive refraction on either subpath keeps the hero wavelength only for what it joins.
//
// Iterations are independent but for the radius, which follows the iteration's index: a
// distributed render (docs/mpi.md) gives each rank whole iterations.
#pragma once

#include "integrators/integrator.h"
#include "params/parameters.h"
#include "spatial/photon_map.h"


namespace caustica {

class VCM final : public Integrator {
  public:
    enum class Mode { VertexConnectionMerging, BidirectionalPhotonMapping };

    // Parameters: "maxdepth" (5), the most scattering events of a path; "radius" (0:
    // default_merge_radius() on surfaces, default_medium_merge_radius() in media), the initial
    // merge radius r_0 in scene units;
    // "alpha" (0.75), the radius reduction exponent; "wavelengthgroups" (16), the wavelength
    // groups per iteration; "photonsearch" ("hashgrid" or "flann"), the range search;
    // "lightvertices" ("store" or "retrace", see below).
    VCM(Mode mode, const ParameterDictionary &params, const Scene &scene);
    void render(const Scene &scene, const RenderBudget &budget, RenderStats &stats,
                const ProgressCallback &progress) override;
    double splat_scale(const Scene &scene, const RenderStats &stats) const override;

  private:
    Mode mode_;
    int max_depth_;
    float base_radius_, base_medium_radius_;
    float alpha_;
    int wavelength_groups_;
    PhotonSearch photon_search_;
    // vcm connects each camera path to the light path traced for its pixel. "store" keeps every
    // light vertex of the iteration once, without its BSDF, in the photon maps (a 60-byte
    // StoredLightVertex with its point and identity, which merging reads as a photon), and
    // shades the pixel's again just before its camera path; "retrace" keeps only 44-byte
    // photons and traces the pixel's light path again, from the same random numbers, instead:
    // three quarters of the memory for the time of tracing the light paths twice. The two give
    // the same image, to the precision of the kept vertices' directions and hits
    // (light_vertex.h).
    bool retrace_light_paths_ = false;
    uint64_t light_paths_traced_ = 0;
};

} // namespace caustica
