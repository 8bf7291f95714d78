#include "camera/spherical_camera.h"

#include "lights/equal_area_mapping.h"

#include <cmath>

namespace caustica {

Vec3f SphericalCamera::direction(Vec2f p_raster) const {
    Vec2f uv{p_raster.x / float(film_.full_resolution.x), p_raster.y / float(film_.full_resolution.y)};
    Vec3f d;
    if (mapping_ == Mapping::Equirectangular) {
        const float theta = Pi * uv.y, phi = 2 * Pi * uv.x;
        d = {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
    } else {
        // Filter offsets may reach past the square's edge: the octahedral map continues across
        // it by mirroring, as pbrt-v4's WrapEqualAreaSquare does.
        if (uv.x < 0) uv = {-uv.x, 1 - uv.y};
        else if (uv.x > 1) uv = {2 - uv.x, 1 - uv.y};
        if (uv.y < 0) uv = {1 - uv.x, -uv.y};
        else if (uv.y > 1) uv = {1 - uv.x, 2 - uv.y};
        d = equal_area_square_to_sphere(uv);
    }
    return {d.x, d.z, d.y};
}

std::optional<CameraRay> SphericalCamera::ray_at_rest(const CameraSample &sample, const SampledWavelengths &) const {
    CameraRay cr;
    cr.ray.o = world_from_camera_.apply_point({0, 0, 0});
    cr.ray.d = normalize(world_from_camera_.apply_vector(direction(sample.p_film)));
    return cr;
}

} // namespace caustica
