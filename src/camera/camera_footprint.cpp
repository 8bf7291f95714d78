#include "camera/camera_footprint.h"

#include "geometry/interaction.h"

#include <algorithm>
#include <cmath>

namespace caustica {

namespace {

// The rotation taking the unit vector `from` onto `to`, as the product of two reflections
// (Moller and Hughes 1999, "Efficiently building a matrix to rotate one vector to another"; the
// construction of pbrt-v4's RotateFromTo, so that the footprint's axes match pbrt-v4's).
class Rotation {
  public:
    Rotation(Vec3f from, Vec3f to) {
        Vec3f axis{0, 0, 1};
        if (std::abs(from.x) < 0.72f && std::abs(to.x) < 0.72f) axis = {1, 0, 0};
        else if (std::abs(from.y) < 0.72f && std::abs(to.y) < 0.72f) axis = {0, 1, 0};
        const Vec3f u = axis - from, v = axis - to;
        const float uu = dot(u, u), vv = dot(v, v), uv = dot(u, v);
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                m_[i][j] = (i == j ? 1.f : 0.f) - 2 / uu * u[i] * u[j] - 2 / vv * v[i] * v[j] +
                           4 * uv / (uu * vv) * v[i] * u[j];
    }
    Vec3f apply(Vec3f w) const {
        return {m_[0][0] * w.x + m_[0][1] * w.y + m_[0][2] * w.z, m_[1][0] * w.x + m_[1][1] * w.y + m_[1][2] * w.z,
                m_[2][0] * w.x + m_[2][1] * w.y + m_[2][2] * w.z};
    }
    // A rotation's inverse is its transpose.
    Vec3f apply_inverse(Vec3f w) const {
        return {m_[0][0] * w.x + m_[1][0] * w.y + m_[2][0] * w.z, m_[0][1] * w.x + m_[1][1] * w.y + m_[2][1] * w.z,
                m_[0][2] * w.x + m_[1][2] * w.y + m_[2][2] * w.z};
    }

