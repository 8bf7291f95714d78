#include "materials/disney_material.h"

#include "materials/microfacet_roughness.h"

#include "geometry/interaction.h"
#include "materials/dielectric_material.h"
#include "materials/random_walk_albedo.h"
#include "materials/subsurface_coefficients.h"
#include "media/homogeneous_medium.h"
#include "params/constant_textures.h"
#include "params/parameters.h"
#include "spectral/cie.h"
#include "spectral/color_space.h"
#include "spectral/ior.h"
#include "spectral/rgb_spectrum.h"

#include <cmath>
#include <sstream>

namespace caustica {

namespace {

// CIE Y of a reflectance under an equal-energy illuminant: the ybar-weighted mean of the
// texture at 16 equally spaced wavelengths (midpoints of [LambdaMin, LambdaMax] cut in 16).
// The tints only need the colour's hue, and a grey gives exactly its value whatever the
// quadrature, so the midpoint rule's small error in Y does not matter.
float luminance(const SpectrumTexture &texture, const TextureEvalContext &ctx) {
    constexpr int Groups = 4;
    float weighted = 0, weights = 0;
    for (int g = 0; g < Groups; ++g) {
        // sample_uniform spaces its lanes (LambdaMax - LambdaMin) / NumWavelengths apart, so the
        // groups' offsets interleave them into one evenly spaced set.
        SampledWavelengths lambda = SampledWavelengths::sample_uniform((g + 0.5f) / (Groups * NumWavelengths));
        SampledSpectrum value = texture.evaluate(ctx, lambda);
        for (int i = 0; i < NumWavelengths; ++i) {
            float y = cie_y()(lambda[i]);
            weighted += clamp(value[i], 0.f, 1.f) * y;
            weights += y;
        }
    }
    return weighted / weights;
}

float evaluate_clamped(const FloatTexturePtr &texture, const TextureEvalContext &ctx, float lo, float hi) {
    return clamp(texture->evaluate(ctx), lo, hi);
}

std::string number(float v) {
    std::ostringstream s;
    s << v;
    return s.str();
}

// A float parameter (value or texture); a constant value must lie in [lo, hi].
FloatTexturePtr read_float(const ParameterDictionary &params, const NamedTextures &textures,
                           const std::string &name, float def, float lo, float hi) {
    FloatTexturePtr texture = params.get_float_texture(name, def, textures);
    const float *v = texture->constant_value();
    if (v && !(*v >= lo && *v <= hi)) {
        std::string range = hi == Infinity ? "a non-negative number" : "in [" + number(lo) + ", " + number(hi) + "]";
        throw InputError(params.location(name), "\"" + name + "\" must be " + range + ", not " + number(*v));
    }
    return texture;
}

// The random-walk interior's coefficient at each wavelength, from baseColor A and
// scatterDistance d there (random_walk_albedo.h): sigma_t = 1 / l(d, A), split by the
// single-scattering albedo that reflects A, plus any Beer-Lambert absorption of the solid.
// The random walk's interior at one wavelength for base colour A and scatter distance d.
struct RandomWalkCoefficients {
    float sigma_s, sigma_a;
};
RandomWalkCoefficients random_walk_coefficients(float A, float d) {
    A = clamp(A, 0.f, 1.f);
    // A zero distance is the diffuse BRDF's limit; a tiny one keeps sigma_t finite.
    d = std::max(d, 1e-6f);
    const float sigma_t = 1 / random_walk_mean_free_path(d, A);
    // Light that enters returns with probability R; the BRDF's Lambertian part reflects A times
    // the exit lobe's albedo 41/42, so that is what R must be.
    const float alpha = random_walk_single_scattering_albedo(A * 41 / 42);
    return {alpha * sigma_t, (1 - alpha) * sigma_t};
}

class RandomWalkCoefficient final : public Spectrum {
  public:
    enum Kind { Scattering, Absorption };
    RandomWalkCoefficient(SpectrumPtr albedo, SpectrumPtr distance, SpectrumPtr absorption, Kind kind)
        : albedo_(std::move(albedo)), distance_(std::move(distance)), absorption_(std::move(absorption)),
          kind_(kind) {
        for (int lambda = int(LambdaMin); lambda <= int(LambdaMax); ++lambda)
            max_ = std::max(max_, (*this)(float(lambda)));
    }
    float operator()(float lambda) const override {
        const RandomWalkCoefficients c = random_walk_coefficients((*albedo_)(lambda), (*distance_)(lambda));
        if (kind_ == Scattering) return c.sigma_s;
        return c.sigma_a + (absorption_ ? (*absorption_)(lambda) : 0.f);
    }
    float max_value() const override { return max_; }

