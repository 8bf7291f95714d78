// The random walk of one subpath, camera or light, shared by every integrator: SmallVCM's single
// loop (Davidovic's vertexcm.hxx), with each integrator's strategies layered on it. The walk owns
// the mechanics of moving a path through the scene:
//   - tracing, and crossing surfaces that only bound media (shapes without a material, and the
//     "interface" material);
//   - free flights through participating media, and the medium the path is in, tracked across
//     every interface (medium_after);
//   - the spectral MIS over the carried wavelengths for the decisions that depend on them: free
//     flights and rough dispersive refraction (SpectralMIS, spectral_mis.h);
//   - Beer-Lambert absorption inside absorbing dielectrics;
//   - sampling the phase function or the BSDF in the subpath's transport mode, with the adjoint
//     shading-normal correction for importance (Veach 1997, 5.3) and eta^2 bookkeeping for
//     radiance (pbrt-v4 14.1);
//   - dispersive termination of the secondary wavelengths (Wilkie et al. 2014; pbrt-v4's
//     SampledWavelengths::TerminateSecondary);
//   - fluorescent re-radiation, which moves the light to another wavelength (reradiation.h);
//   - the jump through a profile-subsurface solid (profile_subsurface.h);
//   - Russian roulette;
//   - on camera subpaths, the emission of emissive media met along each segment (emitted()).
// An integrator drives it one vertex at a time:
//
//     SubpathWalk walk(scene, mode, lambda, sampler, scratch, rays);
//     walk.start(ray, medium, beta);
//     while (walk.advance() == WalkEvent::Vertex) {
//         ... the integrator's strategies at walk.vertex() ...
//         std::optional<WalkScatter> s = walk.scatter();
//         ... its MIS bookkeeping with s's densities; walk.jump() if s->profile ...
//     }
//
// and owns only what it does at each vertex: next-event estimation, connections, merges,
// photons, its MIS quantities and its path-length rule. Each call draws the sampler dimensions
// that the integrators drew before they shared the walk, in the same order.
#pragma once

#include "geometry/interaction.h"
#include "geometry/ray.h"
#include "integrators/common/path_segment.h"
#include "integrators/common/scattering_point.h"
#include "integrators/common/stored_scattering_point.h"
#include "materials/bsdf.h"
#include "spectral/sampled_spectrum.h"
#include "spectral/sampled_wavelengths.h"

#include <cstdint>
#include <optional>

namespace caustica {

class ProfileSubsurfaceMaterial;
class Material;
class Medium;
class Sampler;
class Scene;
class ScratchBuffer;

enum class WalkEvent {
    Vertex,  // the path reached a scattering vertex (a surface or a medium event), or an emitter
    Escaped, // the ray left the scene (environment lights may be seen along walk.ray())
    Ended,   // the throughput became zero
};

// How the path left a vertex.
struct WalkScatter {
    Vec3f wi;
    // Solid-angle densities at the vertex: of sampling wi (the BSDF's density when the sample's
    // own is only proportional to it), and, when the walk keeps reverse densities, of sampling
    // the direction the path arrived from, starting from wi, in the adjoint mode. Medium vertices:
    // the phase function's value, both ways (it is sampled exactly, and symmetric).
    float pdf_fwd = 0, pdf_rev = 0;
    float cos_out = 1;        // |wi . ng|, the area conversion at this end; 1 in a medium
    bool specular = false;    // a delta lobe: the densities are deltas, equal both ways
    // The sample enters a profile-subsurface solid: the path has not moved, and the integrator
    // calls jump() to reach the exit (after its own bookkeeping at the entry).
    const ProfileSubsurfaceMaterial *profile = nullptr;
};

class SubpathWalk {
  public:
    // Radiance: a camera subpath; Importance: a light subpath. reverse_densities: fill
    // WalkScatter::pdf_rev (bidirectional MIS needs it; a path tracer does not).
    SubpathWalk(const Scene &scene, TransportMode mode, SampledWavelengths &lambda, Sampler &sampler,
                ScratchBuffer &bsdf_memory, uint64_t &rays, bool reverse_densities);

    // Lets the walk re-radiate at fluorescent surfaces (reradiation.h). Without it, the
    // re-radiated share of such a surface's scattering absorbs the path, consistently with the
    // elastic lobe's densities: the light subpaths of the integrators that join subpaths, whose
    // camera subpaths gather the re-radiated light alone (path_tracing.h).
    void allow_reradiation();

    // pbrt-v4's "regularize": once the path has scattered non-specularly (off a surface's
    // non-delta lobe, in a medium, or through a subsurface profile), each BSDF it meets has its
    // microfacet lobes widened (BSDF::regularize) before it is used, for next-event estimation
    // and connections as for sampling.
    void regularize_after_non_specular_bounces() { regularize_ = true; }

    // The path leaves along ray, in medium, carrying beta. A camera ray's differential gives the
    // texture footprint at the first surface it reaches (camera/camera_footprint.h); every other
    // vertex takes the camera's approximate footprint.
    void start(const Ray &ray, const Medium *medium, const SampledSpectrum &beta,
               const std::optional<RayDifferential> &differential = std::nullopt);

