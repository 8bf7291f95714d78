#include "sampler/halton_sampler.h"

#include "core/sampling.h"
#include "sampler/sample_hash.h"

#include <algorithm>
#include <array>
#include <utility>
#include <vector>

namespace caustica {

namespace {

constexpr int MaxHaltonResolution = 128;
constexpr int PrimeCount = 1000;

// The first 1000 primes (the bases of the Halton dimensions), by a sieve.
const std::array<int, PrimeCount> &primes() {
    static const std::array<int, PrimeCount> table = [] {
        std::array<int, PrimeCount> p{};
        std::vector<bool> composite(8000, false); // the 1000th prime is 7919
        int n = 0;
        for (int i = 2; n < PrimeCount; ++i) {
            if (composite[size_t(i)]) continue;
            p[size_t(n++)] = i;
            for (size_t k = size_t(i) * size_t(i); k < composite.size(); k += size_t(i)) composite[k] = true;
        }
        return p;
    }();
    return table;
}

// x with a x = 1 (mod n), for coprime a and n (extended Euclid).
uint64_t multiplicative_inverse(int64_t a, int64_t n) {
    int64_t t = 0, new_t = 1, r = n, new_r = a % n;
    while (new_r != 0) {
        int64_t q = r / new_r;
        t = std::exchange(new_t, t - q * new_t);
        r = std::exchange(new_r, r - q * new_r);
    }
    return uint64_t(t < 0 ? t + n : t);
}

// The index whose first `digits` base-b digits, reversed, are those of `inverse`.
uint64_t inverse_radical_inverse(uint64_t inverse, int base, int digits) {
    uint64_t index = 0;
    for (int i = 0; i < digits; ++i) {
        index = index * uint64_t(base) + inverse % uint64_t(base);
        inverse /= uint64_t(base);
    }
    return index;
}

// Dimensions whose permutations are tabled; the others permute digit by digit.
constexpr int TabledDimensions = 128;

// Digit positions that still change a float: those whose weight base^-k times the largest digit
// exceeds 2^-26.
int digit_positions(uint64_t base) {
    int n = 0;
    for (double scale = 1.0 / double(base); scale * double(base - 1) > 0x1p-26; scale /= double(base)) ++n;
    return n;
}

uint64_t dimension_seed(uint64_t seed, int dimension) { return mix_bits(seed ^ (uint64_t(dimension) << 32)); }

} // namespace

HaltonSampler::HaltonSampler(int samples_per_pixel, Vec2i resolution, int seed, Randomization randomization)
    : samples_per_pixel_(samples_per_pixel), seed_(uint64_t(uint32_t(seed))), randomization_(randomization) {
    const int bases[2] = {2, 3};
    for (int i = 0; i < 2; ++i) {
        const int extent = std::min(i == 0 ? resolution.x : resolution.y, MaxHaltonResolution);
        uint64_t scale = 1;
        int exponent = 0;
        while (scale < uint64_t(std::max(extent, 1))) {
            scale *= uint64_t(bases[i]);
            ++exponent;
        }
        base_scales_[i] = scale;
        base_exponents_[i] = exponent;
    }
    if (randomization_ == Randomization::PermuteDigits) {
        auto tables = std::make_shared<HaltonDigitPermutations>();
        for (int d = 0; d < TabledDimensions; ++d) {
            const uint64_t base = uint64_t(primes()[size_t(d)]);
            tables->offsets.push_back(uint32_t(tables->digits.size()));
            const uint64_t key = dimension_seed(seed_, d);
            for (int position = 0; position < digit_positions(base); ++position)
                for (uint64_t digit = 0; digit < base; ++digit)
                    tables->digits.push_back(
                        uint16_t(permutation_element(uint32_t(digit), uint32_t(base), key + uint64_t(position))));
        }
        tables_ = std::move(tables);
    }
    multiplicative_inverses_[0] = multiplicative_inverse(int64_t(base_scales_[1]), int64_t(base_scales_[0]));
    multiplicative_inverses_[1] = multiplicative_inverse(int64_t(base_scales_[0]), int64_t(base_scales_[1]));
}

void HaltonSampler::start_pixel_sample(Vec2i pixel, int sample_index, int dimension) {
    // The index within the tile's period whose first base-2 and base-3 digits place it in this
    // pixel: by the Chinese remainder theorem, from the two digit strings.
    const uint64_t stride = base_scales_[0] * base_scales_[1];
    uint64_t index = 0;
    if (stride > 1) {
        const int local[2] = {((pixel.x % MaxHaltonResolution) + MaxHaltonResolution) % MaxHaltonResolution,
                              ((pixel.y % MaxHaltonResolution) + MaxHaltonResolution) % MaxHaltonResolution};
        for (int i = 0; i < 2; ++i) {
            const uint64_t offset = inverse_radical_inverse(uint64_t(local[i]), i == 0 ? 2 : 3, base_exponents_[i]);
            index += offset * (stride / base_scales_[i]) % stride * multiplicative_inverses_[i] % stride;
        }
        index %= stride;
    }
    halton_index_ = index + uint64_t(uint32_t(sample_index)) * stride;
    dimension_ = uint64_t(std::max(dimension, 0));
}

int HaltonSampler::halton_dimension(uint64_t d) { return 2 + int(d % uint64_t(PrimeCount - 2)); }

float HaltonSampler::sample_dimension(int dimension, uint64_t index) const {
    const uint64_t base = uint64_t(primes()[size_t(dimension)]);
    if (randomization_ == Randomization::None) return radical_inverse(base, index);
    double value = 0, scale = 1.0 / double(base);
    // Every digit position counts once permuted, the zeros beyond the index's last digit too
    // (a permutation need not keep 0 in place), until digits no longer change a float.
    if (tables_ && dimension < TabledDimensions) {
        const uint16_t *table = tables_->digits.data() + tables_->offsets[size_t(dimension)];
        const int positions = digit_positions(base);
        for (int position = 0; position < positions; ++position, scale /= double(base), table += base) {
            value += double(table[index % base]) * scale;
            index /= base;
        }
        return std::min(OneMinusEpsilon, float(value));
    }
    const uint64_t seed = dimension_seed(seed_, dimension);
    uint64_t above = 0; // the original digits so far: the node of Owen's tree
    for (uint64_t position = 0; scale * double(base - 1) > 0x1p-26; ++position, scale /= double(base)) {
        const uint64_t digit = index % base;
        index /= base;
        const uint64_t key = randomization_ == Randomization::PermuteDigits
                                 ? seed + position
                                 : mix_bits(seed ^ (above * 0x9e3779b97f4a7c15ULL + position));
        value += double(permutation_element(uint32_t(digit), uint32_t(base), key)) * scale;
        above = above * base + digit;
    }
    return std::min(OneMinusEpsilon, float(value));
}

float HaltonSampler::get_1d() { return sample_dimension(halton_dimension(dimension_++), halton_index_); }

Vec2f HaltonSampler::get_2d() {
    float a = sample_dimension(halton_dimension(dimension_), halton_index_);
    float b = sample_dimension(halton_dimension(dimension_ + 1), halton_index_);
    dimension_ += 2;
    return {a, b};
}

Vec2f HaltonSampler::get_pixel_2d() {
    // The first two Halton dimensions without their tile digits, unscrambled as in pbrt-v4: the
    // position within the pixel.
    dimension_ += 2;
    return {radical_inverse(2, halton_index_ >> base_exponents_[0]),
            radical_inverse(3, halton_index_ / base_scales_[1])};
}

std::unique_ptr<Sampler> HaltonSampler::clone() const { return std::make_unique<HaltonSampler>(*this); }

} // namespace caustica
