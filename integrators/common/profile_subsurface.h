// Profile subsurface scattering (a separable BSSRDF, pbrt-v3 section 15.4: the Disney material's
// normalized diffusion and dipole models, pbrt-v4's "subsurface"; profile_subsurface_material.h)
// as a path meets it, from either end. Light that a BSDF
// sample sends into such a solid from outside leaves it at a point sampled by probe rays against
// the profile (subsurface_probe.h) and continues through the exit lobe there.
//
// The BSSRDF w (1 - F_in / 2) R(r) (1 - F_out / 2) / pi (docs/disney.md) is symmetric in its two
// ends, so camera paths (pt, bdpt, sppm, bpm, vcm) and light paths (lt, bdpt, the photon
// integrators') use the same pieces in the same order: the entry event (DisneyBxDF's discrete
// crossing, f |cos| / pdf carrying w (1 - F / 2) of the direction the path came from), the
// profile's weight R / pdf at the sampled exit, and the exit lobe towards the direction the path
// leaves in. Entry and exit are one scattering event for maxdepth, as the BRDF they converge to
// is.
#pragma once

#include "geometry/interaction.h"
#include "materials/bsdf.h"
#include "spectral/sampled_spectrum.h"

#include <cstdint>
#include <optional>

namespace caustica {

class ProfileSubsurfaceMaterial;
class Sampler;
class ScratchBuffer;
class Scene;
class SampledWavelengths;

// The material whose profile subsurface the BSDF sample bs, taken at si, enters, or null.
// The material's BSDF samples that entry from outside as its only diffuse transmission
// (disney_bxdf.h, subsurface_entry_bxdf.h); a random walk's crossing looks the same but leads
// into the interior medium.
const ProfileSubsurfaceMaterial *profile_entry(const SurfaceInteraction &si, const BSDFSample &bs);

struct ProfileExit {
    SurfaceInteraction si;  // the exit point; its wo is -n, as the light arrives through the interior
    BSDF bsdf;              // the exit lobe there
    SampledSpectrum weight; // R(r) / pdf of the exit, times the material's cavity fade
};

// Samples where the light entering at `entry` leaves (three sampler dimensions, one probe ray
// counted in `rays`); empty when the probe finds no exit (a zero-valued sample). The exit lobe's
// BxDF lives in `scratch`.
std::optional<ProfileExit> sample_profile_exit(const Scene &scene, const ProfileSubsurfaceMaterial &material,
                                               const SurfaceInteraction &entry, const SampledWavelengths &lambda,
                                               Sampler &sampler, ScratchBuffer &scratch, uint64_t &rays);

// The solid-angle density with which the exit lobe at `entry` would sample entry.wo: what a walk
// from the other end, jumping to this point, would take to leave it towards where this path came
// from. Bidirectional MIS needs it as the reverse density at an entry.
float profile_exit_density(const ProfileSubsurfaceMaterial &material, const SurfaceInteraction &entry, ScratchBuffer &scratch);

} // namespace caustica
