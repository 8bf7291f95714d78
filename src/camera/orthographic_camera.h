// pbrt-v4's OrthographicCamera: parallel rays along +z from the screen window (in camera-space
// units), with pbrt-v4's optional thin lens. Its importance is not modelled (pbrt-v4 leaves it
// unimplemented too): a pinhole orthographic camera's importance is a Dirac delta in direction
// that no light-path vertex can connect to.
#pragma once

#include "camera/projective_camera.h"

namespace caustica {

class OrthographicCamera final : public ProjectiveCamera {
  public:
    OrthographicCamera(const Transform &world_from_camera, const FilmExtent &film,
                       const ScreenWindow &screen, float lens_radius, float focal_distance);

    std::optional<CameraRay> ray_at_rest(const CameraSample &sample,
                                          const SampledWavelengths &lambda) const override;
    // Zero / empty: see models_importance().
    SampledSpectrum we_at_rest(const Ray &ray, const SampledWavelengths &lambda,
                       Vec2f *p_raster = nullptr) const override;
    void pdf_we_at_rest(const Ray &ray, float *pdf_pos, float *pdf_dir) const override;
    std::optional<CameraWiSample> sample_wi_at_rest(Vec3f ref, Vec2f u,
                                            const SampledWavelengths &lambda) const override;
    bool models_importance() const override { return false; }
};

} // namespace caustica
