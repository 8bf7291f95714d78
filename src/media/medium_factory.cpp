#include "media/medium_factory.h"

#include "materials/dielectric_material.h"
#include "materials/subsurface_coefficients.h"
#include "spectral/color_space.h"
#include "spectral/rgb_spectrum.h"
#include "media/homogeneous_medium.h"

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

} // namespace

MediumPtr create_medium(const std::string &type, const ParameterDictionary &params, const SourceLocation &loc) {
    if (type != "homogeneous")
        throw InputError(loc, "medium type \"" + type + "\" is not supported (Caustica has \"homogeneous\")");
    if (params.has("Le")) {
        SpectrumPtr Le = params.get_one_spectrum("Le", nullptr, SpectrumType::Illuminant);
        float lo, hi;
        spectrum_range(*Le, &lo, &hi);
        float Le_scale = params.get_one_float("Lescale", 1);
        if (hi * Le_scale != 0)
            throw InputError(params.location("Le"), "emissive media are not supported: \"Le\" must be zero");
    }
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
    float scale = params.get_one_float("scale", 1);
    if (!(std::isfinite(scale) && scale >= 0))
        throw InputError(params.location("scale"), "\"scale\" must be a finite non-negative number");
    float g = params.get_one_float("g", 0);
    if (!(g > -1 && g < 1))
        throw InputError(params.location("g"), "\"g\" must lie in (-1, 1): the Henyey-Greenstein lobe "
                                               "is a delta at +-1");
    return std::make_shared<HomogeneousMedium>(std::move(sigma_a), std::move(sigma_s), scale, g);
}

} // namespace caustica
