// The "disney" material: Burley 2015's Disney BSDF (disney_bxdf.h) with every parameter a value
// or a texture. docs/disney.md lists the parameters, their defaults and the model's choices.
//
// Solids may have Beer-Lambert absorption inside ("transmittance" at "atDistance", as the
// dielectric material), which integrators apply to paths that refracted in. A solid with a
// non-zero "scatterDistance" has subsurface scattering (Burley 2015, sections 2.4 and 2.5), by
// one of three models ("string subsurface"):
//   - "randomwalk" (default): path-traced. The interior is a homogeneous medium, isotropic,
//     whose single-scattering albedo makes the surface reflect baseColor (random_walk_albedo.h)
//     and whose mean free path gives the walk the spread of the normalised diffusion profile
//     with d = scatterDistance; the BxDF's Lambertian part becomes the crossing into it
//     (disney_bxdf.h). The interior absorption, if any, adds to the medium's. The volume is one
//     per object, so baseColor and scatterDistance must then be constants.
//   - "diffusion": a separable BSSRDF with Burley's normalised diffusion profile
//     (normalized_diffusion.h), albedo baseColor at the entry point, d = scatterDistance.
//   - "dipole": the same with Jensen et al. 2001's dipole (dipole_profile.h), whose coefficients
//     come either from (baseColor, scatterDistance), chosen so that the dipole reflects
//     baseColor with the spread of the normalised profile of the same d, or from a measured
//     medium of Jensen's table ("string preset", in mm^-1, times "float scale").
//   - "beamdiffusion": the same with the photon beam diffusion profile of Habel et al. 2013
//     (photon_beam_diffusion.h, pbrt-v4's "subsurface" material's), whose coefficients come
//     either from (baseColor, scatterDistance), the single-scattering albedo whose profile
//     reflects baseColor and the mean free path d s(A) (as for the dipole), or from a preset.
// For the profile models the separable BSSRDF is
//     S(x_o, w_o; x_i, w_i) = w (1 - F(w_i) / 2) R(|x_o - x_i|) (1 - F(w_o) / 2) / pi,
// the crossing's entering share, the profile (which integrates to its albedo) and the exit lobe
// (DisneySubsurfaceExitBxDF); as the scatter distance vanishes it is eq. 4's Lambertian part.
// The path tracer alone renders it (integrators/pt: it samples the exit point with probe rays).
#pragma once

#include "core/error.h"
#include "materials/dipole_profile.h"
#include "materials/disney_bxdf.h"
#include "materials/photon_beam_diffusion.h"
#include "materials/profile_subsurface_material.h"
#include "materials/thin_film.h"
#include "materials/normalized_diffusion.h"
#include "media/medium.h"
#include "spectral/spectrum.h"
#include "textures/texture.h"

#include <algorithm>
#include <variant>

namespace caustica {

class ParameterDictionary;

struct DisneyTextures {
    SpectrumTexturePtr base_color;
    FloatTexturePtr metallic, roughness, anisotropic, specular_tint, sheen, sheen_tint, clearcoat,
        clearcoat_gloss, spec_trans;
    // Thin surfaces only (null for solids).
    FloatTexturePtr diff_trans, flatness;
    // Caustica's interference film ("filmthickness", "filmeta") on the specular lobes.
    FilmLayer film;
};

enum class SubsurfaceModel { RandomWalk, Diffusion, Dipole, BeamDiffusion };

// A solid's subsurface scattering; `enabled` false (the default) for none.
struct DisneySubsurface {
    bool enabled = false;
    SubsurfaceModel model = SubsurfaceModel::RandomWalk;
    // Random walk: the interior volume, or null when baseColor or scatterDistance is a texture;
    // then each entry point gets its own (DisneyMaterial::interior_medium), with walk_absorption (the solid's
    // Beer-Lambert absorption, or null) added.
    MediumPtr medium;
    SpectrumPtr walk_absorption;
    // Random walk, diffusion, and dipole without a preset: d per wavelength, a value or a texture.
    SpectrumTexturePtr scatter_distance;
    // Dipole or beam diffusion with a preset: the measured coefficients (mm^-1) and the scene
    // units' conversion.
    SpectrumPtr sigma_a, sigma_s_reduced;
    // Beam diffusion: the profile's table, for g = 0 and the solid's index.
    std::shared_ptr<const BeamDiffusionTable> beam_table;
    float scale = 1;
    // Profile models: the strength of the cavity fade (see DisneyMaterial::cavity_fade).
    float cavity_fade = 0;
};

// The profile of a diffusion or dipole solid for light entering at one point.
using DisneySubsurfaceProfile = std::variant<NormalizedDiffusionProfile, DipoleProfile, BeamDiffusionProfile>;
inline const SubsurfaceProfile &as_profile(const DisneySubsurfaceProfile &profile) {
    return std::visit([](const auto &p) -> const SubsurfaceProfile & { return p; }, profile);
}

class DisneyMaterial final : public ProfileSubsurfaceMaterial {
  public:
    // eta: index of the inside relative to the outside (a constant or a dispersion curve).
    // sigma_a: interior absorption per unit length, or null (always null for thin surfaces).
    DisneyMaterial(DisneyTextures textures, SpectrumPtr eta, bool thin, SpectrumPtr sigma_a,
                   DisneySubsurface subsurface);

