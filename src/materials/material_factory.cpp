#include "materials/material_factory.h"

#include "materials/coated_conductor_material.h"
#include "materials/coated_diffuse_material.h"
#include "materials/conductor_material.h"
#include "materials/dielectric_material.h"
#include "materials/diffuse_material.h"
#include "materials/diffuse_transmission_material.h"
#include "materials/disney_material.h"
#include "materials/fluorescent_material.h"
#include "materials/hair_material.h"
#include "materials/measured_material.h"
#include "materials/mix_material.h"
#include "materials/shading_perturbation.h"
#include "materials/subsurface_coefficients.h"
#include "materials/subsurface_material.h"
#include "params/constant_textures.h"
#include "params/parameters.h"
#include "spectral/color_space.h"
#include "spectral/ior.h"
#include "spectral/named_spectra.h"
#include "spectral/rgb_spectrum.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace caustica {

namespace {


std::string quoted(const std::string &s) { return "\"" + s + "\""; }

// Throws unless the constant value of a float texture (if it is constant) is a number >= 0.
void check_non_negative_texture(const ParameterDictionary &params, const std::string &name,
                                const FloatTexturePtr &texture) {
    const float *v = texture->constant_value();
    if (v && !(*v >= 0))
        throw InputError(params.location(name),
                         quoted(name) + " must be a non-negative number, not " + std::to_string(*v));
}

// "uroughness", "vroughness" and "roughness", after a prefix ("interface." for a coat).
MicrofacetRoughness read_roughness(const ParameterDictionary &params, const NamedTextures &textures,
                                   const std::string &prefix = "") {
    MicrofacetRoughness r;
    r.u = params.get_float_texture_or_null(prefix + "uroughness", textures);
    r.v = params.get_float_texture_or_null(prefix + "vroughness", textures);
    if (r.u) check_non_negative_texture(params, prefix + "uroughness", r.u);
    if (r.v) check_non_negative_texture(params, prefix + "vroughness", r.v);
    if (!r.u || !r.v) {
        FloatTexturePtr both = params.get_float_texture(prefix + "roughness", 0, textures);
        check_non_negative_texture(params, prefix + "roughness", both);
        if (!r.u) r.u = both;
        if (!r.v) r.v = both;
    }
    r.remap = params.get_one_bool("remaproughness", true);
    return r;
}

// Throws unless the spectrum is finite and > 0 (or >= 0 when zero_allowed) at every wavelength.
void check_spectrum(const ParameterDictionary &params, const std::string &name, const Spectrum &s,
                    bool zero_allowed, const std::string &what) {
    float lo, hi;
    spectrum_range(s, &lo, &hi);
    bool ok = std::isfinite(lo) && std::isfinite(hi) && (zero_allowed ? lo >= 0 : lo > 0);
    if (!ok)
        throw InputError(params.location(name),
                         quoted(name) + " must be " + what + " at every wavelength in [" +
                             std::to_string(int(LambdaMin)) + ", " + std::to_string(int(LambdaMax)) +
                             "] nm (its values range over [" + std::to_string(lo) + ", " +
                             std::to_string(hi) + "])");
}

void check_spectrum_texture(const ParameterDictionary &params, const std::string &name,
                            const SpectrumTexturePtr &texture, bool zero_allowed, const std::string &what) {
    if (auto *c = dynamic_cast<const ConstantSpectrumTexture *>(texture.get()))
        check_spectrum(params, name, *c->spectrum(), zero_allowed, what);
}

// The index of refraction of a dielectric from "eta" or the Sellmeier / Cauchy extensions.
SpectrumPtr read_ior(const ParameterDictionary &params) {
    bool sellmeier = params.has("sellmeierB") || params.has("sellmeierC");
    bool cauchy = params.has("cauchyA") || params.has("cauchyB");
    const char *first_formula = sellmeier ? "sellmeierB" : "cauchyA";
    if (sellmeier && cauchy)
        throw InputError(params.location("cauchyA"),
                         "give either the Sellmeier or the Cauchy coefficients, not both");
    if ((sellmeier || cauchy) && params.has("eta"))
        throw InputError(params.location(first_formula),
                         "give either \"eta\" or dispersion coefficients, not both");

    SpectrumPtr eta;
    std::string name = "eta";
    if (sellmeier) {
        std::vector<float> b = params.get_float_array("sellmeierB"), c = params.get_float_array("sellmeierC");
        if (b.empty() || b.size() != c.size() || b.size() > 3)
            throw InputError(params.location(b.empty() ? "sellmeierC" : "sellmeierB"),
                             "\"sellmeierB\" and \"sellmeierC\" need the same number (1 to 3) of "
                             "coefficients; got " + std::to_string(b.size()) + " and " +
                             std::to_string(c.size()));
        for (float v : b) if (!std::isfinite(v)) throw InputError(params.location("sellmeierB"), "\"sellmeierB\" must be finite");
        for (float v : c) if (!std::isfinite(v)) throw InputError(params.location("sellmeierC"), "\"sellmeierC\" must be finite");
        eta = std::make_shared<SellmeierSpectrum>(b, c);
        name = "sellmeierB";
    } else if (cauchy) {
        float a = params.get_one_float("cauchyA", 1.5f), b = params.get_one_float("cauchyB", 0);
        if (!std::isfinite(b)) throw InputError(params.location("cauchyB"), "\"cauchyB\" must be finite");
        eta = std::make_shared<CauchySpectrum>(a, b);
        name = "cauchyA";
    } else {
        // A "float eta" reads as a constant spectrum; named spectra ("glass-BK7") and inline or
        // file spectra are dispersion curves.
        eta = params.get_one_spectrum("eta", std::make_shared<ConstantSpectrum>(1.5f), SpectrumType::Unbounded);
    }
    check_spectrum(params, name, *eta, false, "a positive index of refraction");
    return eta;
}

// Beer-Lambert absorption of a dielectric's interior, or null.
SpectrumPtr read_interior_absorption(const ParameterDictionary &params) {
    bool has_sigma = params.has("sigma_a"), has_transmittance = params.has("transmittance");
    if (has_sigma && has_transmittance)
        throw InputError(params.location("transmittance"),
                         "give either \"sigma_a\" or \"transmittance\", not both");
    if (has_sigma) {
        SpectrumPtr sigma_a = params.get_one_spectrum("sigma_a", nullptr, SpectrumType::Unbounded);
        if (!sigma_a) return nullptr;
        check_spectrum(params, "sigma_a", *sigma_a, true, "a non-negative absorption coefficient");
        return sigma_a;
    }
    if (has_transmittance) {
        SpectrumPtr t = params.get_one_spectrum("transmittance", nullptr, SpectrumType::Albedo);
        float d = params.get_one_float("atDistance", 1);
        if (!(d > 0 && std::isfinite(d)))
            throw InputError(params.location("atDistance"), "\"atDistance\" must be a positive distance");
        if (!t) return nullptr;
        check_spectrum(params, "transmittance", *t, true, "non-negative");
        return std::make_shared<TransmittanceAbsorptionSpectrum>(t, d);
    }
    return nullptr;
}

// A metal's index ("eta", "k", after a prefix) or its "reflectance"; default copper.
struct ConductorIndex {
    SpectrumTexturePtr eta, k, reflectance;
};
ConductorIndex read_conductor_index(const ParameterDictionary &params, const NamedTextures &textures,
                                    const std::string &prefix = "") {
    ConductorIndex c;
    c.eta = params.get_spectrum_texture_or_null(prefix + "eta", SpectrumType::Unbounded, textures);
    c.k = params.get_spectrum_texture_or_null(prefix + "k", SpectrumType::Unbounded, textures);
    c.reflectance = params.get_spectrum_texture_or_null("reflectance", SpectrumType::Albedo, textures);
    if (c.reflectance && (c.eta || c.k))
        throw InputError(params.location("reflectance"),
                         "a conductor takes either \"reflectance\" or " + quoted(prefix + "eta") + " and " +
                             quoted(prefix + "k") + ", not both");
    if (!c.reflectance) {
        if (!c.eta) c.eta = std::make_shared<ConstantSpectrumTexture>(get_named_spectrum("metal-Cu-eta"));
        if (!c.k) c.k = std::make_shared<ConstantSpectrumTexture>(get_named_spectrum("metal-Cu-k"));
        check_spectrum_texture(params, prefix + "eta", c.eta, false, "positive");
        check_spectrum_texture(params, prefix + "k", c.k, true, "non-negative");
    }
    return c;
}

// A thin dielectric's "filmthickness" (nm): the slab itself is the film, of the slab's index, so
// a separate "filmeta" would contradict "eta".
FloatTexturePtr read_slab_film(const ParameterDictionary &params, const NamedTextures &textures) {
    if (params.has("filmeta"))
        throw InputError(params.location("filmeta"),
                         "a thindielectric film is the slab itself: its index is \"eta\", not \"filmeta\"");
    FloatTexturePtr thickness = params.get_float_texture_or_null("filmthickness", textures);
    if (thickness) check_non_negative_texture(params, "filmthickness", thickness);
    return thickness;
}

// An interference film: "filmthickness" (nm) and "filmeta".
FilmLayer read_film(const ParameterDictionary &params, const NamedTextures &textures) {
    FilmLayer film;
    film.thickness = params.get_float_texture_or_null("filmthickness", textures);
    if (!film.thickness) return film;
    check_non_negative_texture(params, "filmthickness", film.thickness);
    film.eta = params.get_one_spectrum("filmeta", std::make_shared<ConstantSpectrum>(1.33f), SpectrumType::Unbounded);
    check_spectrum(params, "filmeta", *film.eta, false, "a positive index of refraction");
    return film;
}

MaterialPtr create_conductor(const ParameterDictionary &params, const NamedTextures &textures) {
    ConductorIndex c = read_conductor_index(params, textures);
    MicrofacetRoughness roughness = read_roughness(params, textures);
    return std::make_shared<ConductorMaterial>(c.eta, c.k, c.reflectance, roughness, read_film(params, textures));
}

// The coat and slab of "coateddiffuse" / "coatedconductor"; the coat's parameters carry the
// prefix ("interface." for coatedconductor).
Coating read_coating(const ParameterDictionary &params, const NamedTextures &textures, const std::string &prefix) {
    Coating c;
    c.eta = params.get_one_spectrum(prefix + "eta", std::make_shared<ConstantSpectrum>(1.5f), SpectrumType::Unbounded);
    check_spectrum(params, prefix + "eta", *c.eta, false, "a positive index of refraction");
    c.roughness = read_roughness(params, textures, prefix);
    c.thickness = params.get_float_texture("thickness", 0.01f, textures);
    check_non_negative_texture(params, "thickness", c.thickness);
    c.albedo = params.get_spectrum_texture("albedo", std::make_shared<ConstantSpectrum>(0.f), SpectrumType::Albedo,
                                           textures);
    check_spectrum_texture(params, "albedo", c.albedo, true, "non-negative");
    c.g = params.get_float_texture("g", 0, textures);
    if (const float *g = c.g->constant_value(); g && !(std::abs(*g) < 1))
        throw InputError(params.location("g"), "\"g\" must lie strictly between -1 and 1, not " + std::to_string(*g));
    c.max_depth = params.get_one_int("maxdepth", 10);
    if (c.max_depth < 1)
        throw InputError(params.location("maxdepth"),
                         "\"maxdepth\" must be at least 1, not " + std::to_string(c.max_depth));
    c.n_samples = params.get_one_int("nsamples", 1);
    if (c.n_samples < 1)
        throw InputError(params.location("nsamples"),
                         "\"nsamples\" must be at least 1, not " + std::to_string(c.n_samples));
    return c;
}

MaterialPtr create_coated_conductor(const ParameterDictionary &params, const NamedTextures &textures) {
    ConductorIndex c = read_conductor_index(params, textures, "conductor.");
    MicrofacetRoughness roughness = read_roughness(params, textures, "conductor.");
    Coating coating = read_coating(params, textures, "interface.");
    return std::make_shared<CoatedConductorMaterial>(c.eta, c.k, c.reflectance, roughness, coating);
}

MaterialPtr create_mix(const ParameterDictionary &params, const NamedTextures &textures,
                       const std::map<std::string, MaterialPtr> *named) {
    const std::vector<std::string> names = params.get_string_array("materials");
    if (names.size() != 2)
        throw InputError(params.location("materials"),
                         "\"materials\" must name two materials, not " + std::to_string(names.size()));
    static const std::map<std::string, MaterialPtr> none;
    const std::map<std::string, MaterialPtr> &table = named ? *named : none;
    MaterialPtr m[2];
    for (int i = 0; i < 2; ++i) {
        const auto it = table.find(names[i]);
        if (it == table.end())
            throw InputError(params.location("materials"),
                             "named material " + quoted(names[i]) + " is not defined before the mix");
        m[i] = it->second;
        if (!m[i] || m[i]->has_interior_medium() || m[i]->has_interior_absorption() || m[i]->has_subsurface() ||
            m[i]->has_profile_subsurface())
            throw InputError(params.location("materials"),
                             "material " + quoted(names[i]) +
                                 " cannot be mixed: a mix takes materials without an interior (no "
                                 "\"interface\", medium, absorption or subsurface scattering)");
    }
    return std::make_shared<MixMaterial>(m[0], m[1], params.get_float_texture("amount", 0.5f, textures));
}

SpectrumTexturePtr read_reflectance(const ParameterDictionary &params, const NamedTextures &textures) {
    return params.get_spectrum_texture("reflectance", std::make_shared<ConstantSpectrum>(0.5f),
                                       SpectrumType::Albedo, textures);
}

// pbrt-v4's "hair": the absorption from "sigma_a", else "reflectance" or "color", else the
// melanin concentrations, else eumelanin 1.3; the sources not used are named in a warning, as
// pbrt-v4 does. pbrt-v4 clamps beta_m and beta_n to [0.01, 1] where it evaluates them, and so
// does HairMaterial; negative values are errors here.
MaterialPtr create_hair(const ParameterDictionary &params, const NamedTextures &textures, const SourceLocation &loc) {
    HairMaterial::Absorption a;
    a.sigma_a = params.get_spectrum_texture_or_null("sigma_a", SpectrumType::Unbounded, textures);
    std::string color_name = "reflectance";
    a.color = params.get_spectrum_texture_or_null(color_name, SpectrumType::Albedo, textures);
    if (!a.color) {
        color_name = "color";
        a.color = params.get_spectrum_texture_or_null(color_name, SpectrumType::Albedo, textures);
    }
    a.eumelanin = params.get_float_texture_or_null("eumelanin", textures);
    a.pheomelanin = params.get_float_texture_or_null("pheomelanin", textures);
    auto ignoring = [&](const std::string &ignored, const std::string &used) {
        warning(loc, "ignoring " + quoted(ignored) + " since " + used + " is given");
    };
    if (a.sigma_a) {
        check_spectrum_texture(params, "sigma_a", a.sigma_a, true, "a non-negative absorption coefficient");
        if (a.color) ignoring(color_name, quoted("sigma_a"));
        if (a.eumelanin) ignoring("eumelanin", quoted("sigma_a"));
        if (a.pheomelanin) ignoring("pheomelanin", quoted("sigma_a"));
        a.color = nullptr, a.eumelanin = a.pheomelanin = nullptr;
    } else if (a.color) {
        check_spectrum_texture(params, color_name, a.color, true, "non-negative");
        if (a.eumelanin) ignoring("eumelanin", quoted(color_name));
        if (a.pheomelanin) ignoring("pheomelanin", quoted(color_name));
        a.eumelanin = a.pheomelanin = nullptr;
    } else if (a.eumelanin || a.pheomelanin) {
        if (a.eumelanin) check_non_negative_texture(params, "eumelanin", a.eumelanin);
        if (a.pheomelanin) check_non_negative_texture(params, "pheomelanin", a.pheomelanin);
    } else {
        // Brown hair.
        a.eumelanin = std::make_shared<ConstantFloatTexture>(1.3f);
    }

    FloatTexturePtr eta = params.get_float_texture("eta", 1.55f, textures);
    if (const float *e = eta->constant_value(); e && !(*e > 0 && std::isfinite(*e)))
        throw InputError(params.location("eta"), "\"eta\" must be a positive index of refraction, not " +
                                                     std::to_string(*e));
    FloatTexturePtr beta_m = params.get_float_texture("beta_m", 0.3f, textures);
    check_non_negative_texture(params, "beta_m", beta_m);
    FloatTexturePtr beta_n = params.get_float_texture("beta_n", 0.3f, textures);
    check_non_negative_texture(params, "beta_n", beta_n);
    FloatTexturePtr alpha = params.get_float_texture("alpha", 2.f, textures);
    if (const float *v = alpha->constant_value(); v && !std::isfinite(*v))
        throw InputError(params.location("alpha"), "\"alpha\" must be a finite angle in degrees");
    return std::make_shared<HairMaterial>(std::move(a), eta, beta_m, beta_n, alpha);
}

SpectrumTexturePtr constant_rgb(const RGB &rgb) {
    return std::make_shared<ConstantSpectrumTexture>(std::make_shared<RGBUnboundedSpectrum>(RGBColorSpace::srgb(), rgb));
}

// pbrt-v4's "subsurface" (subsurface_material.h): the coefficients by "name", else "sigma_a" with
// "sigma_s", else "reflectance" with "mfp", else pbrt-v4's default; one of sigma_a and sigma_s
// without the other is an error, as in pbrt-v4.
MaterialPtr create_subsurface(const ParameterDictionary &params, const NamedTextures &textures) {
    SubsurfaceMaterial::Coefficients c;
    float g = params.get_one_float("g", 0);
    const std::string name = params.get_one_string("name", "");
    if (!name.empty()) {
        const auto medium = find_measured_subsurface_medium(name);
        if (!medium)
            throw InputError(params.location("name"), "unknown measured medium " + quoted(name) + " (known: " +
                                                          measured_subsurface_media_names() + ")");
        if (g != 0) warning(params.location("g"), "\"g\" is ignored with a named medium, whose tables give reduced scattering");
        g = 0;
        c.sigma_a = constant_rgb(medium->sigma_a);
        c.sigma_s = constant_rgb(medium->sigma_s_reduced);
    } else {
        c.sigma_a = params.get_spectrum_texture_or_null("sigma_a", SpectrumType::Unbounded, textures);
        c.sigma_s = params.get_spectrum_texture_or_null("sigma_s", SpectrumType::Unbounded, textures);
        if (bool(c.sigma_a) != bool(c.sigma_s))
            throw InputError(params.location(c.sigma_a ? "sigma_a" : "sigma_s"),
                             "\"sigma_a\" and \"sigma_s\" must be given together");
        if (c.sigma_a) {
            check_spectrum_texture(params, "sigma_a", c.sigma_a, true, "a non-negative absorption coefficient");
            check_spectrum_texture(params, "sigma_s", c.sigma_s, true, "a non-negative scattering coefficient");
        } else if ((c.reflectance = params.get_spectrum_texture_or_null("reflectance", SpectrumType::Albedo, textures))) {
            c.mfp = params.get_spectrum_texture("mfp", std::make_shared<ConstantSpectrum>(1.f), SpectrumType::Unbounded,
                                                textures);
            check_spectrum_texture(params, "mfp", c.mfp, true, "a non-negative mean free path");
        } else {
            // Whole milk in mm^-1 (Jensen et al. 2001).
            c.sigma_a = constant_rgb(RGB{.0011f, .0024f, .014f});
            c.sigma_s = constant_rgb(RGB{2.55f, 3.21f, 3.77f});
        }
    }
    c.scale = params.get_one_float("scale", 1);
    if (!(c.scale >= 0) || !std::isfinite(c.scale))
        throw InputError(params.location("scale"), "\"scale\" must be a non-negative number");
    if (!(std::abs(g) < 1)) throw InputError(params.location("g"), "\"g\" must lie in (-1, 1)");
    const float eta = params.get_one_float("eta", 1.33f);
    if (!(eta > 0) || !std::isfinite(eta))
        throw InputError(params.location("eta"), "\"eta\" must be a positive index of refraction");
    return std::make_shared<SubsurfaceMaterial>(std::move(c), g, eta, read_roughness(params, textures));
}

// pbrt-v4's "measured": the RGL BSDF file "filename" (required), relative to the scene file.
MaterialPtr create_measured(const ParameterDictionary &params) {
    const std::string filename = params.get_one_string("filename", "");
    if (filename.empty()) throw InputError(params.location("filename"), "a \"measured\" material needs a \"filename\"");
    try {
        return std::make_shared<MeasuredMaterial>(MeasuredBRDF::read(params.file_path("filename", filename)));
    } catch (const InputError &e) {
        if (!e.location().file.empty()) throw;
        throw InputError(params.location("filename"), e.message());
    }
}

// pbrt-v4's "normalmap" (an image file) or "displacement" (a float texture); the normal map
// wins when both are given, as in pbrt-v4.
std::shared_ptr<const ShadingPerturbation> read_shading_perturbation(const ParameterDictionary &params,
                                                                     const NamedTextures &textures) {
    const std::string normal_map = params.get_one_string("normalmap", "");
    if (!normal_map.empty()) {
        if (params.has("displacement"))
            warning(params.location("displacement"), "\"displacement\" is ignored where a \"normalmap\" "
                                                     "is given, as in pbrt-v4");
        try {
            return ShadingPerturbation::normal_map(
                read_linear_texels(params.file_path("normalmap", normal_map), 3));
        } catch (const std::runtime_error &e) {
            throw InputError(params.location("normalmap"), e.what());
        }
    }
    if (FloatTexturePtr displacement = params.get_float_texture_or_null("displacement", textures))
        return ShadingPerturbation::bump(std::move(displacement));
    return nullptr;
}

// "fluorescent": a Caustica extension (fluorescent_material.h).
MaterialPtr create_fluorescent(const ParameterDictionary &params, const NamedTextures &textures,
                               const SourceLocation &loc) {
    for (const char *name : {"absorption", "emission"})
        if (!params.has(name))
            throw InputError(loc, std::string("a fluorescent material needs \"spectrum ") + name + "\"");
    SpectrumPtr absorption = params.get_one_spectrum("absorption", nullptr, SpectrumType::Albedo);
    SpectrumPtr emission = params.get_one_spectrum("emission", nullptr, SpectrumType::Unbounded);
    if (!absorption || !emission)
        throw InputError(params.location(absorption ? "emission" : "absorption"), "expected a spectrum");
    const float yield = params.get_one_float("quantumyield", 1);
    if (!(yield >= 0 && yield <= 1))
        throw InputError(params.location("quantumyield"), "\"quantumyield\" must lie in [0, 1]");
    std::shared_ptr<const Fluorophore> dye;
    try {
        dye = std::make_shared<Fluorophore>(absorption, emission, yield);
    } catch (const std::invalid_argument &e) {
        throw InputError(params.location("emission"), e.what());
    }
    return std::make_shared<FluorescentMaterial>(read_reflectance(params, textures), std::move(dye));
}

} // namespace

