#include "materials/shading_perturbation.h"

#include "geometry/interaction.h"

#include <cmath>

namespace caustica {

namespace {

// The finite-difference step in u or v: half the footprint's extent in it, as pbrt-v4 takes it,
// or pbrt-v4's 0.0005 without one.
float bump_step(float d_dx, float d_dy) {
    const float step = 0.5f * (std::abs(d_dx) + std::abs(d_dy));
    return step > 0 ? step : 0.0005f;
}

bool finite(Vec3f v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

} // namespace

std::shared_ptr<const ShadingPerturbation> ShadingPerturbation::bump(FloatTexturePtr displacement) {
    auto p = std::make_shared<ShadingPerturbation>();
    p->displacement_ = std::move(displacement);
    return p;
}

std::shared_ptr<const ShadingPerturbation> ShadingPerturbation::normal_map(std::shared_ptr<const TexelImage> image) {
    auto p = std::make_shared<ShadingPerturbation>();
    p->normal_map_ = std::move(image);
    return p;
}

void ShadingPerturbation::apply(SurfaceInteraction &si) const {
    const Vec3f n = si.shading.n, dpdu = si.shading.dpdu, dpdv = si.shading.dpdv;
    Vec3f bumped_dpdu, bumped_dpdv;
    if (normal_map_) {
        float rgb[3];
        normal_map_->lookup(si.uv, ImageWrap::Repeat, rgb);
        const Vec3f local = normalize(Vec3f(2 * rgb[0] - 1, 2 * rgb[1] - 1, 2 * rgb[2] - 1));
        const Vec3f ns = Frame::from_xz(normalize(dpdu), n).from_local(local);
        // Tangents of the same lengths, perpendicular to the new normal.
        bumped_dpdu = normalize(dpdu - ns * dot(dpdu, ns)) * length(dpdu);
        bumped_dpdv = normalize(cross(ns, bumped_dpdu)) * length(dpdv);
    } else {
        const TextureEvalContext ctx(si);
        const float d = displacement_->evaluate(ctx);
        const float du = bump_step(si.dudx, si.dudy), dv = bump_step(si.dvdx, si.dvdy);
        TextureEvalContext shifted = ctx;
        shifted.p = si.p + du * dpdu;
        shifted.uv = si.uv + Vec2f(du, 0);
        const float d_u = displacement_->evaluate(shifted);
        shifted.p = si.p + dv * dpdv;
        shifted.uv = si.uv + Vec2f(0, dv);
        const float d_v = displacement_->evaluate(shifted);
        bumped_dpdu = dpdu + n * ((d_u - d) / du);
        bumped_dpdv = dpdv + n * ((d_v - d) / dv);
    }
    const Vec3f ns = normalize(cross(bumped_dpdu, bumped_dpdv));
    if (!finite(ns) || !finite(bumped_dpdu) || !finite(bumped_dpdv)) return;
    si.set_shading(ns, bumped_dpdu, bumped_dpdv);
}

} // namespace caustica
