#include "media/medium_factory.h"

#include "materials/dielectric_material.h"
#include "materials/subsurface_coefficients.h"
#include "spectral/color_space.h"
#include "spectral/rgb_spectrum.h"
#include "media/cloud_medium.h"
#include "media/grid_media.h"
#include "media/homogeneous_medium.h"
#include "media/nanovdb_medium.h"

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
    return std::make_shared<HomogeneousMedium>(std::move(sigma_a), std::move(sigma_s), read_scale(params),
                                               read_g(params));
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
    return std::make_shared<UniformGridMedium>(render_from_medium, read_bounds(params), read_coefficient(params, "sigma_a"),
                                               read_coefficient(params, "sigma_s"), read_scale(params), read_g(params),
                                               VoxelGrid<float>(std::move(density), n[0], n[1], n[2]));
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
    return std::make_shared<RGBGridMedium>(render_from_medium, read_bounds(params), read_g(params),
                                           grid(sigma_a, "sigma_a"), grid(sigma_s, "sigma_s"), read_scale(params));
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
    NanoVDBMedium::Handle density, temperature;
    try {
        density = read_nanovdb_grid(path, grid_name);
        if (params.get_one_float("Lescale", 1) > 0) temperature = read_nanovdb_grid(path, temperature_name);
    } catch (const std::exception &e) {
        throw InputError(params.location("filename"), "cannot read NanoVDB file \"" + file + "\": " + e.what());
    }
    if (!density)
        throw InputError(params.location("filename"), "NanoVDB file \"" + file + "\" has no grid named \"" + grid_name + "\"");
    if (temperature)
        throw InputError(params.location("filename"), "NanoVDB file \"" + file + "\" has a \"" + temperature_name +
                                                          "\" grid: emissive media are not supported yet (set "
                                                          "\"float Lescale\" 0 to render it without emission)");
    return std::make_shared<NanoVDBMedium>(render_from_medium, std::move(density), read_coefficient(params, "sigma_a"),
                                           read_coefficient(params, "sigma_s"), read_scale(params), read_g(params));
}

// Emission ("Le", "Lescale", "temperature") is not rendered yet: an emissive medium is an error
// rather than silently dark.
void reject_emission(const ParameterDictionary &params) {
    if (params.has("temperature"))
        throw InputError(params.location("temperature"), "emissive media are not supported yet: remove \"temperature\"");
    if (!params.has("Le")) return;
    float hi = 0;
    if (SpectrumPtr Le = params.get_one_spectrum("Le", nullptr, SpectrumType::Illuminant)) {
        float lo;
        spectrum_range(*Le, &lo, &hi);
    } else {
        for (const Vec3f &c : params.get_rgb_array("Le")) hi = std::max({hi, c.x, c.y, c.z});
    }
    const std::vector<float> Le_scale = params.get_float_array("Lescale");
    float scale = Le_scale.empty() ? 1.f : 0.f;
    for (float s : Le_scale) scale = std::max(scale, s);
    if (hi * scale != 0)
        throw InputError(params.location("Le"), "emissive media are not supported yet: \"Le\" must be zero");
}

} // namespace

MediumPtr create_medium(const std::string &type, const ParameterDictionary &params, const SourceLocation &loc,
                        const Transform &render_from_medium) {
    if (type == "homogeneous" || type == "uniformgrid" || type == "rgbgrid") reject_emission(params);
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
