#include "spectral/rgb_spectrum.h"

#include <tuple>
#include <utility>

namespace caustica {

namespace {

// The scale 2 m and the coefficients of rgb / (2 m) shared by the unbounded flavours.
std::pair<float, SigmoidPolynomial> scaled_coefficients(const RGBColorSpace &cs, const RGB &rgb) {
    RGB c = clamp_zero(rgb);
    float scale = 2 * c.max_component();
    return {scale, cs.to_coefficients(scale > 0 ? c / scale : RGB{})};
}

} // namespace

RGBUnboundedSpectrum::RGBUnboundedSpectrum(const RGBColorSpace &cs, const RGB &rgb) {
    std::tie(scale_, rsp_) = scaled_coefficients(cs, rgb);
}

RGBIlluminantSpectrum::RGBIlluminantSpectrum(const RGBColorSpace &cs, const RGB &rgb)
    : illuminant_(&cs.illuminant()) {
    std::tie(scale_, rsp_) = scaled_coefficients(cs, rgb);
}

} // namespace caustica
