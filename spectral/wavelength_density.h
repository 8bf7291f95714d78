// The density that hero wavelengths are drawn from, fitted to the light a scene emits.
//
// pbrt-v4 draws wavelengths from one fixed density close to the eye's response
// (visible_wavelengths_pdf). Under spiky light (a sodium lamp's 8-nm line, the fluorescent
// illuminants F1-F12, lasers, LEDs) most of those wavelengths fall where nothing is emitted, and
// the few that hit a line carry the whole image: the estimate is heavy-tailed in every integrator,
// and the photon integrators, whose wavelength groups share one set of wavelengths over many
// pixels (wavelength_groups.h), make that noise correlated over whole groups.
//
// So the density is a defensive mixture (Hesterberg 1995): half the visible density, half the
// visible density times the scene's emitted spectral power Phi(lambda), normalised,
//
//     p(lambda) = 1/2 p_vis(lambda) + 1/2 p_vis(lambda) Phi(lambda) / int p_vis Phi.
//
// Half of all wavelengths then fall where the lights emit, in proportion to how much they emit
// there and how much the eye sees it, while no wavelength's density drops below half the visible
// density, so no estimate's weight grows by more than 2 against pbrt-v4's choice. Under smooth
// light the two halves nearly coincide. The density is tabulated in bins of 1 nm (each bin's mean
// of both terms, from four points per bin), piecewise constant; sampling inverts its cumulative
// distribution exactly, so pdf() is the density of sample().
#pragma once

#include <functional>
#include <vector>

namespace caustica {

class WavelengthDensity {
  public:
    // power(lambda): the scene's emitted spectral power at lambda, >= 0 (any positive scale).
    // Without visible power the density is the visible one alone.
    explicit WavelengthDensity(const std::function<float(float)> &power);

    float pdf(float lambda) const;
    // The wavelength at u in [0, 1) of the inverse cumulative distribution.
    float sample(float u) const;

  private:
    // The bin whose cumulative range holds u: the last b with cdf_[b] <= u, within [0, bins).
    int bin_of(float u) const;

    std::vector<float> pdf_, cdf_; // per bin of BinWidth nm from LambdaMin; cdf_ has one more entry
    std::vector<int> guide_;       // guide_[k] = bin_of(k / bins), where sample() starts looking
};

} // namespace caustica
