// Where Snell's law puts the thin emissive line behind the N-BK7 prism of
// scenes/prism-dispersion.pbrt, wavelength by wavelength: the closed form that the dispersion
// and spectral-film tests check renders against.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <vector>

namespace caustica::testing {

// Schott N-BK7 Sellmeier coefficients (Schott optical glass data sheet), lambda in um.
inline double bk7_index(double lambda_nm) {
    const double B[3] = {1.03961212, 0.231792344, 1.01046945};
    const double C[3] = {0.00600069867, 0.0200179144, 103.560653};
    double l2 = lambda_nm * lambda_nm * 1e-6, n2 = 1;
    for (int i = 0; i < 3; ++i) n2 += B[i] * l2 / (l2 - C[i]);
    return std::sqrt(n2);
}

struct V2 { double x, z; };

// The prism's cross-section (counter-clockwise in x-z) and the line's plane, as in the scene.
const std::array<V2, 3> kPrism = {{{-0.707642, 5.593782}, {-0.160409, 4.090274}, {0.868051, 5.315945}}};
constexpr double kLineX = -20.1157, kLineZ = 30;
constexpr int kWidth = 320, kHeight = 240;
constexpr double kFovDegrees = 16;

// Refracts unit d at a surface with unit normal n facing against d; eta = n_from / n_to.
inline std::optional<V2> refract(V2 d, V2 n, double eta) {
    double c = -(d.x * n.x + d.z * n.z);
    double k = 1 - eta * eta * (1 - c * c);
    if (k < 0) return std::nullopt;
    double t = eta * c - std::sqrt(k);
    return V2{eta * d.x + t * n.x, eta * d.z + t * n.z};
}

// Where the ray for raster column px (centre row) meets the line's plane, refracting into and
// out of the prism. Camera at the origin looking down +z: pbrt's LookAt gives camera +x = world
// +x here, and the fov spans the shorter (vertical) axis.
inline std::optional<double> hit_x(double px, double n) {
    double aspect = double(kWidth) / kHeight;
    double sx = px / kWidth * 2 * aspect - aspect;
    V2 o{0, 0}, d{sx * std::tan(kFovDegrees / 2 * M_PI / 180), 1};
    double len = std::hypot(d.x, d.z);
    d = {d.x / len, d.z / len};
    bool inside = false;
    for (int crossing = 0; crossing < 2; ++crossing) {
        double best_t = 1e30;
        V2 best_normal{};
        for (int i = 0; i < 3; ++i) {
            V2 p = kPrism[i], q = kPrism[(i + 1) % 3];
            V2 e{q.x - p.x, q.z - p.z};
            double det = d.x * -e.z + e.x * d.z;
            if (std::abs(det) < 1e-12) continue;
            double rx = p.x - o.x, rz = p.z - o.z;
            double t = (rx * -e.z + e.x * rz) / det;
            double u = (d.x * rz - d.z * rx) / det;
            if (t > 1e-9 && u >= 0 && u <= 1 && t < best_t) {
                double len_e = std::hypot(e.x, e.z);
                best_t = t;
                best_normal = {e.z / len_e, -e.x / len_e}; // outward for counter-clockwise
            }
        }
        if (best_t == 1e30) return std::nullopt;
        o = {o.x + best_t * d.x, o.z + best_t * d.z};
        auto r = inside ? refract(d, {-best_normal.x, -best_normal.z}, n) : refract(d, best_normal, 1 / n);
        if (!r) return std::nullopt;
        d = *r;
        inside = !inside;
    }
    return o.x + (kLineZ - o.z) / d.z * d.x;
}

// The column (continuous) where the refracted ray meets the line: bisection on a bracket.
inline double predicted_column(double lambda_nm) {
    double n = bk7_index(lambda_nm);
    double lo = 150, hi = 175;
    auto f = [&](double px) { return *hit_x(px, n) - kLineX; };
    EXPECT_LT(f(lo) * f(hi), 0) << "no bracket at " << lambda_nm << " nm";
    for (int i = 0; i < 60; ++i) {
        double mid = (lo + hi) / 2;
        (f(lo) * f(mid) <= 0 ? hi : lo) = mid;
    }
    return (lo + hi) / 2;
}

// Where the refracted line crosses the centre rows of an image `width` wide whose value at
// (x, y) is value(x, y): the intensity-weighted centroid within 4 pixels of the brightest
// column, searched from column `from` on. (A fainter, undispersed copy of the line, reflected by
// the prism's faces, appears left of the refracted one, around column 125, and must not pull
// the centroid.)
template <typename Value> double measured_column(int width, Value &&value, int from = 0) {
    std::vector<double> column(width, 0.0);
    for (int y = kHeight / 2 - 3; y < kHeight / 2 + 3; ++y)
        for (int x = 0; x < width; ++x) column[x] += value(x, y);
    int peak = int(std::max_element(column.begin() + from, column.end()) - column.begin());
    double sum = 0, weighted = 0;
    for (int x = std::max(0, peak - 4); x <= std::min(width - 1, peak + 4); ++x) {
        sum += column[x];
        weighted += column[x] * (x + 0.5);
    }
    return weighted / sum;
}

} // namespace caustica::testing
