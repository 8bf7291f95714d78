// What happens to a path along one ray segment, between the vertex it leaves and the surface it
// hits (or infinity): free flight through the participating medium it is in (which may end in a
// scattering event), and Beer-Lambert absorption inside an absorbing dielectric (a material's
// interior_sigma_a). Every integrator traces its camera and light subpaths through this, so that
// they all see the same media.
#pragma once

#include "integrators/common/spectral_mis.h"
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

// ray: the segment's start and unit direction; segment_length: distance to the surface hit,
// Infinity if the ray escapes. Distances are sampled with the subpath's spectral MIS lane. Draws
// one sampler dimension when the path is in a medium, and the lane's the first time.
inline PathSegment traverse_segment(const Medium *medium, const Material *absorbing_interior, const Ray &ray,
                                    float segment_length, const SampledWavelengths &lambda, Sampler &sampler,
                                    SpectralMIS &mis) {
    PathSegment segment;
    segment.t = segment_length;
    if (medium) {
        const int lane = mis.lane(lambda, sampler);
        const MediumEvent event = medium->sample_distance(ray, segment_length, lambda, lane, sampler.get_1d());
        const float mis_scale = mis.inverse_density(event.density);
        segment = {event.scattered, event.t, event.f * mis_scale, event.emitted * mis_scale};
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
