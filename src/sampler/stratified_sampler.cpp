#include "sampler/stratified_sampler.h"

#include "sampler/sample_hash.h"

#include <cmath>

namespace caustica {

StratifiedSampler::StratifiedSampler(int x_samples, int y_samples, bool jitter, int seed)
    : x_samples_(x_samples), y_samples_(y_samples), jitter_(jitter), seed_(seed) {}

void StratifiedSampler::start_pixel_sample(Vec2i pixel, int sample_index, int dimension) {
    int spp = samples_per_pixel();
    pixel_ = pixel;
    index_in_round_ = sample_index % spp;
    round_ = sample_index / spp;
    jitter_key_ = hash_values(pixel.x, pixel.y, sample_index, seed_);
    dimension_ = uint64_t(dimension);
}

int StratifiedSampler::stratum() {
    uint64_t permutation_seed = hash_values(pixel_.x, pixel_.y, dimension_, seed_, round_);
    return int(permutation_element(uint32_t(index_in_round_), uint32_t(samples_per_pixel()),
                                   permutation_seed));
}

float StratifiedSampler::get_1d() {
    int s = stratum();
    float delta = jitter_ ? sample_hash_uniform(jitter_key_, dimension_) : 0.5f;
    ++dimension_;
    return std::min((s + delta) / samples_per_pixel(), OneMinusEpsilon);
}

Vec2f StratifiedSampler::get_2d() {
    int s = stratum();
    int x = s % x_samples_, y = s / x_samples_;
    float dx = jitter_ ? sample_hash_uniform(jitter_key_, dimension_) : 0.5f;
    float dy = jitter_ ? sample_hash_uniform(jitter_key_, dimension_ + 1) : 0.5f;
    dimension_ += 2;
    return {std::min((x + dx) / x_samples_, OneMinusEpsilon),
            std::min((y + dy) / y_samples_, OneMinusEpsilon)};
}

std::unique_ptr<Sampler> StratifiedSampler::clone() const {
    return std::make_unique<StratifiedSampler>(*this);
}

Vec2i stratified_grid(int n) {
    int div = std::max(1, int(std::sqrt(double(n))));
    while (n % div != 0) --div;
    return {n / div, div};
}

} // namespace caustica
