#include "lights/medium_emitter.h"

#include "core/rng.h"
#include "core/sampling.h"

#include <bit>
#include <cmath>
#include <numbers>

namespace caustica {

namespace {

float box_volume(const Bounds3f &b) {
    const Vec3f d = b.diagonal();
    return d.x * d.y * d.z;
}

bool inside(Vec3f p, const Bounds3f &b) {
    return p.x >= b.lo.x && p.x <= b.hi.x && p.y >= b.lo.y && p.y <= b.hi.y && p.z >= b.lo.z && p.z <= b.hi.z;
}

} // namespace

MediumEmitter::MediumEmitter(const Medium &medium) : medium_(medium) { set_medium(&medium); }

void MediumEmitter::preprocess(const Bounds3f &scene_bounds) { scene_bounds_ = scene_bounds; }

SampledSpectrum MediumEmitter::phi(const SampledWavelengths &lambda) const {
    const float four_pi = 4 * std::numbers::pi_v<float>;
    if (medium_.has_emission_sampling()) return medium_.emitted_power(lambda) * four_pi;
    const float volume = box_volume(scene_bounds_);
    if (!(volume > 0)) return SampledSpectrum(0.f);
    return L(scene_bounds_.lo, {}, {}, {}, lambda) * (four_pi * volume);
}

SampledSpectrum MediumEmitter::L(Vec3f p, Vec3f, Vec2f, Vec3f, const SampledWavelengths &lambda) const {
    return medium_.properties(p, lambda).sigma_a * medium_.Le(p, lambda);
}

std::optional<LightLeSample> MediumEmitter::sample_le(Vec2f u1, Vec2f u2, const SampledWavelengths &lambda) const {
    Rng rng(hash_values(std::bit_cast<uint32_t>(u1.x), std::bit_cast<uint32_t>(u1.y)),
            hash_values(std::bit_cast<uint32_t>(u2.x), std::bit_cast<uint32_t>(u2.y)));
    const Vec3f u_within{rng.uniform(), rng.uniform(), rng.uniform()};
    EmissionPoint start;
    if (medium_.has_emission_sampling()) {
        const std::optional<EmissionPoint> e = medium_.sample_emission_point(u1.x, u_within);
        if (!e) return std::nullopt;
        start = *e;
    } else {
        const float volume = box_volume(scene_bounds_);
        if (!(volume > 0)) return std::nullopt;
        const Vec3f d = scene_bounds_.diagonal();
        start = {scene_bounds_.lo + Vec3f{u_within.x * d.x, u_within.y * d.y, u_within.z * d.z}, 1 / volume};
    }
    LightLeSample les;
    les.L = L(start.p, {}, {}, {}, lambda);
    les.ray = Ray{start.p, sample_uniform_sphere(u2), Infinity};
    les.pdf_pos = start.pdf;
    les.pdf_dir = uniform_sphere_pdf();
    return les;
}

void MediumEmitter::pdf_le(const Ray &ray, Vec3f, float *pdf_pos, float *pdf_dir) const {
    *pdf_dir = uniform_sphere_pdf();
    if (medium_.has_emission_sampling()) {
        *pdf_pos = medium_.emission_point_pdf(ray.o);
        return;
    }
    const float volume = box_volume(scene_bounds_);
    *pdf_pos = volume > 0 && inside(ray.o, scene_bounds_) ? 1 / volume : 0;
}

} // namespace caustica
