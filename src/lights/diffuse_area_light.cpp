#include "lights/diffuse_area_light.h"

#include "core/sampling.h"

namespace caustica {

DiffuseAreaLight::DiffuseAreaLight(std::shared_ptr<const Shape> shape, SpectrumPtr radiance,
                                   float scale, bool two_sided, std::shared_ptr<const AlphaMask> alpha,
                                   std::shared_ptr<const EmissionImage> image)
    : shape_(std::move(shape)),
      alpha_(alpha && !alpha->removes_everything() ? alpha : nullptr),
      image_(std::move(image)),
      area_(shape_->area()),
      uniform_by_area_(shape_->samples_uniformly_by_area()),
      radiance_(std::move(radiance)),
      scale_(scale),
      two_sided_(two_sided),
      invisible_(alpha && alpha->removes_everything()) {}

SampledSpectrum DiffuseAreaLight::phi(const SampledWavelengths &lambda) const {
    // Radiance integrated over the hemisphere (pi) and the area, per emitting side; an image's
    // radiance averaged over its pixels (as if it covered the shape evenly, as pbrt-v4 assumes).
    const SampledSpectrum radiance = image_ ? image_->mean_radiance(lambda) : radiance_->sample(lambda);
    return Pi * (two_sided_ ? 2.f : 1.f) * area_ * scale_ * radiance;
}

bool DiffuseAreaLight::masked(const ShapeSample &s) const {
    if (!alpha_) return false;
    TextureEvalContext ctx;
    ctx.p = s.p;
    ctx.n = s.n;
    ctx.uv = s.uv;
    return !alpha_->stops(ctx, AlphaMask::uniform(s.p.x, s.p.y, s.p.z));
}

// Unlike pbrt-v4, L does not apply the alpha mask again: a ray that reached the point has already
// met it (GeometryScene), and a second, independent test would make a partly transparent emitter
// appear with alpha^2 of its radiance to rays and alpha to light sampling.
SampledSpectrum DiffuseAreaLight::L(Vec3f, Vec3f n, Vec2f uv, Vec3f w,
                                    const SampledWavelengths &lambda) const {
    if (!two_sided_ && dot(n, w) < 0) return {};
    if (image_) return scale_ * image_->radiance(uv, lambda);
    return scale_ * radiance_->sample(lambda);
}

std::optional<LightLiSample> DiffuseAreaLight::sample_li(const LightSampleContext &ctx, Vec2f u,
                                                         const SampledWavelengths &lambda) const {
    std::optional<ShapeSample> ss = shape_->sample(ctx.p, u);
    if (!ss || !(ss->pdf > 0) || length_squared(ss->p - ctx.p) == 0 || masked(*ss)) return {};
    Vec3f wi = normalize(ss->p - ctx.p);
    SampledSpectrum Le = L(ss->p, ss->n, ss->uv, -wi, lambda);
    if (Le.is_black()) return {};
    LightLiSample s;
    s.L = Le;
    s.wi = wi;
    s.pdf = ss->pdf;
    s.p_light = ss->p;
    s.n_light = ss->n;
    s.error_scale_light = ss->error_scale;
    return s;
}

float DiffuseAreaLight::pdf_li(const LightSampleContext &ctx, Vec3f wi) const {
    return shape_->pdf(ctx.p, wi);
}

std::optional<LightLeSample> DiffuseAreaLight::sample_le(Vec2f u1, Vec2f u2,
                                                         const SampledWavelengths &lambda) const {
    std::optional<ShapeSample> ss = shape_->sample(u1);
    if (!ss || !(ss->pdf > 0) || masked(*ss)) return {};
    // Cosine-weighted direction about the normal; two-sided lights first pick a side with equal
    // probability, reusing u2.x rescaled to [0, 1).
    Vec3f w;
    float pdf_dir;
    if (two_sided_) {
        bool back = u2.x >= 0.5f;
        u2.x = std::min(back ? (u2.x - 0.5f) * 2 : u2.x * 2, OneMinusEpsilon);
        w = sample_cosine_hemisphere(u2);
        if (back) w.z = -w.z;
        pdf_dir = cosine_hemisphere_pdf(std::abs(w.z)) / 2;
    } else {
        w = sample_cosine_hemisphere(u2);
        pdf_dir = cosine_hemisphere_pdf(w.z);
    }
    if (!(pdf_dir > 0)) return {};
    w = Frame::from_z(ss->n).from_local(w);
    LightLeSample s;
    s.L = L(ss->p, ss->n, ss->uv, w, lambda);
    s.ray = spawn_ray(ss->p, ss->n, ss->error_scale, w, 0); // the light path's time is set where it starts
    s.n = ss->n;
    s.error_scale = ss->error_scale;
    s.uv = ss->uv;
    s.pdf_pos = ss->pdf;
    s.pdf_dir = pdf_dir;
    return s;
}

void DiffuseAreaLight::pdf_le(const Ray &ray, Vec3f n, float *pdf_pos, float *pdf_dir) const {
    *pdf_pos = uniform_by_area_ ? 1 / area_ : shape_->pdf_area(ray.o);
    float cos_t = dot(n, normalize(ray.d));
    *pdf_dir = two_sided_ ? cosine_hemisphere_pdf(std::abs(cos_t)) / 2
                          : std::max(0.f, cosine_hemisphere_pdf(cos_t));
}

}  // namespace caustica
