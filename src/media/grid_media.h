// pbrt-v4's two media given by voxel grids in the scene file (pbrt-v4 section 11.4.3):
//   "uniformgrid": one density per voxel, which scales spectra sigma_a and sigma_s;
//   "rgbgrid":     an RGB sigma_a and sigma_s per voxel, each made a spectrum (RGBUnboundedSpectrum).
// Both are heterogeneous media (heterogeneous_medium.h) over the box p0-p1 of the medium's space,
// and both may emit (pbrt-v4's "Le", "Lescale", and the uniform grid's "temperature").
#pragma once

#include "media/heterogeneous_medium.h"
#include "spectral/rgb_spectrum.h"
#include "spectral/spectrum.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <vector>

namespace caustica {

// Values at the centres of nx x ny x nz voxels over the unit cube, interpolated trilinearly as
// pbrt-v4's SampledGrid does: sample (i, j, k) sits at ((i + 0.5) / nx, ...), and samples
// outside the grid are zero, so the field falls to zero over the outer half voxel.
template <typename T> class VoxelGrid {
  public:
    VoxelGrid(std::vector<T> values, int nx, int ny, int nz)
        : values_(std::move(values)), nx_(nx), ny_(ny), nz_(nz) {}

    // convert(const T &) gives what is interpolated (a float, or a SampledSpectrum).
    template <typename Convert> auto lookup(Vec3f u, Convert convert) const {
        const float x = u.x * nx_ - 0.5f, y = u.y * ny_ - 0.5f, z = u.z * nz_ - 0.5f;
        const int ix = int(std::floor(x)), iy = int(std::floor(y)), iz = int(std::floor(z));
        const float dx = x - ix, dy = y - iy, dz = z - iz;
        auto v = [&](int i, int j, int k) { return at(ix + i, iy + j, iz + k, convert); };
        auto lerp = [](float t, auto a, auto b) { return a * (1 - t) + b * t; };
        return lerp(dz, lerp(dy, lerp(dx, v(0, 0, 0), v(1, 0, 0)), lerp(dx, v(0, 1, 0), v(1, 1, 0))),
                    lerp(dy, lerp(dx, v(0, 0, 1), v(1, 0, 1)), lerp(dx, v(0, 1, 1), v(1, 1, 1))));
    }
    // The largest converted value among the samples that influence any point of box b.
    template <typename Convert> float max_over(const Bounds3f &b, Convert convert) const;
    // A majorant grid of res^3 cells over this grid: each cell's largest influencing sample.
    template <typename Convert> MajorantGrid majorants(int res, Convert convert) const {
        MajorantGrid grid(res, res, res);
        for (int z = 0; z < res; ++z)
            for (int y = 0; y < res; ++y)
                for (int x = 0; x < res; ++x) grid.set(x, y, z, max_over(grid.cell_bounds(x, y, z), convert));
        return grid;
    }

  private:
    template <typename Convert> auto at(int x, int y, int z, Convert convert) const {
        using Result = decltype(convert(values_[0]));
        if (x < 0 || y < 0 || z < 0 || x >= nx_ || y >= ny_ || z >= nz_) return Result(0.f);
        return Result(convert(values_[(size_t(z) * ny_ + y) * nx_ + x]));
    }

    std::vector<T> values_;
    int nx_, ny_, nz_;
};

template <typename T>
template <typename Convert>
float VoxelGrid<T>::max_over(const Bounds3f &b, Convert convert) const {
    const int lo[3] = {std::max(0, int(std::floor(b.lo.x * nx_ - 0.5f))), std::max(0, int(std::floor(b.lo.y * ny_ - 0.5f))),
                       std::max(0, int(std::floor(b.lo.z * nz_ - 0.5f)))};
    const int hi[3] = {std::min(nx_ - 1, int(std::floor(b.hi.x * nx_ - 0.5f)) + 1),
                       std::min(ny_ - 1, int(std::floor(b.hi.y * ny_ - 0.5f)) + 1),
                       std::min(nz_ - 1, int(std::floor(b.hi.z * nz_ - 0.5f)) + 1)};
    float m = 0;
    for (int z = lo[2]; z <= hi[2]; ++z)
        for (int y = lo[1]; y <= hi[1]; ++y)
            for (int x = lo[0]; x <= hi[0]; ++x) m = std::max(m, float(convert(values_[(size_t(z) * ny_ + y) * nx_ + x])));
    return m;
}

// Blackbody emission (normalised to a peak of 1, as pbrt-v4's BlackbodySpectrum) at a grid's
// temperature after pbrt-v4's "temperatureoffset" (or "temperaturecutoff") and
// "temperaturescale"; none at or below 100 K, as in pbrt-v4.
struct TemperatureEmission {
    float offset = 0, scale = 1;
    SampledSpectrum at(float temperature, const SampledWavelengths &lambda) const;
};

// A "uniformgrid" medium's emission (pbrt-v4's GridMedium): Le(u) = Lescale(u) times either
// blackbody emission at the "temperature" grid's value or the "Le" spectrum. Lescale is a grid of
// the density's resolution, or one value (a 1^3 grid, which pbrt-v4's interpolation makes fall to
// half at the faces of the box), divided by the luminance of "Le" (pbrt-v4's photometric
// normalisation of emission spectra).
struct UniformGridEmission {
    SpectrumPtr Le;                             // null: no "Le" (emissive only with a temperature)
    std::optional<VoxelGrid<float>> temperature;
    TemperatureEmission blackbody;
    VoxelGrid<float> Le_scale{{1.f}, 1, 1, 1};

