#include "materials/thin_film.h"

#include "core/vecmath.h"
#include "textures/texture.h"

#include <cmath>

namespace caustica {

namespace {

using Complex = std::complex<double>;

// n cos(theta) in a medium of index n for light whose direction has sin^2(theta1) = sin2_1 in
// the first medium (Snell's law: n sin(theta) is conserved), on the branch with a non-negative
// imaginary part (a decaying wave when evanescent or absorbed).
Complex n_cos(Complex n, double sin2_1) {
    Complex c = std::sqrt(n * n - sin2_1);
    return c.imag() < 0 ? -c : c;
}

struct Amplitudes {
    Complex r, t;
};

// Fresnel amplitudes from medium i into medium j, with ni_cos = n_i cos(theta_i) and so on.
Amplitudes s_amplitudes(Complex ni_cos, Complex nj_cos) {
    return {(ni_cos - nj_cos) / (ni_cos + nj_cos), 2.0 * ni_cos / (ni_cos + nj_cos)};
}
Amplitudes p_amplitudes(Complex ni, Complex nj, Complex ni_cos, Complex nj_cos) {
    // With cos_i = ni_cos / ni: (n_j cos_i - n_i cos_j) / (n_j cos_i + n_i cos_j), multiplied
    // through by n_i n_j to stay in the n cos terms.
    Complex a = nj * nj * ni_cos, b = ni * ni * nj_cos;
    return {(a - b) / (a + b), 2.0 * ni * nj * ni_cos / (a + b)};
}

} // namespace

FilmResponse thin_film_response(float cos_i, float film_eta, std::complex<float> base_eta,
                                float thickness_nm, float lambda_nm) {
    const double cos1 = clamp(double(cos_i), 0.0, 1.0), sin2_1 = 1 - cos1 * cos1;
    const Complex n1 = 1, n2 = double(film_eta), n3(base_eta.real(), base_eta.imag());
    const Complex c1 = cos1, c2 = n_cos(n2, sin2_1), c3 = n_cos(n3, sin2_1);
    // Phase across the film and back: e^{2 i delta}.
    const Complex delta = 2 * 3.14159265358979323846 * double(thickness_nm) / double(lambda_nm) * c2;
    const Complex phase = std::exp(Complex(0, 1) * delta), phase2 = phase * phase;
    FilmResponse response;
    for (int polarisation = 0; polarisation < 2; ++polarisation) {
        Amplitudes a12 = polarisation == 0 ? s_amplitudes(c1, c2) : p_amplitudes(n1, n2, c1, c2);
        Amplitudes a23 = polarisation == 0 ? s_amplitudes(c2, c3) : p_amplitudes(n2, n3, c2, c3);
        const Complex denominator = 1.0 + a12.r * a23.r * phase2;
        const Complex r = (a12.r + a23.r * phase2) / denominator;
        const Complex t = a12.t * a23.t * phase / denominator;
        response.reflectance += float(std::norm(r) / 2);
        // Power into the base: the ratio of normal energy fluxes. The p amplitudes are of the
        // electric field, whose flux carries the same factor Re(n3 cos3) / (n1 cos1).
        if (base_eta.imag() == 0 && cos1 > 0)
            response.transmittance += float(c3.real() / cos1 * std::norm(t) / 2);
    }
    return response;
}

SampledSpectrum ThinFilm::over_conductor(float cos_i, const SampledSpectrum &base_eta,
                                         const SampledSpectrum &k) const {
    SampledSpectrum r;
    for (int i = 0; i < NumWavelengths; ++i)
        r[i] = thin_film_response(cos_i, eta[i], {base_eta[i], k[i]}, thickness_nm, lambda[i]).reflectance;
    return r;
}

float ThinFilm::over_dielectric(float cos_d, float base_eta, int lane) const {
    if (cos_d >= 0) return thin_film_response(cos_d, eta[lane], base_eta, thickness_nm, lambda[lane]).reflectance;
    // Seen from inside: indices relative to the dielectric's; the thickness scaled by its index
    // keeps the film's phase, which depends on the film's absolute index.
    return thin_film_response(-cos_d, eta[lane] / base_eta, 1 / base_eta, thickness_nm * base_eta, lambda[lane])
        .reflectance;
}

ThinFilm FilmLayer::at(const TextureEvalContext &ctx, const SampledWavelengths &lambda) const {
    ThinFilm film;
    if (!thickness) return film;
    film.thickness_nm = std::max(thickness->evaluate(ctx), 0.f);
    if (!film.present()) return film;
    film.eta = eta->sample(lambda);
    for (int i = 0; i < NumWavelengths; ++i) film.lambda[i] = lambda[i];
    return film;
}

bool FilmLayer::may_be_present() const {
    if (!thickness) return false;
    const float *constant = thickness->constant_value();
    return !constant || *constant > 0;
}

} // namespace caustica
