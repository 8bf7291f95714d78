// pbrt-v4's RealisticCamera: a film of physical size behind a lens system traced exactly
// (lens_system.h), so that depth of field, vignetting, distortion and the shape of out-of-focus
// highlights are the lens's own. Rays leave a film point towards the exit pupil, the part of the
// rear element through which light reaches that point, bounded in advance for 64 rings of film
// radius (Kolb et al. 1995; Physically Based Rendering, 4th edition, section 5.4).
//
// A ray's weight is the measurement equation's cos^4(theta) A / d^2 (the film-to-pupil
// geometry, with A the area of the sampled pupil bounds and d the rear element's distance),
// times the aperture mask, so the image is the film's irradiance rather than a radiance: scenes
// made for pbrt-v4 set the sensor's "iso" or "exposuretime" for it, as for a real camera.
// Importance is not modelled (nor in pbrt-v4): integrators that connect light paths to the lens
// refuse this camera.
#pragma once

#include "camera/aperture_mask.h"
#include "camera/camera.h"
#include "camera/lens_system.h"

#include <array>

namespace caustica {

// A rectangle of the rear element's plane through which rays from a ring of film radii pass.
struct PupilBounds {
    double x0 = 0, y0 = 0, x1 = -1, y1 = -1;
    bool empty() const { return !(x1 > x0 && y1 > y0); }
    double area() const { return empty() ? 0 : (x1 - x0) * (y1 - y0); }
};

class RealisticCamera final : public CameraWithoutImportance {
  public:
    static constexpr int PupilRings = 64;  // rings of film radius with their own pupil bounds

    // `lens` is focused already; the film's physical size comes from film.diagonal.
    RealisticCamera(const Transform &world_from_camera, const FilmExtent &film, LensSystem lens,
                    std::optional<ApertureMask> mask);

    std::optional<CameraRay> ray_at_rest(const CameraSample &sample,
                                          const SampledWavelengths &lambda) const override;
    Vec3f position() const override { return world_from_camera_.apply_point({0, 0, 0}); }

    // True if the lens passes light to some part of the film.
    bool transmits() const;

  private:
    // The pupil bounds of the ring of film radii [r0, r1), found by tracing a low-discrepancy
    // set of rays from that ring to a square 1.5 times the rear element's radius, grown by twice
    // the sample spacing. Empty when no ray passes. The aperture mask is left out: it only
    // removes light from inside the round stop, so these bounds contain the masked pupil too.
    // (pbrt-v4 bounds the masked pupil, and its bounds cut off the tips of the "star", whose
    // image is 0.7% darker for it in scenes/cameras/realistic-gaussian's layout.)
    PupilBounds bound_exit_pupil(double r0, double r1) const;

    Transform world_from_camera_;
    FilmExtent film_;
    LensSystem lens_;
    std::optional<ApertureMask> mask_;
    double half_width_ = 0, half_height_ = 0;  // of the film, metres
    std::array<PupilBounds, PupilRings> pupil_bounds_;
};

} // namespace caustica
