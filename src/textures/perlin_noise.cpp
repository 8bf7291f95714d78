#include "textures/perlin_noise.h"

#include <cmath>
#include <cstdint>

namespace caustica {

namespace {

// Perlin's reference permutation of 0..255 (Perlin 2002), repeated so that lattice hashes of
// cell + 1 need no wrap.
constexpr uint8_t Permutation[256] = {
    151, 160, 137, 91,  90,  15,  131, 13,  201, 95,  96,  53,  194, 233, 7,   225, 140, 36,
    103, 30,  69,  142, 8,   99,  37,  240, 21,  10,  23,  190, 6,   148, 247, 120, 234, 75,
    0,   26,  197, 62,  94,  252, 219, 203, 117, 35,  11,  32,  57,  177, 33,  88,  237, 149,
    56,  87,  174, 20,  125, 136, 171, 168, 68,  175, 74,  165, 71,  134, 139, 48,  27,  166,
    77,  146, 158, 231, 83,  111, 229, 122, 60,  211, 133, 230, 220, 105, 92,  41,  55,  46,
    245, 40,  244, 102, 143, 54,  65,  25,  63,  161, 1,   216, 80,  73,  209, 76,  132, 187,
    208, 89,  18,  169, 200, 196, 135, 130, 116, 188, 159, 86,  164, 100, 109, 198, 173, 186,
    3,   64,  52,  217, 226, 250, 124, 123, 5,   202, 38,  147, 118, 126, 255, 82,  85,  212,
    207, 206, 59,  227, 47,  16,  58,  17,  182, 189, 28,  42,  223, 183, 170, 213, 119, 248,
    152, 2,   44,  154, 163, 70,  221, 153, 101, 155, 167, 43,  172, 9,   129, 22,  39,  253,
    19,  98,  108, 110, 79,  113, 224, 232, 178, 185, 112, 104, 218, 246, 97,  228, 251, 34,
    242, 193, 238, 210, 144, 12,  191, 179, 162, 241, 81,  51,  145, 235, 249, 14,  239, 107,
    49,  192, 214, 31,  181, 199, 106, 157, 184, 84,  204, 176, 115, 121, 50,  45,  127, 4,
    150, 254, 138, 236, 205, 93,  222, 114, 67,  29,  24,  72,  243, 141, 128, 195, 78,  66,
    215, 61,  156, 180};

int perm(int i) { return Permutation[i & 255]; }

// The dot product of the offset (dx, dy, dz) with one of the 12 edge directions of a cube
// (four repeated), chosen by hashing the lattice point.
float gradient(int x, int y, int z, float dx, float dy, float dz) {
    int h = perm(perm(perm(x) + y) + z) & 15;
    float u = h < 8 || h == 12 || h == 13 ? dx : dy;
    float v = h < 4 || h == 12 || h == 13 ? dy : dz;
    return ((h & 1) ? -u : u) + ((h & 2) ? -v : v);
}

// Perlin's quintic fade, whose first and second derivatives vanish at 0 and 1.
float fade(float t) { return t * t * t * (t * (t * 6 - 15) + 10); }

} // namespace

float perlin_noise(float x, float y, float z) {
    // Reduce far coordinates first so that the cell index fits an int.
    x = std::fmod(x, float(1 << 30));
    y = std::fmod(y, float(1 << 30));
    z = std::fmod(z, float(1 << 30));
    float fx = std::floor(x), fy = std::floor(y), fz = std::floor(z);
    float dx = x - fx, dy = y - fy, dz = z - fz;
    int ix = int(fx) & 255, iy = int(fy) & 255, iz = int(fz) & 255;
    float wx = fade(dx), wy = fade(dy), wz = fade(dz);
    auto corner = [&](int i, int j, int k) {
        return gradient(ix + i, iy + j, iz + k, dx - float(i), dy - float(j), dz - float(k));
    };
    float z0 = lerp(wy, lerp(wx, corner(0, 0, 0), corner(1, 0, 0)),
                    lerp(wx, corner(0, 1, 0), corner(1, 1, 0)));
    float z1 = lerp(wy, lerp(wx, corner(0, 0, 1), corner(1, 0, 1)),
                    lerp(wx, corner(0, 1, 1), corner(1, 1, 1)));
    return lerp(wz, z0, z1);
}

namespace {

// How many octaves the footprint resolves, fractionally: those whose lattice spacing is wider
// than about twice the footprint (pbrt-v4's FBm).
float resolved_octaves(Vec3f dpdx, Vec3f dpdy, int octaves) {
    const float len2 = std::max(length_squared(dpdx), length_squared(dpdy));
    if (!(len2 > 0)) return float(octaves);
    return clamp(-1 - std::log2(len2) / 2, 0.f, float(octaves));
}

float smooth_step(float x, float a, float b) {
    const float t = clamp((x - a) / (b - a), 0.f, 1.f);
    return t * t * (3 - 2 * t);
}

} // namespace

float fractional_brownian_motion(Vec3f p, float omega, int octaves, Vec3f dpdx, Vec3f dpdy) {
    const float n = resolved_octaves(dpdx, dpdy, octaves);
    const int whole = int(std::floor(n));
    float sum = 0, frequency = 1, amplitude = 1;
    for (int i = 0; i < whole; ++i) {
        sum += amplitude * perlin_noise(frequency * p);
        frequency *= 1.99f;
        amplitude *= omega;
    }
    const float fade = smooth_step(n - float(whole), 0.3f, 0.7f);
    if (fade > 0) sum += amplitude * fade * perlin_noise(frequency * p);
    return sum;
}

float turbulence(Vec3f p, float omega, int octaves, Vec3f dpdx, Vec3f dpdy) {
    const float n = resolved_octaves(dpdx, dpdy, octaves);
    const int whole = int(std::floor(n));
    float sum = 0, frequency = 1, amplitude = 1;
    for (int i = 0; i < whole; ++i) {
        sum += amplitude * std::abs(perlin_noise(frequency * p));
        frequency *= 1.99f;
        amplitude *= omega;
    }
    // The partly resolved octave fades from |noise| to its mean, about 0.2; each dropped octave
    // adds that mean, starting at the partial octave's amplitude as pbrt-v4 counts them.
    const float fade = smooth_step(n - float(whole), 0.3f, 0.7f);
    sum += amplitude * (fade > 0 ? lerp(fade, 0.2f, std::abs(perlin_noise(frequency * p))) : 0.2f);
    for (int i = whole; i < octaves; ++i) {
        sum += amplitude * 0.2f;
        amplitude *= omega;
    }
    return sum;
}

} // namespace caustica
