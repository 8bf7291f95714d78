// One vertex of a camera or light subpath, shared by the bidirectional integrators (BDPT now;
// photon mapping and VCM reuse it). The representation follows Veach 1997 section 10.2 and
// pbrt-v4 section 16.3: every vertex stores the throughput of the subpath up to it and the
// densities with which it is generated from either direction, both in the AREA measure, so that
// multiple-importance weights can be computed as products of ratios (Veach 1997, section 10.2.1).
//
// Vertices "at infinity" (an environment light, or a distant light) have no position: their
// densities are kept per unit solid angle instead, and no distance or cosine conversion is
// applied when a density is expressed at them (pbrt-v4's ConvertDensity does the same).
#pragma once

#include "geometry/interaction.h"
#include "lights/light.h"
#include "materials/bsdf.h"

namespace caustica {

class Scene;

enum class PathVertexType {
    Camera,  // the lens point; si.n is zero (connections to it are not cosine-weighted there)
    Light,   // the first vertex of a light subpath, or where a camera subpath escaped to infinity
    Surface, // a scattering surface; may also carry an area light (si.area_light)
};

struct PathVertex {
    PathVertexType type = PathVertexType::Surface;
    // Subpath throughput up to and including this vertex: the product of the sampled
    // functions over their densities (for light subpaths it starts at Le / (pmf * pdf_pos)).
    SampledSpectrum beta{0.f};
    // Position and geometric normal (zero when the vertex is not on a surface: point lights,
    // the lens, points at infinity); on surface vertices also the shading frame, uv and wo.
    SurfaceInteraction si;
    BSDF bsdf;                    // surface vertices only
    const Light *light = nullptr; // light vertices; null for an escaped camera subpath, whose
                                  // emission is the sum over all infinite lights
    // The BSDF sample that left this vertex was specular: the vertex cannot be connected, and
    // strategies that would need to connect it have zero density.
    bool delta = false;
    bool at_infinity = false;     // an environment or distant light vertex (see above)
    // Density of generating this vertex from its predecessor on its own subpath (pdf_fwd) and
    // from its successor, i.e. by the other subpath's sampling (pdf_rev); area measure.
    float pdf_fwd = 0, pdf_rev = 0;

    Vec3f p() const { return si.p; }
    Vec3f ng() const { return si.n; }
    Vec3f ns() const { return si.shading.n; }
    bool on_surface() const { return si.n != Vec3f{}; }
    // Emits light that a connection or a camera subpath can receive.
    bool is_light() const { return type == PathVertexType::Light || si.area_light != nullptr; }
    bool is_delta_light() const {
        return type == PathVertexType::Light && light && caustica::is_delta_light(light->type());
    }
    // Whether a deterministic connection to another vertex can have non-zero value.
    bool connectible() const;

    // The density pdf (solid angle at this vertex) expressed in the area measure at next:
    // times |cos| at next over the squared distance (Veach 1997, eq. 8.10).
    float convert_density(float pdf, const PathVertex &next) const;
    // Area density with which this vertex, reached from prev (null for an endpoint), samples
    // next: the BSDF's or the camera's directional density, or the light's emission density.
    float pdf(const Scene &scene, const PathVertex *prev, const PathVertex &next) const;
    // Area density at v of a ray emitted by this (light) vertex towards it.
    float pdf_light(const Scene &scene, const PathVertex &v) const;
    // Density with which a light subpath starts at this (light) vertex: light selection times
    // the position density (area), or the directional density for lights at infinity.
    float pdf_light_origin(const Scene &scene, const PathVertex &v) const;
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
