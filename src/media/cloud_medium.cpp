#include "media/cloud_medium.h"

#include "textures/perlin_noise.h"

#include <algorithm>

namespace caustica {

namespace {

MajorantGrid unit_majorant() {
    MajorantGrid grid(1, 1, 1);
    grid.set(0, 0, 0, 1);
    return grid;
}

// pbrt-v4's DNoise: the noise's gradient by forward differences of 0.01.
Vec3f noise_gradient(Vec3f p) {
    constexpr float delta = 0.01f;
    const float n = perlin_noise(p);
    return Vec3f{perlin_noise(p + Vec3f{delta, 0, 0}) - n, perlin_noise(p + Vec3f{0, delta, 0}) - n,
                 perlin_noise(p + Vec3f{0, 0, delta}) - n} /
           delta;
}

} // namespace

CloudMedium::CloudMedium(const Transform &render_from_medium, const Bounds3f &bounds, SpectrumPtr sigma_a,
                         SpectrumPtr sigma_s, float g, float density, float wispiness, float frequency)
    : ScalarDensityMedium(render_from_medium, bounds, g, unit_majorant(), std::move(sigma_a), std::move(sigma_s), 1),
      lo_(bounds.lo), extent_(bounds.diagonal()), density_(density), wispiness_(wispiness), frequency_(frequency) {}

float CloudMedium::density(Vec3f p) const {
    Vec3f pp = p * frequency_;
    if (wispiness_ > 0) {
        // Displace the lookup point by the noise's gradient, for wisps.
        float omega = 0.05f * wispiness_, lambda = 10;
        for (int i = 0; i < 2; ++i) {
            pp = pp + noise_gradient(pp * lambda) * omega;
            omega *= 0.5f;
            lambda *= 1.99f;
        }
    }
    float d = 0, omega = 0.5f, lambda = 1;
    for (int i = 0; i < 5; ++i) {
        d += omega * perlin_noise(pp * lambda);
        omega *= 0.5f;
        lambda *= 1.99f;
    }
    // Thinner with altitude, and solid at and below y = 0 (the cloud's flat base).
    d = std::clamp((1 - p.y) * 4.5f * density_ * d, 0.f, 1.f);
    d += 2 * std::max(0.f, 0.5f - p.y);
    return std::clamp(d, 0.f, 1.f);
}

float CloudMedium::density_at(Vec3f u) const {
    return density(lo_ + Vec3f{u.x * extent_.x, u.y * extent_.y, u.z * extent_.z});
}

} // namespace caustica
