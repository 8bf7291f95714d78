#include "media/medium_factory.h"

#include "materials/dielectric_material.h"
#include "materials/subsurface_coefficients.h"
#include "spectral/color_space.h"
#include "spectral/rgb_spectrum.h"
#include "media/cloud_medium.h"
#include "media/grid_media.h"
#include "media/homogeneous_medium.h"
#include "media/nanovdb_medium.h"
#include "spectral/photometric.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace caustica {

namespace {

SpectrumPtr read_coefficient(const ParameterDictionary &params, const std::string &name) {
    SpectrumPtr s = params.get_one_spectrum(name, std::make_shared<ConstantSpectrum>(1.f), SpectrumType::Unbounded);
    float lo, hi;
    spectrum_range(*s, &lo, &hi);
    if (!(std::isfinite(lo) && std::isfinite(hi) && lo >= 0))
        throw InputError(params.location(name), "\"" + name + "\" must be finite and non-negative at every "
                                                "wavelength (its values range over [" +
                                                    std::to_string(lo) + ", " + std::to_string(hi) + "])");
    return s;
}

float read_scale(const ParameterDictionary &params) {
    float scale = params.get_one_float("scale", 1);
    if (!(std::isfinite(scale) && scale >= 0))
        throw InputError(params.location("scale"), "\"scale\" must be a finite non-negative number");
    return scale;
}

float read_g(const ParameterDictionary &params) {
    float g = params.get_one_float("g", 0);
    if (!(g > -1 && g < 1))
        throw InputError(params.location("g"), "\"g\" must lie in (-1, 1): the Henyey-Greenstein lobe "
                                               "is a delta at +-1");
    return g;
}

// "Le" (an emission spectrum, null when absent or zero everywhere), checked to be finite and
// non-negative.
SpectrumPtr read_emission(const ParameterDictionary &params) {
    SpectrumPtr Le = params.get_one_spectrum("Le", nullptr, SpectrumType::Illuminant);
    if (!Le) return nullptr;
    float lo, hi;
    spectrum_range(*Le, &lo, &hi);
    if (!(std::isfinite(lo) && std::isfinite(hi) && lo >= 0))
        throw InputError(params.location("Le"), "\"Le\" must be finite and non-negative at every wavelength (its "
                                                "values range over [" + std::to_string(lo) + ", " +
                                                    std::to_string(hi) + "])");
    return hi > 0 ? Le : nullptr;
}

// pbrt-v4 divides an emission spectrum by its luminance, so that "Le" gives only a colour and
// "Lescale" the level (lights/photometric.h).
float photometric_normalisation(const Spectrum &Le) {
    const float y = spectrum_to_photometric(Le);
    return y > 0 ? 1 / y : 0.f;
}

float read_Le_scale(const ParameterDictionary &params) {
    const float s = params.get_one_float("Lescale", 1);
    if (!(std::isfinite(s) && s >= 0))
        throw InputError(params.location("Lescale"), "\"Lescale\" must be a finite non-negative number");
    return s;
}

TemperatureEmission read_temperature_mapping(const ParameterDictionary &params) {
    TemperatureEmission t;
    const float cutoff = params.get_one_float("temperaturecutoff", 0);
    t.offset = params.get_one_float("temperatureoffset", cutoff);
    t.scale = params.get_one_float("temperaturescale", 1);
    for (const char *name : {"temperatureoffset", "temperaturecutoff", "temperaturescale"})
        if (params.has(name) && !std::isfinite(params.get_one_float(name, 0)))
            throw InputError(params.location(name), std::string("\"") + name + "\" must be finite");
    return t;
}

MediumPtr create_homogeneous(const ParameterDictionary &params) {
    SpectrumPtr sigma_a, sigma_s;
    std::string preset = params.get_one_string("preset", "");
    if (!preset.empty()) {
        auto measured = find_measured_subsurface_medium(preset);
        if (!measured)
            throw InputError(params.location("preset"), "unknown medium preset \"" + preset +
                                                            "\" (Jensen et al. 2001's media: " +
                                                            measured_subsurface_media_names() + ")");
        // The reduced scattering coefficient stands for sigma_s with isotropic scattering
        // (similarity theory), as pbrt does with these presets.
        sigma_a = std::make_shared<RGBUnboundedSpectrum>(RGBColorSpace::srgb(), measured->sigma_a);
        sigma_s = std::make_shared<RGBUnboundedSpectrum>(RGBColorSpace::srgb(), measured->sigma_s_reduced);
    } else {
        sigma_a = read_coefficient(params, "sigma_a");
        sigma_s = read_coefficient(params, "sigma_s");
    }
    SpectrumPtr Le = read_emission(params);
    const float Le_scale = Le ? read_Le_scale(params) * photometric_normalisation(*Le) : 0.f;
    return std::make_shared<HomogeneousMedium>(std::move(sigma_a), std::move(sigma_s), read_scale(params),
                                               read_g(params), std::move(Le), Le_scale);
}

// The box p0-p1 of the medium's space that a grid or cloud fills.
Bounds3f read_bounds(const ParameterDictionary &params) {
    const Vec3f p0 = params.get_one_point3("p0", {0, 0, 0}), p1 = params.get_one_point3("p1", {1, 1, 1});
    Bounds3f b;
    b.expand(p0);
    b.expand(p1);
    const Vec3f extent = b.diagonal();
    if (!(extent.x > 0 && extent.y > 0 && extent.z > 0 && std::isfinite(extent.x) && std::isfinite(extent.y) &&
          std::isfinite(extent.z)))
        throw InputError(params.has("p1") ? params.location("p1") : params.directive_location(),
                         "\"p0\" and \"p1\" must span a box of finite, non-zero size on every axis");
    return b;
}

// "nx", "ny", "nz", checked against the number of values of the grid parameter `name`.
std::array<int, 3> read_resolution(const ParameterDictionary &params, const std::string &name, size_t values) {
    std::array<int, 3> n{params.get_one_int("nx", 1), params.get_one_int("ny", 1), params.get_one_int("nz", 1)};
    for (int i = 0; i < 3; ++i)
        if (n[i] < 1) {
            const char *axis[3] = {"nx", "ny", "nz"};
            throw InputError(params.location(axis[i]), std::string("\"") + axis[i] + "\" must be at least 1");
        }
    if (uint64_t(n[0]) * uint64_t(n[1]) * uint64_t(n[2]) != values)
        throw InputError(params.location(name), "\"" + name + "\" has " + std::to_string(values) +
                                                    " values; nx * ny * nz = " + std::to_string(n[0]) + " * " +
                                                    std::to_string(n[1]) + " * " + std::to_string(n[2]) +
                                                    " needs as many");
    return n;
}

void check_grid_values(const ParameterDictionary &params, const std::string &name, const float *v, size_t count) {
    for (size_t i = 0; i < count; ++i)
        if (!(std::isfinite(v[i]) && v[i] >= 0))
            throw InputError(params.location(name), "\"" + name + "\" value " + std::to_string(i) + " is " +
                                                        std::to_string(v[i]) +
                                                        "; grid values must be finite and non-negative");
}

MediumPtr create_uniform_grid(const ParameterDictionary &params, const SourceLocation &loc,
                              const Transform &render_from_medium) {
    std::vector<float> density = params.get_float_array("density");
    if (density.empty()) throw InputError(loc, "a \"uniformgrid\" medium needs \"float density\" values");
    const std::array<int, 3> n = read_resolution(params, "density", density.size());
    check_grid_values(params, "density", density.data(), density.size());
    // Emission: a "temperature" grid or an "Le" spectrum, times "Lescale" (one value or a grid).
    UniformGridEmission emission;
    auto grid_of_density_size = [&](const std::string &name, float multiplier) {
        std::vector<float> v = params.get_float_array(name);
        read_resolution(params, name, v.size());
        check_grid_values(params, name, v.data(), v.size());
        for (float &x : v) x *= multiplier;
        return VoxelGrid<float>(std::move(v), n[0], n[1], n[2]);
    };
    emission.Le = read_emission(params);
    if (params.has("temperature")) {
        if (emission.Le)
            throw InputError(params.location("Le"), "\"Le\" and \"temperature\" were both given: a grid medium "
                                                    "emits one or the other");
        emission.temperature = grid_of_density_size("temperature", 1);
        emission.blackbody = read_temperature_mapping(params);
    }
    const float norm = emission.Le ? photometric_normalisation(*emission.Le) : 1.f;
    if (params.get_float_array("Lescale").size() > 1 || (params.has("Lescale") && density.size() == 1)) {
        emission.Le_scale = grid_of_density_size("Lescale", norm);
    } else {
        emission.Le_scale = VoxelGrid<float>({read_Le_scale(params) * norm}, 1, 1, 1);
    }
    return std::make_shared<UniformGridMedium>(render_from_medium, read_bounds(params), read_coefficient(params, "sigma_a"),
                                               read_coefficient(params, "sigma_s"), read_scale(params), read_g(params),
                                               VoxelGrid<float>(std::move(density), n[0], n[1], n[2]),
                                               std::move(emission));
}

MediumPtr create_rgb_grid(const ParameterDictionary &params, const SourceLocation &loc,
                          const Transform &render_from_medium) {
    const std::vector<Vec3f> sigma_a = params.get_rgb_array("sigma_a"), sigma_s = params.get_rgb_array("sigma_s");
    if (sigma_a.empty() && sigma_s.empty())
        throw InputError(loc, "an \"rgbgrid\" medium needs \"rgb sigma_a\" or \"rgb sigma_s\" values (or both)");
    if (!sigma_a.empty() && !sigma_s.empty() && sigma_a.size() != sigma_s.size())
        throw InputError(params.location("sigma_s"), "\"sigma_s\" has " + std::to_string(sigma_s.size()) +
                                                          " values and \"sigma_a\" " + std::to_string(sigma_a.size()) +
                                                          "; they must match");
    const std::string first = sigma_a.empty() ? "sigma_s" : "sigma_a";
    const std::array<int, 3> n = read_resolution(params, first, std::max(sigma_a.size(), sigma_s.size()));
    const RGBColorSpace &cs = params.color_space();
    auto grid = [&](const std::vector<Vec3f> &rgb, const std::string &name) {
        std::unique_ptr<VoxelGrid<RGBUnboundedSpectrum>> g;
        if (rgb.empty()) return g;
        check_grid_values(params, name, &rgb[0].x, rgb.size() * 3);
        std::vector<RGBUnboundedSpectrum> spectra;
        spectra.reserve(rgb.size());
        for (const Vec3f &c : rgb) spectra.emplace_back(cs, RGB{c.x, c.y, c.z});
        return std::make_unique<VoxelGrid<RGBUnboundedSpectrum>>(std::move(spectra), n[0], n[1], n[2]);
    };
    const std::vector<Vec3f> Le = params.get_rgb_array("Le");
    std::unique_ptr<VoxelGrid<RGBIlluminantSpectrum>> Le_grid;
    if (!Le.empty()) {
        if (sigma_a.empty())
            throw InputError(params.location("Le"), "an emissive \"rgbgrid\" needs \"rgb sigma_a\": the emission is "
                                                    "sigma_a Le");
        read_resolution(params, "Le", Le.size());
        check_grid_values(params, "Le", &Le[0].x, Le.size() * 3);
        std::vector<RGBIlluminantSpectrum> spectra;
        spectra.reserve(Le.size());
        for (const Vec3f &c : Le) spectra.emplace_back(cs, RGB{c.x, c.y, c.z});
        Le_grid = std::make_unique<VoxelGrid<RGBIlluminantSpectrum>>(std::move(spectra), n[0], n[1], n[2]);
    }
    return std::make_shared<RGBGridMedium>(render_from_medium, read_bounds(params), read_g(params),
                                           grid(sigma_a, "sigma_a"), grid(sigma_s, "sigma_s"), read_scale(params),
                                           std::move(Le_grid), read_Le_scale(params));
}

MediumPtr create_cloud(const ParameterDictionary &params, const Transform &render_from_medium) {
    auto finite = [&](const char *name, float def) {
        const float v = params.get_one_float(name, def);
        if (!std::isfinite(v)) throw InputError(params.location(name), std::string("\"") + name + "\" must be finite");
        return v;
    };
    const float density = finite("density", 1), wispiness = finite("wispiness", 1), frequency = finite("frequency", 5);
    return std::make_shared<CloudMedium>(render_from_medium, read_bounds(params), read_coefficient(params, "sigma_a"),
                                         read_coefficient(params, "sigma_s"), read_g(params), density, wispiness,
                                         frequency);
}

MediumPtr create_nanovdb(const ParameterDictionary &params, const SourceLocation &loc,
                         const Transform &render_from_medium) {
    const std::string file = params.get_one_string("filename", "");
    if (file.empty()) throw InputError(loc, "a \"nanovdb\" medium needs \"string filename\"");
    const std::string path = params.file_path("filename", file);
    const std::string grid_name = params.get_one_string("gridname", "density");
    const std::string temperature_name = params.get_one_string("temperaturename", "temperature");
    const float Le_scale = read_Le_scale(params);
    NanoVDBMedium::Handle density, temperature;
    try {
        density = read_nanovdb_grid(path, grid_name);
        if (Le_scale > 0) temperature = read_nanovdb_grid(path, temperature_name);
    } catch (const std::exception &e) {
        throw InputError(params.location("filename"), "cannot read NanoVDB file \"" + file + "\": " + e.what());
    }
    if (!density)
        throw InputError(params.location("filename"), "NanoVDB file \"" + file + "\" has no grid named \"" + grid_name + "\"");
    // As in pbrt-v4, a file without the temperature grid is a medium that does not emit.
    return std::make_shared<NanoVDBMedium>(render_from_medium, std::move(density), read_coefficient(params, "sigma_a"),
                                           read_coefficient(params, "sigma_s"), read_scale(params), read_g(params),
                                           std::move(temperature), Le_scale, read_temperature_mapping(params));
}

} // namespace

MediumPtr create_medium(const std::string &type, const ParameterDictionary &params, const SourceLocation &loc,
                        const Transform &render_from_medium) {
    if (type == "homogeneous") return create_homogeneous(params);
    if (type == "uniformgrid") return create_uniform_grid(params, loc, render_from_medium);
    if (type == "rgbgrid") return create_rgb_grid(params, loc, render_from_medium);
    if (type == "cloud") return create_cloud(params, render_from_medium);
    if (type == "nanovdb") return create_nanovdb(params, loc, render_from_medium);
    throw InputError(loc, "medium type \"" + type +
                              "\" is not supported (Caustica has \"homogeneous\", \"uniformgrid\", \"rgbgrid\", "
                              "\"cloud\" and \"nanovdb\")");
}

} // namespace caustica
