#include "materials/subsurface_entry_bxdf.h"

namespace caustica {

SampledSpectrum SubsurfaceEntryBxDF::f(Vec3f wo, Vec3f wi, TransportMode mode) const {
    if (wo.z > 0 && wi.z <= 0) return {};
    return boundary_.f(wo, wi, mode);
}

float SubsurfaceEntryBxDF::pdf(Vec3f wo, Vec3f wi, TransportMode mode, SampleFlags flags) const {
    if (wo.z > 0 && wi.z <= 0) return 0;
    return boundary_.pdf(wo, wi, mode, flags);
}

std::optional<BSDFSample> SubsurfaceEntryBxDF::sample_f(Vec3f wo, float uc, Vec2f u, TransportMode mode,
                                                        SampleFlags flags) const {
    std::optional<BSDFSample> s = boundary_.sample_f(wo, uc, u, mode, flags);
    if (!s || wo.z <= 0 || !s->is_transmission()) return s;
    const float cos_in = std::abs(s->wi.z);
    SampledSpectrum weight = s->f * (cos_in / s->pdf);
    if (mode == TransportMode::Radiance) weight *= sqr(s->eta);
    BSDFSample entry;
    entry.wi = {0, 0, -1};
    entry.pdf = s->pdf;
    entry.f = weight * entry.pdf;
    entry.flags = BxDFDiffuseTransmission;
    return entry;
}

} // namespace caustica