    BSDF get_bsdf(const SurfaceInteraction &si, const SampledWavelengths &lambda,
                  ScratchBuffer &scratch) const override;
    bool is_dispersive() const override { return dispersive_; }
    bool has_specular_lobe() const override { return specular_; }
    bool forms_caustics() const override { return focuses_; }
    SampledSpectrum interior_sigma_a(const SampledWavelengths &lambda) const override {
        return sigma_a_ ? sigma_a_->sample(lambda) : SampledSpectrum();
    }
    bool has_interior_absorption() const override { return sigma_a_ != nullptr; }
    bool is_wavelength_independent() const override;
    bool has_subsurface() const override { return subsurface_.enabled; }
    bool has_interior_medium() const override {
        return subsurface_.enabled && subsurface_.model == SubsurfaceModel::RandomWalk;
    }
    const Medium *interior_medium() const override { return subsurface_.medium.get(); }
    // With a textured baseColor or scatterDistance, the random walk's volume for a path entering
    // at si: the coefficients of the base colour and scatter distance there, kept for the whole
    // walk (as Cycles does; the volume is not resampled as the walk moves under other colours).
    const Medium *interior_medium(const SurfaceInteraction &si, const SampledWavelengths &lambda,
                                  ScratchBuffer &scratch) const override;

    SubsurfaceModel subsurface_model() const { return subsurface_.model; }
    // Subsurface scattering by a profile (diffusion or dipole), a BSSRDF (profile_subsurface.h).
    bool has_profile_subsurface() const override {
        return subsurface_.enabled && subsurface_.model != SubsurfaceModel::RandomWalk;
    }
    // For profile subsurface: the profile of light entering at si, and the BSDF of its exit lobe
    // at a point where it leaves (wo must point inside there).
    DisneySubsurfaceProfile subsurface_profile(const SurfaceInteraction &si, const SampledWavelengths &lambda) const;
    const SubsurfaceProfile &entry_profile(const SurfaceInteraction &si, const SampledWavelengths &lambda,
                                           ScratchBuffer &scratch) const override {
        return as_profile(*scratch.make<DisneySubsurfaceProfile>(subsurface_profile(si, lambda)));
    }
    BSDF subsurface_exit_bsdf(const SurfaceInteraction &si, ScratchBuffer &scratch) const override;
    // Burley 2015, section 2.4 and Figure 12: a profile is the answer for a flat half-space and
    // overestimates what crosses a cavity between surfaces that face each other, so the notes
    // fade the diffusion result "as the surfaces become opposing", by the angle between the
    // entry's and the exit's (outward) normals. The factor is
    //     1 - cavityFade * max(0, -n_entry . n_exit):
    // 1 wherever the normals are within 90 degrees of each other (flat and convex geometry are
    // untouched), falling linearly to 1 - cavityFade for exactly opposed ones. On a thin sheet
    // the half-space profile, applied to both faces, reflects up to twice its albedo; a full
    // fade brings it back to what a half-space reflects (tested), but it also removes the light
    // a thin part really transmits (ears, fingers), which has no other path here. So it is an
    // artist's control, off by default (cavityFade 0); the random walk needs no fade.
    float cavity_fade(Vec3f entry_normal, Vec3f exit_normal) const override {
        return 1 - subsurface_.cavity_fade * std::clamp(-dot(entry_normal, exit_normal), 0.f, 1.f);
    }

    bool is_thin() const { return thin_; }
    // The BxDF's inputs at a point: textures evaluated and clamped to their ranges.
    DisneyParameters parameters(const TextureEvalContext &ctx, const SampledWavelengths &lambda) const;

  private:
    DisneyTextures textures_;
    SpectrumPtr eta_;
    float reference_eta_;
    bool thin_;
    SpectrumPtr sigma_a_;
    DisneySubsurface subsurface_;
    // Profile models: no channel's scatter distance goes below this (see subsurface_profile);
    // negative for a textured scatter distance, whose floor is set per point.
    float min_scatter_distance_ = 0;
    // The base colour's luminance when the base colour is a constant (else negative: computed
    // per point, and only when a tint needs it).
    float constant_luminance_ = -1;
    bool dispersive_ = false, specular_ = false;
    bool focuses_ = false; // forms_caustics()
};

// The coefficients of Jensen's dipole that reflects `albedo` (its total diffuse reflectance R_d is
// the albedo) with the mean free path of the normalised diffusion profile of scatter distance d,
// 1 / sigma_t' = d s(A) (Christensen and Burley's diffuse-transmission fit, as for the random
// walk), for a boundary of relative index eta >= 1. Per wavelength.
struct DipoleCoefficients {
    SampledSpectrum sigma_a, sigma_s_reduced;
};
DipoleCoefficients dipole_coefficients(const SampledSpectrum &albedo, const SampledSpectrum &scatter_distance,
                                       float eta);
// Jensen et al. 2001's total diffuse reflectance of the dipole for reduced albedo alpha' and
// relative index eta, and its inverse (alpha' for a reflectance in [0, 1]).
float dipole_diffuse_reflectance(float reduced_albedo, float eta);
float dipole_reduced_albedo(float reflectance, float eta);

// The random-walk interior for baseColor `albedo` and `scatter_distance` (both reflectances /
// lengths per wavelength), with the solid's Beer-Lambert absorption (or null) added.
MediumPtr create_random_walk_medium(SpectrumPtr albedo, SpectrumPtr scatter_distance, SpectrumPtr interior_sigma_a);

// Reads the "disney" parameters (see docs/disney.md). The index of refraction and the interior
// absorption are read by the material factory, as for "dielectric" (so "eta" may be a float, a
// named glass or any spectrum, or Sellmeier/Cauchy coefficients), and so is the film. Throws
// InputError at a parameter whose constant value is out of range.
MaterialPtr create_disney_material(const ParameterDictionary &params, const NamedTextures &textures,
                                   SpectrumPtr eta, SpectrumPtr interior_sigma_a, FilmLayer film);

} // namespace caustica
