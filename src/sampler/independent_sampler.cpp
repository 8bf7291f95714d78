#include "sampler/independent_sampler.h"

#include "sampler/sample_hash.h"

namespace caustica {

IndependentSampler::IndependentSampler(int samples_per_pixel, int seed)
    : samples_per_pixel_(samples_per_pixel), seed_(seed) {}

void IndependentSampler::start_pixel_sample(Vec2i pixel, int sample_index, int dimension) {
    key_ = hash_values(pixel.x, pixel.y, sample_index, seed_);
    dimension_ = uint64_t(dimension);
}

float IndependentSampler::get_1d() { return sample_hash_uniform(key_, dimension_++); }

Vec2f IndependentSampler::get_2d() {
    float u0 = sample_hash_uniform(key_, dimension_);
    float u1 = sample_hash_uniform(key_, dimension_ + 1);
    dimension_ += 2;
    return {u0, u1};
}

std::unique_ptr<Sampler> IndependentSampler::clone() const {
    return std::make_unique<IndependentSampler>(*this);
}

} // namespace caustica