    // Follows the ray to the next vertex: a medium scattering event, or a surface that scatters
    // or emits. Surfaces that do neither are crossed.
    WalkEvent advance();
    // Radiance subpaths: the emission of emissive media that the last advance() collected, times
    // the throughput (a collision estimator: counted where the medium scatters or absorbs the
    // path, so it is there even when advance() returned Ended because the collision absorbed).
    // Zero for importance subpaths. bdpt, vcm and bpm weigh it against their light subpaths that
    // start at the collision; pt and sppm count it in full.
    const SampledSpectrum &emitted() const { return emitted_; }
    // Where that emission was collected: the collision, which may also be the vertex reached.
    Vec3f emission_point() const { return emission_point_; }

    // The vertex reached (after advance() returned Vertex). At a surface, hit() is the
    // intersection and vertex().bsdf may be null when the surface only emits.
    const ScatteringPoint &vertex() const { return point_; }
    const SurfaceInteraction &hit() const { return si_; }
    bool in_medium() const { return point_.in_medium(); }
    // Where the current segment began: the previous vertex, or the start.
    Vec3f origin() const { return previous_p_; }
    // Squared distance from origin() to this vertex.
    float distance_squared() const { return length_squared(point_.p - previous_p_); }
    // This vertex is the exit of a jump through a profile solid (entered at the one before).
    bool after_jump() const { return after_jump_; }
    // The vertex in compact form, before scatter() moves on: a medium point, or a surface point
    // with a BSDF. Its medium must outlive the record: a walk whose records are kept past the
    // BSDFs' memory makes the media it meets there in `memory` (keep_media_in).
    StoredScatteringPoint stored_vertex() const;
    // Media that the walk makes at the surfaces it enters (a random walk's interior under a
    // textured colour) go to `memory` instead of the BSDFs' memory.
    void keep_media_in(ScratchBuffer &memory) { media_memory_ = &memory; }
    // A vertex that stored_vertex() gave, with its BSDF shaded again (in `memory`) as advance()
    // or jump() shaded it, for the wavelengths it had then. Only `time` and the sampler's
    // samples_per_pixel (the camera's footprint at the point) are not in the record, as every
    // vertex of a subpath shares them.
    static ScatteringPoint rebuild(const Scene &scene, const StoredScatteringPoint &stored,
                                   const SampledWavelengths &lambda, float time, ScratchBuffer &memory,
                                   int samples_per_pixel);

    // Samples how the path leaves the vertex and moves it onto that ray; empty when the path
    // ends here (no sample). A vertex after a jump samples its exit lobe.
    std::optional<WalkScatter> scatter();
    // Continues through a surface that emits but does not scatter (vertex().bsdf null).
    void pass_through();
    // The rest of a profile event that scatter() began: samples the exit and makes it the
    // vertex (after_jump()); false when the profile finds no exit or the throughput vanishes.
    bool jump(const ProfileSubsurfaceMaterial &profile);

    // Russian roulette once `depth` scattering vertices lie behind (from the second on), on the
    // throughput with the radiance-mode 1/eta^2 undone (importance has none); false when the path
    // ends.
    bool russian_roulette(int depth);

    // The wavelengths the path carries now: the caller's, until a re-radiation moves every lane
    // to one new wavelength. For a light subpath the caller's set itself is moved (keeping each
    // lane's density, SampledWavelengths::shift_to), so that its splats land at the new
    // wavelength; a camera subpath leaves the caller's set, the film's, as it was, and lane j's
    // throughput then holds what reaches the film's wavelength j from light at lambda().
    const SampledWavelengths &lambda() const { return shifted_ ? shifted_lambda_ : lambda_; }
    bool reradiated() const { return shifted_; }

    const Ray &ray() const { return ray_; }
    const Medium *medium() const { return medium_; }
    SampledSpectrum beta;

  private:
    // The BSDF at a surface hit (null where it has no material): with its texture footprint,
    // from the ray's differential if any, else from the camera's footprint when the scene
    // reads one.
    static BSDF surface_bsdf(const Scene &scene, SurfaceInteraction &si, const RayDifferential *differential,
                             const SampledWavelengths &lambda, ScratchBuffer &memory, ScratchBuffer *media_memory,
                             int samples_per_pixel);
    void leave(const SurfaceInteraction &from, Vec3f wi);
    // The re-radiated part of a fluorescent vertex's scattering, chosen by scatter().
    std::optional<WalkScatter> reradiate(const Reradiation &reradiation, Vec3f wo);

    const Scene &scene_;
    TransportMode mode_;
    SampledWavelengths &lambda_;
    Sampler &sampler_;
    ScratchBuffer &bsdf_memory_;
    ScratchBuffer *media_memory_ = nullptr; // keep_media_in()
    uint64_t &rays_;
    bool reverse_densities_;

    Ray ray_;
    std::optional<RayDifferential> differential_;
    const Medium *medium_ = nullptr;
    const Material *absorbing_interior_ = nullptr;
    SpectralMIS spectral_mis_;
    SampledSpectrum emitted_{0.f};
    Vec3f emission_point_;
    SurfaceInteraction si_;
    ScatteringPoint point_;
    Vec3f previous_p_;
    bool after_jump_ = false;
    bool regularized_ = false; // the vertex's BSDF
    // Product of eta^2 over the radiance-mode refractions (1 for importance).
    float eta_scale_ = 1;
    bool reradiation_allowed_ = false;
    bool regularize_ = false, any_non_specular_bounce_ = false;
    // After a re-radiation, every lane carries one wavelength (lambda()).
    bool shifted_ = false;
    SampledWavelengths shifted_lambda_;
};

} // namespace caustica
