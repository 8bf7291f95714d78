#include "sampler/pmj02bn_sampler.h"

#include "core/rng.h"
#include "sampler/quadtree_shuffle.h"
#include "sampler/randomization.h"
#include "sampler/sample_hash.h"

#include <algorithm>
#include <array>
#include <bit>
#include <mutex>

namespace caustica {

namespace {

// Truncated to float, so that a point stays in every dyadic stratum (down to 2^-24) that it was
// placed in.
Vec2f to_point(FixedPoint2 p) { return {bits_to_unit_float(p.x), bits_to_unit_float(p.y)}; }

// Adds an offset modulo 1.
float rotate(float u, float offset) {
    u += offset;
    if (u >= 1) u -= 1;
    return std::min(u, OneMinusEpsilon);
}

// The pixel's value of blue-noise texture `instance` (see the header): the Morton code of the
// pixel within its 256 x 256 tile, scrambled, with its base-4 digits read finest first, plus a
// hashed offset within the last 1/65536.
float blue_noise(Vec2i pixel, uint64_t instance) {
    constexpr int Bits = 16;
    const uint32_t morton = morton_code(uint16_t(pixel.x & 255), uint16_t(pixel.y & 255));
    const uint64_t key = hash_values(instance, 0x626c7565ULL);
    const uint64_t scrambled = shuffle_digits(morton, morton | (1u << Bits), Bits, 0, key);
    uint32_t reversed = 0;
    for (int digit = 0; digit < Bits / 2; ++digit)
        reversed = (reversed << 2) | uint32_t((scrambled >> (2 * digit)) & 3);
    return std::min(OneMinusEpsilon, (float(reversed) + sample_hash_uniform(key, morton)) * 0x1p-16f);
}

// Set 0's points in pixel (x, y) of a tile x tile pattern, `per_pixel` each, in sequence order.
std::vector<Vec2f> tile_pixel_samples(int tile, int per_pixel) {
    const int log2_tile = std::countr_zero(uint32_t(tile));
    std::vector<Vec2f> samples(size_t(tile) * tile * per_pixel);
    std::vector<int> stored(size_t(tile) * tile, 0);
    for (FixedPoint2 p : pmj02bn_set(0)) {
        const uint32_t px = log2_tile ? p.x >> (32 - log2_tile) : 0, py = log2_tile ? p.y >> (32 - log2_tile) : 0;
        const size_t pixel = size_t(py) * tile + px;
        if (stored[pixel] == per_pixel) continue;  // spp not a power of 4: the first spp
        // The position within the pixel: the bits below the pixel's.
        samples[pixel * per_pixel + stored[pixel]++] = to_point({p.x << log2_tile, p.y << log2_tile});
    }
    return samples;
}

} // namespace

const std::vector<FixedPoint2> &pmj02bn_set(int s) {
    static std::array<std::once_flag, Pmj02bnSampler::SetCount> once;
    static std::array<std::vector<FixedPoint2>, Pmj02bnSampler::SetCount> sets;
    std::call_once(once[s], [s] { sets[s] = generate_pmj02bn(Pmj02bnSampler::SetSize, 0x9e3779b9ULL * (s + 1)); });
    return sets[s];
}

Pmj02bnSampler::Pmj02bnSampler(int samples_per_pixel, int seed)
    : samples_per_pixel_(samples_per_pixel), pattern_(std::min(samples_per_pixel, SetSize)), seed_(seed) {
    // T^2 x (P rounded up to a power of 4) = 65536.
    int log4 = 0;
    while ((1 << (2 * log4)) < pattern_) ++log4;
    tile_ = 1 << (8 - log4);
    pixel_samples_ = std::make_shared<const std::vector<Vec2f>>(tile_pixel_samples(tile_, pattern_));
}

void Pmj02bnSampler::start_pixel_sample(Vec2i pixel, int sample_index, int dimension) {
    pixel_ = pixel;
    index_in_round_ = sample_index % pattern_;
    round_ = sample_index / pattern_;
    dimension_ = uint64_t(dimension);
    if (pixel.x != cached_pixel_.x || pixel.y != cached_pixel_.y) {
        cached_pixel_ = pixel;
        cached_offsets_ = 0;
    }
}

uint64_t Pmj02bnSampler::dimension_hash() const {
    return hash_values(pixel_.x, pixel_.y, dimension_, seed_, round_);
}

float Pmj02bnSampler::offset(uint64_t dimension) {
    if (round_ > 0) return sample_hash_uniform(hash_values(pixel_.x, pixel_.y, seed_, round_), dimension);
    if (dimension >= uint64_t(CachedDimensions)) return blue_noise(pixel_, hash_values(dimension, seed_));
    if (!((cached_offsets_ >> dimension) & 1)) {
        offsets_[dimension] = blue_noise(pixel_, hash_values(dimension, seed_));
        cached_offsets_ |= uint64_t(1) << dimension;
    }
    return offsets_[dimension];
}

float Pmj02bnSampler::get_1d() {
    const uint32_t index = permutation_element(uint32_t(index_in_round_), uint32_t(pattern_), dimension_hash());
    const float u = (float(index) + offset(dimension_)) / float(pattern_);
    ++dimension_;
    return std::min(u, OneMinusEpsilon);
}

Vec2f Pmj02bnSampler::get_2d() {
    const uint64_t instance = dimension_ / 2;
    uint32_t index = uint32_t(index_in_round_);
    if (instance >= uint64_t(SetCount) || round_ > 0)
        index = permutation_element(index, uint32_t(pattern_), dimension_hash());
    const Vec2f u = to_point(pmj02bn_set(int(instance % SetCount))[index]);
    const Vec2f result{rotate(u.x, offset(dimension_)), rotate(u.y, offset(dimension_ + 1))};
    dimension_ += 2;
    return result;
}

Vec2f Pmj02bnSampler::get_pixel_2d() {
    const int x = ((pixel_.x % tile_) + tile_) % tile_, y = ((pixel_.y % tile_) + tile_) % tile_;
    Vec2f u = (*pixel_samples_)[(size_t(y) * tile_ + x) * pattern_ + index_in_round_];
    // Later rounds rotate the pixel's points by their own hash.
    if (round_ > 0) u = {rotate(u.x, offset(dimension_)), rotate(u.y, offset(dimension_ + 1))};
    dimension_ += 2;
    return u;
}

std::unique_ptr<Sampler> Pmj02bnSampler::clone() const { return std::make_unique<Pmj02bnSampler>(*this); }

} // namespace caustica
