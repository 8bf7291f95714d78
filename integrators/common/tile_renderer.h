// Renders camera samples over the image in parallel tiles (oneTBB). Every sample's random numbers
// depend only on (pixel, sample index, seed), and the film sums in fixed point, so the image is
// bit-identical whatever the number of threads or MPI ranks (RenderShare), and whether or not
// the render was interrupted and resumed from a checkpoint.
#pragma once

#include "core/scratch_buffer.h"
#include "integrators/integrator.h"
#include "sampler/sampler.h"
#include "spectral/sampled_wavelengths.h"

#include <functional>

namespace caustica {

struct CameraRay;

// Radiance along a camera ray for the path's wavelengths (which the estimator may terminate).
using RadianceFunction = std::function<SampledSpectrum(const CameraRay &ray, SampledWavelengths &lambda,
                                                       Sampler &sampler, ScratchBuffer &scratch,
                                                       uint64_t &rays)>;

// Samples the path's wavelengths as the scene's overrides ask (hero, single, or fixed): from the
// scene's wavelength density, fitted to its lights (spectral/wavelength_density.h), or from a
// spectral film's own range. A light path that is not joined to a camera path (lt's) draws them
// from the density fitted to the lights alone (Scene::light_path_wavelength_density).
enum class WavelengthsFor { CameraPath, LightPath };
SampledWavelengths sample_wavelengths(const Scene &scene, float u, WavelengthsFor use = WavelengthsFor::CameraPath);

// What the work for one (pixel, sample index) may use: the thread's sampler, already started at
// that pixel and index, its scratch memory (reset after every sample) and its counters.
struct PixelSampleContext {
    Sampler &sampler;
    ScratchBuffer &scratch;
    uint64_t &rays;
    uint64_t &non_finite;
};

using PixelSampleFunction = std::function<void(Vec2i pixel, int sample_index, PixelSampleContext &ctx)>;

// Calls work(pixel, s) for every pixel of the film's pixel bounds and s = 0, 1, ... up to the
// budget's sample count (or until its time is used), tile by tile in parallel, skipping the
// samples `stats` says were taken (a resumed render). Fills in stats.rays, non_finite_samples,
// pixel_samples, samples_per_pixel (the samples completed for every pixel), pixel_sample_counts
// (when interrupted) and seconds, reports progress after each tile and calls the budget's
// at_boundary after every wave and when interrupted.
void for_each_pixel_sample(const Scene &scene, const RenderBudget &budget, RenderStats &stats,
                           const ProgressCallback &progress, const PixelSampleFunction &work);

// Camera-path rendering on top of for_each_pixel_sample: one camera ray per pixel sample, its
// radiance estimate added to the film at that pixel.
void render_tiles(const Scene &scene, const RenderBudget &budget, RenderStats &stats,
                  const ProgressCallback &progress, const RadianceFunction &radiance);

} // namespace caustica
