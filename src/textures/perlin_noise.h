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

// Sums of up to `octaves` octaves, each of twice (1.99x, to keep lattices from lining up) the
// frequency and `omega` times the amplitude of the one before. As in pbrt-v4, the octaves finer
// than the pixel's footprint (dp/dx, dp/dy in texture space; camera/camera_footprint.h) are
// dropped, the last one kept fading out smoothly; without a footprint every octave is summed.
float fractional_brownian_motion(Vec3f p, float omega, int octaves, Vec3f dpdx = {}, Vec3f dpdy = {});
// The same sum of |noise|, with pbrt-v4's allowance of 0.2 of the amplitude (the mean of
// |noise|) for each dropped octave and for the one after the last.
float turbulence(Vec3f p, float omega, int octaves, Vec3f dpdx = {}, Vec3f dpdy = {});

} // namespace caustica