MaterialPtr create_material(const std::string &type, const ParameterDictionary &params,
                            const NamedTextures &textures, const SourceLocation &loc,
                            const std::map<std::string, MaterialPtr> *named) {
    MaterialPtr material;
    if (type == "interface") {
        material = nullptr;
    } else if (type == "diffuse") {
        material = std::make_shared<DiffuseMaterial>(read_reflectance(params, textures));
    } else if (type == "conductor") {
        material = create_conductor(params, textures);
    } else if (type == "mix") {
        material = create_mix(params, textures, named);
    } else if (type == "diffusetransmission") {
        SpectrumTexturePtr t = params.get_spectrum_texture("transmittance", std::make_shared<ConstantSpectrum>(0.25f),
                                                           SpectrumType::Albedo, textures);
        SpectrumTexturePtr r = params.get_spectrum_texture("reflectance", std::make_shared<ConstantSpectrum>(0.25f),
                                                           SpectrumType::Albedo, textures);
        const float scale = params.get_one_float("scale", 1);
        if (!(scale >= 0 && std::isfinite(scale)))
            throw InputError(params.location("scale"), "\"scale\" must be a non-negative number");
        material = std::make_shared<DiffuseTransmissionMaterial>(r, t, scale);
    } else if (type == "coateddiffuse") {
        material = std::make_shared<CoatedDiffuseMaterial>(read_reflectance(params, textures),
                                                           read_coating(params, textures, ""));
    } else if (type == "coatedconductor") {
        material = create_coated_conductor(params, textures);
    } else if (type == "dielectric") {
        SpectrumPtr eta = read_ior(params);
        MicrofacetRoughness roughness = read_roughness(params, textures);
        material = std::make_shared<DielectricMaterial>(eta, roughness, read_interior_absorption(params),
                                                        read_film(params, textures));
    } else if (type == "disney") {
        material = create_disney_material(params, textures, read_ior(params), read_interior_absorption(params),
                                          read_film(params, textures));
    } else if (type == "hair") {
        material = create_hair(params, textures, loc);
    } else if (type == "measured") {
        material = create_measured(params);
    } else if (type == "thindielectric") {
        material = std::make_shared<ThinDielectricMaterial>(read_ior(params), read_slab_film(params, textures));
    } else if (type == "fluorescent") {
        material = create_fluorescent(params, textures, loc);
    } else if (type == "subsurface") {
        material = create_subsurface(params, textures);
    } else {
        throw InputError(loc, "unknown material type " + quoted(type));
    }
    if (material) {
        // The factory holds the only reference to the new material.
        if (auto perturbation = read_shading_perturbation(params, textures))
            std::const_pointer_cast<Material>(material)->set_shading_perturbation(std::move(perturbation));
    }
    params.report_unused();
    return material;
}

} // namespace caustica
