// What happens to a path along one ray segment, between the vertex it leaves and the surface it
// hits (or infinity): free flight through the participating medium it is in (which may end in a
// scattering event), and Beer-Lambert absorption inside an absorbing dielectric (a material's
// interior_sigma_a). Every integrator traces its camera and light subpaths through this, so that
// they all see the same media.
#pragma once

#include "materials/material.h"
#include "media/medium.h"
#include "sampler/sampler.h"

#include <algorithm>
#include <cmath>

namespace caustica {

struct PathSegment {
    bool scattered = false;   // the path scatters in the medium at distance t
    float t = 0;              // distance travelled along the segment
    SampledSpectrum weight{1.f}; // throughput factor (transmittance over its sampling density)
    // Emission counted at the scattering event, on the scale of weight: the collision estimator
    // of the medium's emission along the segment (MediumEvent::emitted). Zero unless it emits.
    SampledSpectrum emitted{0.f};
};

// Multiple importance sampling over the wavelengths for the free-flight distances of one subpath
// (Wilkie et al. 2014, "Hero Wavelength Spectral Sampling"; pbrt-v4's r_u ratios). A chromatic
// medium's distances can be sampled with any one wavelength's extinction. The subpath picks one,
// its lane, uniformly at its first medium event and samples all its distances with it; for each
// wavelength i it then carries f_i / mean_k p_k, with p_k the density of all its events so far
// under wavelength k's coefficients: the one-sample balance heuristic over the NumWavelengths
// ways of sampling the whole subpath (Veach and Guibas 1995). That weight is at most
// NumWavelengths f_i / p_i, the weight had wavelength i sampled alone: bounded over the whole
// subpath, however many events it has. (Weighing each event on its own, with a fresh choice of
// wavelength per event, bounds each event's weight but lets their product become heavy-tailed
// over long walks in strongly chromatic media: docs/media.md has the measurement.)
//
// The lane is chosen independently for each subpath, so when a camera and a light subpath are
// joined (a connection or a merge) their two weights multiply into the balance heuristic over
// the NumWavelengths^2 ways of sampling the pair: the stored throughput of a vertex is complete.
// Terminating the secondary wavelengths does not change which wavelength samples: the hero's
// weight stays the balance heuristic over the same ways.
struct FreeFlightMIS {
    int lane = -1; // the wavelength that samples distances; -1 until the subpath meets a medium
    // Per wavelength, the density of the subpath's events so far over the lane's, scaled so
    // that the largest is 1 (only their ratios to each other matter).
    SampledSpectrum density{1.f};
};

// ray: the segment's start and unit direction; segment_length: distance to the surface hit,
// Infinity if the ray escapes. Draws one sampler dimension when the path is in a medium, two the
// first time.
inline PathSegment traverse_segment(const Medium *medium, const Material *absorbing_interior, const Ray &ray,
                                    float segment_length, const SampledWavelengths &lambda, Sampler &sampler,
                                    FreeFlightMIS &mis) {
    PathSegment segment;
    segment.t = segment_length;
    if (medium) {
        if (mis.lane < 0) mis.lane = std::min(int(sampler.get_1d() * NumWavelengths), NumWavelengths - 1);
        const MediumEvent event = medium->sample_distance(ray, segment_length, lambda, mis.lane, sampler.get_1d());
        // f_i / mean_k p_k before and after the event, with the densities relative to the lane's.
        const SampledSpectrum density = mis.density * (event.density / event.density[mis.lane]);
        const float before = mis.density.average(), after = density.average();
        const float mis_scale = before / (event.density[mis.lane] * after);
        segment = {event.scattered, event.t, event.f * mis_scale, event.emitted * mis_scale};
        mis.density = density / density.max_value();
    }
    if (absorbing_interior) {
        SampledSpectrum sigma_a = absorbing_interior->interior_sigma_a(lambda);
        // A clear wavelength transmits fully even along an escaping (infinite) segment.
        for (int i = 0; i < NumWavelengths; ++i)
            if (sigma_a[i] > 0) {
                const float T = std::exp(-sigma_a[i] * segment.t);
                segment.weight[i] *= T;
                segment.emitted[i] *= T;
            }
    }
    return segment;
}

} // namespace caustica
