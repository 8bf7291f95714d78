// pbrt-v4's PerspectiveCamera: a pinhole or thin lens (Potmesil and Chakravarty 1981) with the
// field of view measured across the shorter image axis, and its importance function for
// bidirectional methods (Veach 1997 section 10.2; pbrt-v4 section 16.1.1): We is normalised so
// that its integral over the lens area and the solid angle of directions through the image is
// one, which makes the lens a "sensor" whose whole-image measurement is one pixel-average.
#pragma once

#include "camera/projective_camera.h"

namespace caustica {

class PerspectiveCamera final : public ProjectiveCamera {
  public:
    // fov in degrees; lens_radius 0 gives a pinhole; the plane z = focal_distance (camera space)
    // is in focus.
    PerspectiveCamera(const Transform &world_from_camera, const FilmExtent &film, float fov,
                      const ScreenWindow &screen, float lens_radius, float focal_distance);

    std::optional<CameraRay> ray_at_rest(const CameraSample &sample,
                                          const SampledWavelengths &lambda) const override;
    SampledSpectrum we_at_rest(const Ray &ray, const SampledWavelengths &lambda,
                       Vec2f *p_raster = nullptr) const override;
    void pdf_we_at_rest(const Ray &ray, float *pdf_pos, float *pdf_dir) const override;
    std::optional<CameraWiSample> sample_wi_at_rest(Vec3f ref, Vec2f u,
                                            const SampledWavelengths &lambda) const override;

    // Area of the image on the plane z = 1 in camera space.
    float image_plane_area() const { return image_area_; }

  private:
    // Where a ray leaving the lens crosses the film, and the cosine of its angle to the view
    // direction; false when it points away from the image or lands outside the sample bounds.
    bool project(const Ray &ray, float *cos_theta, Vec2f *p_raster) const;

    float cos_total_width_;  // cosine of the widest angle that still reaches a pixel
    float image_area_;
};

} // namespace caustica