  private:
    float m_[3][3];
};

// Where the ray o + t d meets the plane through p with normal n; nothing when it runs parallel.
std::optional<Vec3f> plane_hit(Vec3f o, Vec3f d, Vec3f p, Vec3f n) {
    const float t = dot(n, p - o) / dot(n, d);
    const Vec3f hit = o + d * t;
    if (!is_finite(hit)) return std::nullopt;
    return hit;
}

// One shifted ray, from the sample's by a finite difference of `generate` (pbrt-v4 tries 1/20
// pixel to the right first, then to the left, in case the first falls off the lens or film).
template <typename Generate>
bool shifted_ray(const Generate &generate, CameraSample sample, const Ray &ray, int axis, Vec3f *origin,
                 Vec3f *direction) {
    for (const float eps : {0.05f, -0.05f}) {
        CameraSample shifted = sample;
        (axis == 0 ? shifted.p_film.x : shifted.p_film.y) += eps;
        if (const std::optional<CameraRay> r = generate(shifted)) {
            *origin = ray.o + (r->ray.o - ray.o) / eps;
            *direction = ray.d + (r->ray.d - ray.d) / eps;
            return true;
        }
    }
    return false;
}

template <typename Generate>
std::optional<RayDifferential> differential_of(const Generate &generate, const CameraSample &sample, const Ray &ray,
                                               float scale) {
    RayDifferential rd;
    if (!shifted_ray(generate, sample, ray, 0, &rd.rx_origin, &rd.rx_direction) ||
        !shifted_ray(generate, sample, ray, 1, &rd.ry_origin, &rd.ry_direction))
        return std::nullopt;
    rd.rx_origin = ray.o + (rd.rx_origin - ray.o) * scale;
    rd.ry_origin = ray.o + (rd.ry_origin - ray.o) * scale;
    rd.rx_direction = ray.d + (rd.rx_direction - ray.d) * scale;
    rd.ry_direction = ray.d + (rd.ry_direction - ray.d) * scale;
    return rd;
}

} // namespace

float differential_scale(int spp) { return std::max(0.125f, 1 / std::sqrt(float(std::max(spp, 1)))); }

std::optional<CameraRay> generate_ray_differential(const Camera &camera, const CameraSample &sample,
                                                   const SampledWavelengths &lambda, float scale) {
    std::optional<CameraRay> r = camera.generate_ray(sample, lambda);
    if (!r) return r;
    const auto generate = [&](const CameraSample &s) { return camera.generate_ray(s, lambda); };
    r->differential = differential_of(generate, sample, r->ray, scale);
    return r;
}

CameraFootprint::CameraFootprint(const Camera &camera, const Transform &camera_from_world, Vec2i full_resolution)
    : camera_from_world_(camera_from_world), world_from_camera_(camera_from_world.inverse()) {
    const Vec3f unbounded{Infinity, Infinity, Infinity};
    min_pos_x_ = min_pos_y_ = min_dir_x_ = min_dir_y_ = unbounded;
    const SampledWavelengths lambda = SampledWavelengths::sample_visible(0.5f);
    const auto generate = [&](const CameraSample &s) { return camera.ray_at_rest(s, lambda); };
    // Along the film's diagonal, as pbrt-v4's FindMinimumDifferentials.
    constexpr int n = 512;
    for (int i = 0; i < n; ++i) {
        CameraSample sample;
        sample.p_lens = {0.5f, 0.5f};
        sample.p_film = {float(i) / (n - 1) * full_resolution.x, float(i) / (n - 1) * full_resolution.y};
        const std::optional<CameraRay> cr = generate(sample);
        if (!cr) continue;
        const std::optional<RayDifferential> rd = differential_of(generate, sample, cr->ray, 1.f);
        if (!rd) continue;
        const Vec3f dox = camera_from_world.apply_vector(rd->rx_origin - cr->ray.o);
        const Vec3f doy = camera_from_world.apply_vector(rd->ry_origin - cr->ray.o);
        if (length(dox) < length(min_pos_x_)) min_pos_x_ = dox;
        if (length(doy) < length(min_pos_y_)) min_pos_y_ = doy;
        // The direction differentials in pbrt-v4's frame around the ray: Frame::from_z of its
        // direction along the world's axes (pbrt-v4's default render space, "cameraworld", has
        // them), which approximate_dp_dxy then applies in the camera frame turned onto the point.
        const Frame f = Frame::from_z(normalize(cr->ray.d));
        const Vec3f z{0, 0, 1};
        const Vec3f dx = normalize(f.to_local(normalize(rd->rx_direction))) - z;
        const Vec3f dy = normalize(f.to_local(normalize(rd->ry_direction))) - z;
        if (length(dx) < length(min_dir_x_)) min_dir_x_ = dx;
        if (length(dy) < length(min_dir_y_)) min_dir_y_ = dy;
    }
    // A camera that generated no ray anywhere on the diagonal gives no footprint.
    for (Vec3f *v : {&min_pos_x_, &min_pos_y_, &min_dir_x_, &min_dir_y_})
        if (!is_finite(*v)) *v = Vec3f{};
}

void CameraFootprint::approximate_dp_dxy(Vec3f p, Vec3f n, int spp, Vec3f *dpdx, Vec3f *dpdy) const {
    *dpdx = *dpdy = Vec3f{};
    const Vec3f p_camera = camera_from_world_.apply_point(p);
    const float distance = length(p_camera);
    if (!(distance > 0)) return;
    // Turn the camera so that p lies on +z; the smallest differentials are offsets of the ray
    // down the z axis there, met with p's tangent plane.
    const Rotation down_z(p_camera / distance, {0, 0, 1});
    const Vec3f p_down = down_z.apply(p_camera);
    const Vec3f n_down = down_z.apply(normalize(camera_from_world_.apply_normal(n)));
    const std::optional<Vec3f> px = plane_hit(min_pos_x_, Vec3f{0, 0, 1} + min_dir_x_, p_down, n_down);
    const std::optional<Vec3f> py = plane_hit(min_pos_y_, Vec3f{0, 0, 1} + min_dir_y_, p_down, n_down);
    if (!px || !py) return;
    const float scale = differential_scale(spp);
    *dpdx = world_from_camera_.apply_vector(down_z.apply_inverse(*px - p_down)) * scale;
    *dpdy = world_from_camera_.apply_vector(down_z.apply_inverse(*py - p_down)) * scale;
}

void compute_differentials(SurfaceInteraction &si, const RayDifferential *ray, const CameraFootprint *footprint,
                           int spp) {
    si.dpdx = si.dpdy = Vec3f{};
    si.dudx = si.dvdx = si.dudy = si.dvdy = 0;
    std::optional<Vec3f> px, py;
    if (ray && dot(si.n, ray->rx_direction) != 0 && dot(si.n, ray->ry_direction) != 0) {
        px = plane_hit(ray->rx_origin, ray->rx_direction, si.p, si.n);
        py = plane_hit(ray->ry_origin, ray->ry_direction, si.p, si.n);
    }
    if (px && py) {
        si.dpdx = *px - si.p;
        si.dpdy = *py - si.p;
    } else if (footprint) {
        footprint->approximate_dp_dxy(si.p, si.n, spp, &si.dpdx, &si.dpdy);
    } else {
        return;
    }
    // Least squares for (du/dx, dv/dx) from dp/dx = dp/du du/dx + dp/dv dv/dx (and y alike).
    const float a00 = dot(si.dpdu, si.dpdu), a01 = dot(si.dpdu, si.dpdv), a11 = dot(si.dpdv, si.dpdv);
    float inv_det = 1 / (a00 * a11 - a01 * a01);
    if (!std::isfinite(inv_det)) inv_det = 0;
    const float b0x = dot(si.dpdu, si.dpdx), b1x = dot(si.dpdv, si.dpdx);
    const float b0y = dot(si.dpdu, si.dpdy), b1y = dot(si.dpdv, si.dpdy);
    // Clamped as pbrt-v4 does, so that a degenerate parameterisation cannot blow a lookup up.
    const auto bounded = [](float v) { return std::isfinite(v) ? std::clamp(v, -1e8f, 1e8f) : 0.f; };
    si.dudx = bounded((a11 * b0x - a01 * b1x) * inv_det);
    si.dvdx = bounded((a00 * b1x - a01 * b0x) * inv_det);
    si.dudy = bounded((a11 * b0y - a01 * b1y) * inv_det);
    si.dvdy = bounded((a00 * b1y - a01 * b0y) * inv_det);
}

} // namespace caustica
