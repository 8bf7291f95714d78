#include "integrators/common/path_vertex.h"

#include "camera/camera.h"
#include "integrators/common/light_path_start.h"
#include "integrators/common/medium_emission.h"
#include "lights/light_sampler.h"
#include "media/medium_interface.h"
#include "scene/scene.h"

namespace caustica {

float importance_cosine(Vec3f ng, Vec3f ns, Vec3f wo, Vec3f wi) {
    float wo_ng = abs_dot(wo, ng);
    if (wo_ng == 0) return 0;
    return abs_dot(wo, ns) * abs_dot(wi, ng) / wo_ng;
}

bool PathVertex::connectible() const {
    switch (type) {
    case PathVertexType::Camera: return true;
    // A distant light's one direction cannot be met by a connection; environment lights are
    // connected by sampling a direction (the s = 1 strategy).
    case PathVertexType::Light: return !light || light->type() != LightType::DeltaDirection;
    case PathVertexType::Surface: return bsdf && is_non_specular(bsdf.flags());
    // Caustica's phase functions are never Dirac deltas (|g| < 1).
    case PathVertexType::Medium: return true;
    }
    return false;
}

const Medium *PathVertex::medium_towards(Vec3f w) const {
    return type == PathVertexType::Surface ? medium_after(si, w, medium) : medium;
}

SampledSpectrum PathVertex::f(Vec3f w, TransportMode mode) const {
    if (type == PathVertexType::Medium) return SampledSpectrum(medium->phase().p(si.wo, w));
    return bsdf.f(si.wo, w, mode);
}

float PathVertex::cosine(Vec3f w, TransportMode mode) const {
    if (type == PathVertexType::Medium) return 1;
    return mode == TransportMode::Radiance ? abs_dot(w, ns()) : importance_cosine(si, si.wo, w);
}

float PathVertex::convert_density(float pdf, const PathVertex &next) const {
    if (next.at_infinity) return pdf;
    Vec3f w = next.p() - p();
    float dist2 = length_squared(w);
    if (dist2 == 0) return 0;
    if (next.on_surface()) pdf *= abs_dot(next.ng(), w / std::sqrt(dist2));
    if (next.is_medium_emitter()) pdf *= collision_density(next.collision_sigma, std::sqrt(dist2));
    return pdf / dist2;
}

float PathVertex::pdf(const Scene &scene, const PathVertex *prev, const PathVertex &next) const {
    if (type == PathVertexType::Light) return pdf_light(scene, next);
    Vec3f wn = next.p() - p();
    if (length_squared(wn) == 0) return 0;
    wn = normalize(wn);
    float pdf = 0;
    if (type == PathVertexType::Camera) {
        float pdf_pos;
        scene.camera->pdf_we(Ray{p(), wn, Infinity, si.time}, &pdf_pos, &pdf);
    } else {
        // Back across a jump: the reverse jump's density (see after_jump).
        if (after_jump && &next == this - 1) return 1;
        if (!prev) return 0;
        // Arrived through a jump: the light comes from inside (si.wo), not from prev's position.
        Vec3f wp = after_jump && prev == this - 1 ? si.wo : prev->p() - p();
        if (length_squared(wp) == 0) return 0;
        pdf = type == PathVertexType::Medium ? medium->phase().pdf(normalize(wp), wn)
                                             : bsdf.pdf(normalize(wp), wn);
    }
    return convert_density(pdf, next);
}

namespace {

// The light a light vertex stands for: its own, or the area light of a surface it lies on.
const Light *emitter(const PathVertex &v) {
    return v.type == PathVertexType::Light ? v.light : v.si.area_light;
}

} // namespace

float PathVertex::pdf_light(const Scene &scene, const PathVertex &v) const {
    Vec3f w = v.p() - p();
    float dist2 = length_squared(w);
    if (dist2 == 0) return 0;
    w = w / std::sqrt(dist2);
    float pdf;
    if (at_infinity) {
        // Emission from infinity starts on the disk perpendicular to the direction that
        // bounds the scene: its density per unit disk area (the same for every infinite and
        // distant light, which share the scene's bounding sphere).
        const Light *light_at_infinity = light ? light : scene.infinite_lights.front();
        float pdf_dir;
        light_at_infinity->pdf_le(Ray{p(), w, Infinity}, Vec3f{}, &pdf, &pdf_dir);
    } else {
        float pdf_pos;
        emitter(*this)->pdf_le(Ray{p(), w, Infinity}, ng(), &pdf_pos, &pdf);
        pdf /= dist2;
    }
    if (v.on_surface()) pdf *= abs_dot(v.ng(), w);
    return pdf;
}

namespace {

// The probability that `light` is chosen for a path whose vertex after it is v.
float light_choice_pmf(const Scene &scene, const Light &light, const PathVertex &v, PathVertex::LightChoice choice) {
    return choice == PathVertex::LightChoice::NextEvent
               ? scene.light_sampler->pmf(LightSampleContext{v.p(), v.ng(), v.ns()}, &light)
               : light_path_start_pmf(scene, light);
}

} // namespace

float PathVertex::pdf_light_origin(const Scene &scene, const PathVertex &v, LightChoice choice) const {
    Vec3f w = v.p() - p();
    if (length_squared(w) == 0) return 0;
    w = normalize(w);
    const LightSampleContext receiver{v.p(), v.ng(), v.ns()};
    auto pmf = [&](const Light &light) { return light_choice_pmf(scene, light, v, choice); };
    if (at_infinity) {
        // A direction from infinity is generated by any of the infinite lights (an escaped
        // camera subpath receives all of them): the selection-weighted sum of their directional
        // densities towards -w, as in pbrt-v4's InfiniteLightDensity.
        float pdf = 0;
        for (const Light *infinite : scene.infinite_lights) pdf += pmf(*infinite) * infinite->pdf_li(receiver, -w);
        return pdf;
    }
    const Light *light_here = emitter(*this);
    // Next-event estimation does not sample emissive media: s = 1 joins the light subpath's start.
    if (light_here->type() == LightType::Volume) return medium_start_density(scene, *light_here, p());
    float pdf_pos, pdf_dir;
    light_here->pdf_le(Ray{p(), w, Infinity}, ng(), &pdf_pos, &pdf_dir);
    return pmf(*light_here) * pdf_pos;
}

float PathVertex::next_event_ratio(const Scene &scene, const PathVertex &v) const {
    if (at_infinity) {
        const float light_subpath = pdf_light_origin(scene, v);
        return light_subpath > 0 ? pdf_light_origin(scene, v, LightChoice::NextEvent) / light_subpath : 1.f;
    }
    const Light &light = *emitter(*this);
    if (light.type() == LightType::Volume) return 1;
    const float light_subpath = light_choice_pmf(scene, light, v, LightChoice::LightSubpath);
    return light_subpath > 0 ? light_choice_pmf(scene, light, v, LightChoice::NextEvent) / light_subpath : 1.f;
}

SampledSpectrum PathVertex::Le(const Scene &scene, const PathVertex &v,
                               const SampledWavelengths &lambda) const {
    if (!is_light()) return SampledSpectrum(0.f);
    Vec3f w = v.p() - p();
    if (length_squared(w) == 0) return SampledSpectrum(0.f);
    w = normalize(w);
    if (at_infinity) {
        SampledSpectrum L(0.f);
        for (const Light *infinite : scene.infinite_lights) L += infinite->Le(Ray{p(), -w, Infinity}, lambda);
        return L;
    }
    return emitter(*this)->L(p(), ng(), si.uv, w, lambda);
}

} // namespace caustica
