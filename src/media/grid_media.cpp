#include "media/grid_media.h"

namespace caustica {

namespace {

constexpr int kMajorantResolution = 16; // pbrt-v4's

float identity(float v) { return v; }
float largest(const RGBUnboundedSpectrum &s) { return s.max_value(); }

} // namespace

SampledSpectrum TemperatureEmission::at(float temperature, const SampledWavelengths &lambda) const {
    const float t = (temperature - offset) * scale;
    return t > 100 ? BlackbodySpectrum(t).sample(lambda) : SampledSpectrum(0.f);
}

SampledSpectrum UniformGridEmission::at(Vec3f u, const SampledWavelengths &lambda) const {
    const float s = Le_scale.lookup(u, identity);
    if (!(s > 0)) return SampledSpectrum(0.f);
    if (temperature) return blackbody.at(temperature->lookup(u, identity), lambda) * s;
    return Le ? Le->sample(lambda) * s : SampledSpectrum(0.f);
}

UniformGridMedium::UniformGridMedium(const Transform &render_from_medium, const Bounds3f &bounds, SpectrumPtr sigma_a,
                                     SpectrumPtr sigma_s, float scale, float g, VoxelGrid<float> density,
                                     UniformGridEmission emission)
    : ScalarDensityMedium(render_from_medium, bounds, g, density.majorants(kMajorantResolution, identity),
                          std::move(sigma_a), std::move(sigma_s), scale),
      density_(std::move(density)), emission_(std::move(emission)) {}

float UniformGridMedium::density_at(Vec3f u) const { return density_.lookup(u, identity); }

namespace {

MajorantGrid rgb_majorants(const VoxelGrid<RGBUnboundedSpectrum> *sigma_a, const VoxelGrid<RGBUnboundedSpectrum> *sigma_s,
                           float scale) {
    MajorantGrid grid(kMajorantResolution, kMajorantResolution, kMajorantResolution);
    for (int z = 0; z < grid.nz(); ++z)
        for (int y = 0; y < grid.ny(); ++y)
            for (int x = 0; x < grid.nx(); ++x) {
                const Bounds3f b = grid.cell_bounds(x, y, z);
                const float a = sigma_a ? sigma_a->max_over(b, largest) : 1.f;
                const float s = sigma_s ? sigma_s->max_over(b, largest) : 1.f;
                grid.set(x, y, z, scale * (a + s));
            }
    return grid;
}

} // namespace

RGBGridMedium::RGBGridMedium(const Transform &render_from_medium, const Bounds3f &bounds, float g,
                             std::unique_ptr<VoxelGrid<RGBUnboundedSpectrum>> sigma_a,
                             std::unique_ptr<VoxelGrid<RGBUnboundedSpectrum>> sigma_s, float scale,
                             std::unique_ptr<VoxelGrid<RGBIlluminantSpectrum>> Le, float Le_scale)
    : HeterogeneousMedium(render_from_medium, bounds, g, rgb_majorants(sigma_a.get(), sigma_s.get(), scale)),
      sigma_a_(std::move(sigma_a)), sigma_s_(std::move(sigma_s)), scale_(scale), Le_(std::move(Le)),
      Le_scale_(Le_scale) {
    MajorantGrid all(1, 1, 1);
    scatters_ = scale_ > 0 && (!sigma_s_ || sigma_s_->max_over(all.cell_bounds(0, 0, 0), largest) > 0);
}

MediumProperties RGBGridMedium::local(Vec3f u, const SampledWavelengths &lambda) const {
    auto spectrum = [&lambda](const RGBUnboundedSpectrum &s) { return s.sample(lambda); };
    return {sigma_a_ ? sigma_a_->lookup(u, spectrum) * scale_ : SampledSpectrum(scale_),
            sigma_s_ ? sigma_s_->lookup(u, spectrum) * scale_ : SampledSpectrum(scale_)};
}

SampledSpectrum RGBGridMedium::local_Le(Vec3f u, const SampledWavelengths &lambda) const {
    return Le_->lookup(u, [&lambda](const RGBIlluminantSpectrum &s) { return s.sample(lambda); }) * Le_scale_;
}

} // namespace caustica
