// What pbrt-v4's perspective and orthographic cameras share: the chain of transforms from raster
// space (pixels, y down) through NDC and screen space (the screen window on the plane of the
// projection) to camera space, where the camera looks down +z with +y up and +x to the right
// (pbrt's left-handed LookAt: camera +x = cross(up, viewing direction)).
#pragma once

#include "camera/camera.h"

namespace caustica {

// The rectangle of screen space that the image covers.
struct ScreenWindow {
    Vec2f min, max;
};

// pbrt-v4's default screen window for a frame aspect ratio (width / height): [-1, 1] along the
// shorter image axis, so a perspective camera's fov applies to that axis.
ScreenWindow default_screen_window(float frame_aspect_ratio);

class ProjectiveCamera : public Camera {
  public:
    Vec3f position() const override { return world_from_camera_.apply_point({0, 0, 0}); }
    const Transform &camera_from_raster() const { return camera_from_raster_; }
    const Transform &world_from_camera() const { return world_from_camera_; }

  protected:
    ProjectiveCamera(const Transform &world_from_camera, const Transform &screen_from_camera,
                     const ScreenWindow &screen, const FilmExtent &film, float lens_radius,
                     float focal_distance);

    // Lens area for importance; 1 for a pinhole, where the delta in position cancels out
    // between We and the position density (pbrt-v4's convention).
    float lens_area() const { return lens_radius_ != 0 ? Pi * sqr(lens_radius_) : 1.f; }
    bool inside_sample_bounds(Vec2f p_raster) const;

    Transform world_from_camera_, camera_from_world_;
    Transform camera_from_raster_, raster_from_camera_;
    FilmExtent film_;
    float lens_radius_, focal_distance_;
    Vec3f forward_;  // the viewing direction in world space, unit
};

} // namespace caustica
