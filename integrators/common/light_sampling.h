// Next-event estimation shared by the integrators that connect surface points to lights.
#pragma once

#include "core/scratch_buffer.h"
#include "lights/light.h"
#include "materials/bsdf.h"
#include "sampler/sampler.h"

namespace caustica {

class Medium;
class Scene;
struct SurfaceInteraction;

// Density (solid angle at ctx) with which sample_direct_lighting picks direction wi on light:
// the light-selection probability at ctx (the scene's light sampler may prefer lights near the
// point) times the light's own pdf.
float light_pdf(const Scene &scene, const Light &light, const LightSampleContext &ctx, Vec3f wi);

// Whether the caller also finds lights by BSDF sampling from the same point (and weights those
// hits with the complementary MIS weight), or relies on light sampling alone.
enum class DirectLighting { WeightedAgainstBsdfSampling, LightSamplingOnly };

// One light sample: the contribution f * Le * |cos| * T / pdf, before the path throughput,
// weighted against BSDF sampling with the power heuristic unless light sampling is the only
// strategy. T is the transmittance of the shadow ray, which leaves si into the medium on the
// side of the light (`medium` is the one the path arrived in). Shadow rays are counted in rays.
SampledSpectrum sample_direct_lighting(const Scene &scene, const SurfaceInteraction &si,
                                       const BSDF &bsdf, const LightSampleContext &ctx,
                                       const SampledWavelengths &lambda, Sampler &sampler,
                                       uint64_t &rays, TransportMode mode = TransportMode::Radiance,
                                       DirectLighting strategy = DirectLighting::WeightedAgainstBsdfSampling,
                                       const Medium *medium = nullptr);

// The same at a scattering point p inside `medium`, with its phase function in place of the
// BSDF (and no cosine); wo points back along the path, whose time is `time`.
SampledSpectrum sample_direct_lighting_in_medium(const Scene &scene, Vec3f p, float time, Vec3f wo, const Medium &medium,
                                                 const SampledWavelengths &lambda, Sampler &sampler,
                                                 uint64_t &rays,
                                                 DirectLighting strategy = DirectLighting::WeightedAgainstBsdfSampling);

} // namespace caustica
