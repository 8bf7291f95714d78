// Subsurface scattering coefficients: Christensen and Burley's mean-free-path fit, which relates
// the Disney material's scatterDistance to a medium (random_walk_albedo.h), and the measured media
// of Jensen et al. 2001 by name.
#pragma once

#include "spectral/color.h"
#include "spectral/sampled_spectrum.h"

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace caustica {

// Christensen and Burley 2015's fitted ratio s(A) = l / d between the mean free path
// l = 1 / sigma_t of a medium and the d of the normalized diffusion profile that matches its
// reflectance ("Approximate Reflectance Profiles for Efficient Subsurface Scattering"), in their
// fit for light entering through a diffusely transmitting surface: s = 1.9 - A + 3.5 (A - 0.8)^2.
// (Their other mean-free-path fit, 1.85 - A + 7 |A - 0.8|^3, is for a searchlight beam at normal
// incidence.)
float christensen_burley_scaling(float albedo);

// A measured scattering medium of Jensen, Marschner, Levoy and Hanrahan 2001, "A Practical Model
// for Subsurface Light Transport", Table 1: reduced scattering sigma_s' and absorption sigma_a in
// mm^-1 for the red, green and blue bands of their measurements, and the relative index of
// refraction they used with them.
struct MeasuredSubsurfaceMedium {
    std::string_view name;
    RGB sigma_s_reduced; // mm^-1
    RGB sigma_a;         // mm^-1
    float eta;
};

// All the media of Jensen et al.'s table; those of Narasimhan et al. 2006's (liquids and powders
// in water: some scatter nothing in a band); and one looked up by name in either, ignoring case
// ("skin1", "Skin1", "Regular Milk"), as pbrt-v4's named media.
std::span<const MeasuredSubsurfaceMedium> measured_subsurface_media();
std::span<const MeasuredSubsurfaceMedium> diluted_media();
std::optional<MeasuredSubsurfaceMedium> find_measured_subsurface_medium(std::string_view name);
// The media's names, comma-separated, for error messages about unknown presets.
std::string measured_subsurface_media_names();

} // namespace caustica
