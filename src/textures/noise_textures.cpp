#include "textures/noise_textures.h"

#include "spectral/rgb_spectrum.h"

#include <algorithm>
#include <cmath>

namespace caustica {

RGB MarbleTexture::colour(Vec3f p, Vec3f dpdx, Vec3f dpdy) const {
    float marble = p.y + variation_ * fractional_brownian_motion(p, omega_, octaves_, dpdx, dpdy);
    float t = 0.5f + 0.5f * std::sin(marble);
    // pbrt-v4's spline: nine control points, six cubic segments of four consecutive points.
    static constexpr RGB Colours[] = {
        {.58f, .58f, .6f}, {.58f, .58f, .6f}, {.58f, .58f, .6f}, {.5f, .5f, .5f},   {.6f, .59f, .58f},
        {.58f, .58f, .6f}, {.58f, .58f, .6f}, {.2f, .2f, .33f},  {.58f, .58f, .6f},
    };
    constexpr int Segments = int(std::size(Colours)) - 3;
    int first = std::min(int(std::floor(t * Segments)), Segments - 1);
    float u = t * Segments - float(first);
    // The cubic Bernstein basis at u.
    float b0 = (1 - u) * (1 - u) * (1 - u), b1 = 3 * u * (1 - u) * (1 - u), b2 = 3 * u * u * (1 - u),
          b3 = u * u * u;
    const RGB *c = Colours + first;
    RGB rgb;
    for (int i = 0; i < 3; ++i)
        rgb[i] = 1.5f * (b0 * c[0][i] + b1 * c[1][i] + b2 * c[2][i] + b3 * c[3][i]);
    return rgb;
}

SampledSpectrum MarbleTexture::evaluate(const TextureEvalContext &ctx,
                                        const SampledWavelengths &lambda) const {
    return RGBAlbedoSpectrum(RGBColorSpace::srgb(), colour(scale_ * mapping_.map(ctx), scale_ * mapping_.map_vector(ctx.dpdx),
                                                         scale_ * mapping_.map_vector(ctx.dpdy))).sample(lambda);
}

bool inside_polka_dot(Vec2f st) {
    float s_cell = std::floor(st.x + 0.5f), t_cell = std::floor(st.y + 0.5f);
    if (!(perlin_noise(s_cell + 0.5f, t_cell + 0.5f, 0.5f) > 0)) return false;
    constexpr float Radius = 0.35f, MaxShift = 0.5f - Radius;
    float s_centre = s_cell + MaxShift * perlin_noise(s_cell + 1.5f, t_cell + 2.8f, 0.5f);
    float t_centre = t_cell + MaxShift * perlin_noise(s_cell + 4.5f, t_cell + 9.8f, 0.5f);
    float ds = st.x - s_centre, dt = st.y - t_centre;
    return ds * ds + dt * dt < Radius * Radius;
}

} // namespace caustica
