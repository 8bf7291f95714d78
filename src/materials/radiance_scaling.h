// The 1/eta'^2 factor of refraction (Veach 1997, section 5.2; seed 000, section 2.2): radiance
// is compressed into a smaller solid angle when it enters a denser medium, so a BSDF that
// transmits radiance carries 1/eta'^2, where eta' is the relative IOR (inside over outside, in
// the direction the light travels). Importance and photon power are not densities per solid
// angle of the light, so the adjoint BSDF used on light paths has no such factor.
//
// Every refracting BxDF asks radiance_scaling() for the factor instead of testing the mode
// itself, so that the asymmetry test can break it on purpose: the environment variable
// CAUSTICA_TEST_FAULT, read once, set to "eta-importance" applies the factor in both modes,
// and set to "eta-drop" applies it in neither. It exists only for that negative control
// (tests/integrators/asymmetry_test.cpp), which proves that the agreement tests detect the
// error; no user should set it.
#pragma once

#include "materials/bxdf.h"

namespace caustica {

enum class RadianceScalingFault { None, AlsoImportance, DropFromRadiance };

// The fault selected by CAUSTICA_TEST_FAULT (None unless a test sets it).
RadianceScalingFault radiance_scaling_fault();

// The factor a transmitted value carries in `mode` for relative IOR etap: 1/etap^2 for
// radiance, 1 for importance (unless the test fault says otherwise).
inline float radiance_scaling(TransportMode mode, float etap) {
    bool apply = mode == TransportMode::Radiance;
    switch (radiance_scaling_fault()) {
    case RadianceScalingFault::None: break;
    case RadianceScalingFault::AlsoImportance: apply = true; break;
    case RadianceScalingFault::DropFromRadiance: apply = false; break;
    }
    return apply ? 1 / (etap * etap) : 1.f;
}

} // namespace caustica
