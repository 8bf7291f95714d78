// Cameras generate primary rays and, for bidirectional methods, evaluate importance We and the
// densities needed to connect light-path vertices to the lens (Veach 1997 ch. 10; pbrt-v4 16.1).
#pragma once

#include "core/animated_transform.h"
#include "core/transform.h"
#include "geometry/ray.h"
#include "spectral/sampled_wavelengths.h"

#include <memory>
#include <optional>

namespace caustica {

struct CameraSample {
    Vec2f p_film;              // raster coordinates, including the filter offset
    Vec2f p_lens;              // [0,1)^2
    float time = 0;            // scene time within the shutter (geometry/ray.h)
    float filter_weight = 1;
};

// The interval over which the shutter is open: pbrt-v4's "shutteropen" and "shutterclose".
// Camera rays spread uniformly over it; moving geometry blurs over it (motion blur).
struct Shutter {
    float open = 0, close = 1;
    float time(float u) const { return open + u * (close - open); }
};

struct CameraRay {
    Ray ray;
    SampledSpectrum weight{1};
    // Set by generate_ray_differential (camera_footprint.h) for texture filtering.
    std::optional<RayDifferential> differential;
};

// For t = 1 connections: importance arriving at ref from a sampled lens point.
struct CameraWiSample {
    SampledSpectrum We;
    Vec3f wi;            // from ref towards the lens point, unit
    float pdf = 0;       // solid angle at ref
    Vec2f p_raster;      // where the contribution lands on the film
    Vec3f p_lens, n_lens;
};

// The film as a camera sees it (pbrt-v4's FilmBase): raster coordinates span the full
// resolution, with (0, 0) at the top-left corner of the image and y pointing down. Importance is
// non-zero over the sample bounds: the (cropped) pixel bounds grown by the filter radius less
// half a pixel, i.e. wherever a splat still reaches a pixel of the image.
struct FilmExtent {
    Vec2i full_resolution;
    Vec2f sample_min, sample_max;
    Vec2f filter_radius{0.5f, 0.5f};
    float diagonal = 0.035f;  // the film's physical diagonal in metres (the realistic camera's)

    // The whole image, splats reaching pixels through a filter of this radius.
    static FilmExtent whole_image(Vec2i resolution, Vec2f filter_radius = {0.5f, 0.5f}) {
        Vec2f grow{filter_radius.x - 0.5f, filter_radius.y - 0.5f};
        return {resolution, Vec2f{0, 0} - grow, Vec2f{float(resolution.x), float(resolution.y)} + grow,
                filter_radius};
    }
};

class Camera {
  public:
    virtual ~Camera() = default;

    // Every query takes the time of its ray (geometry/ray.h). A moving camera (pbrt-v4's
    // animated CameraTransform: set_motion) does everything at rest, in its placement at the
    // start, and moves the result to where it is at that time. The move is rigid (a motion that
    // changes the camera's scale is refused by set_motion), so importance and densities do not
    // change with it.

    // The ray for a film and lens sample, leaving at the sample's time.
    std::optional<CameraRay> generate_ray(const CameraSample &sample, const SampledWavelengths &lambda) const;
    // Importance of a ray leaving the lens; *p_raster receives its film position. Zero when
    // the ray misses the film.
    SampledSpectrum We(const Ray &ray, const SampledWavelengths &lambda, Vec2f *p_raster = nullptr) const;
    void pdf_we(const Ray &ray, float *pdf_pos, float *pdf_dir) const;
    // A lens point seen from ref at the given time.
    std::optional<CameraWiSample> sample_wi(Vec3f ref, Vec2f u, const SampledWavelengths &lambda,
                                            float time = 0) const;
    // Where the camera is at rest.
    virtual Vec3f position() const = 0;
    // False when the camera's importance is not modelled (the orthographic camera, whose
    // pinhole importance is a Dirac delta in direction, as in pbrt-v4): We and pdf_we are then
    // zero and sample_wi empty, so integrators that connect light paths to the lens must refuse
    // such a camera rather than silently lose those paths.
    virtual bool models_importance() const { return true; }

    // The camera moves from world_from_camera.start (where it was built) to .end over the
    // TransformTimes. Returns false, and leaves the camera still, when the motion is not rigid.
    bool set_motion(const AnimatedTransform &world_from_camera, TransformTimes times);
    bool moves() const { return moves_; }

    // The same at rest: what each camera implements.
    virtual std::optional<CameraRay> ray_at_rest(const CameraSample &sample,
                                                 const SampledWavelengths &lambda) const = 0;
    virtual SampledSpectrum we_at_rest(const Ray &ray, const SampledWavelengths &lambda,
                                       Vec2f *p_raster = nullptr) const = 0;
    virtual void pdf_we_at_rest(const Ray &ray, float *pdf_pos, float *pdf_dir) const = 0;
    virtual std::optional<CameraWiSample> sample_wi_at_rest(Vec3f ref, Vec2f u,
                                                            const SampledWavelengths &lambda) const = 0;

  private:
    // The move from rest to the placement at `time` (identity when still).
    Transform moved_at(float time) const;

    AnimatedTransform motion_;       // world from camera, start and end
    AffineFactors start_factors_, end_factors_; // of motion_'s placements, for interpolate()
    Transform rest_from_world_;      // the inverse of motion_.start
    TransformTimes times_;
    bool moves_ = false;
};

// A camera whose importance is not modelled (pbrt-v4 leaves it unimplemented for the same
// cameras): We and pdf_we are zero and sample_wi empty, and integrators that connect light
// paths to the lens refuse it.
class CameraWithoutImportance : public Camera {
  public:
    SampledSpectrum we_at_rest(const Ray &, const SampledWavelengths &, Vec2f * = nullptr) const override {
        return SampledSpectrum(0.f);
    }
    void pdf_we_at_rest(const Ray &, float *pdf_pos, float *pdf_dir) const override { *pdf_pos = *pdf_dir = 0; }
    std::optional<CameraWiSample> sample_wi_at_rest(Vec3f, Vec2f, const SampledWavelengths &) const override {
        return std::nullopt;
    }
    bool models_importance() const override { return false; }
};

using CameraPtr = std::shared_ptr<const Camera>;

} // namespace caustica