    bool emissive() const { return temperature || Le; }
    SampledSpectrum at(Vec3f u, const SampledWavelengths &lambda) const;
};

// "uniformgrid": sigma_a(p) = d(p) sigma_a, sigma_s(p) = d(p) sigma_s, with sigma_a and sigma_s
// already multiplied by "scale". Majorant: the cell's largest density times sigma_t.
class UniformGridMedium final : public ScalarDensityMedium {
  public:
    UniformGridMedium(const Transform &render_from_medium, const Bounds3f &bounds, SpectrumPtr sigma_a,
                      SpectrumPtr sigma_s, float scale, float g, VoxelGrid<float> density,
                      UniformGridEmission emission = {});
    bool is_emissive() const override { return emission_.emissive(); }

  private:
    float density_at(Vec3f u) const override;
    SampledSpectrum local_Le(Vec3f u, const SampledWavelengths &lambda) const override {
        return emission_.at(u, lambda);
    }

    VoxelGrid<float> density_;
    UniformGridEmission emission_;
};

// "rgbgrid": per-voxel RGB coefficients (a missing grid is 1 everywhere, as in pbrt-v4), times
// "scale". Majorant: the cell's largest sigma_a plus largest sigma_s over all wavelengths.
class RGBGridMedium final : public HeterogeneousMedium {
  public:
    // Either grid may be absent (empty optional-like: nullptr).
    // Le: per-voxel emission (RGBIlluminantSpectrum), times Le_scale; may be absent.
    RGBGridMedium(const Transform &render_from_medium, const Bounds3f &bounds, float g,
                  std::unique_ptr<VoxelGrid<RGBUnboundedSpectrum>> sigma_a,
                  std::unique_ptr<VoxelGrid<RGBUnboundedSpectrum>> sigma_s, float scale,
                  std::unique_ptr<VoxelGrid<RGBIlluminantSpectrum>> Le = nullptr, float Le_scale = 0);
    bool is_emissive() const override { return Le_ && Le_scale_ > 0; }

  protected:
    MediumProperties local(Vec3f u, const SampledWavelengths &lambda) const override;
    SampledSpectrum majorant_scale(const SampledWavelengths &) const override { return SampledSpectrum(1.f); }
    bool may_scatter(const SampledWavelengths &, int) const override { return scatters_; }
    SampledSpectrum local_Le(Vec3f u, const SampledWavelengths &lambda) const override;

  private:
    std::unique_ptr<VoxelGrid<RGBUnboundedSpectrum>> sigma_a_, sigma_s_;
    float scale_;
    std::unique_ptr<VoxelGrid<RGBIlluminantSpectrum>> Le_;
    float Le_scale_;
    bool scatters_;
};

} // namespace caustica
