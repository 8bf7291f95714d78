// Shape sampling: densities integrate to one, agree with pdf(), and reproduce closed-form solid
// angles and areas. Integrals use jittered stratified grids with fixed seeds; tolerances are a
// few times the error such grids show for these (piecewise smooth) integrands.
#include "core/sampling.h"
#include "geometry/disk.h"
#include "geometry/sphere.h"
#include "geometry/triangle.h"
#include "geometry_test_util.h"

#include <functional>

namespace caustica {
namespace {

// Calls f(u) on an n x n jittered grid of [0,1)^2.
void for_each_stratum(int n, uint64_t seed, const std::function<void(Vec2f)> &f) {
    Rng rng(seed, 17);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
            f({std::min(OneMinusEpsilon, (i + rng.uniform()) / n),
               std::min(OneMinusEpsilon, (j + rng.uniform()) / n)});
}

// Integral of shape.pdf(ref, .) over all directions.
double integrate_pdf(const Shape &shape, Vec3f ref, int n = 1000) {
    double sum = 0;
    for_each_stratum(n, 1, [&](Vec2f u) { sum += shape.pdf(ref, sample_uniform_sphere(u)); });
    return sum * 4 * M_PI / (double(n) * n);
}

// Solid angle of the shape seen from ref, by ray casting alone (independent of sampling).
double solid_angle_by_casting(const Shape &shape, Vec3f ref, int n = 1000) {
    double hits = 0;
    for_each_stratum(n, 2, [&](Vec2f u) {
        hits += shape.intersect(ref, sample_uniform_sphere(u), Infinity).has_value();
    });
    return hits * 4 * M_PI / (double(n) * n);
}

struct SampleStats {
    double mean_inverse_pdf = 0;
    double max_pdf_mismatch = 0; // relative difference between sample pdf and pdf()
    int failures = 0;
};

SampleStats sample_from(const Shape &shape, Vec3f ref, int n = 300) {
    SampleStats stats;
    double sum = 0;
    for_each_stratum(n, 3, [&](Vec2f u) {
        auto ss = shape.sample(ref, u);
        if (!ss) {
            ++stats.failures;
            return;
        }
        sum += 1 / double(ss->pdf);
        float pdf = shape.pdf(ref, normalize(ss->p - ref));
        stats.max_pdf_mismatch =
            std::max(stats.max_pdf_mismatch, double(std::abs(pdf - ss->pdf) / ss->pdf));
    });
    stats.mean_inverse_pdf = sum / (double(n) * n);
    return stats;
}

TEST(SphereSampling, ConeFromOutside) {
    // Render radius R = 2 at c; seen from distance d = 3.
    Vec3f c{1, -2, 3};
    auto s = std::make_shared<Sphere>(Transform::translate(c) * Transform::scale(2, 2, 2), false, 1,
                                      -1, 1, 360);
    Vec3f ref = c + normalize(Vec3f{1, 1, -1}) * 3;
    double omega = 2 * M_PI * (1 - std::sqrt(1 - 4.0 / 9));
    SampleStats stats = sample_from(*s, ref);
    EXPECT_EQ(stats.failures, 0);
    EXPECT_NEAR(stats.mean_inverse_pdf, omega, 1e-4 * omega);
    EXPECT_LT(stats.max_pdf_mismatch, 1e-3);
    EXPECT_NEAR(integrate_pdf(*s, ref), 1, 2e-3);
    EXPECT_NEAR(solid_angle_by_casting(*s, ref), omega, 2e-3 * omega);

    // Samples are visible points on the sphere, uniform in the cone: cos theta from the axis
    // is uniform on [cos theta_max, 1]. 10 bins of 1e5 samples: each holds 0.1 +- 0.001 (one
    // standard deviation), so a 0.006 bound fails only for a real bias.
    Vec3f axis = normalize(c - ref);
    double cos_max = std::sqrt(1 - 4.0 / 9);
    int bins[10] = {};
    Rng rng(4, 4);
    const int n = 100000;
    for (int i = 0; i < n; ++i) {
        auto ss = s->sample(ref, rng.uniform2());
        ASSERT_TRUE(ss);
        ASSERT_NEAR(distance(ss->p, c), 2, 1e-5);
        ASSERT_GT(dot(ss->n, ref - ss->p), -1e-4f);
        double cos_theta = dot(normalize(ss->p - ref), axis);
        int bin = std::clamp(int((1 - cos_theta) / (1 - cos_max) * 10), 0, 9);
        ++bins[bin];
    }
    for (int count : bins) EXPECT_NEAR(count / double(n), 0.1, 0.006);
}

TEST(SphereSampling, FromInside) {
    auto s = std::make_shared<Sphere>(Transform::translate({0, 0, 1}), false, 2, -2, 2, 360);
    Vec3f ref{0.6f, -0.3f, 1.5f};
    SampleStats stats = sample_from(*s, ref);
    EXPECT_EQ(stats.failures, 0);
    EXPECT_NEAR(stats.mean_inverse_pdf, 4 * M_PI, 5e-3 * 4 * M_PI);
    EXPECT_LT(stats.max_pdf_mismatch, 1e-3);
    EXPECT_NEAR(integrate_pdf(*s, ref), 1, 2e-3);
}

TEST(SphereSampling, EllipsoidDensitiesAreExact) {
    // A non-uniform scale: area and solid-angle densities must carry the transform's distortion.
    Transform t = Transform::translate({0.5f, 0, -1}) * Transform::rotate(30, {0, 1, 1}) *
                  Transform::scale(1, 2, 0.5f);
    auto s = std::make_shared<Sphere>(t, false, 1, -1, 1, 360);
    for (Vec3f ref : {Vec3f{3, 1, 0}, Vec3f{0.6f, 0.2f, -0.9f}}) {
        SampleStats stats = sample_from(*s, ref);
        EXPECT_EQ(stats.failures, 0);
        EXPECT_LT(stats.max_pdf_mismatch, 2e-3);
        EXPECT_NEAR(integrate_pdf(*s, ref), 1, 3e-3);
        double omega = solid_angle_by_casting(*s, ref);
        EXPECT_NEAR(stats.mean_inverse_pdf, omega, 5e-3 * omega);
    }
    // Area sampling: the mean of 1 / pdf over samples is the area, here against the oblate
    // spheroid's closed form (semi-axes a = 2, c = 1).
    auto spheroid = std::make_shared<Sphere>(Transform::scale(2, 2, 1), false, 1, -1, 1, 360);
    double a = 2, c = 1, e = std::sqrt(1 - c * c / (a * a));
    double area = 2 * M_PI * a * a + M_PI * c * c / e * std::log((1 + e) / (1 - e));
    double sum = 0;
    for_each_stratum(300, 5, [&](Vec2f u) {
        auto ss = spheroid->sample(u);
        sum += 1 / double(ss->pdf);
        // On the surface x^2/4 + y^2/4 + z^2 = 1.
        EXPECT_NEAR(sqr(ss->p.x / 2) + sqr(ss->p.y / 2) + sqr(ss->p.z), 1, 1e-5);
    });
    EXPECT_NEAR(sum / (300.0 * 300), area, 2e-3 * area);
}

std::shared_ptr<const TriangleMesh> single_triangle(Vec3f a, Vec3f b, Vec3f c) {
    return test::mesh_group({}, false, {0, 1, 2}, {a, b, c})->mesh;
}

// Uniform in solid angle: the share of samples landing in each of the four midpoint
// sub-triangles equals its share of the solid angle. With 1e5 samples a share's standard
// deviation is below 0.0016, so the 0.008 bound fails only for a real bias.
void expect_uniform_over_subtriangles(const Triangle &tri, Vec3f p0, Vec3f p1, Vec3f p2,
                                      Vec3f ref) {
    Vec3f m01 = (p0 + p1) * 0.5f, m12 = (p1 + p2) * 0.5f, m20 = (p2 + p0) * 0.5f;
    Triangle sub[4] = {Triangle(single_triangle(p0, m01, m20), 0),
                       Triangle(single_triangle(m01, p1, m12), 0),
                       Triangle(single_triangle(m20, m12, p2), 0),
                       Triangle(single_triangle(m01, m12, m20), 0)};
    Vec3f n = normalize(cross(p1 - p0, p2 - p0));
    double omega = tri.solid_angle(ref);
    int counts[4] = {};
    Rng rng(6, 6);
    const int n_samples = 100000;
    for (int i = 0; i < n_samples; ++i) {
        auto ss = tri.sample(ref, rng.uniform2());
        ASSERT_TRUE(ss);
        ASSERT_NEAR(dot(ss->p - p0, n), 0, 1e-5f); // on the triangle's plane
        Vec3f w = normalize(ss->p - ref);
        for (int k = 0; k < 4; ++k)
            if (sub[k].intersect(ref, w, Infinity)) {
                ++counts[k];
                break;
            }
    }
    for (int k = 0; k < 4; ++k)
        EXPECT_NEAR(counts[k] / double(n_samples), sub[k].solid_angle(ref) / omega, 0.008) << k;
}

TEST(TriangleSampling, SphericalTriangleOfAnOctant) {
    // Any triangle with one vertex on each positive axis covers an octant of directions seen from
    // the origin: pi / 2.
    Triangle tri(single_triangle({1, 0, 0}, {0, 2, 0}, {0, 0, 3}), 0);
    Vec3f ref{0, 0, 0};
    EXPECT_NEAR(tri.solid_angle(ref), Pi / 2, 1e-6);
    SampleStats stats = sample_from(tri, ref);
    EXPECT_EQ(stats.failures, 0);
    EXPECT_NEAR(stats.mean_inverse_pdf, M_PI / 2, 1e-5);
    EXPECT_LT(stats.max_pdf_mismatch, 1e-5);
    EXPECT_NEAR(integrate_pdf(tri, ref), 1, 2e-3);

    expect_uniform_over_subtriangles(tri, {1, 0, 0}, {0, 2, 0}, {0, 0, 3}, ref);
}

TEST(TriangleSampling, NearlyHemisphericalTriangle) {
    // Seen from just above, a large triangle covers most of the hemisphere.
    Vec3f p0{-10, -10, 0}, p1{10, -10, 0}, p2{0, 10, 0};
    Triangle tri(single_triangle(p0, p1, p2), 0);
    Vec3f ref{0.5f, -2, 1};
    double omega = tri.solid_angle(ref);
    EXPECT_GT(omega, 4);
    SampleStats stats = sample_from(tri, ref);
    EXPECT_EQ(stats.failures, 0);
    EXPECT_NEAR(stats.mean_inverse_pdf, omega, 1e-5 * omega);
    EXPECT_LT(stats.max_pdf_mismatch, 1e-5);
    EXPECT_NEAR(integrate_pdf(tri, ref), 1, 2e-3);
    EXPECT_NEAR(solid_angle_by_casting(tri, ref), omega, 2e-3 * omega);
    expect_uniform_over_subtriangles(tri, p0, p1, p2, ref);
}

TEST(TriangleSampling, SmallAndGrazingTrianglesUseAreaSampling) {
    // Far away (solid angle ~1e-5 sr) and tilted against the viewing direction.
    Triangle tri(single_triangle({50, 0, 0}, {50.2f, 0.3f, 0}, {49.9f, 0.1f, 0.25f}), 0);
    Vec3f ref{0, 0.1f, 0.05f};
    double omega = tri.solid_angle(ref);
    EXPECT_LT(omega, 1e-4);
    SampleStats stats = sample_from(tri, ref);
    EXPECT_EQ(stats.failures, 0);
    EXPECT_NEAR(stats.mean_inverse_pdf, omega, 1e-3 * omega);
    EXPECT_LT(stats.max_pdf_mismatch, 1e-3);
    // Casting rays into a cone around the triangle: hit fraction and pdf integral.
    Vec3f axis = normalize(Vec3f{50, 0.1f, 0.1f} - ref);
    Frame frame = Frame::from_z(axis);
    double cos_max = std::cos(0.01);
    double cone = 2 * M_PI * (1 - cos_max), hits = 0, pdf_sum = 0;
    const int n = 1000;
    for_each_stratum(n, 8, [&](Vec2f u) {
        Vec3f w = frame.from_local(sample_uniform_cone(u, float(cos_max)));
        hits += tri.intersect(ref, w, Infinity).has_value();
        pdf_sum += tri.pdf(ref, w);
    });
    EXPECT_NEAR(hits * cone / (double(n) * n), omega, 5e-3 * omega);
    EXPECT_NEAR(pdf_sum * cone / (double(n) * n), 1, 5e-3);
}

TEST(TriangleSampling, AreaSamplingIsUniform) {
    Triangle tri(single_triangle({0, 0, 0}, {4, 0, 0}, {0, 3, 1}), 0);
    EXPECT_NEAR(tri.area(), 0.5 * length(cross(Vec3f{4, 0, 0}, Vec3f{0, 3, 1})), 1e-5);
    // The centroid of uniform samples is the triangle's centroid.
    Vec3f sum{};
    const int n = 300;
    for_each_stratum(n, 9, [&](Vec2f u) {
        auto ss = tri.sample(u);
        EXPECT_FLOAT_EQ(ss->pdf, 1 / tri.area());
        sum += ss->p;
    });
    test::expect_near_vec(sum / float(n * n), Vec3f{4, 3, 1} / 3, 2e-3f);
}

TEST(DiskSampling, SolidAngleOnAxisMatchesClosedForm) {
    // From height h on the axis: 2 pi (h / sqrt(h^2 + ri^2) - h / sqrt(h^2 + r^2)).
    Transform t = Transform::translate({1, 2, 3}) * Transform::rotate(40, {1, 0, 0});
    for (float inner : {0.f, 0.5f}) {
        auto disk = std::make_shared<Disk>(t, false, 0.5f, 2, inner, 360);
        float h = 1.5f;
        Vec3f ref = t.apply_point({0, 0, 0.5f + h});
        double omega = 2 * M_PI * (h / std::hypot(h, inner) - h / std::hypot(h, 2.0));
        SampleStats stats = sample_from(*disk, ref, 500);
        EXPECT_EQ(stats.failures, 0);
        EXPECT_NEAR(stats.mean_inverse_pdf, omega, 2e-3 * omega);
        EXPECT_LT(stats.max_pdf_mismatch, 1e-3);
        EXPECT_NEAR(integrate_pdf(*disk, ref), 1, 2e-3);
    }
}

TEST(DiskSampling, AreaUnderNonUniformScale) {
    // Scaled to an ellipse with semi-axes 3 and 1 (radius 1): area 3 pi, uniform samples.
    auto disk = std::make_shared<Disk>(Transform::scale(3, 1, 1), false, 0, 1, 0, 360);
    EXPECT_NEAR(disk->area(), 3 * Pi, 1e-5);
    // Uniform by area: half the samples fall in the concentric ellipse scaled by 1/sqrt(2).
    double inside = 0, inner = 0;
    const int n = 200;
    for_each_stratum(n, 10, [&](Vec2f u) {
        auto ss = disk->sample(u);
        EXPECT_NEAR(ss->pdf, 1 / (3 * Pi), 1e-7);
        float rho2 = sqr(ss->p.x / 3) + sqr(ss->p.y);
        inside += rho2 <= 1.0001f;
        inner += rho2 <= 0.5f;
    });
    EXPECT_EQ(inside, double(n) * n);
    EXPECT_NEAR(inner / (double(n) * n), 0.5, 2e-3);
}

// sample_bilinear's points have the moments of the bilinear density of the corner weights
// w = {1, 3, 2, 5}: E[u] = (w00/6 + w10/3 + w01/6 + w11/3) / 2 over the mean weight, 0.57576,
// and E[v] likewise 0.54545; and bilinear_pdf is their density: the mean of 1 / pdf is the
// square's area, 1. On a 300 x 300 jittered grid the errors are below 1e-4; a density 3% off
// fails the last check thirty times over.
TEST(BilinearSampling, PointsHaveTheMomentsOfTheDensity) {
    const float w[4] = {1, 3, 2, 5};
    double mean_u = 0, mean_v = 0, mean_inverse_pdf = 0;
    constexpr int n = 300;
    for_each_stratum(n, 5, [&](Vec2f u) {
        const Vec2f p = sample_bilinear(u, w);
        mean_u += p.x;
        mean_v += p.y;
        mean_inverse_pdf += 1 / bilinear_pdf(p, w);
    });
    EXPECT_NEAR(mean_u / (n * n), 0.575758, 1e-3);
    EXPECT_NEAR(mean_v / (n * n), 0.545455, 1e-3);
    EXPECT_NEAR(mean_inverse_pdf / (n * n), 1, 1e-3);
    // Equal weights are the identity, zero weights uniform.
    const float equal[4] = {2, 2, 2, 2}, zero[4] = {0, 0, 0, 0};
    EXPECT_NEAR(sample_bilinear({0.3f, 0.7f}, equal).x, 0.3f, 1e-6f);
    EXPECT_NEAR(sample_bilinear({0.3f, 0.7f}, zero).y, 0.7f, 1e-6f);
    EXPECT_EQ(bilinear_pdf({0.3f, 0.7f}, zero), 1);
}

} // namespace
} // namespace caustica
