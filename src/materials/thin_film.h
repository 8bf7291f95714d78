// Thin-film interference: a transparent film of index n_f and thickness d on an interface, as
// on soap bubbles, oil on water, anti-reflection coatings and tempered steel. Light reflected at
// the film's top and at its base interferes with itself; summing the film's multiple
// reflections (the Airy summation, Born and Wolf, "Principles of Optics", section 7.6.1) gives
// the amplitudes
//   r = (r12 + r23 e^{2 i delta}) / (1 + r12 r23 e^{2 i delta}),
//   t = t12 t23 e^{i delta} / (1 + r12 r23 e^{2 i delta}),  delta = (2 pi / lambda) n_f d cos theta_f,
// with r_ij, t_ij the Fresnel amplitudes of each interface, for s and p polarisation; R = |r|^2
// and T = Re(n3 cos theta3) / (n1 cos theta1) |t|^2 are averaged over the two (unpolarised
// light). A complex base index (a metal) brings its phase shift through r23. Per wavelength this
// is exact, as a spectral renderer can afford (Belcour and Barla 2017 derive the same terms and
// then integrate them over RGB bands, which Caustica need not do).
//
// Indices are relative to the medium the light arrives from (n1 = 1).
#pragma once

#include "spectral/sampled_spectrum.h"
#include "spectral/sampled_wavelengths.h"
#include "spectral/spectrum.h"
#include "textures/texture.h"

#include <complex>

namespace caustica {

struct FilmResponse {
    float reflectance = 0, transmittance = 0;
};

// For light arriving with cosine cos_i > 0 (clamped to [0, 1]) at wavelength lambda_nm. The
// transmittance is into a non-absorbing base (0 for a metal, whose absorption takes the rest).
// A thickness of 0 is the bare interface.
FilmResponse thin_film_response(float cos_i, float film_eta, std::complex<float> base_eta,
                                float thickness_nm, float lambda_nm);

// A film over a surface, at the wavelengths a path carries; no film when thickness_nm is 0.
struct ThinFilm {
    float thickness_nm = 0;
    SampledSpectrum eta;  // the film's index per wavelength
    SampledSpectrum lambda;  // the wavelengths, nm
    bool present() const { return thickness_nm > 0; }
    // Reflectance over a metal of complex index eta + i k, per wavelength.
    SampledSpectrum over_conductor(float cos_i, const SampledSpectrum &base_eta, const SampledSpectrum &k) const;
    // Reflectance of wavelength `lane` over a dielectric of relative index base_eta, for light
    // meeting it with cosine cos_d: from outside (cos_d > 0) or from inside the dielectric
    // (cos_d < 0, total internal reflection included). The film is lossless, so the rest is
    // transmitted.
    float over_dielectric(float cos_d, float base_eta, int lane) const;
};

// A thin film over a surface (above), as materials declare it: "filmthickness" in nm (a
// float texture; 0, the default, is no film) and "filmeta" (the film's index, default 1.33).
struct FilmLayer {
    FloatTexturePtr thickness;
    SpectrumPtr eta;
    // The film at a surface point for the path's wavelengths (absent where the thickness is 0).
    ThinFilm at(const TextureEvalContext &ctx, const SampledWavelengths &lambda) const;
    bool may_be_present() const;
};

} // namespace caustica
