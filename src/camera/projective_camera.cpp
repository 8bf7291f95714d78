#include "camera/projective_camera.h"

namespace caustica {

ScreenWindow default_screen_window(float frame) {
    if (frame > 1) return {{-frame, -1}, {frame, 1}};
    return {{-1, -1 / frame}, {1, 1 / frame}};
}

ProjectiveCamera::ProjectiveCamera(const Transform &world_from_camera,
                                   const Transform &screen_from_camera, const ScreenWindow &screen,
                                   const FilmExtent &film, float lens_radius, float focal_distance)
    : world_from_camera_(world_from_camera), camera_from_world_(world_from_camera.inverse()),
      film_(film), lens_radius_(lens_radius), focal_distance_(focal_distance) {
    // Screen -> NDC: the window's top-left corner (min.x, max.y) goes to the origin, and the
    // window to the unit square; NDC -> raster scales by the resolution, flipping y so that
    // raster y grows downwards.
    Transform ndc_from_screen =
        Transform::scale(1 / (screen.max.x - screen.min.x), 1 / (screen.max.y - screen.min.y), 1) *
        Transform::translate({-screen.min.x, -screen.max.y, 0});
    Transform raster_from_ndc =
        Transform::scale(float(film.full_resolution.x), -float(film.full_resolution.y), 1);
    Transform raster_from_screen = raster_from_ndc * ndc_from_screen;
    camera_from_raster_ = screen_from_camera.inverse() * raster_from_screen.inverse();
    raster_from_camera_ = camera_from_raster_.inverse();
    forward_ = normalize(world_from_camera_.apply_vector({0, 0, 1}));
}

bool ProjectiveCamera::inside_sample_bounds(Vec2f p) const {
    return p.x >= film_.sample_min.x && p.x <= film_.sample_max.x && p.y >= film_.sample_min.y &&
           p.y <= film_.sample_max.y;
}

} // namespace caustica
