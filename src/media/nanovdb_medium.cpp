#include "media/nanovdb_medium.h"

#include <nanovdb/util/IO.h>
#include <nanovdb/util/SampleFromVoxels.h>

#include <algorithm>
#include <stdexcept>

namespace caustica {

namespace {

constexpr int kMajorantResolution = 64; // pbrt-v4's

const nanovdb::FloatGrid &float_grid(const NanoVDBMedium::Handle &handle) {
    const nanovdb::FloatGrid *grid = handle.grid<float>();
    if (!grid) throw std::runtime_error("the grid does not hold float values");
    return *grid;
}

Bounds3f world_bounds(const nanovdb::FloatGrid &grid) {
    const auto box = grid.worldBBox();
    return {{float(box.min()[0]), float(box.min()[1]), float(box.min()[2])},
            {float(box.max()[0]), float(box.max()[1]), float(box.max()[2])}};
}

// Per majorant cell, the largest voxel value within one voxel (the interpolation's reach) of the
// cell's index-space bounds, clipped to the grid's index bounding box (pbrt-v4's choice).
MajorantGrid nanovdb_majorants(const nanovdb::FloatGrid &grid) {
    MajorantGrid majorants(kMajorantResolution, kMajorantResolution, kMajorantResolution);
    const Bounds3f bounds = world_bounds(grid);
    const Vec3f extent = bounds.diagonal();
    const auto index_box = grid.indexBBox();
    auto accessor = grid.getAccessor();
    for (int z = 0; z < majorants.nz(); ++z)
        for (int y = 0; y < majorants.ny(); ++y)
            for (int x = 0; x < majorants.nx(); ++x) {
                const Bounds3f cell = majorants.cell_bounds(x, y, z);
                const auto i0 = grid.worldToIndexF(nanovdb::Vec3R(bounds.lo.x + cell.lo.x * extent.x,
                                                                  bounds.lo.y + cell.lo.y * extent.y,
                                                                  bounds.lo.z + cell.lo.z * extent.z));
                const auto i1 = grid.worldToIndexF(nanovdb::Vec3R(bounds.lo.x + cell.hi.x * extent.x,
                                                                  bounds.lo.y + cell.hi.y * extent.y,
                                                                  bounds.lo.z + cell.hi.z * extent.z));
                int lo[3], hi[3];
                for (int a = 0; a < 3; ++a) {
                    lo[a] = std::max(int(std::min(i0[a], i1[a]) - 1), index_box.min()[a]);
                    hi[a] = std::min(int(std::max(i0[a], i1[a]) + 1), index_box.max()[a]);
                }
                float m = 0;
                for (int k = lo[2]; k <= hi[2]; ++k)
                    for (int j = lo[1]; j <= hi[1]; ++j)
                        for (int i = lo[0]; i <= hi[0]; ++i) m = std::max(m, accessor.getValue({i, j, k}));
                majorants.set(x, y, z, m);
            }
    return majorants;
}

} // namespace

NanoVDBMedium::Handle read_nanovdb_grid(const std::string &path, const std::string &name) {
    NanoVDBMedium::Handle handle = nanovdb::io::readGrid<nanovdb::HostBuffer>(path, name);
    if (handle) float_grid(handle);
    return handle;
}

NanoVDBMedium::NanoVDBMedium(const Transform &render_from_medium, Handle density, SpectrumPtr sigma_a,
                             SpectrumPtr sigma_s, float scale, float g, Handle temperature, float Le_scale,
                             TemperatureEmission blackbody)
    : ScalarDensityMedium(render_from_medium, world_bounds(float_grid(density)), g,
                          nanovdb_majorants(float_grid(density)), std::move(sigma_a), std::move(sigma_s), scale),
      handle_(std::move(density)), temperature_(std::move(temperature)), grid_(&float_grid(handle_)),
      Le_scale_(Le_scale), blackbody_(blackbody) {
    if (temperature_) temperature_grid_ = &float_grid(temperature_);
    const Bounds3f bounds = world_bounds(*grid_);
    lo_ = bounds.lo;
    extent_ = bounds.diagonal();
}

float NanoVDBMedium::sample(const nanovdb::FloatGrid &grid, Vec3f u) const {
    const Vec3f p = lo_ + Vec3f{u.x * extent_.x, u.y * extent_.y, u.z * extent_.z};
    const auto index = grid.worldToIndexF(nanovdb::Vec3f(p.x, p.y, p.z));
    using Sampler = nanovdb::SampleFromVoxels<nanovdb::FloatGrid::TreeType, 1, false>;
    return Sampler(grid.tree())(index);
}

float NanoVDBMedium::density_at(Vec3f u) const { return sample(*grid_, u); }

SampledSpectrum NanoVDBMedium::local_Le(Vec3f u, const SampledWavelengths &lambda) const {
    return blackbody_.at(sample(*temperature_grid_, u), lambda) * Le_scale_;
}

} // namespace caustica
