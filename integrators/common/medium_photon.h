// Photons in participating media (sppm, bpm, vcm). The volumetric photon map's estimate (Jensen
// and Christensen 1998) holds sigma_s twice, once in each subpath's throughput, where the path
// has it once at its merged vertex; vcm.cpp's merge_in_medium derives it. The photon's own is
// divided out when it is stored: the gather then averages a quantity that is smooth across the
// merge sphere, where dividing by sigma_s at the gather point would weigh photons from denser
// parts of a heterogeneous medium by the ratio of the two densities.
#pragma once

#include "media/medium.h"
#include "spectral/sampled_spectrum.h"
#include "spectral/sampled_wavelengths.h"

namespace caustica {

// The throughput of a photon at point p of the medium, over sigma_s there (zero at a wavelength
// where sigma_s is zero, where the photon's throughput is zero too).
inline SampledSpectrum over_sigma_s(const SampledSpectrum &beta, const Medium &medium, Vec3f p,
                                    const SampledWavelengths &lambda) {
    const SampledSpectrum sigma_s = medium.properties(p, lambda).sigma_s;
    SampledSpectrum result(0.f);
    for (int i = 0; i < NumWavelengths; ++i)
        if (sigma_s[i] > 0) result[i] = beta[i] / sigma_s[i];
    return result;
}

} // namespace caustica
