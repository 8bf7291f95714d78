// The Henyey-Greenstein phase function (Henyey and Greenstein 1941), the scattering lobe of
// Caustica's media. Directions follow the BSDF convention: wo points back along the path (towards
// the camera for radiance transport), wi towards the next vertex, so forward scattering means
// wi close to -wo, and g > 0 favours it. The function is normalised over the sphere and
// symmetric in wo and wi, so the same value serves radiance and importance transport.
#pragma once

#include "core/vecmath.h"

#include <cmath>

namespace caustica {

struct PhaseSample {
    float p = 0;   // phase function value, equal to the density: sampling is exact
    Vec3f wi;
};

class HenyeyGreenstein {
  public:
    HenyeyGreenstein() = default;
    // g in (-1, 1); the factory rejects |g| >= 1, where the lobe becomes a delta. |g| < 1e-3 is
    // treated as isotropic: the sampling inversion divides by g, and the lobes differ by < 0.3%.
    explicit HenyeyGreenstein(float g) : g_(std::abs(g) < 1e-3f ? 0.f : g) {}

    float g() const { return g_; }
    float p(Vec3f wo, Vec3f wi) const { return density(dot(-wo, wi)); }
    float pdf(Vec3f wo, Vec3f wi) const { return p(wo, wi); }
    PhaseSample sample_p(Vec3f wo, Vec2f u) const;

  private:
    // Density per solid angle of scattering by angle theta, cos_theta = cos(theta) between the
    // incident propagation direction and the scattered one.
    float density(float cos_theta) const;
    float g_ = 0;
};

} // namespace caustica
