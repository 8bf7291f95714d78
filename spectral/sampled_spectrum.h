// A spectral quantity evaluated at the path's four wavelengths (see sampled_wavelengths.h).
// Four floats in one 16-byte aligned register: element-wise arithmetic auto-vectorises.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

namespace caustica {

inline constexpr int NumWavelengths = 4;

class alignas(16) SampledSpectrum {
  public:
    SampledSpectrum() = default;
    explicit SampledSpectrum(float c) { v_.fill(c); }
    SampledSpectrum(float a, float b, float c, float d) : v_{a, b, c, d} {}

    float operator[](int i) const { return v_[i]; }
    float &operator[](int i) { return v_[i]; }

#define CAUSTICA_SPECTRUM_OP(op)                                                                   \
    SampledSpectrum &operator op##=(const SampledSpectrum & o) {                                   \
        for (int i = 0; i < NumWavelengths; ++i) v_[i] op## = o.v_[i];                             \
        return *this;                                                                              \
    }                                                                                              \
    SampledSpectrum operator op(const SampledSpectrum &o) const {                                  \
        SampledSpectrum r = *this;                                                                 \
        return r op## = o;                                                                         \
    }                                                                                              \
    SampledSpectrum &operator op##=(float s) {                                                     \
        for (int i = 0; i < NumWavelengths; ++i) v_[i] op## = s;                                   \
        return *this;                                                                              \
    }                                                                                              \
    SampledSpectrum operator op(float s) const {                                                   \
        SampledSpectrum r = *this;                                                                 \
        return r op## = s;                                                                         \
    }
    CAUSTICA_SPECTRUM_OP(+)
    CAUSTICA_SPECTRUM_OP(-)
    CAUSTICA_SPECTRUM_OP(*)
    CAUSTICA_SPECTRUM_OP(/)
#undef CAUSTICA_SPECTRUM_OP

    SampledSpectrum operator-() const { return *this * -1.f; }
    bool operator==(const SampledSpectrum &o) const { return v_ == o.v_; }

    // True when every wavelength is exactly zero: lets paths terminate early.
    bool is_black() const {
        for (float x : v_)
            if (x != 0) return false;
        return true;
    }
    explicit operator bool() const { return !is_black(); }
    bool has_non_finite() const {
        for (float x : v_)
            if (!std::isfinite(x)) return true;
        return false;
    }
    float max_value() const { return std::max(std::max(v_[0], v_[1]), std::max(v_[2], v_[3])); }
    float min_value() const { return std::min(std::min(v_[0], v_[1]), std::min(v_[2], v_[3])); }
    float average() const { return (v_[0] + v_[1] + v_[2] + v_[3]) * 0.25f; }
    const std::array<float, NumWavelengths> &values() const { return v_; }

  private:
    std::array<float, NumWavelengths> v_{};
};

inline SampledSpectrum operator*(float s, const SampledSpectrum &v) { return v * s; }
inline SampledSpectrum operator/(float s, const SampledSpectrum &v) { return SampledSpectrum(s) / v; }

// Element-wise functions; safe_div returns 0 where the divisor is 0 (as for terminated wavelengths).
inline SampledSpectrum safe_div(SampledSpectrum a, const SampledSpectrum &b) {
    for (int i = 0; i < NumWavelengths; ++i) a[i] = b[i] != 0 ? a[i] / b[i] : 0.f;
    return a;
}
inline SampledSpectrum sqrt(SampledSpectrum s) {
    for (int i = 0; i < NumWavelengths; ++i) s[i] = std::sqrt(std::max(0.f, s[i]));
    return s;
}
inline SampledSpectrum exp(SampledSpectrum s) {
    for (int i = 0; i < NumWavelengths; ++i) s[i] = std::exp(s[i]);
    return s;
}
inline SampledSpectrum clamp_zero(SampledSpectrum s) {
    for (int i = 0; i < NumWavelengths; ++i) s[i] = std::max(0.f, s[i]);
    return s;
}
inline SampledSpectrum lerp(float t, const SampledSpectrum &a, const SampledSpectrum &b) {
    return a * (1 - t) + b * t;
}

} // namespace caustica