  private:
    SpectrumPtr albedo_, distance_, absorption_;
    Kind kind_;
    float max_ = 0;
};

// Profile models: the smallest scatter distance of a channel, as a fraction of the largest. A
// channel with d = 0 would hold its energy at the entry point, where no probe ray can find it
// (normalized_diffusion.h); at a thousandth of the widest channel's spread it is the BRDF limit
// at every scale where the others matter, and probes still reach it.
constexpr float MinScatterDistanceFraction = 1e-3f;

} // namespace

float dipole_diffuse_reflectance(float reduced_albedo, float eta) {
    double fdr = diffuse_fresnel_reflectance(eta);
    double boundary = (1 + fdr) / (1 - fdr);
    double a = clamp(reduced_albedo, 0.f, 1.f), s = std::sqrt(3 * (1 - a));
    return float(a / 2 * (1 + std::exp(-4.0 / 3 * boundary * s)) * std::exp(-s));
}

namespace {

// The absorbing fraction 1 - alpha' = sigma_a / sigma_t' of the dipole with total diffuse
// reflectance `reflectance` in (0, 1), computed without forming alpha' (near white it is far
// below a float's resolution at 1).
double dipole_absorption_fraction(double reflectance, float eta) {
    // In x = sqrt(3 (1 - alpha')) the reflectance alpha' / 2 (1 + e^{-k x}) e^{-x}, k = 4 A / 3,
    // falls smoothly from 1 at x = 0 to 0 at x = sqrt(3) (alpha' = 0), while in alpha' itself it
    // has a square-root cusp at 1. Newton's method in x, kept inside a shrinking bracket.
    double fdr = diffuse_fresnel_reflectance(eta);
    double k = 4.0 / 3 * (1 + fdr) / (1 - fdr);
    double lo = 0, hi = std::sqrt(3.0), x = 0.5 * hi;
    for (int iteration = 0; iteration < 100 && hi - lo > 1e-15; ++iteration) {
        double a = 1 - x * x / 3, e = std::exp(-k * x), ex = std::exp(-x);
        double value = a / 2 * (1 + e) * ex - reflectance;
        if (std::abs(value) <= 1e-12 * reflectance) break;
        (value > 0 ? lo : hi) = x;
        double slope = ex / 2 * (-2 * x / 3 * (1 + e) - a * k * e - a * (1 + e));
        double next = x - value / slope;
        x = next > lo && next < hi ? next : 0.5 * (lo + hi);
    }
    return x * x / 3;
}

} // namespace

float dipole_reduced_albedo(float reflectance, float eta) {
    float target = clamp(reflectance, 0.f, 1.f);
    if (target == 0 || target == 1) return target;
    return float(1 - dipole_absorption_fraction(target, eta));
}

DipoleCoefficients dipole_coefficients(const SampledSpectrum &albedo, const SampledSpectrum &scatter_distance,
                                       float eta) {
    DipoleCoefficients c;
    for (int i = 0; i < NumWavelengths; ++i) {
        float A = clamp(albedo[i], 0.f, 1.f), d = scatter_distance[i];
        if (!(d > 0) || A == 0) continue; // no scattering: the dipole reflects nothing
        double sigma_t = 1 / (double(d) * christensen_burley_scaling(A));
        double absorbing = A == 1 ? 0 : dipole_absorption_fraction(A, eta);
        c.sigma_s_reduced[i] = float((1 - absorbing) * sigma_t);
        c.sigma_a[i] = float(absorbing * sigma_t);
    }
    return c;
}

MediumPtr create_random_walk_medium(SpectrumPtr albedo, SpectrumPtr scatter_distance, SpectrumPtr interior_sigma_a) {
    auto sigma_s = std::make_shared<RandomWalkCoefficient>(albedo, scatter_distance, nullptr,
                                                           RandomWalkCoefficient::Scattering);
    auto sigma_a = std::make_shared<RandomWalkCoefficient>(albedo, scatter_distance, interior_sigma_a,
                                                           RandomWalkCoefficient::Absorption);
    return std::make_shared<HomogeneousMedium>(std::move(sigma_a), std::move(sigma_s), 1, 0);
}

DisneyMaterial::DisneyMaterial(DisneyTextures textures, SpectrumPtr eta, bool thin, SpectrumPtr sigma_a,
                               DisneySubsurface subsurface)
    : textures_(std::move(textures)), eta_(std::move(eta)), reference_eta_((*eta_)(FraunhoferD)),
      thin_(thin), sigma_a_(thin ? nullptr : std::move(sigma_a)),
      subsurface_(thin ? DisneySubsurface() : std::move(subsurface)) {
    if (auto *d = dynamic_cast<const ConstantSpectrumTexture *>(subsurface_.scatter_distance.get()))
        min_scatter_distance_ = MinScatterDistanceFraction * d->spectrum()->max_value();
    else if (subsurface_.scatter_distance)
        min_scatter_distance_ = -1;
    if (dynamic_cast<const ConstantSpectrumTexture *>(textures_.base_color.get()))
        constant_luminance_ = luminance(*textures_.base_color, TextureEvalContext());

    // Dispersion: only refraction through a solid's specular BSDF bends wavelengths apart.
    float lo, hi;
    spectrum_range(*eta_, &lo, &hi);
    const float *spec_trans = textures_.spec_trans->constant_value();
    const float *metallic = textures_.metallic->constant_value();
    bool may_refract = !thin_ && (!spec_trans || *spec_trans > 0) && (!metallic || *metallic < 1);
    dispersive_ = may_refract && !eta_->is_constant() && lo != hi;

    // Delta lobes: roughness that may be (effectively) zero, or an index-matched solid, whose
    // specular BSDF is a pass-through.
    const float *roughness = textures_.roughness->constant_value();
    const float *anisotropic = textures_.anisotropic->constant_value();
    bool index_matched = std::abs(lo - 1) < DielectricBxDF::IndexMatchedTolerance &&
                         std::abs(hi - 1) < DielectricBxDF::IndexMatchedTolerance;
    if (!roughness || !anisotropic) {
        specular_ = focuses_ = true;
    } else {
        const TrowbridgeReitzDistribution d = DisneyBxDF::specular_distribution(*roughness, *anisotropic);
        focuses_ = std::max(d.alpha_x(), d.alpha_y()) < MicrofacetRoughness::NearSpecularAlpha;
        float thin_roughness = DisneyBxDF::thin_transmission_roughness(*roughness, reference_eta_);
        specular_ = DisneyBxDF::specular_distribution(*roughness, *anisotropic).effectively_smooth() ||
                    (thin_ && DisneyBxDF::specular_distribution(thin_roughness, *anisotropic).effectively_smooth()) ||
                    (may_refract && index_matched);
    }
    focuses_ = focuses_ || specular_;
}

DisneyParameters DisneyMaterial::parameters(const TextureEvalContext &ctx, const SampledWavelengths &lambda) const {
    DisneyParameters p;
    p.base_color = textures_.base_color->evaluate(ctx, lambda);
    p.metallic = evaluate_clamped(textures_.metallic, ctx, 0, 1);
    p.roughness = evaluate_clamped(textures_.roughness, ctx, 0, 1);
    p.anisotropic = evaluate_clamped(textures_.anisotropic, ctx, 0, 1);
    p.specular_tint = evaluate_clamped(textures_.specular_tint, ctx, 0, 1);
    p.sheen = evaluate_clamped(textures_.sheen, ctx, 0, Infinity);
    p.sheen_tint = evaluate_clamped(textures_.sheen_tint, ctx, 0, 1);
    p.clearcoat = evaluate_clamped(textures_.clearcoat, ctx, 0, Infinity);
    p.clearcoat_gloss = evaluate_clamped(textures_.clearcoat_gloss, ctx, 0, 1);
    p.spec_trans = evaluate_clamped(textures_.spec_trans, ctx, 0, 1);
    p.eta = eta_->sample(lambda);
    p.reference_eta = reference_eta_;
    p.film = textures_.film.at(ctx, lambda);
    p.thin = thin_;
    p.subsurface = subsurface_.enabled;
    p.profile_subsurface = has_profile_subsurface();
    if (thin_) {
        p.diff_trans = evaluate_clamped(textures_.diff_trans, ctx, 0, 2);
        p.flatness = evaluate_clamped(textures_.flatness, ctx, 0, 1);
    }
    // The tints need the luminance; a textured base colour costs extra evaluations, so it is
    // only computed where a tint is in use.
    if (constant_luminance_ >= 0)
        p.base_luminance = constant_luminance_;
    else if (p.specular_tint > 0 || (p.sheen > 0 && p.sheen_tint > 0))
        p.base_luminance = luminance(*textures_.base_color, ctx);
    return p;
}

bool DisneyMaterial::is_wavelength_independent() const {
    if (!textures_.base_color->is_wavelength_independent() || !is_flat(*eta_) || (sigma_a_ && !is_flat(*sigma_a_)) ||
        textures_.film.may_be_present())
        return false;
    if (!subsurface_.enabled) return true;
    const DisneySubsurface &s = subsurface_;
    if (s.scatter_distance && !s.scatter_distance->is_wavelength_independent()) return false;
    for (const SpectrumPtr &spectrum : {s.walk_absorption, s.sigma_a, s.sigma_s_reduced})
        if (spectrum && !is_flat(*spectrum)) return false;
    return !s.medium || s.medium->is_wavelength_independent();
}

BSDF DisneyMaterial::get_bsdf(const SurfaceInteraction &si, const SampledWavelengths &lambda,
                              ScratchBuffer &scratch) const {
    auto *bxdf = scratch.make<DisneyBxDF>(parameters(TextureEvalContext(si), lambda));
    return BSDF(si.shading.n, si.shading.dpdu, bxdf);
}

DisneySubsurfaceProfile DisneyMaterial::subsurface_profile(const SurfaceInteraction &si,
                                                            const SampledWavelengths &lambda) const {
    if (subsurface_.sigma_a) {
        const SampledSpectrum sigma_a = subsurface_.sigma_a->sample(lambda) * subsurface_.scale;
        const SampledSpectrum sigma_s = subsurface_.sigma_s_reduced->sample(lambda) * subsurface_.scale;
        if (subsurface_.model == SubsurfaceModel::BeamDiffusion)
            return BeamDiffusionProfile(*subsurface_.beam_table, sigma_a, sigma_s);
        return DipoleProfile(sigma_a, sigma_s, reference_eta_);
    }
    SampledSpectrum albedo = textures_.base_color->evaluate(TextureEvalContext(si), lambda);
    SampledSpectrum d = subsurface_.scatter_distance->evaluate(TextureEvalContext(si), lambda);
    // A textured distance has its floor set from the widest of the path's channels here (and a
    // point where all are zero gets a tiny spread: the BRDF limit).
    float floor = min_scatter_distance_;
    if (floor < 0) floor = std::max(MinScatterDistanceFraction * d.max_value(), 1e-6f);
    for (int i = 0; i < NumWavelengths; ++i) {
        albedo[i] = clamp(albedo[i], 0.f, 1.f);
        d[i] = std::max(d[i], floor);
    }
    if (subsurface_.model == SubsurfaceModel::Diffusion) return NormalizedDiffusionProfile(albedo, d);
    if (subsurface_.model == SubsurfaceModel::BeamDiffusion) {
        SampledSpectrum mean_free_path, sigma_a, sigma_s;
        for (int i = 0; i < NumWavelengths; ++i) mean_free_path[i] = d[i] * christensen_burley_scaling(albedo[i]);
        beam_diffusion_from_diffuse(*subsurface_.beam_table, albedo, mean_free_path, &sigma_a, &sigma_s);
        return BeamDiffusionProfile(*subsurface_.beam_table, sigma_a, sigma_s);
    }
    DipoleCoefficients c = dipole_coefficients(albedo, d, reference_eta_);
    return DipoleProfile(c.sigma_a, c.sigma_s_reduced, reference_eta_);
}

const Medium *DisneyMaterial::interior_medium(const SurfaceInteraction &si, const SampledWavelengths &lambda,
                                             ScratchBuffer &scratch) const {
    if (subsurface_.medium || !has_interior_medium()) return subsurface_.medium.get();
    const SampledSpectrum albedo = textures_.base_color->evaluate(TextureEvalContext(si), lambda);
    const SampledSpectrum d = subsurface_.scatter_distance->evaluate(TextureEvalContext(si), lambda);
    SampledSpectrum sigma_s(0.f), sigma_a(0.f);
    if (subsurface_.walk_absorption) sigma_a = subsurface_.walk_absorption->sample(lambda);
    for (int i = 0; i < NumWavelengths; ++i) {
        const RandomWalkCoefficients c = random_walk_coefficients(albedo[i], d[i]);
        sigma_s[i] = c.sigma_s;
        sigma_a[i] += c.sigma_a;
    }
    return scratch.make<SampledHomogeneousMedium>(sigma_a, sigma_s, 0.f, this);
}

BSDF DisneyMaterial::subsurface_exit_bsdf(const SurfaceInteraction &si, ScratchBuffer &scratch) const {
    return BSDF(si.shading.n, si.shading.dpdu, scratch.make<DisneySubsurfaceExitBxDF>());
}

namespace {

SubsurfaceModel read_subsurface_model(const ParameterDictionary &params) {
    std::string name = params.get_one_string("subsurface", "randomwalk");
    if (name == "randomwalk") return SubsurfaceModel::RandomWalk;
    if (name == "diffusion") return SubsurfaceModel::Diffusion;
    if (name == "dipole") return SubsurfaceModel::Dipole;
    if (name == "beamdiffusion") return SubsurfaceModel::BeamDiffusion;
    throw InputError(params.location("subsurface"),
                     "unknown subsurface model \"" + name + "\" (randomwalk, diffusion, dipole or beamdiffusion)");
}

// A solid's subsurface parameters (docs/disney.md); interior_sigma_a moves into the random walk's
// volume when there is one.
DisneySubsurface read_subsurface(const ParameterDictionary &params, const NamedTextures &textures,
                                 const SpectrumTexturePtr &base_color, float reference_eta,
                                 SpectrumPtr &interior_sigma_a) {
    DisneySubsurface sub;
    sub.model = read_subsurface_model(params);
    if (sub.model == SubsurfaceModel::Dipole || sub.model == SubsurfaceModel::BeamDiffusion) {
        std::string preset = params.get_one_string("preset", "");
        if (!preset.empty()) {
            auto measured = find_measured_subsurface_medium(preset);
            if (!measured)
                throw InputError(params.location("preset"),
                                 "unknown subsurface preset \"" + preset + "\" (the measured media: " +
                                     measured_subsurface_media_names() + ")");
            if (params.has("scatterDistance"))
                throw InputError(params.location("scatterDistance"),
                                 "give either \"preset\" or \"scatterDistance\", not both");
            sub.scale = params.get_one_float("scale", 1);
            if (!(std::isfinite(sub.scale) && sub.scale > 0))
                throw InputError(params.location("scale"), "\"scale\" must be a positive number");
            // Reduced scattering with an isotropic phase function, as pbrt does with this table.
            sub.sigma_a = std::make_shared<RGBUnboundedSpectrum>(RGBColorSpace::srgb(), measured->sigma_a);
            sub.sigma_s_reduced = std::make_shared<RGBUnboundedSpectrum>(RGBColorSpace::srgb(),
                                                                         measured->sigma_s_reduced);
            sub.enabled = true;
        }
    }
    if (!sub.enabled) {
        SpectrumTexturePtr scatter_distance =
            params.get_spectrum_texture_or_null("scatterDistance", SpectrumType::Unbounded, textures);
        if (!scatter_distance) return sub;
        // A constant is checked here; a texture's negative values are read as 0 (textures are
        // not range-checked, as for the other parameters).
        if (auto *distance = dynamic_cast<const ConstantSpectrumTexture *>(scatter_distance.get())) {
            float lo, hi;
            spectrum_range(*distance->spectrum(), &lo, &hi);
            if (!(lo >= 0 && std::isfinite(hi)))
                throw InputError(params.location("scatterDistance"), "\"scatterDistance\" must be non-negative");
            if (hi == 0) return sub;  // the diffuse BRDF
        }
        sub.enabled = true;
        sub.scatter_distance = std::move(scatter_distance);
    }
    if (params.has("cavityFade")) {
        if (sub.model == SubsurfaceModel::RandomWalk)
            throw InputError(params.location("cavityFade"),
                             "\"cavityFade\" applies to the profile models (\"string subsurface\" \"diffusion\", "
                             "\"dipole\" or \"beamdiffusion\"); the random walk follows the geometry and needs no fade");
        sub.cavity_fade = params.get_one_float("cavityFade", 0);
        if (!(sub.cavity_fade >= 0 && sub.cavity_fade <= 1))
            throw InputError(params.location("cavityFade"), "\"cavityFade\" must lie in [0, 1]");
    }
    if (sub.model == SubsurfaceModel::Dipole && !(reference_eta >= 1))
        throw InputError(params.location("eta"), "the dipole needs an interior index \"eta\" >= 1 (its boundary "
                                                 "condition is for light leaving a denser medium)");
    if (sub.enabled && sub.model == SubsurfaceModel::BeamDiffusion)
        sub.beam_table = std::make_shared<const BeamDiffusionTable>(compute_beam_diffusion_table(0, reference_eta));
    if (sub.model == SubsurfaceModel::RandomWalk) {
        // The interior takes over the solid's absorption: one volume for a constant base colour,
        // one per entry point for a textured one.
        auto *albedo = dynamic_cast<const ConstantSpectrumTexture *>(base_color.get());
        auto *distance = dynamic_cast<const ConstantSpectrumTexture *>(sub.scatter_distance.get());
        if (albedo && distance)
            sub.medium = create_random_walk_medium(albedo->spectrum(), distance->spectrum(), interior_sigma_a);
        else
            sub.walk_absorption = interior_sigma_a;
        interior_sigma_a = nullptr;
    }
    return sub;
}

} // namespace

MaterialPtr create_disney_material(const ParameterDictionary &params, const NamedTextures &textures,
                                   SpectrumPtr eta, SpectrumPtr interior_sigma_a, FilmLayer film) {
    DisneyTextures t;
    t.film = std::move(film);
    t.base_color = params.get_spectrum_texture("baseColor", std::make_shared<ConstantSpectrum>(0.5f),
                                               SpectrumType::Albedo, textures);
    t.metallic = read_float(params, textures, "metallic", 0, 0, 1);
    t.roughness = read_float(params, textures, "roughness", 0.5f, 0, 1);
    t.anisotropic = read_float(params, textures, "anisotropic", 0, 0, 1);
    t.specular_tint = read_float(params, textures, "specularTint", 0, 0, 1);
    t.sheen = read_float(params, textures, "sheen", 0, 0, Infinity);
    t.sheen_tint = read_float(params, textures, "sheenTint", 0.5f, 0, 1);
    t.clearcoat = read_float(params, textures, "clearcoat", 0, 0, Infinity);
    t.clearcoat_gloss = read_float(params, textures, "clearcoatGloss", 1, 0, 1);
    t.spec_trans = read_float(params, textures, "specTrans", 0, 0, 1);

    // Burley 2015, section 3.4: solids add scatterDistance, thin surfaces diffTrans and
    // flatness. Parameters of the other kind are left unread, so they are reported as unused.
    bool thin = params.get_one_bool("thin", false);
    DisneySubsurface subsurface;
    if (thin) {
        t.diff_trans = read_float(params, textures, "diffTrans", 0, 0, 2);
        t.flatness = read_float(params, textures, "flatness", 0, 0, 1);
        if (interior_sigma_a) {
            const char *name = params.has("transmittance") ? "transmittance" : "sigma_a";
            warning(params.location(name), std::string("a thin surface has no interior: \"") + name + "\" is ignored");
        }
    } else {
        subsurface = read_subsurface(params, textures, t.base_color, (*eta)(FraunhoferD), interior_sigma_a);
    }
    return std::make_shared<DisneyMaterial>(std::move(t), std::move(eta), thin, std::move(interior_sigma_a),
                                            std::move(subsurface));
}

} // namespace caustica
