// Perlin's improved gradient noise (Perlin 2002, "Improving Noise") and the two sums of octaves
// that pbrt-v4's procedural textures are built from: fractional Brownian motion and turbulence
// (Ebert et al., "Texturing and Modeling", ch. 2; pbrt-v4 section 10.6). The lattice uses
// Perlin's reference permutation, so the patterns are the ones pbrt-v4 draws.
#pragma once

#include "core/vecmath.h"

namespace caustica {

// Noise in [-1, 1] with value 0 at every integer lattice point. pbrt-v4's two-argument form
// evaluates the plane z = 0.5.
float perlin_noise(float x, float y, float z);
inline float perlin_noise(Vec3f p) { return perlin_noise(p.x, p.y, p.z); }

// Sums of `octaves` octaves, each of twice (1.99x, to keep lattices from lining up) the
// frequency and `omega` times the amplitude of the one before. pbrt-v4 drops the octaves finer
// than the pixel footprint its ray differentials give; Caustica has no ray differentials, so
// every octave is summed and pixel sampling does the antialiasing.
float fractional_brownian_motion(Vec3f p, float omega, int octaves);
// The same sum of |noise|, plus pbrt-v4's allowance of 0.2 of the amplitude for the clamped
// octave, so the average level matches its antialiased version.
float turbulence(Vec3f p, float omega, int octaves);

} // namespace caustica
