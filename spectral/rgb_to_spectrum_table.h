// RGB to spectrum (Jakob and Hanika 2019): the sigmoid polynomial (sigmoid_polynomial.h) whose
// spectrum, as a reflectance under a colour space's illuminant, has a given RGB colour. The
// coefficients are optimised offline on a grid and interpolated trilinearly here.
#pragma once

#include "spectral/color.h"
#include "spectral/rgb_to_spectrum_data.h"
#include "spectral/sigmoid_polynomial.h"

namespace caustica {

class RGBToSpectrumTable {
  public:
    explicit RGBToSpectrumTable(const RGBToSpectrumTableData &data);
    // rgb must lie in [0, 1]^3.
    SigmoidPolynomial operator()(const RGB &rgb) const;
    int resolution() const { return resolution_; }

  private:
    int resolution_;
    const float *scale_;
    const float *coefficients_;
};

} // namespace caustica
