#include "materials/mix_material.h"

#include "core/rng.h"
#include "geometry/interaction.h"

#include <cstring>

namespace caustica {

namespace {

uint32_t float_bits(float v) {
    uint32_t b;
    std::memcpy(&b, &v, sizeof b);
    return b;
}

} // namespace

const Material &MixMaterial::choose(const SurfaceInteraction &si) const {
    const float amount = amount_->evaluate(TextureEvalContext(si));
    if (amount <= 0) return *materials_[0];
    if (amount >= 1) return *materials_[1];
    const uint64_t h = hash_values(float_bits(si.p.x), float_bits(si.p.y), float_bits(si.p.z),
                                   float_bits(si.wo.x), float_bits(si.wo.y), float_bits(si.wo.z));
    const float u = float(h >> 40) * 0x1p-24f;
    return amount < u ? *materials_[0] : *materials_[1];
}

BSDF MixMaterial::get_bsdf(const SurfaceInteraction &si, const SampledWavelengths &lambda,
                           ScratchBuffer &scratch) const {
    return choose(si).get_bsdf(si, lambda, scratch);
}

} // namespace caustica
