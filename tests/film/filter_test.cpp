#include "core/rng.h"
#include "film/filter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

using namespace caustica;

namespace {

ParsedParameter float_param(const std::string &name, float v) {
    ParsedParameter p;
    p.type = "float";
    p.name = name;
    p.numbers = {double(v)};
    return p;
}

ParameterDictionary dict(std::vector<ParsedParameter> params) {
    return ParameterDictionary(std::move(params), SourceLocation{"scene.pbrt", 2, 1}, nullptr, ".");
}

// Midpoint quadrature of g over the filter's support, in double: independent of the filters'
// own integral() formulas and of their samplers.
double quadrature(const Filter &f, const std::function<double(Vec2f)> &g, int n = 600) {
    Vec2f r = f.radius();
    double hx = 2.0 * r.x / n, hy = 2.0 * r.y / n, sum = 0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            Vec2f p{float(-r.x + (i + 0.5) * hx), float(-r.y + (j + 0.5) * hy)};
            sum += g(p);
        }
    return sum * hx * hy;
}

struct SampledMoments {
    double mean_weight;           // E[w]
    double weighted_mean_r2;      // E[w |p|^2] / E[w]
    double weighted_mean_x;       // E[w x] / E[w]
};

// Drives sample() with a fine stratified grid of u, so the averages are deterministic and
// converge much faster than independent samples would.
SampledMoments sampled_moments(const Filter &f, int n = 500) {
    double w = 0, wr2 = 0, wx = 0;
    Vec2f r = f.radius();
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            FilterSample s = f.sample({(i + 0.5f) / n, (j + 0.5f) / n});
            EXPECT_LE(std::abs(s.p.x), r.x);
            EXPECT_LE(std::abs(s.p.y), r.y);
            w += s.weight;
            wr2 += s.weight * (sqr(s.p.x) + sqr(s.p.y));
            wx += s.weight * s.p.x;
        }
    return {w / (double(n) * n), wr2 / w, wx / w};
}

std::vector<std::unique_ptr<Filter>> all_filters() {
    std::vector<std::unique_ptr<Filter>> f;
    f.push_back(std::make_unique<BoxFilter>());
    f.push_back(std::make_unique<BoxFilter>(Vec2f{1.5f, 0.75f}));
    f.push_back(std::make_unique<GaussianFilter>());
    f.push_back(std::make_unique<GaussianFilter>(Vec2f{2, 1}, 0.8f));
    f.push_back(std::make_unique<TriangleFilter>());
    f.push_back(std::make_unique<TriangleFilter>(Vec2f{1, 0.5f}));
    f.push_back(std::make_unique<MitchellFilter>());
    f.push_back(std::make_unique<MitchellFilter>(Vec2f{1.5f, 2}, 0.2f, 0.6f));
    f.push_back(std::make_unique<LanczosSincFilter>());
    f.push_back(std::make_unique<LanczosSincFilter>(Vec2f{2, 3}, 2));
    return f;
}

} // namespace

TEST(Filter, IntegralMatchesQuadrature) {
    // Tolerance: the midpoint rule's error for these smooth (piecewise polynomial / analytic)
    // functions with 600 cells per axis is far below 1e-4 of the integral.
    for (auto &f : all_filters()) {
        double q = quadrature(*f, [&](Vec2f p) { return f->evaluate(p); });
        EXPECT_NEAR(f->integral(), q, 2e-4 * std::abs(q) + 1e-6);
    }
}

TEST(Filter, GaussianIsShiftedToZeroAtTheRadius) {
    GaussianFilter g;  // pbrt-v4's default: radius 1.5, sigma 0.5
    EXPECT_EQ(g.radius().x, 1.5f);
    EXPECT_NEAR(g.evaluate({1.5f, 0}), 0, 1e-7);
    EXPECT_EQ(g.evaluate({1.6f, 0}), 0);
    double peak = 1 / std::sqrt(2 * M_PI * 0.25), edge = peak * std::exp(-1.5 * 1.5 / 0.5);
    EXPECT_NEAR(g.evaluate({0, 0}), sqr(peak - edge), 1e-6);
}

TEST(Filter, SamplesReproduceTheFilterAsADensity) {
    // For the film, weighted samples must act as the filter: E[w g(p)] / E[w] equals
    // (integral of f g) / (integral of f) for any g. Checked with g = |p|^2 (is the spread
    // right?) and g = x (is it centred?) for the non-negative filters, driving sample() with a
    // fine stratified grid (deterministic, converges fast). Tabulated filters sample a
    // piecewise-constant table with 16 cells per pixel, whose moments are accurate to ~1e-3.
    std::unique_ptr<Filter> filters[] = {
        std::make_unique<BoxFilter>(), std::make_unique<BoxFilter>(Vec2f{1.5f, 0.75f}),
        std::make_unique<GaussianFilter>(), std::make_unique<GaussianFilter>(Vec2f{2, 1}, 0.8f),
        std::make_unique<TriangleFilter>(), std::make_unique<TriangleFilter>(Vec2f{1, 0.5f})};
    for (auto &f : filters) {
        SampledMoments m = sampled_moments(*f);
        double integral = quadrature(*f, [&](Vec2f p) { return f->evaluate(p); });
        double r2 = quadrature(*f, [&](Vec2f p) { return f->evaluate(p) * (sqr(p.x) + sqr(p.y)); }) /
                    integral;
        EXPECT_NEAR(m.weighted_mean_r2, r2, 3e-3 * r2);
        EXPECT_NEAR(m.weighted_mean_x, 0, 2e-3 * f->radius().x);
    }
}

