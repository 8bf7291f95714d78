// pbrt-v4's SphericalCamera: every pixel a direction of the whole sphere around the camera
// position, for panoramas and environment maps. "equalarea" (the default) lays the sphere out on
// a square film with Clarberg's equal-area octahedral map (lights/equal_area_mapping.h), as
// pbrt-v4 stores environment maps; "equirectangular" maps x to the azimuth and y to the polar
// angle. As in pbrt-v4, the mapped direction has its y and z swapped, so the image's centre
// (equal area) or top row (equirectangular) looks along camera-space +y, the up vector of
// LookAt. Its importance is not modelled (nor in pbrt-v4): integrators that connect light paths
// to the lens refuse it.
#pragma once

#include "camera/camera.h"

namespace caustica {

class SphericalCamera final : public CameraWithoutImportance {
  public:
    enum class Mapping { EqualArea, Equirectangular };
    SphericalCamera(const Transform &world_from_camera, const FilmExtent &film, Mapping mapping)
        : world_from_camera_(world_from_camera), film_(film), mapping_(mapping) {}

    std::optional<CameraRay> ray_at_rest(const CameraSample &sample,
                                          const SampledWavelengths &lambda) const override;
    // Camera-space direction of a raster position.
    Vec3f direction(Vec2f p_raster) const;
    Vec3f position() const override { return world_from_camera_.apply_point({0, 0, 0}); }

  private:
    Transform world_from_camera_;
    FilmExtent film_;
    Mapping mapping_;
};

} // namespace caustica
