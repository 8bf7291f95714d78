// The albedo mapping of the Disney material's random-walk subsurface: which single-scattering
// albedo a semi-infinite interior needs for the surface to reflect a given colour.
//
// R(alpha), the total diffuse reflectance of a semi-infinite isotropic medium under the Disney
// BxDF's subsurface boundary (disney_bxdf.h: Lambertian entry, exit with probability 41/42,
// Lambertian internal reflection otherwise), depends on alpha alone. It has no closed form for
// this boundary, so it is tabulated by Monte Carlo (scripts/tabulate-random-walk-albedo.cpp) and
// inverted by interpolation. The mapping is exact for the model the integrators trace, which is
// what makes a vanishing scatterDistance converge to the diffuse BRDF (Burley 2015, section
// 2.4: "our diffusion model converge[s] to the same result as the diffuse BRDF when the scatter
// distance is small"); van de Hulst's and Christensen-Burley's inversions assume other
// boundaries.
#pragma once

namespace caustica {

// R(alpha) for alpha in [0, 1] (R(1) = 1: a conservative half-space reflects everything).
float random_walk_reflectance(float single_scattering_albedo);
// The inverse: the alpha with R(alpha) = reflectance, for reflectance in [0, 1].
float random_walk_single_scattering_albedo(float reflectance);

// The mean free path (1 / sigma_t) that gives the walk the spatial spread of Burley's
// normalised diffusion profile with shape parameter d = scatterDistance for multiple-scattering
// albedo A: l = d s(A) with Christensen and Burley 2015's fit for light entering through a
// diffusely transmitting surface (christensen_burley_scaling in subsurface_coefficients.h).
float random_walk_mean_free_path(float scatter_distance, float albedo);

} // namespace caustica
