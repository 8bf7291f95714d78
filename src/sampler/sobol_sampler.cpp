#include "sampler/sobol_sampler.h"

#include "core/rng.h"
#include "sampler/sobol_sequence.h"

#include <stdexcept>
#include <utility>

namespace caustica {

namespace {

// Digits of each coordinate that the pixel fixes.
constexpr int PixelBits = 16;

// The first PixelBits digits of a 32-bit binary fraction, as an integer.
uint32_t leading_digits(uint32_t bits) { return bits >> (32 - PixelBits); }

} // namespace

SobolSampler::SobolSampler(int samples_per_pixel, int seed, Randomization randomization)
    : samples_per_pixel_(samples_per_pixel), seed_(seed), randomization_(randomization) {
    // Index digits 16..31 act on the leading digits of coordinate 1 through a 16 x 16 matrix T
    // (column j: the leading digits of generator column 16 + j). Gauss-Jordan elimination on
    // the pairs (T v, v), starting from the unit vectors v, ends with T v = unit vector b.
    std::array<uint32_t, PixelBits> image{}, preimage{};
    for (int j = 0; j < PixelBits; ++j) {
        image[j] = leading_digits(sobol_generator_column(1, PixelBits + j));
        preimage[j] = uint32_t(1) << j;
    }
    for (int b = 0; b < PixelBits; ++b) {
        int pivot = b;
        while (pivot < PixelBits && !((image[pivot] >> b) & 1)) ++pivot;
        // T is invertible because dimensions 0 and 1 form a (0,2)-sequence; a failure here
        // means the generator matrices are wrong.
        if (pivot == PixelBits) throw std::logic_error("Sobol pixel system is singular");
        std::swap(image[b], image[pivot]);
        std::swap(preimage[b], preimage[pivot]);
        for (int r = 0; r < PixelBits; ++r)
            if (r != b && ((image[r] >> b) & 1)) {
                image[r] ^= image[b];
                preimage[r] ^= preimage[b];
            }
    }
    inverse_columns_ = preimage;
}

uint64_t SobolSampler::sequence_index(Vec2i pixel, int sample_index) const {
    const uint32_t px = uint32_t(pixel.x) & 0xffffu, py = uint32_t(pixel.y) & 0xffffu;
    // Coordinate 0 is the index's bits reversed: its leading digits are px exactly when index
    // digits 0..15 are px's bits reversed.
    const uint64_t low = reverse_bits(px) >> (32 - PixelBits);
    const uint64_t block = uint64_t(uint32_t(sample_index)) << (2 * PixelBits);
    // Coordinate 1 is linear in the index: choose digits 16..31 to make up the difference.
    const uint32_t target = py ^ leading_digits(sobol_second_dimension(low | block));
    uint64_t middle = 0;
    for (int b = 0; b < PixelBits; ++b)
        if ((target >> b) & 1) middle ^= inverse_columns_[b];
    return block | (middle << PixelBits) | low;
}

void SobolSampler::start_pixel_sample(Vec2i pixel, int sample_index, int dimension) {
    index_ = sequence_index(pixel, sample_index);
    dimension_ = uint64_t(dimension);
}

float SobolSampler::sample_dimension(uint64_t sobol_dimension) const {
    const uint64_t seed = hash_values(sobol_dimension, seed_);
    if (sobol_dimension < uint64_t(SobolDimensionCount)) {
        uint32_t bits = sobol_bits(index_, int(sobol_dimension));
        return bits_to_unit_float(randomize(bits, randomization_, seed));
    }
    const int reused = 2 + int((sobol_dimension - 2) % uint64_t(SobolDimensionCount - 2));
    uint32_t bits = randomize(sobol_bits(index_, reused), randomization_, seed);
    return bits_to_unit_float(owen_scramble(bits, hash_values(seed, 1)));
}

float SobolSampler::get_1d() { return sample_dimension(2 + dimension_++); }

Vec2f SobolSampler::get_2d() {
    Vec2f u{sample_dimension(2 + dimension_), sample_dimension(3 + dimension_)};
    dimension_ += 2;
    return u;
}

Vec2f SobolSampler::get_pixel_2d() {
    dimension_ += 2;
    // The digits after the 16 the pixel fixed: the position within the pixel.
    const uint32_t x = reverse_bits(uint32_t(index_)) << PixelBits;
    const uint32_t y = sobol_second_dimension(index_) << PixelBits;
    return {bits_to_unit_float(x), bits_to_unit_float(y)};
}

std::unique_ptr<Sampler> SobolSampler::clone() const { return std::make_unique<SobolSampler>(*this); }

} // namespace caustica
