// One vertex of a camera or light subpath, shared by the bidirectional integrators (BDPT now;
// photon mapping and VCM reuse it). The representation follows Veach 1997 section 10.2 and
// pbrt-v4 section 16.3: every vertex stores the throughput of the subpath up to it and the
// densities with which it is generated from either direction, both in the AREA measure, so that
// multiple-importance weights can be computed as products of ratios (Veach 1997, section 10.2.1).
//
// Vertices "at infinity" (an environment light, or a distant light) have no position: their
// densities are kept per unit solid angle instead, and no distance or cosine conversion is
// applied when a density is expressed at them (pbrt-v4's ConvertDensity does the same).
//
// Medium vertices (scattering events inside a participating medium) have no normal: their
// scattering function is the phase function, with no cosine factor, and converting a density to
// the area measure at them divides by the squared distance alone (as in pbrt-v4's BDPT). The
// densities of sampling free-flight distances are left out of every stored density, as in
// pbrt-v4: every strategy omits them alike, so the MIS weights still sum to one and the
// estimator stays unbiased.
//
// The one exception is a point of an emissive medium where a light subpath starts (a "medium
// emitter" vertex, is_medium_emitter): the camera side's density there includes the free
// flight's (integrators/common/medium_emission.h), which convert_density applies.
#pragma once

#include "geometry/interaction.h"
#include "lights/light.h"
#include "materials/bsdf.h"
#include "media/medium.h"

namespace caustica {

class Scene;

enum class PathVertexType {
    Camera,  // the lens point; si.n is zero (connections to it are not cosine-weighted there)
    Light,   // the first vertex of a light subpath, or where a camera subpath escaped to infinity
    Surface, // a scattering surface; may also carry an area light (si.area_light)
    Medium,  // a scattering event inside a participating medium (si.p and si.wo only)
};

struct PathVertex {
    PathVertexType type = PathVertexType::Surface;
    // Subpath throughput up to and including this vertex: the product of the sampled
    // functions over their densities (for light subpaths it starts at Le / (pmf * pdf_pos)).
    SampledSpectrum beta{0.f};
    // Position and geometric normal (zero when the vertex is not on a surface: point lights,
    // the lens, points at infinity, medium vertices); on surface vertices also the shading
    // frame and uv; on surface and medium vertices wo, towards the subpath's previous vertex.
    SurfaceInteraction si;
    BSDF bsdf;                    // surface vertices only
    // The participating medium (null: vacuum) the vertex lies in: for a surface vertex the one
    // the subpath arrived through, for the lens the camera's, for a light point the light's.
    // Connections leave the vertex in medium_towards(direction).
    const Medium *medium = nullptr;
    const Light *light = nullptr; // light vertices; null for an escaped camera subpath, whose
                                  // emission is the sum over all infinite lights
    // The BSDF sample that left this vertex was specular: the vertex cannot be connected, and
    // strategies that would need to connect it have zero density.
    bool delta = false;
    bool at_infinity = false;     // an environment or distant light vertex (see above)
    // Profile subsurface (profile_subsurface.h): the vertex is where the subpath left a profile
    // solid that it entered at its predecessor. That edge is a jump through the solid, not a
    // ray: no strategy can join its two ends by a connection, and the densities of the jump
    // are taken as 1 in both directions (a fixed pair keeps the MIS weights a partition of
    // unity, and cancels from every strategy that counts, as each holds both ends or neither).
    // A subpath's vertices are stored one after another, so the predecessor is this - 1.
    bool after_jump = false;
    // Jumps on the subpath up to this vertex: entry and exit are one scattering event, as in
    // the path tracer, so a strategy's path depth leaves them out.
    uint16_t jumps = 0;
    // Density of generating this vertex from its predecessor on its own subpath (pdf_fwd) and
    // from its successor, i.e. by the other subpath's sampling (pdf_rev); area measure (volume
    // at a medium emitter vertex).
    float pdf_fwd = 0, pdf_rev = 0;
    // Medium emitter vertices: the mean extinction over the carried wavelengths at the point,
    // which sets the free-flight density of reaching it (see above).
    float collision_sigma = 0;
    // A light subpath's origin: next_event_ratio towards the subpath's next vertex, which every
    // strategy with s >= 2 weighs (mis_weight.cpp); kept once for all of them. A light point
    // that next-event estimation sampled: the ratio towards the vertex it was sampled from.
    float next_event_ratio_ahead = 1;

