// What a light subpath leaves behind for the camera pass of an iteration (SmallVCM's light
// vertex):
//
// - LightVertex: a full scattering vertex, with its BSDF, for vertex connection (a camera vertex
//   is joined to every vertex of the light path traced for its pixel).
// - StoredLightVertex ("lightvertices" "store", vcm's default): each light vertex kept through
//   the iteration once, in its group's photon map, where merging reads it as a photon and its
//   pixel's camera path finds it by identity (PhotonMap::by_id) and shades it again
//   (SubpathWalk::rebuild) from its point, its direction and its hit, the last two rounded
//   (about 1e-4 radians, and 2^-17 in (u, v)): connections to it differ from connections to the
//   vertex as traced by that much.
// - Photon: all that merging reads, for bpm and "retrace" (which traces a pixel's light path
//   again for its connections): 32 bytes, 44 with its position in the photon map. Its direction
//   is rounded as a StoredLightVertex's, so the two merge alike.
//
// All carry the recursive MIS quantities of Georgiev et al. 2012 ("Implementing vertex
// connection and merging", tech. report, section 5) at their vertex: see vcm_mis.h. Vertices
// inside participating media are stored too, flagged as such: they are connected like surface
// vertices, and their photons go to separate photon maps, gathered only at camera vertices in a
// medium (within a sphere, not a disk).
#pragma once

#include "core/octahedral.h"
#include "geometry/embree_scene.h"
#include "integrators/common/photon_side.h"
#include "integrators/common/scattering_point.h"
#include "integrators/common/stored_scattering_point.h"
#include "spectral/sampled_spectrum.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>

namespace caustica {

struct LightVertex {
    SampledSpectrum beta;  // light subpath throughput, emitted flux included (first: its 16-byte
                           // alignment would otherwise pad the record)
    ScatteringPoint point; // bsdf in the iteration's scratch memory
    float d_vcm, d_vc;
    uint16_t path_length;  // segments from the light to this vertex
    bool secondary_terminated;
    // The exit of a jump through a profile solid (vcm_mis.h): connected, never merged at, and
    // the density of reaching its predecessor from it is the jump's, 1.
    bool after_jump = false;
    // The start of a light path in an emissive medium (medium_emission.h): joined to camera
    // vertices by its own strategy (beta is the emission over the start's density), never
    // merged at, never joined to the lens; path_length 1, as it counts as a scattering event.
    bool medium_start = false;
};

struct Photon {
    // As LightVertex::beta, unaligned (SampledSpectrum's 16-byte alignment would pad the
    // record).
    std::array<float, NumWavelengths> beta_values;
    float d_vcm, d_vc;
    uint32_t wo;           // octahedral-encoded direction towards the previous vertex
    // Octahedral-encoded geometric normal, coarsely: merging only gathers photons that lie on a
    // surface oriented like the camera vertex's, within 60 degrees (see photon_side.h). Unused
    // for a photon in a medium (photons in media are kept in maps of their own).
    uint16_t normal;
    uint16_t path_length : 15; // at most "maxdepth", which StoredLightVertex::MaxPathLength bounds
    uint16_t secondary_terminated : 1;

    static constexpr int MaxPathLength = (1 << 15) - 1;
    SampledSpectrum beta() const { return {beta_values[0], beta_values[1], beta_values[2], beta_values[3]}; }
    Vec3f towards_previous() const { return decode_octahedral(wo); }
    bool merges() const { return true; }
};

// A LightVertex through the iteration, in 44 bytes, 60 with its point and identity in the photon
// map: its photon, and its StoredScatteringPoint packed. The direction is octahedral-encoded as
// a photon's; the hit is packed (GeometryScene::pack), or, at a point in a medium, its 8 bytes
// after the shape hold the medium's address. The start of a light path in a medium and the exit
// of a jump are kept too, for connections, though they are not merged at (merges()).
struct StoredLightVertex {
    // The photon's throughput, over sigma_s at a point in a medium (add_photons says why); a
    // start in a medium keeps its own.
    std::array<float, NumWavelengths> beta_values;
    float d_vcm, d_vc;
    uint32_t wo;            // octahedral-encoded, as Photon::wo
    PackedSurfaceHit where; // shape None at a point in a medium, its medium after it
    uint16_t normal;        // as Photon::normal
    uint16_t path_length : 13;
    uint16_t secondary_terminated : 1;
    // On a surface: Plain, AfterJump (the exit of a jump, its BSDF the exit lobe) or
    // Regularized; in a medium: Plain or MediumStart.
    uint16_t kind : 2;
    enum Kind : uint16_t { Plain, AfterJump, Regularized, MediumStart = AfterJump };

    // vcm's "maxdepth" is at most this.
    static constexpr int MaxPathLength = (1 << 13) - 1;

    StoredLightVertex() = default;
    // Requires geometry.packs_hits().
    StoredLightVertex(const LightVertex &v, const SampledSpectrum &photon_beta, const StoredScatteringPoint &stored,
                      const GeometryScene &geometry)
        : beta_values{photon_beta[0], photon_beta[1], photon_beta[2], photon_beta[3]}, d_vcm(v.d_vcm), d_vc(v.d_vc),
          wo(encode_octahedral(stored.wo)), normal(v.point.in_medium() ? uint16_t(0) : encode_octahedral_coarse(v.point.ng)),
          path_length(v.path_length), secondary_terminated(v.secondary_terminated) {
        if (stored.in_medium()) {
            static_assert(sizeof(stored.medium) == sizeof(where) - offsetof(PackedSurfaceHit, primitive));
            std::memcpy(&where.primitive, &stored.medium, sizeof(stored.medium));
            kind = v.medium_start ? MediumStart : Plain;
        } else {
            where = geometry.pack(stored.hit);
            kind = stored.exit_lobe ? AfterJump : stored.regularized ? Regularized : Plain;
        }
    }

    SampledSpectrum beta() const { return {beta_values[0], beta_values[1], beta_values[2], beta_values[3]}; }
    Vec3f towards_previous() const { return decode_octahedral(wo); }
    bool in_medium() const { return where.shape == SurfaceHit::None; }
    bool after_jump() const { return !in_medium() && kind == AfterJump; }
    bool medium_start() const { return in_medium() && kind == MediumStart; }
    bool merges() const { return kind != AfterJump; } // neither an exit of a jump nor a start in a medium
    // The point, found at p.
    StoredScatteringPoint point(Vec3f p, const GeometryScene &geometry) const {
        if (in_medium()) {
            const Medium *medium;
            std::memcpy(&medium, &where.primitive, sizeof(medium));
            return {p, towards_previous(), SurfaceHit{}, false, false, medium};
        }
        return {p, towards_previous(), geometry.unpack(where), kind == AfterJump, kind == Regularized, nullptr};
    }
    // The vertex with its point rebuilt, and beta its throughput.
    LightVertex with(const ScatteringPoint &rebuilt, const SampledSpectrum &beta) const {
        LightVertex v{beta, rebuilt, d_vcm, d_vc, uint16_t(path_length), secondary_terminated != 0, after_jump()};
        v.medium_start = medium_start();
        return v;
    }
};

static_assert(sizeof(Photon) == 32, "photons are kept compact: see the comment above");
static_assert(sizeof(StoredLightVertex) == 44, "vcm keeps one for every light vertex of an iteration, unpadded");

} // namespace caustica
