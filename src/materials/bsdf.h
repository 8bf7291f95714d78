// A BxDF placed in the world by a shading frame. Rejects light leaks through the geometric
// normal is not done here: integrators own that decision.
#pragma once

#include "materials/bxdf.h"

namespace caustica {

class BSDF {
  public:
    BSDF() = default;
    BSDF(Vec3f ns, Vec3f dpdus, const BxDF *bxdf) : frame_(Frame::from_xz(dpdus, ns)), bxdf_(bxdf) {}
    // Another BxDF in the same shading frame.
    BSDF(const Frame &frame, const BxDF *bxdf) : frame_(frame), bxdf_(bxdf) {}

    explicit operator bool() const { return bxdf_ != nullptr; }
    // Path regularisation (BxDF::regularized): the BxDF is replaced, never changed in place, so
    // a BxDF that a material shares between points is left as it is.
    void regularize(ScratchBuffer &scratch) { bxdf_ = bxdf_->regularized(scratch); }
    BxDFFlags flags() const { return bxdf_->flags(); }
    const Frame &frame() const { return frame_; }
    Vec3f to_local(Vec3f v) const { return frame_.to_local(v); }
    Vec3f from_local(Vec3f v) const { return frame_.from_local(v); }

    SampledSpectrum f(Vec3f wo_world, Vec3f wi_world, TransportMode mode = TransportMode::Radiance) const {
        Vec3f wo = to_local(wo_world), wi = to_local(wi_world);
        if (wo.z == 0) return {};
        return bxdf_->f(wo, wi, mode);
    }
    std::optional<BSDFSample> sample_f(Vec3f wo_world, float uc, Vec2f u2,
                                       TransportMode mode = TransportMode::Radiance,
                                       SampleFlags sample_flags = SampleFlags::All) const {
        Vec3f wo = to_local(wo_world);
        if (wo.z == 0 || !(unsigned(bxdf_->flags()) & unsigned(sample_flags))) return {};
        auto bs = bxdf_->sample_f(wo, uc, u2, mode, sample_flags);
        if (!bs || bs->f.is_black() || bs->pdf == 0 || bs->wi.z == 0) return {};
        bs->wi = from_local(bs->wi);
        return bs;
    }
    bool has_lane_lobes() const { return bxdf_->has_lane_lobes(); }
    const Reradiation *reradiation() const { return bxdf_->reradiation(); }
    // sample_f as wavelength `lane` samples (BxDF::sample_f_as).
    std::optional<BSDFSample> sample_f_as(int lane, Vec3f wo_world, float uc, Vec2f u2,
                                          TransportMode mode = TransportMode::Radiance) const {
        Vec3f wo = to_local(wo_world);
        if (wo.z == 0) return {};
        auto bs = bxdf_->sample_f_as(lane, wo, uc, u2, mode);
        if (!bs || bs->f.is_black() || bs->pdf == 0 || bs->wi.z == 0) return {};
        bs->wi = from_local(bs->wi);
        return bs;
    }
    float pdf(Vec3f wo_world, Vec3f wi_world, TransportMode mode = TransportMode::Radiance,
              SampleFlags sample_flags = SampleFlags::All) const {
        Vec3f wo = to_local(wo_world), wi = to_local(wi_world);
        if (wo.z == 0) return 0;
        return bxdf_->pdf(wo, wi, mode, sample_flags);
    }

    // f(wo, wi) and the densities of sampling wi from wo (in mode) and wo from wi (in the adjoint
    // mode), with one change of frame and one call into the BxDF.
    BxDFEvaluation evaluate(Vec3f wo_world, Vec3f wi_world, TransportMode mode = TransportMode::Radiance) const {
        Vec3f wo = to_local(wo_world), wi = to_local(wi_world);
        if (wo.z == 0) return {};
        BxDFEvaluation e = bxdf_->evaluate(wo, wi, mode);
        if (wi.z == 0) e.pdf_reverse = 0;
        return e;
    }

  private:
    Frame frame_;
    const BxDF *bxdf_ = nullptr;
};

} // namespace caustica
