// What a light subpath leaves behind for the camera pass of an iteration (SmallVCM's light
// vertex, split in two by use):
//
// - LightVertex: a full scattering vertex, with its BSDF, for vertex connection (a camera vertex
//   is joined to every vertex of the light path traced for its pixel). It is kept through the
//   iteration as a StoredLightVertex, without its BSDF, and rebuilt when its pixel's camera path
//   is traced (SubpathWalk::rebuild): value for value as it was on triangles and bilinear
//   patches, to rounding on analytic shapes and curves (GeometryScene::interaction).
// - Photon: the compact record gathered by vertex merging, read in bulk by range queries, so it
//   is kept small: 32 bytes, 44 with its position in the photon map (spatial/photon_map.h).
//
// Both carry the recursive MIS quantities of Georgiev et al. 2012 ("Implementing vertex
// connection and merging", tech. report, section 5) at their vertex: see vcm_mis.h. Vertices
// inside participating media are stored too, flagged as such: they are connected like surface
// vertices, and their photons go to separate photon maps, gathered only at camera vertices in a
// medium (within a sphere, not a disk).
#pragma once

#include "core/octahedral.h"
#include "integrators/common/photon_side.h"
#include "integrators/common/scattering_point.h"
#include "integrators/common/stored_scattering_point.h"
#include "spectral/sampled_spectrum.h"

#include <array>
#include <cstdint>

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
    uint16_t path_length : 15; // vcm's "maxdepth" is at most MaxPathLength
    uint16_t secondary_terminated : 1;

    static constexpr int MaxPathLength = (1 << 15) - 1;
    SampledSpectrum beta() const { return {beta_values[0], beta_values[1], beta_values[2], beta_values[3]}; }
};

// A LightVertex through the iteration: its point without the BSDF, and the rest as it was.
struct StoredLightVertex {
    // As LightVertex::beta, unaligned (see Photon).
    std::array<float, NumWavelengths> beta_values;
    float d_vcm, d_vc;
    uint16_t path_length;
    bool secondary_terminated, after_jump, medium_start;
    StoredScatteringPoint point;

    StoredLightVertex() = default;
    StoredLightVertex(const LightVertex &v, const StoredScatteringPoint &stored)
        : beta_values{v.beta[0], v.beta[1], v.beta[2], v.beta[3]}, d_vcm(v.d_vcm), d_vc(v.d_vc),
          path_length(v.path_length), secondary_terminated(v.secondary_terminated), after_jump(v.after_jump),
          medium_start(v.medium_start), point(stored) {}
    // The vertex with its point rebuilt.
    LightVertex with(const ScatteringPoint &rebuilt) const {
        return LightVertex{{beta_values[0], beta_values[1], beta_values[2], beta_values[3]},
                           rebuilt, d_vcm, d_vc, path_length, secondary_terminated, after_jump, medium_start};
    }
};

static_assert(sizeof(Photon) == 32, "photons are kept compact: see the comment above");
static_assert(sizeof(StoredLightVertex) <= 96, "vcm keeps one for every light vertex of an iteration");

} // namespace caustica
