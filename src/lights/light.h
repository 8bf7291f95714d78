// Light sources: emission, sampling of incident illumination (for next-event estimation) and
// sampling of emitted rays (for light tracing, BDPT, photon mapping and VCM).
#pragma once

#include "core/vecmath.h"
#include "geometry/direction_cone.h"
#include "geometry/ray.h"
#include "spectral/sampled_wavelengths.h"

#include <memory>
#include <optional>

namespace caustica {

class Spectrum;

class Medium;

enum class LightType {
    DeltaPosition,  // point, spot
    DeltaDirection, // distant
    Area,           // emission from a shape's surface
    Infinite,       // emission from infinitely far away (environment)
    Volume,         // emission from inside a participating medium (medium_emitter.h)
};
inline bool is_delta_light(LightType t) {
    return t == LightType::DeltaPosition || t == LightType::DeltaDirection;
}

// The receiving point for next-event estimation; n is zero for points in media.
struct LightSampleContext {
    Vec3f p, n, ns;
};

// The directions a light emits towards: every emitting point's normal lies in `normals`, and
// emits within angle theta_e of it (pi / 2 for a diffuse surface). The default, theta_e = pi / 2
// about the entire sphere of normals, bounds any light. Two-sided emitters emit about -n as well.
struct EmissionDirections {
    DirectionCone normals = DirectionCone::entire_sphere();
    float cos_theta_e = 0;
    bool two_sided = false;
};

struct LightLiSample {
    SampledSpectrum L;   // radiance (or intensity / irradiance for delta lights) arriving
    Vec3f wi;            // unit direction from the receiving point towards the light
    float pdf = 0;       // solid angle (1 for delta lights)
    Vec3f p_light, n_light; // point on the light and its normal (n zero for point lights)
    float error_scale_light = 0; // p_light's, as SurfaceInteraction::error_scale
    bool is_infinite = false; // p_light is only a direction: occlusion ray is unbounded
};

struct LightLeSample {
    SampledSpectrum L;
    Ray ray;
    Vec3f n;                   // normal at the ray origin (zero if none)
    float error_scale = 0;     // the origin's, as SurfaceInteraction::error_scale
    Vec2f uv;                  // surface lights: the origin's uv, on which L may depend
    float pdf_pos = 0, pdf_dir = 0;
};

class Light {
  public:
    virtual ~Light() = default;
    virtual LightType type() const = 0;
    // Called once after the scene is built (distant and infinite lights need its bounds).
    virtual void preprocess(const Bounds3f &scene_bounds) { (void)scene_bounds; }
    // The spectrum of which everything the light emits is a multiple (its colour), or null when
    // the colour varies over the light (an environment image). See SceneFeatures::achromatic.
    virtual const Spectrum *emission_spectrum() const { return nullptr; }
    // Total emitted power at the wavelengths, for light selection by power.
    virtual SampledSpectrum phi(const SampledWavelengths &lambda) const = 0;
    // Where the light's emitting points lie, for light selection by distance; empty for lights
    // at infinity (distant, infinite).
    virtual std::optional<Bounds3f> spatial_bounds() const { return std::nullopt; }
    // Towards which directions the light emits, for light selection (lights/light_bounds.h).
    virtual EmissionDirections emission_directions() const { return {}; }

    virtual std::optional<LightLiSample> sample_li(const LightSampleContext &ctx, Vec2f u,
                                                   const SampledWavelengths &lambda) const = 0;
    virtual float pdf_li(const LightSampleContext &ctx, Vec3f wi) const = 0;

    // Area lights: radiance leaving point p (normal n, uv) in direction w.
    virtual SampledSpectrum L(Vec3f p, Vec3f n, Vec2f uv, Vec3f w,
                              const SampledWavelengths &lambda) const {
        (void)p; (void)n; (void)uv; (void)w; (void)lambda;
        return {};
    }
    // Infinite lights: radiance arriving along a ray that escapes the scene.
    virtual SampledSpectrum Le(const Ray &ray, const SampledWavelengths &lambda) const {
        (void)ray; (void)lambda;
        return {};
    }

    // Emitted-ray sampling for light paths; pdf_pos is per area (or per unit of the disk
    // perpendicular to a distant/infinite light), pdf_dir per solid angle. As in pbrt-v4, the
    // delta part of a delta light is 1 in sample_le (the one position or direction, chosen with
    // certainty) but 0 in pdf_le (a given ray cannot hit it by chance). For area lights, pdf_le
    // takes the ray leaving a point on the light (ray.o) and that point's normal n.
    virtual std::optional<LightLeSample> sample_le(Vec2f u1, Vec2f u2,
                                                   const SampledWavelengths &lambda) const = 0;
    virtual void pdf_le(const Ray &ray, Vec3f n, float *pdf_pos, float *pdf_dir) const = 0;

    // The medium around the light (the outside medium of the MediumInterface in effect where it
    // was declared), in which its light paths start; null for vacuum. An area light's paths
    // start in the medium on the side of its shape they leave by, when the shape is a transition.
    const Medium *medium() const { return medium_; }
    void set_medium(const Medium *medium) { medium_ = medium; }

  private:
    const Medium *medium_ = nullptr;
};

using LightPtr = std::shared_ptr<Light>;

} // namespace caustica