    Vec3f p() const { return si.p; }
    Vec3f ng() const { return si.n; }
    Vec3f ns() const { return si.shading.n; }
    bool on_surface() const { return si.n != Vec3f{}; }
    // Emits light that a connection or a camera subpath can receive.
    bool is_light() const { return type == PathVertexType::Light || si.area_light != nullptr; }
    // A point inside an emissive medium, where a light subpath starts or a camera subpath
    // collects the emission (lights/medium_emitter.h).
    bool is_medium_emitter() const {
        return type == PathVertexType::Light && light && light->type() == LightType::Volume;
    }
    bool is_delta_light() const {
        return type == PathVertexType::Light && light && caustica::is_delta_light(light->type());
    }
    // Whether a deterministic connection to another vertex can have non-zero value.
    bool connectible() const;
    // The medium a segment leaving this vertex in direction w travels through: the other side
    // of a surface that separates two media, else the vertex's own medium.
    const Medium *medium_towards(Vec3f w) const;
    // Scattering function of a surface or medium vertex from si.wo to the unit direction w: the
    // BSDF for the given transport mode, or the phase function (the same in both modes).
    SampledSpectrum f(Vec3f w, TransportMode mode) const;
    // The cosine that goes with f towards w: |w . ns| in radiance mode, the adjoint-corrected
    // importance_cosine in importance mode, and 1 at a medium vertex, which has no surface.
    float cosine(Vec3f w, TransportMode mode) const;

    // The density pdf (solid angle at this vertex) expressed in the area measure at next:
    // times |cos| at next over the squared distance (Veach 1997, eq. 8.10); no cosine when next
    // is not on a surface (a medium vertex, a point light, the lens); times the free-flight
    // density when next is a medium emitter (volume measure, see above).
    float convert_density(float pdf, const PathVertex &next) const;
    // Area density with which this vertex, reached from prev (null for an endpoint), samples
    // next: the BSDF's, the phase function's or the camera's directional density, or the
    // light's emission density.
    float pdf(const Scene &scene, const PathVertex *prev, const PathVertex &next) const;
    // Area density at v of a ray emitted by this (light) vertex towards it.
    float pdf_light(const Scene &scene, const PathVertex &v) const;
    // Density of this (light) vertex as the start of a path whose next vertex is v: the light's
    // choice times the position density (area, or volume in an emissive medium), or the
    // directional density for lights at infinity. A light subpath chooses the light by power
    // over the lights and emissive media; next-event estimation by v's position.
    enum class LightChoice { LightSubpath, NextEvent };
    float pdf_light_origin(const Scene &scene, const PathVertex &v,
                           LightChoice choice = LightChoice::LightSubpath) const;
    // pdf_light_origin with next-event estimation's choice over that with the light subpath's:
    // for a light with a position, the ratio of the two choices alone.
    float next_event_ratio(const Scene &scene, const PathVertex &v) const;
    // Radiance this (light) vertex emits towards v.
    SampledSpectrum Le(const Scene &scene, const PathVertex &v, const SampledWavelengths &lambda) const;
};

// The cosine factor of an importance-transport scattering event at si, light arriving from wo and
// leaving towards wi, including the adjoint shading-normal correction (Veach 1997, section 5.3):
// the BSDF's |wi.ns| times |wo.ns| |wi.ng| / (|wo.ng| |wi.ns|), written without the |wi.ns| that
// cancels (it may be zero).
float importance_cosine(Vec3f ng, Vec3f ns, Vec3f wo, Vec3f wi);
inline float importance_cosine(const SurfaceInteraction &si, Vec3f wo, Vec3f wi) {
    return importance_cosine(si.n, si.shading.n, wo, wi);
}

} // namespace caustica
