#include "sampler/padded_sobol_sampler.h"

#include "core/rng.h"
#include "sampler/sample_hash.h"
#include "sampler/sobol_sequence.h"

namespace caustica {

PaddedSobolSampler::PaddedSobolSampler(int samples_per_pixel, int seed, Randomization randomization)
    : samples_per_pixel_(samples_per_pixel), seed_(seed), randomization_(randomization) {}

void PaddedSobolSampler::start_pixel_sample(Vec2i pixel, int sample_index, int dimension) {
    const uint32_t index = uint32_t(sample_index);
    pixel_key_ = hash_values(pixel.x, pixel.y, seed_);
    round_ = index / uint32_t(samples_per_pixel_);
    index_in_round_ = index % uint32_t(samples_per_pixel_);
    dimension_ = uint64_t(dimension);
}

uint64_t PaddedSobolSampler::sequence_index(uint64_t dimension_key) const {
    const uint32_t n = uint32_t(samples_per_pixel_);
    return round_ * n + permutation_element(index_in_round_, n, dimension_key ^ (round_ * 0xd1b54a32d192ed03ull));
}

// The key of a dimension (pair) in this pixel; key + 1 and key + 2 seed the scrambles of its
// coordinates (randomize() hashes its seed again, so consecutive seeds are fine).
uint64_t PaddedSobolSampler::dimension_key() const {
    return mix_bits(pixel_key_ + (dimension_ + 1) * 0x9e3779b97f4a7c15ull);
}

float PaddedSobolSampler::get_1d() {
    const uint64_t key = dimension_key();
    ++dimension_;
    const uint32_t bits = reverse_bits(uint32_t(sequence_index(key)));
    return bits_to_unit_float(randomize(bits, randomization_, key + 1));
}

Vec2f PaddedSobolSampler::get_2d() {
    const uint64_t key = dimension_key();
    dimension_ += 2;
    const uint64_t index = sequence_index(key);
    const uint32_t x = reverse_bits(uint32_t(index));
    const uint32_t y = sobol_second_dimension(index);
    return {bits_to_unit_float(randomize(x, randomization_, key + 1)),
            bits_to_unit_float(randomize(y, randomization_, key + 2))};
}

std::unique_ptr<Sampler> PaddedSobolSampler::clone() const {
    return std::make_unique<PaddedSobolSampler>(*this);
}

} // namespace caustica
