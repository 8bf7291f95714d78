#include "film/filter.h"

#include <cmath>

namespace caustica {

// ---- FilterSampler ----

FilterSampler::FilterSampler(const Filter &filter)
    : radius_(filter.radius()), nx_(std::max(1, int(32 * radius_.x))),
      ny_(std::max(1, int(32 * radius_.y))) {
    // The filter at cell centres, row by row (rows are y).
    f_.resize(size_t(nx_) * ny_);
    for (int y = 0; y < ny_; ++y)
        for (int x = 0; x < nx_; ++x) {
            Vec2f p{lerp((x + 0.5f) / nx_, -radius_.x, radius_.x),
                    lerp((y + 0.5f) / ny_, -radius_.y, radius_.y)};
            f_[size_t(y) * nx_ + x] = filter.evaluate(p);
        }
    distribution_ = PiecewiseConstant2D(f_, nx_, ny_);
    // The density of a cell is its |f| over the integral of |f| over the support, so f / pdf is
    // that integral, with f's sign, in every cell.
    abs_integral_ = distribution_.integral() * 4 * radius_.x * radius_.y;
}

FilterSample FilterSampler::sample(Vec2f u) const {
    Vec2f p01 = distribution_.sample(u, nullptr);
    int x = clamp(int(p01.x * nx_), 0, nx_ - 1), y = clamp(int(p01.y * ny_), 0, ny_ - 1);
    const float f = f_[size_t(y) * nx_ + x];
    Vec2f p{lerp(p01.x, -radius_.x, radius_.x), lerp(p01.y, -radius_.y, radius_.y)};
    return {p, f > 0 ? abs_integral_ : (f < 0 ? -abs_integral_ : 0.f)};
}

// ---- Box ----

float BoxFilter::evaluate_x(float x) const { return std::abs(x) <= radius_.x ? 1.f : 0.f; }
float BoxFilter::evaluate_y(float y) const { return std::abs(y) <= radius_.y ? 1.f : 0.f; }

FilterSample BoxFilter::sample(Vec2f u) const {
    return {{lerp(u.x, -radius_.x, radius_.x), lerp(u.y, -radius_.y, radius_.y)}, 1.f};
}

// ---- Gaussian ----

namespace {

float gaussian(float x, float sigma) {
    return std::exp(-sqr(x) / (2 * sqr(sigma))) / std::sqrt(2 * Pi * sqr(sigma));
}

// Integral of gaussian() over [x0, x1].
float gaussian_integral(float x0, float x1, float sigma) {
    float s = sigma * std::sqrt(2.f);
    return 0.5f * (std::erf(x1 / s) - std::erf(x0 / s));
}

} // namespace

GaussianFilter::GaussianFilter(Vec2f radius, float sigma)
    : radius_(radius), sigma_(sigma), value_at_radius_x_(gaussian(radius.x, sigma)),
      value_at_radius_y_(gaussian(radius.y, sigma)) {
    sampler_ = FilterSampler(*this);
}

float GaussianFilter::evaluate_x(float x) const {
    return std::max(0.f, gaussian(x, sigma_) - value_at_radius_x_);
}
float GaussianFilter::evaluate_y(float y) const {
    return std::max(0.f, gaussian(y, sigma_) - value_at_radius_y_);
}

float GaussianFilter::integral() const {
    return (gaussian_integral(-radius_.x, radius_.x, sigma_) - 2 * radius_.x * value_at_radius_x_) *
           (gaussian_integral(-radius_.y, radius_.y, sigma_) - 2 * radius_.y * value_at_radius_y_);
}

// ---- Triangle ----

float TriangleFilter::evaluate_x(float x) const { return std::max(0.f, radius_.x - std::abs(x)); }
float TriangleFilter::evaluate_y(float y) const { return std::max(0.f, radius_.y - std::abs(y)); }

namespace {

// Inverts the CDF of the tent (r - |x|) on [-r, r]: each half is chosen with probability 1/2
// and the linear density within it is inverted in closed form.
float sample_tent(float u, float r) {
    if (u < 0.5f) {
        float v = std::min(u * 2, OneMinusEpsilon);
        return -r + r * std::sqrt(v);
    }
    float v = std::min(u * 2 - 1, OneMinusEpsilon);
    return r * (1 - std::sqrt(1 - v));
}

} // namespace

FilterSample TriangleFilter::sample(Vec2f u) const {
    return {{sample_tent(u.x, radius_.x), sample_tent(u.y, radius_.y)}, 1.f};
}

// ---- Mitchell ----

MitchellFilter::MitchellFilter(Vec2f radius, float b, float c) : radius_(radius), b_(b), c_(c) {
    sampler_ = FilterSampler(*this);
}

float MitchellFilter::mitchell_1d(float x) const {
    x = std::abs(x);
    const float b = b_, c = c_;
    if (x <= 1)
        return ((12 - 9 * b - 6 * c) * x * x * x + (-18 + 12 * b + 6 * c) * x * x + (6 - 2 * b)) /
               6;
    if (x <= 2)
        return ((-b - 6 * c) * x * x * x + (6 * b + 30 * c) * x * x + (-12 * b - 48 * c) * x +
                (8 * b + 24 * c)) /
               6;
    return 0;
}

float MitchellFilter::evaluate_x(float x) const { return mitchell_1d(2 * x / radius_.x); }
float MitchellFilter::evaluate_y(float y) const { return mitchell_1d(2 * y / radius_.y); }

// ---- Lanczos sinc ----

namespace {

double sinc(double x) {
    if (std::abs(x) < 1e-5) return 1 - sqr(Pi * x) / 6;
    return std::sin(Pi * x) / (Pi * x);
}

double windowed_sinc(double x, double radius, double tau) {
    if (std::abs(x) > radius) return 0;
    return sinc(x) * sinc(x / tau);
}

// The 1D windowed sinc integrated over [-radius, radius] by composite Simpson quadrature; the
// filter is separable, so its 2D integral is the product of two of these. (pbrt-v4 estimates the
// 2D integral by Monte Carlo instead; this is the exact value up to ~1e-9.)
double windowed_sinc_integral(double radius, double tau) {
    const int n = 4096; // even
    double h = 2 * radius / n, sum = 0;
    for (int i = 0; i <= n; ++i) {
        double w = (i == 0 || i == n) ? 1 : (i % 2 == 1 ? 4 : 2);
        sum += w * windowed_sinc(-radius + i * h, radius, tau);
    }
    return sum * h / 3;
}

} // namespace

LanczosSincFilter::LanczosSincFilter(Vec2f radius, float tau)
    : radius_(radius), tau_(tau),
      integral_(float(windowed_sinc_integral(radius.x, tau) * windowed_sinc_integral(radius.y, tau))) {
    sampler_ = FilterSampler(*this);
}

float LanczosSincFilter::evaluate_x(float x) const {
    return float(windowed_sinc(x, radius_.x, tau_));
}
float LanczosSincFilter::evaluate_y(float y) const {
    return float(windowed_sinc(y, radius_.y, tau_));
}

// ---- Factory ----

namespace {

Vec2f read_radius(const ParameterDictionary &params, float def) {
    Vec2f r{params.get_one_float("xradius", def), params.get_one_float("yradius", def)};
    if (!(r.x > 0)) throw InputError(params.location("xradius"), "\"xradius\" must be positive");
    if (!(r.y > 0)) throw InputError(params.location("yradius"), "\"yradius\" must be positive");
    if (r.x > MaxFilterRadius)
        throw InputError(params.location("xradius"), "\"xradius\" must be at most " +
                                                         std::to_string(int(MaxFilterRadius)) + " pixels");
    if (r.y > MaxFilterRadius)
        throw InputError(params.location("yradius"), "\"yradius\" must be at most " +
                                                         std::to_string(int(MaxFilterRadius)) + " pixels");
    return r;
}

} // namespace

std::unique_ptr<Filter> create_filter(const std::string &type, const ParameterDictionary &params,
                                      const SourceLocation &loc) {
    if (type == "box") return std::make_unique<BoxFilter>(read_radius(params, 0.5f));
    if (type == "gaussian") {
        Vec2f r = read_radius(params, 1.5f);
        float sigma = params.get_one_float("sigma", 0.5f);
        if (!(sigma > 0)) throw InputError(params.location("sigma"), "\"sigma\" must be positive");
        return std::make_unique<GaussianFilter>(r, sigma);
    }
    if (type == "triangle") return std::make_unique<TriangleFilter>(read_radius(params, 2));
    if (type == "mitchell") {
        Vec2f r = read_radius(params, 2);
        return std::make_unique<MitchellFilter>(r, params.get_one_float("B", 1.f / 3),
                                                params.get_one_float("C", 1.f / 3));
    }
    if (type == "sinc") {
        Vec2f r = read_radius(params, 4);
        float tau = params.get_one_float("tau", 3);
        if (!(tau > 0)) throw InputError(params.location("tau"), "\"tau\" must be positive");
        return std::make_unique<LanczosSincFilter>(r, tau);
    }
    throw InputError(loc, "\"" + type + "\": unknown filter type");
}

} // namespace caustica
