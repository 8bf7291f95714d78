// Stochastic progressive photon mapping (Hachisuka and Jensen 2009; pbrt-v4 section 15.4 is
// the model for parameters and structure).
//
// Every iteration traces one camera path per pixel through specular (and glossy, up to the
// last bounce) surfaces to its first diffuse surface, the pixel's visible point, adding direct
// lighting along the way by next-event estimation. Then photons are traced from the lights, and
// each visible point gathers the photons (after their first bounce: direct light is already
// counted) that land within its own radius. The per-pixel statistics of the progressive
// estimator, photon count N and accumulated flux tau, then shrink the radius so that
// N_{i+1} = N_i + gamma M_i photons are kept of the N_i + M_i gathered (gamma = 2/3), which
// makes the estimate consistent: bias and variance both vanish as iterations go on.
//
// Participating media: camera paths scatter through media on their way to the visible point,
// estimating single scattering at each medium vertex by light sampling and gathering there, within
// a sphere, the photons of volumetric caustics (photons deposited in media straight after
// specular bounces); photons are deposited on surfaces after any scattering event (see
// trace_camera_path in sppm.cpp for how the paths are shared between the estimators).
//
// Spectral: camera paths and photons are split into wavelength groups per iteration
// (wavelength_groups.h); a visible point gathers only its group's photons, and each
// iteration's flux is rescaled by all photons over the group's photons, so the final division
// by the total photon count stays right. Flux is accumulated in the sensor's RGB, as pbrt-v4 does.
//
// A distributed render (docs/mpi.md) shares each iteration: a rank traces the visible points of
// its own tiles and a share of the photons, the ranks exchange the photons, and each gathers and
// keeps the statistics of its own pixels.
#pragma once

#include "integrators/integrator.h"
#include "params/parameters.h"
#include "spatial/photon_map.h"
#include "spectral/color.h"

#include <vector>

namespace caustica {

class SPPM final : public Integrator {
  public:
    // Parameters (pbrt-v4 names): "maxdepth" (5; it bounds the scattering events of the whole
    // path, camera and photon parts together, like every other integrator here), "radius" (the initial gather radius in
    // scene units; 0 or absent: default_merge_radius(), not pbrt's fixed 1), "photonsperiteration" (-1: one per pixel), "seed" (0, added to the
    // command line's); Caustica's "wavelengthgroups" (16) and "photonsearch" ("hashgrid" or
    // "flann"). "regularize" is not supported (reported as unused).
    SPPM(const ParameterDictionary &params, const Scene &scene);
    void render(const Scene &scene, const RenderBudget &budget, RenderStats &stats,
                const ProgressCallback &progress) override;
    // The pixels' progressive estimates (checkpoints).
    void save_state(std::ostream &out) const override;
    void restore_state(std::istream &in) override;

  private:
    // The progressive estimate of the light a pixel sees through visible points of one kind,
    // on surfaces (a disk kernel, dimension 2) or in media (a sphere, dimension 3). The two are
    // estimates of disjoint sets of paths, each averaged over every iteration (an iteration
    // without a visible point of a kind adds nothing to its estimate), with radii of their own.
    struct KernelEstimate {
        float radius = 0;
        float photons = 0; // N: photons the estimate is made of
        RGB tau;           // accumulated, radius-scaled flux

        // Keeps gamma of the m photons just gathered (flux phi) and shrinks the kernel's
        // measure (r^dimension) in the same proportion (Hachisuka and Jensen 2009, eqs. 6-7;
        // the volume form is Knaus and Zwicker 2011's). Returns the factor tau + phi was scaled
        // by, for the spectral film's buckets.
        float update(const RGB &phi, float m, int dimension);
    };
    // What a pixel's estimate carries from one iteration to the next.
    struct PixelEstimate {
        KernelEstimate surface, medium;
        RGB direct_sum; // direct lighting along camera paths, summed over iterations
    };

    int max_depth_;
    float initial_radius_, initial_medium_radius_;
    long long photons_per_iteration_;
    int wavelength_groups_;
    uint64_t seed_;
    PhotonSearch photon_search_;
    std::vector<PixelEstimate> estimates_; // row by row over the film's pixel bounds
    // With a spectral film, the buckets of each pixel's direct_sum, surface and medium tau, in
    // that order (3 x the film's bucket count per pixel, in the order of estimates_).
    std::vector<double> bucket_estimates_;
    int buckets_ = 0; // the spectral film's bucket count, or 0
};

} // namespace caustica
