// pbrt-v4's "nanovdb" medium: a density grid read from a NanoVDB file (Museth 2021, "NanoVDB: A
// GPU-Friendly and Portable VDB Data Structure for Real-Time Rendering and Simulation") through
// the NanoVDB library, interpolated trilinearly in index space and scaling sigma_a and sigma_s,
// inside the grid's world bounding box (in the medium's space). Its majorants are pbrt-v4's: a
// 64^3 grid whose cells hold the largest voxel value within one voxel of the cell. A temperature
// grid from the same file makes it emit: "Lescale" times blackbody emission at the temperature
// (grid_media.h's TemperatureEmission), as pbrt-v4 does.
#pragma once

#include "media/grid_media.h"
#include "media/heterogeneous_medium.h"

#include <nanovdb/util/GridHandle.h>
#include <nanovdb/util/HostBuffer.h>

#include <string>

namespace caustica {

class NanoVDBMedium final : public ScalarDensityMedium {
  public:
    using Handle = nanovdb::GridHandle<nanovdb::HostBuffer>;
    // density: a handle holding a float grid (read_nanovdb_density_grid).
    // temperature: an empty handle, or one holding a float grid; Le_scale > 0 makes it emit.
    NanoVDBMedium(const Transform &render_from_medium, Handle density, SpectrumPtr sigma_a, SpectrumPtr sigma_s,
                  float scale, float g, Handle temperature = {}, float Le_scale = 0,
                  TemperatureEmission blackbody = {});
    bool is_emissive() const override { return temperature_grid_ && Le_scale_ > 0; }

  private:
    float density_at(Vec3f u) const override;
    SampledSpectrum local_Le(Vec3f u, const SampledWavelengths &lambda) const override;
    // The grid's trilinear interpolation at point u of the unit cube over the density's bounds.
    float sample(const nanovdb::FloatGrid &grid, Vec3f u) const;

    Handle handle_, temperature_;
    const nanovdb::FloatGrid *grid_, *temperature_grid_ = nullptr;
    Vec3f lo_, extent_;
    float Le_scale_;
    TemperatureEmission blackbody_;
};

// Reads grid `name` from the NanoVDB file at path: a handle holding a float grid, or an empty
// handle when the file has no grid of that name. Throws std::runtime_error when the file cannot
// be read or the grid holds other than floats.
NanoVDBMedium::Handle read_nanovdb_grid(const std::string &path, const std::string &name);

} // namespace caustica
