#include "materials/mix_material.h"

#include "core/rng.h"
#include "geometry/interaction.h"

#include <bit>

namespace caustica {

const Material &MixMaterial::choose(const SurfaceInteraction &si) const {
    const float amount = amount_->evaluate(TextureEvalContext(si));
    if (amount <= 0) return *materials_[0];
    if (amount >= 1) return *materials_[1];
    auto bits = [](float v) { return std::bit_cast<uint32_t>(v); };
    const uint64_t h = hash_values(bits(si.p.x), bits(si.p.y), bits(si.p.z), bits(si.wo.x), bits(si.wo.y), bits(si.wo.z));
    const float u = float(h >> 40) * 0x1p-24f;
    return amount < u ? *materials_[0] : *materials_[1];
}

BSDF MixMaterial::get_bsdf(const SurfaceInteraction &si, const SampledWavelengths &lambda,
                           ScratchBuffer &scratch) const {
    return choose(si).get_bsdf(si, lambda, scratch);
}

} // namespace caustica
