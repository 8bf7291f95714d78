// A fluorophore: a dye that absorbs light at one wavelength and re-emits part of it at a longer
// one (fluorescent inks, fluorescein, optical brighteners in paper, highlighters).
//
// The model is absorption times an emission spectrum (Kasha's rule: the emission spectrum does
// not depend on the wavelength that excited it), not a general re-radiation matrix (Mojzik et
// al. 2018 and Jung et al. 2019 describe both). A separable model is what the users' data is:
// a dye's absorption and emission spectra and its quantum yield are what is measured and
// published, while a full excitation-emission matrix is rarely available. It also lets both
// transport directions sample the new wavelength exactly: a camera path draws the wavelength
// that was absorbed from the absorption spectrum, a light path the one emitted from the
// emission spectrum. For light absorbed at lambda_i and re-emitted at lambda_o, the re-radiated
// part of the BRDF is
//
//     f(lambda_i -> lambda_o) = a(lambda_i) Q e(lambda_o) (lambda_i / lambda_o) [lambda_i <= lambda_o] / pi
//
// per nm of lambda_i, with a the absorbed fraction, Q the quantum yield (photons emitted per
// photon absorbed), e the emission spectrum normalised to unit area over the sampled range, and
// lambda_i / lambda_o the energy each photon loses (radiance carries energy, Q counts photons).
// Emission at wavelengths shorter than the excitation (anti-Stokes) is left out, so no more
// energy leaves than Q times the energy absorbed. The emission is Lambertian, unpolarised and
// instantaneous.
#pragma once

#include "core/sampling.h"
#include "materials/bxdf.h"
#include "spectral/sampled_wavelengths.h"
#include "spectral/spectrum.h"

#include <functional>
#include <vector>

namespace caustica {

class Fluorophore {
  public:
    // absorption: the fraction absorbed by the dye, in [0, 1]; emission: the shape of the
    // re-emitted spectrum (any positive scale); quantum_yield in [0, 1]. Throws
    // std::invalid_argument when the emission has no power over the sampled range.
    Fluorophore(SpectrumPtr absorption, SpectrumPtr emission, float quantum_yield);

    float absorption(float lambda) const { return clamp((*absorption_)(lambda), 0.f, 1.f); }
    // pi times the re-radiated BRDF above (per nm of lambda_in).
    float reradiation(float lambda_in, float lambda_out) const;

    struct WavelengthSample {
        float lambda = 0, pdf = 0; // pdf per nm
    };
    // An absorbed wavelength, with density proportional to a(lambda) lambda (a camera path's
    // choice: the lambda_i factors of f).
    WavelengthSample sample_excitation(float u) const;
    // An emitted wavelength, with density proportional to e(lambda) / lambda (a light path's).
    WavelengthSample sample_emission(float u) const;

    // The re-radiated albedos: the fraction of the energy absorbed at lambda_in that leaves at any
    // wavelength (importance), and the integral over lambda_in of f(lambda_in -> lambda_out) pi
    // (radiance: what a unit spectral irradiance flat over all wavelengths returns at lambda_out).
    float importance_albedo(float lambda_in) const;
    float radiance_albedo(float lambda_out) const;

    // The spectral power the dye re-emits, per nm at each whole nm of the sampled range from
    // LambdaMin, when all of `incident` (power per nm) falls on it: the sum over absorbed
    // wavelengths of incident times pi f. A scene's wavelength density counts it as emitted.
    std::vector<float> reemitted(const std::function<float(float)> &incident) const;

  private:
    float emission(float lambda) const { return std::max((*emission_)(lambda), 0.f) * emission_scale_; }

    SpectrumPtr absorption_, emission_;
    float quantum_yield_;
    float emission_scale_ = 0; // 1 / the emission's integral
    // Densities per 1-nm bin over [LambdaMin, LambdaMax]: of a(lambda) lambda and e(lambda) / lambda,
    // with the running integrals that the albedos need.
    PiecewiseConstant1D excitation_, emission_density_;
    std::vector<float> excitation_below_, emission_above_;
};

// A re-radiation's new wavelength for all carried lanes at once (integrators/common/
// reradiation.h): a camera path (radiance) arriving with the film's lambda_j draws the absorbed
// wavelength from the absorption, and lane j takes albedo[j] = pi f(lambda -> lambda_j) / p(lambda);
// a light path (importance) arriving with lambda_j draws the emitted one from the emission, and
// lane j takes pi f(lambda_j -> lambda) / p(lambda).
struct ReradiationShift {
    float lambda = 0;            // the new wavelength (nm)
    SampledSpectrum albedo{0.f}; // per carried lane
    explicit operator bool() const { return !albedo.is_black(); }
};
ReradiationShift sample_reradiation_shift(const Fluorophore &dye, TransportMode mode, const SampledWavelengths &lambda,
                                          float u);

} // namespace caustica
