// Where a subpath scatters: a surface point with its BSDF, or a point inside a participating
// medium with the medium's phase function. A medium point has no normal, so every cosine at it
// is 1, and the phase function is symmetric, so radiance and importance transport see the same
// function there (no 1/eta^2, no shading-normal correction). Camera and light vertices are both
// built on it, so that connections and light sampling treat the two kinds alike.
#pragma once

#include "integrators/common/path_vertex.h"
#include "materials/bsdf.h"
#include "media/medium.h"
#include "media/medium_interface.h"

namespace caustica {

struct ScatteringPoint {
    // Ordered so that no padding is needed: vcm keeps hundreds of thousands of these.
    Vec3f p;
    Vec3f ng;           // geometric normal; zero in a medium
    Vec3f wo;           // towards the previous vertex of the subpath
    float time = 0;     // the path's time (geometry/ray.h), for the rays that leave or join it
    // Surface points. Its frame's z is the shading normal (ns()), which is not kept twice.
    BSDF bsdf;
    const Medium *medium = nullptr; // medium points: the medium the point lies in
    // Surface points: the media on the side ng points to and on the other (the medium the path
    // arrived in on both, unless the surface is a transition between media).
    const Medium *medium_front = nullptr, *medium_back = nullptr;
    float coverage = 1; // surface points: SurfaceInteraction::coverage
    float error_scale = 0; // surface points: SurfaceInteraction::error_scale

    // The surface hit si, with its BSDF, reached by a path travelling in `arrived_in`: the media
    // on its two sides follow from the hit's medium interface (medium_after).
    static ScatteringPoint on_surface(const SurfaceInteraction &si, const BSDF &bsdf, const Medium *arrived_in) {
        return ScatteringPoint{si.p, si.n, si.wo, si.time, bsdf, nullptr, medium_after(si, si.n, arrived_in),
                               medium_after(si, -si.n, arrived_in), si.coverage, si.error_scale};
    }
    // The scattering event at `distance` along ray inside `medium`.
    static ScatteringPoint in_medium_along(const Ray &ray, float distance, const Medium *medium) {
        const Vec3f wo = -normalize(ray.d);
        return ScatteringPoint{ray.o - wo * distance, Vec3f{}, wo, ray.time, BSDF(), medium, medium, medium};
    }

    bool in_medium() const { return medium != nullptr; }

    // The shading normal of a surface point with a BSDF (every material builds its BSDF's frame
    // around SurfaceInteraction::shading.n); zero in a medium.
    Vec3f ns() const { return in_medium() ? Vec3f{} : bsdf.frame().z; }

    // The medium a ray leaving the point in direction w travels through.
    const Medium *medium_towards(Vec3f w) const {
        if (in_medium()) return medium;
        return dot(w, ng) > 0 ? medium_front : medium_back;
    }

    // |cos| between w and the geometric normal, as area <-> solid angle conversions use it.
    float cosine(Vec3f w) const { return in_medium() ? 1.f : abs_dot(ng, w); }

    // The scattering function towards wi times its cosine: for radiance, the BSDF times
    // |wi.ns|; for importance, with the adjoint shading-normal correction (Veach 1997, 5.3).
    SampledSpectrum f(Vec3f wi, TransportMode mode) const {
        if (in_medium()) return SampledSpectrum(medium->phase().p(wo, wi));
        if (mode == TransportMode::Radiance) return bsdf.f(wo, wi, mode) * abs_dot(wi, ns());
        return bsdf.f(wo, wi, mode) * importance_cosine(ng, ns(), wo, wi);
    }

    // Solid-angle density of sampling `to` from `from` in the given transport mode.
    float pdf(Vec3f from, Vec3f to, TransportMode mode) const {
        if (in_medium()) return medium->phase().pdf(from, to);
        return bsdf.pdf(from, to, mode);
    }

    // What joining this point to another in direction w needs (a connection, a light sample):
    // f(w, mode), the density of sampling w from wo in that mode, and the density of sampling
    // wo from w in the adjoint mode (the other subpath's direction). The densities are left
    // zero when f is, as the caller then drops the connection.
    struct Connection {
        SampledSpectrum f;
        float pdf_forward = 0, pdf_reverse = 0;
    };
    Connection connect_towards(Vec3f w, TransportMode mode) const {
        if (in_medium()) {
            const float p = medium->phase().p(wo, w);
            return {SampledSpectrum(p), p, p};
        }
        const BxDFEvaluation e = bsdf.evaluate(wo, w, mode);
        if (e.f.is_black()) return {};
        const float cosine = mode == TransportMode::Radiance ? abs_dot(w, ns()) : importance_cosine(ng, ns(), wo, w);
        Connection c{e.f * cosine, e.pdf_forward, e.pdf_reverse};
        if (c.f.is_black()) return {};
        return c;
    }
};

} // namespace caustica
