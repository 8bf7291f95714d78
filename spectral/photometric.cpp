#include "spectral/photometric.h"

#include "spectral/color_space.h"
#include "spectral/rgb_spectrum.h"

namespace caustica {

float spectrum_to_photometric(const Spectrum &s) {
    if (auto rgb = dynamic_cast<const RGBIlluminantSpectrum *>(&s))
        return inner_product_y(rgb->illuminant_spectrum());
    return inner_product_y(s);
}

RGB luminance_weights(const RGBColorSpace &cs) {
    const Matrix3 &m = cs.xyz_from_rgb_matrix();
    return {m[1][0], m[1][1], m[1][2]};
}

}  // namespace caustica
