// What pbrt-v4's coated materials ("coateddiffuse", "coatedconductor") share: a dielectric coat
// over a base, with a scattering slab between them (layered_bxdf.h), and the parameters that
// describe it.
#pragma once

#include "materials/layered_bxdf.h"
#include "materials/microfacet_roughness.h"
#include "spectral/spectrum.h"

namespace caustica {

class ScratchBuffer;
class SampledWavelengths;
struct TextureEvalContext;

struct Coating {
    static constexpr float MaxAsymmetry = 0.999f;

    SpectrumPtr eta;                 // index of the coat relative to the outside
    MicrofacetRoughness roughness;   // of the coat's surface
    FloatTexturePtr thickness, g;
    SpectrumTexturePtr albedo;
    int max_depth = 10, n_samples = 1;

    // The coat's index for these wavelengths: the hero's, for every lane (pbrt-v4 gives the
    // coat one index; see layered_bxdf.h on dispersion). An index of 0 means none: 1.
    float hero_eta(const SampledWavelengths &lambda) const;
    bool is_dispersive() const { return !eta->is_constant(); }
    // The coat over base, in scratch.
    const LayeredBxDF *over(const BxDF *base, const TextureEvalContext &ctx, const SampledWavelengths &lambda,
                            ScratchBuffer &scratch) const;
    bool may_be_smooth() const { return roughness.may_be_smooth(); }
    bool may_focus_light() const { return roughness.may_focus_light(); }
    // A slab with a non-zero albedo scatters diffusely; conservatively true for a textured albedo.
    bool may_scatter() const;
    bool is_wavelength_independent() const { return is_flat(*eta) && albedo->is_wavelength_independent(); }
};

} // namespace caustica
