#include "materials/disney_material.h"

#include "geometry/interaction.h"
#include "materials/dielectric_material.h"
#include "materials/random_walk_albedo.h"
#include "media/homogeneous_medium.h"
#include "params/constant_textures.h"
#include "params/parameters.h"
#include "spectral/cie.h"
#include "spectral/ior.h"

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
        float A = clamp((*albedo_)(lambda), 0.f, 1.f);
        // A zero distance is the diffuse BRDF's limit; a tiny one keeps sigma_t finite.
        float d = std::max((*distance_)(lambda), 1e-6f);
        float sigma_t = 1 / random_walk_mean_free_path(d, A);
        // Light that enters returns with probability R; the BRDF's Lambertian part reflects
        // A times the exit lobe's albedo 41/42, so that is what R must be.
        float alpha = random_walk_single_scattering_albedo(A * 41 / 42);
        if (kind_ == Scattering) return alpha * sigma_t;
        return (1 - alpha) * sigma_t + (absorption_ ? (*absorption_)(lambda) : 0.f);
    }
    float max_value() const override { return max_; }

  private:
    SpectrumPtr albedo_, distance_, absorption_;
    Kind kind_;
    float max_ = 0;
};

} // namespace

MediumPtr create_random_walk_medium(SpectrumPtr albedo, SpectrumPtr scatter_distance, SpectrumPtr interior_sigma_a) {
    auto sigma_s = std::make_shared<RandomWalkCoefficient>(albedo, scatter_distance, nullptr,
                                                           RandomWalkCoefficient::Scattering);
    auto sigma_a = std::make_shared<RandomWalkCoefficient>(albedo, scatter_distance, interior_sigma_a,
                                                           RandomWalkCoefficient::Absorption);
    return std::make_shared<HomogeneousMedium>(std::move(sigma_a), std::move(sigma_s), 1, 0);
}

DisneyMaterial::DisneyMaterial(DisneyTextures textures, SpectrumPtr eta, bool thin, SpectrumPtr sigma_a,
                               MediumPtr subsurface)
    : textures_(std::move(textures)), eta_(std::move(eta)), reference_eta_((*eta_)(FraunhoferD)),
      thin_(thin), sigma_a_(thin ? nullptr : std::move(sigma_a)), subsurface_(thin ? nullptr : std::move(subsurface)) {
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
        specular_ = true;
    } else {
        float thin_roughness = DisneyBxDF::thin_transmission_roughness(*roughness, reference_eta_);
        specular_ = DisneyBxDF::specular_distribution(*roughness, *anisotropic).effectively_smooth() ||
                    (thin_ && DisneyBxDF::specular_distribution(thin_roughness, *anisotropic).effectively_smooth()) ||
                    (may_refract && index_matched);
    }
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
    p.thin = thin_;
    p.subsurface = subsurface_ != nullptr;
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

BSDF DisneyMaterial::get_bsdf(const SurfaceInteraction &si, const SampledWavelengths &lambda,
                              ScratchBuffer &scratch) const {
    auto *bxdf = scratch.make<DisneyBxDF>(parameters(TextureEvalContext(si), lambda));
    return BSDF(si.shading.n, si.shading.dpdu, bxdf);
}

MaterialPtr create_disney_material(const ParameterDictionary &params, const NamedTextures &textures,
                                   SpectrumPtr eta, SpectrumPtr interior_sigma_a) {
    DisneyTextures t;
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
    MediumPtr subsurface;
    if (thin) {
        t.diff_trans = read_float(params, textures, "diffTrans", 0, 0, 2);
        t.flatness = read_float(params, textures, "flatness", 0, 0, 1);
        if (interior_sigma_a) {
            const char *name = params.has("transmittance") ? "transmittance" : "sigma_a";
            warning(params.location(name), std::string("a thin surface has no interior: \"") + name + "\" is ignored");
        }
    } else {
        SpectrumTexturePtr scatter_distance =
            params.get_spectrum_texture_or_null("scatterDistance", SpectrumType::Unbounded, textures);
        if (scatter_distance) {
            auto *distance = dynamic_cast<const ConstantSpectrumTexture *>(scatter_distance.get());
            if (!distance)
                throw InputError(params.location("scatterDistance"),
                                 "\"scatterDistance\" must be a constant: the subsurface volume is one per object");
            float lo, hi;
            spectrum_range(*distance->spectrum(), &lo, &hi);
            if (!(lo >= 0 && std::isfinite(hi)))
                throw InputError(params.location("scatterDistance"), "\"scatterDistance\" must be non-negative");
            if (hi > 0) {
                auto *albedo = dynamic_cast<const ConstantSpectrumTexture *>(t.base_color.get());
                if (!albedo)
                    throw InputError(params.location("baseColor"),
                                     "with subsurface scattering (\"scatterDistance\" > 0) \"baseColor\" must be a "
                                     "constant: it sets the albedo of the object's one interior volume");
                subsurface = create_random_walk_medium(albedo->spectrum(), distance->spectrum(), interior_sigma_a);
                interior_sigma_a = nullptr;  // now part of the medium
            }
        }
    }
    return std::make_shared<DisneyMaterial>(std::move(t), std::move(eta), thin, std::move(interior_sigma_a),
                                            std::move(subsurface));
}

} // namespace caustica
