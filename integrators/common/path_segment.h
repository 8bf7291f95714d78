// What happens to a path along one ray segment, between the vertex it leaves and the surface it
// hits (or infinity): free flight through the participating medium it is in (which may end in a
// scattering event), and Beer-Lambert absorption inside an absorbing dielectric (a material's
// interior_sigma_a). Every integrator traces its camera and light subpaths through this, so that
// they all see the same media.
#pragma once

#include "materials/material.h"
#include "media/medium.h"
#include "sampler/sampler.h"

#include <cmath>

namespace caustica {

struct PathSegment {
    bool scattered = false;   // the path scatters in the medium at distance t
    float t = 0;              // distance travelled along the segment
    SampledSpectrum weight{1.f}; // throughput factor (transmittance over its sampling density)
};

// segment_length: distance to the surface hit, Infinity if the ray escapes. Draws two sampler
// dimensions when the path is in a medium, none otherwise.
inline PathSegment traverse_segment(const Medium *medium, const Material *absorbing_interior,
                                    float segment_length, const SampledWavelengths &lambda, Sampler &sampler) {
    PathSegment segment;
    segment.t = segment_length;
    if (medium) {
        float u_channel = sampler.get_1d();
        MediumEvent event = medium->sample_distance(segment_length, lambda, u_channel, sampler.get_1d());
        segment = {event.scattered, event.t, event.weight};
    }
    if (absorbing_interior) {
        SampledSpectrum sigma_a = absorbing_interior->interior_sigma_a(lambda);
        // A clear wavelength transmits fully even along an escaping (infinite) segment.
        for (int i = 0; i < NumWavelengths; ++i)
            if (sigma_a[i] > 0) segment.weight[i] *= std::exp(-sigma_a[i] * segment.t);
    }
    return segment;
}

} // namespace caustica
