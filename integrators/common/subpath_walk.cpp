#include "integrators/common/subpath_walk.h"

#include "camera/camera_footprint.h"
#include "integrators/common/profile_subsurface.h"
#include "integrators/common/reradiation.h"
#include "materials/material.h"
#include "materials/profile_subsurface_material.h"
#include "media/medium_interface.h"
#include "sampler/sampler.h"
#include "scene/scene.h"

namespace caustica {

namespace {

// The cosine that goes with a direction wi sampled at si from wo: |wi . ns| for radiance, the
// adjoint-corrected importance_cosine for importance.
float scattering_cosine(TransportMode mode, const SurfaceInteraction &si, Vec3f wo, Vec3f wi) {
    return mode == TransportMode::Radiance ? abs_dot(wi, si.shading.n) : importance_cosine(si, wo, wi);
}

} // namespace

SubpathWalk::SubpathWalk(const Scene &scene, TransportMode mode, SampledWavelengths &lambda, Sampler &sampler,
                         ScratchBuffer &bsdf_memory, uint64_t &rays, bool reverse_densities)
    : scene_(scene), mode_(mode), lambda_(lambda), sampler_(sampler), bsdf_memory_(bsdf_memory), rays_(rays),
      reverse_densities_(reverse_densities) {}

// Only scenes with a dye pay for asking each BSDF whether it re-radiates.
void SubpathWalk::allow_reradiation() { reradiation_allowed_ = scene_.features.fluorescence; }

void SubpathWalk::start(const Ray &ray, const Medium *medium, const SampledSpectrum &throughput,
                        const std::optional<RayDifferential> &differential) {
    ray_ = ray;
    differential_ = differential;
    medium_ = medium;
    beta = throughput;
    previous_p_ = ray.o;
    any_non_specular_bounce_ = false;
}

WalkEvent SubpathWalk::advance() {
    after_jump_ = false;
    emitted_ = SampledSpectrum(0.f);
    while (true) {
        ++rays_;
        const bool hit = scene_.intersect(ray_, &si_);
        // Outside media and absorbing interiors a segment changes nothing.
        if (medium_ || absorbing_interior_) {
            const float speed = length(ray_.d);
            const PathSegment segment =
                traverse_segment(medium_, absorbing_interior_, Ray{ray_.o, ray_.d / speed, Infinity, ray_.time},
                                 hit ? si_.t * speed : Infinity, lambda(), sampler_, spectral_mis_);
            if (mode_ == TransportMode::Radiance && segment.scattered) {
                emitted_ += beta * segment.emitted;
                emission_point_ = ray_.o + ray_.d * (segment.t / speed);
            }
            beta *= segment.weight;
            if (segment.scattered && !beta.is_black()) {
                differential_.reset();
                point_ = ScatteringPoint::in_medium_along(ray_, segment.t, medium_);
                return WalkEvent::Vertex;
            }
        }
        if (beta.is_black()) return WalkEvent::Ended;
        if (!hit) return WalkEvent::Escaped;
        BSDF bsdf = surface_bsdf(scene_, si_, differential_ ? &*differential_ : nullptr, lambda(), bsdf_memory_,
                                 media_memory_, sampler_.samples_per_pixel());
        regularized_ = bsdf && regularize_ && any_non_specular_bounce_;
        if (regularized_) bsdf.regularize(bsdf_memory_);
        if (bsdf || si_.area_light) {
            point_ = ScatteringPoint::on_surface(si_, bsdf, medium_);
            return WalkEvent::Vertex;
        }
        pass_through();
    }
}

BSDF SubpathWalk::surface_bsdf(const Scene &scene, SurfaceInteraction &si, const RayDifferential *differential,
                               const SampledWavelengths &lambda, ScratchBuffer &memory, ScratchBuffer *media_memory,
                               int samples_per_pixel) {
    if (!si.material) return BSDF();
    // Scenes without textures have neither a footprint nor differentials: nothing reads them.
    if (differential || scene.camera_footprint)
        compute_differentials(si, differential, scene.camera_footprint ? &*scene.camera_footprint : nullptr,
                              samples_per_pixel);
    return shade(si, lambda, memory, media_memory);
}

StoredScatteringPoint SubpathWalk::stored_vertex() const {
    if (point_.in_medium()) return {point_.p, point_.wo, SurfaceHit{}, false, false, medium_};
    return {point_.p, point_.wo, si_.hit, after_jump_, regularized_ && !after_jump_, nullptr};
}

ScatteringPoint SubpathWalk::rebuild(const Scene &scene, const StoredScatteringPoint &stored,
                                     const SampledWavelengths &lambda, float time, ScratchBuffer &memory,
                                     int samples_per_pixel) {
    if (stored.in_medium())
        return ScatteringPoint{stored.p, Vec3f{}, stored.wo, time, BSDF(), stored.medium, stored.medium, stored.medium};
    SurfaceInteraction si = scene.geometry.interaction(stored.hit, stored.p, stored.wo, time);
    BSDF bsdf;
    if (stored.exit_lobe) {
        // The probe keeps only exits of the material whose profile the jump entered.
        bsdf = static_cast<const ProfileSubsurfaceMaterial *>(si.material)->subsurface_exit_bsdf(si, memory);
    } else {
        bsdf = surface_bsdf(scene, si, nullptr, lambda, memory, nullptr, samples_per_pixel);
        if (stored.regularized) bsdf.regularize(memory);
    }
    return ScatteringPoint::on_surface(si, bsdf, stored.medium);
}

void SubpathWalk::pass_through() {
    // The differential rays cross the surface too (pbrt-v4's SkipIntersection).
    if (differential_) {
        differential_->rx_origin += differential_->rx_direction * si_.t;
        differential_->ry_origin += differential_->ry_direction * si_.t;
    }
    leave(si_, ray_.d);
}

void SubpathWalk::leave(const SurfaceInteraction &from, Vec3f wi) {
    medium_ = medium_after(from, wi, medium_);
    ray_ = from.spawn_ray(wi);
}

std::optional<WalkScatter> SubpathWalk::scatter() {
    WalkScatter s;
    differential_.reset();
    previous_p_ = point_.p;
    if (point_.in_medium()) {
        // The phase function is sampled exactly (value = density, so beta is unchanged) and is
        // symmetric: the reverse density is the same.
        const PhaseSample ps = medium_->phase().sample_p(point_.wo, sampler_.get_2d());
        if (!(ps.p > 0)) return std::nullopt;
        s.wi = ps.wi;
        s.pdf_fwd = s.pdf_rev = ps.p;
        any_non_specular_bounce_ = true;
        ray_ = Ray{point_.p, ps.wi, Infinity, point_.time};
        return s;
    }
    const BSDF &bsdf = point_.bsdf;
    const Vec3f wo = si_.wo;
    // Lane lobes (rough dispersive refraction) are sampled with the subpath's spectral MIS lane.
    const int lane = bsdf.has_lane_lobes() ? spectral_mis_.lane(lambda(), sampler_) : -1;
    // A jump's exit leaves by its exit lobe, a single lobe: no lobe choice is drawn.
    const float u = after_jump_ ? 0.f : sampler_.get_1d();
    // A fluorescent surface re-radiates for its share of u; the elastic lobe has the rest.
    const Reradiation *reradiation = reradiation_allowed_ && !after_jump_ ? bsdf.reradiation() : nullptr;
    if (reradiation && u < reradiation->probability(mode_)) return reradiate(*reradiation, wo);
    const std::optional<BSDFSample> bs =
        lane < 0 ? bsdf.sample_f(wo, u, sampler_.get_2d(), mode_) : bsdf.sample_f_as(lane, wo, u, sampler_.get_2d(), mode_);
    if (!bs) return std::nullopt;
    // Hero-wavelength sampling (Wilkie et al. 2014): a direction that depends on wavelength is
    // valid for the hero alone; the other lanes end here, before the densities are evaluated.
    // Once a re-radiation has moved every lane to one wavelength, every lane may follow it.
    if (bs->dispersive && !shifted_ && !lambda_.secondary_terminated()) {
        lambda_.terminate_secondary();
        for (int i = 1; i < NumWavelengths; ++i) beta[i] = 0;
    }
    s.wi = bs->wi;
    // The strategies' MIS takes the BSDF's own density, the lanes' mean for lane lobes.
    s.pdf_fwd = bs->pdf_is_proportional ? bsdf.pdf(wo, bs->wi, mode_) : bs->lane_pdf ? bs->lane_pdf->average() : bs->pdf;
    if (reverse_densities_) s.pdf_rev = bsdf.pdf(bs->wi, wo, adjoint(mode_));
    s.cos_out = abs_dot(si_.n, bs->wi);
    s.specular = bs->is_specular();
    any_non_specular_bounce_ |= !s.specular;
    const float inverse_pdf = bs->lane_pdf ? spectral_mis_.inverse_density(*bs->lane_pdf) : 1 / bs->pdf;
    beta *= bs->f * (scattering_cosine(mode_, si_, wo, bs->wi) * inverse_pdf);
    if (!after_jump_) {
        s.profile = profile_entry(si_, *bs);
        if (s.profile) return s;
    }
    if (bs->is_transmission()) {
        // Radiance is scaled by 1/eta^2 at a refraction, importance is not (Veach 1997, 5.2).
        if (mode_ == TransportMode::Radiance) eta_scale_ *= sqr(bs->eta);
        if (si_.material->has_interior_absorption())
            absorbing_interior_ = dot(bs->wi, si_.n) < 0 ? si_.material : nullptr;
    }
    leave(si_, bs->wi);
    return s;
}

std::optional<WalkScatter> SubpathWalk::reradiate(const Reradiation &reradiation, Vec3f wo) {
    const Vec2f u = sampler_.get_2d();
    const std::optional<ReradiationSample> r = sample_reradiation(reradiation, mode_, lambda(), sampler_.get_1d());
    if (!r) return std::nullopt;
    // The lobe is sampled in the shading frame directly: a second caller of BSDF::sample_f would
    // keep the compiler from inlining it into scatter(), the hot path of every walk.
    const Frame &frame = point_.bsdf.frame();
    const Vec3f wo_local = frame.to_local(wo);
    const std::optional<BSDFSample> bs = r->lobe.sample_f(wo_local, 0.f, u, mode_);
    if (!bs || wo_local.z == 0 || bs->wi.z == 0) return std::nullopt;
    WalkScatter s;
    s.wi = frame.from_local(bs->wi);
    s.pdf_fwd = bs->pdf;
    if (reverse_densities_) s.pdf_rev = r->lobe.pdf(bs->wi, wo_local, adjoint(mode_));
    s.cos_out = abs_dot(si_.n, s.wi);
    beta *= bs->f * (scattering_cosine(mode_, si_, wo, s.wi) / bs->pdf);
    // A light subpath's splats land at the new wavelength; a camera subpath's film keeps its own.
    if (mode_ == TransportMode::Importance) lambda_ = r->lambda;
    shifted_lambda_ = r->lambda;
    shifted_ = true;
    any_non_specular_bounce_ = true;
    leave(si_, s.wi);
    return s;
}

bool SubpathWalk::jump(const ProfileSubsurfaceMaterial &profile) {
    std::optional<ProfileExit> exit = sample_profile_exit(scene_, profile, si_, lambda(), sampler_, bsdf_memory_, rays_);
    if (!exit) return false;
    beta *= exit->weight;
    if (beta.is_black()) return false;
    // A profile solid has no interior medium: the exit lies in the medium the entry does.
    si_ = exit->si;
    point_ = ScatteringPoint::on_surface(si_, exit->bsdf, medium_);
    after_jump_ = true;
    any_non_specular_bounce_ = true;
    return true;
}

bool SubpathWalk::russian_roulette(int depth) {
    const SampledSpectrum rr_beta = beta * eta_scale_;
    if (rr_beta.max_value() < 1 && depth > 1) {
        const float q = std::max(0.f, 1 - rr_beta.max_value());
        if (sampler_.get_1d() < q) return false;
        beta /= 1 - q;
    }
    return !beta.is_black();
}

} // namespace caustica