TEST(Filter, SignedFiltersSubtractThroughNegativeWeights) {
    // Mitchell and Lanczos have negative lobes. With independent random u (a stratified grid
    // would not resolve the cancellation between lobes), the weighted samples estimate
    // integral(f g) for g = 1, |p|^2 and x. Bound: 4.5 standard errors of the estimate plus the
    // table's discretisation error, below 3e-3 of integral(|f g|).
    std::unique_ptr<Filter> filters[] = {
        std::make_unique<MitchellFilter>(), std::make_unique<MitchellFilter>(Vec2f{1.5f, 2}, 0.2f, 0.6f),
        std::make_unique<LanczosSincFilter>(), std::make_unique<LanczosSincFilter>(Vec2f{2, 3}, 2)};
    std::function<double(Vec2f)> moments[] = {[](Vec2f) { return 1.0; },
                                              [](Vec2f p) { return double(sqr(p.x) + sqr(p.y)); },
                                              [](Vec2f p) { return double(p.x); }};
    for (auto &f : filters) {
        for (auto &g : moments) {
            const int n = 200000;
            Rng rng(5, 6);
            double sum = 0, sum_sq = 0;
            for (int i = 0; i < n; ++i) {
                FilterSample s = f->sample(rng.uniform2());
                double v = s.weight * g(s.p);
                sum += v;
                sum_sq += v * v;
            }
            double mean = sum / n, std_error = std::sqrt((sum_sq / n - mean * mean) / n);
            double exact = quadrature(*f, [&](Vec2f p) { return f->evaluate(p) * g(p); }, 300);
            double scale = quadrature(*f, [&](Vec2f p) { return std::abs(f->evaluate(p) * g(p)); }, 300);
            EXPECT_NEAR(mean, exact, 4.5 * std_error + 3e-3 * scale);
        }
        // The negative lobes do produce negative weights.
        bool negative = false;
        for (int i = 0; i < 400 && !negative; ++i) negative = f->sample({(i + 0.5f) / 400, 0.5f}).weight < 0;
        EXPECT_TRUE(negative);
    }
}

TEST(Filter, TabulatedWeightsHaveConstantMagnitude) {
    // pbrt-v4's tabulated sampler returns f/pdf: a constant magnitude, the integral of |f| (of
    // the table, within ~1e-3 of the filter's), whose sign follows the table. For the Gaussian, which
    // never changes sign, the weights therefore average to its integral.
    std::unique_ptr<Filter> tabulated[] = {
        std::make_unique<GaussianFilter>(), std::make_unique<MitchellFilter>(),
        std::make_unique<LanczosSincFilter>(), std::make_unique<MitchellFilter>(Vec2f{1.5f, 2}, 0.2f, 0.6f)};
    for (auto &f : tabulated) {
        double abs_integral = quadrature(*f, [&](Vec2f p) { return std::abs(f->evaluate(p)); });
        for (Vec2f u : {Vec2f{0.5f, 0.5f}, Vec2f{0.02f, 0.3f}, Vec2f{0.97f, 0.99f}, Vec2f{0.3f, 0.7f}}) {
            FilterSample s = f->sample(u);
            EXPECT_NEAR(std::abs(s.weight), abs_integral, 3e-3 * abs_integral);
        }
    }
    GaussianFilter g;
    EXPECT_NEAR(sampled_moments(g).mean_weight, g.integral(), 1e-3 * g.integral());
}

TEST(Filter, ExactSamplersHaveUnitWeight) {
    BoxFilter box;
    TriangleFilter tri;
    for (Vec2f u : {Vec2f{0, 0}, Vec2f{0.3f, 0.9f}, Vec2f{OneMinusEpsilon, 0.5f}}) {
        EXPECT_EQ(box.sample(u).weight, 1);
        EXPECT_EQ(tri.sample(u).weight, 1);
    }
    // Box: uniform, E[x^2] = r^2/3; tent on [-r, r]: E[x^2] = r^2/6 (closed forms).
    EXPECT_NEAR(sampled_moments(box).weighted_mean_r2, 2 * 0.25 / 3, 1e-5);
    EXPECT_NEAR(sampled_moments(tri).weighted_mean_r2, 2 * 4.0 / 6, 5e-4);
}

TEST(FilterFactory, CreatesPbrtFiltersWithTheirDefaults) {
    SourceLocation loc{"scene.pbrt", 2, 1};
    EXPECT_EQ(create_filter("box", dict({}), loc)->radius().x, 0.5f);
    EXPECT_EQ(create_filter("gaussian", dict({}), loc)->radius().y, 1.5f);
    EXPECT_EQ(create_filter("triangle", dict({}), loc)->radius().x, 2.f);
    EXPECT_EQ(create_filter("mitchell", dict({}), loc)->radius().x, 2.f);
    EXPECT_EQ(create_filter("sinc", dict({}), loc)->radius().x, 4.f);
    auto g = create_filter("gaussian", dict({float_param("xradius", 2), float_param("sigma", 1)}), loc);
    EXPECT_EQ(g->radius().x, 2.f);
    EXPECT_EQ(g->radius().y, 1.5f);
    EXPECT_NEAR(g->integral(), GaussianFilter({2, 1.5f}, 1).integral(), 1e-7);
}

TEST(FilterFactory, RejectsBadInput) {
    SourceLocation loc{"scene.pbrt", 2, 1};
    EXPECT_THROW(create_filter("lanczos", dict({}), loc), InputError);
    EXPECT_THROW(create_filter("box", dict({float_param("xradius", -1)}), loc), InputError);
    EXPECT_THROW(create_filter("gaussian", dict({float_param("sigma", 0)}), loc), InputError);
}
