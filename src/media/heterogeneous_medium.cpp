#include "media/heterogeneous_medium.h"

#include "core/rng.h"

#include <algorithm>
#include <bit>
#include <cmath>

namespace caustica {

namespace {

// A stream of random numbers for one ray's tracking, from the ray and one sampler value.
Rng tracking_rng(const Ray &ray, float u) {
    const uint64_t key = hash_values(std::bit_cast<uint32_t>(ray.o.x), std::bit_cast<uint32_t>(ray.o.y),
                                     std::bit_cast<uint32_t>(ray.o.z), std::bit_cast<uint32_t>(ray.d.x),
                                     std::bit_cast<uint32_t>(ray.d.y), std::bit_cast<uint32_t>(ray.d.z));
    // Both the stream and its starting state depend on everything: PCG32 streams that differ
    // only in their increment start out correlated.
    return Rng(key, hash_values(key, std::bit_cast<uint32_t>(u)));
}

float exponential(Rng &rng, float rate) { return -std::log1p(-rng.uniform()) / rate; }

Vec3f componentwise(Vec3f a, Vec3f b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }

} // namespace

HeterogeneousMedium::HeterogeneousMedium(const Transform &render_from_medium, const Bounds3f &bounds, float g,
                                         MajorantGrid majorants)
    : medium_from_render_(render_from_medium.inverse()), lo_(bounds.lo), phase_(g), majorants_(std::move(majorants)) {
    const Vec3f extent = bounds.diagonal();
    inverse_extent_ = {1 / extent.x, 1 / extent.y, 1 / extent.z};
    render_from_unit_cube_ = render_from_medium * Transform::translate(bounds.lo) *
                             Transform::scale(extent.x, extent.y, extent.z);
    const auto &m = render_from_medium.matrix().m;
    const float det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                      m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                      m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    render_volume_ = std::abs(det) * extent.x * extent.y * extent.z;
}

void HeterogeneousMedium::to_unit_cube(const Ray &ray, Vec3f *o, Vec3f *d) const {
    *o = componentwise(medium_from_render_.apply_point(ray.o) - lo_, inverse_extent_);
    *d = componentwise(medium_from_render_.apply_vector(ray.d), inverse_extent_);
}

std::optional<Vec3f> HeterogeneousMedium::unit_cube_point(Vec3f p) const {
    const Vec3f u = componentwise(medium_from_render_.apply_point(p) - lo_, inverse_extent_);
    if (!(u.x >= 0 && u.x <= 1 && u.y >= 0 && u.y <= 1 && u.z >= 0 && u.z <= 1)) return std::nullopt;
    return u;
}

MediumProperties HeterogeneousMedium::properties(Vec3f p, const SampledWavelengths &lambda) const {
    const std::optional<Vec3f> u = unit_cube_point(p);
    return u ? local(*u, lambda) : MediumProperties{};
}

SampledSpectrum HeterogeneousMedium::Le(Vec3f p, const SampledWavelengths &lambda) const {
    const std::optional<Vec3f> u = unit_cube_point(p);
    return u && is_emissive() ? local_Le(*u, lambda) : SampledSpectrum(0.f);
}

std::vector<SampledSpectrum> HeterogeneousMedium::cell_emission(const SampledWavelengths &lambda) const {
    constexpr int k = 4; // points per axis and cell
    const int nx = majorants_.nx(), ny = majorants_.ny(), nz = majorants_.nz();
    std::vector<SampledSpectrum> mean(size_t(nx) * ny * nz, SampledSpectrum(0.f));
    for (int z = 0; z < nz; ++z)
        for (int y = 0; y < ny; ++y)
            for (int x = 0; x < nx; ++x) {
                SampledSpectrum &m = mean[(size_t(z) * ny + y) * nx + x];
                if (!(majorants_.at(x, y, z) > 0)) continue;
                for (int i = 0; i < k * k * k; ++i) {
                    const Vec3f u{(x + (i % k + 0.5f) / k) / nx, (y + (i / k % k + 0.5f) / k) / ny,
                                  (z + (i / (k * k) + 0.5f) / k) / nz};
                    m += local(u, lambda).sigma_a * local_Le(u, lambda);
                }
                m /= float(k * k * k);
            }
    return mean;
}

const DiscreteDistribution &HeterogeneousMedium::emission_cells() const {
    std::call_once(emission_cells_built_, [this] {
        // Eight wavelengths, two sets of four spread by the visible density (which favours the
        // wavelengths the eye sees best).
        std::vector<float> emission, support;
        for (float u : {0.2f, 0.7f}) {
            const SampledWavelengths lambda = SampledWavelengths::sample_visible(u);
            const std::vector<SampledSpectrum> e = cell_emission(lambda);
            emission.resize(e.size(), 0.f);
            for (size_t c = 0; c < e.size(); ++c) emission[c] += e[c].average();
        }
        double emission_sum = 0, support_sum = 0;
        support.resize(emission.size());
        for (int z = 0, c = 0; z < majorants_.nz(); ++z)
            for (int y = 0; y < majorants_.ny(); ++y)
                for (int x = 0; x < majorants_.nx(); ++x, ++c) {
                    support[c] = majorants_.at(x, y, z) > 0 ? 1.f : 0.f;
                    emission_sum += emission[c];
                    support_sum += support[c];
                }
        std::vector<float> weights(emission.size(), 0.f);
        for (size_t c = 0; c < weights.size(); ++c) {
            if (support_sum > 0) weights[c] += float((emission_sum > 0 ? 0.1 : 1.0) * support[c] / support_sum);
            if (emission_sum > 0) weights[c] += float(0.9 * emission[c] / emission_sum);
        }
        emission_cells_ = DiscreteDistribution(weights);
    });
    return emission_cells_;
}

std::optional<EmissionPoint> HeterogeneousMedium::sample_emission_point(float u_cell, Vec3f u_within) const {
    const DiscreteDistribution &cells = emission_cells();
    if (cells.empty()) return std::nullopt;
    float pmf;
    const int c = cells.sample(u_cell, &pmf);
    if (!(pmf > 0)) return std::nullopt;
    const int nx = majorants_.nx(), ny = majorants_.ny(), nz = majorants_.nz();
    const Vec3f u{(c % nx + u_within.x) / nx, (c / nx % ny + u_within.y) / ny, (c / (nx * ny) + u_within.z) / nz};
    return EmissionPoint{render_from_unit_cube_.apply_point(u), pmf * float(nx * ny * nz) / render_volume_};
}

float HeterogeneousMedium::emission_point_pdf(Vec3f p) const {
    const std::optional<Vec3f> u = unit_cube_point(p);
    const DiscreteDistribution &cells = emission_cells();
    if (!u || cells.empty()) return 0;
    const int nx = majorants_.nx(), ny = majorants_.ny(), nz = majorants_.nz();
    const int x = std::min(int(u->x * nx), nx - 1), y = std::min(int(u->y * ny), ny - 1),
              z = std::min(int(u->z * nz), nz - 1);
    return cells.pmf((z * ny + y) * nx + x) * float(nx * ny * nz) / render_volume_;
}

SampledSpectrum HeterogeneousMedium::emitted_power(const SampledWavelengths &lambda) const {
    SampledSpectrum sum(0.f);
    if (!is_emissive()) return sum;
    for (const SampledSpectrum &e : cell_emission(lambda)) sum += e;
    const int cells = majorants_.nx() * majorants_.ny() * majorants_.nz();
    return sum * (render_volume_ / float(cells));
}

SampledSpectrum HeterogeneousMedium::transmittance(const Ray &ray, float distance,
                                                   const SampledWavelengths &lambda) const {
    Vec3f o, d;
    to_unit_cube(ray, &o, &d);
    Rng rng = tracking_rng(ray, distance);
    const float scale = majorant_scale(lambda).max_value();
    SampledSpectrum T(1.f);
    majorants_.traverse(o, d, 0, distance, [&](const MajorantGrid::Segment &s) {
        const float sigma_maj = scale * s.bound;
        if (!(sigma_maj > 0)) return true;
        for (float t = s.t0 + exponential(rng, sigma_maj); t < s.t1; t += exponential(rng, sigma_maj)) {
            const MediumProperties mp = local(o + d * t, lambda);
            const SampledSpectrum sigma_n = SampledSpectrum(sigma_maj) - mp.sigma_a - mp.sigma_s;
            for (int i = 0; i < NumWavelengths; ++i) T[i] *= std::max(0.f, sigma_n[i]) / sigma_maj;
            if (T.max_value() < 0.05f) {
                // Russian roulette: an estimate this small is worth little more tracking.
                if (rng.uniform() < 0.75f) {
                    T = SampledSpectrum(0.f);
                    return false;
                }
                T /= 0.25f;
            }
        }
        return true;
    });
    return T;
}

MediumEvent HeterogeneousMedium::sample_distance(const Ray &ray, float t_max, const SampledWavelengths &lambda,
                                                 int lane, float u_distance) const {
    const int carried = lambda.secondary_terminated() ? 1 : NumWavelengths;
    MediumEvent event;
    event.t = t_max;
    if (!may_scatter(lambda, carried) && !is_emissive()) {
        // Nothing to sample: the event is the transmittance, as in an absorbing homogeneous medium.
        event.f = transmittance(ray, t_max, lambda);
    } else {
        Vec3f o, d;
        to_unit_cube(ray, &o, &d);
        Rng rng = tracking_rng(ray, u_distance);
        const SampledSpectrum scale = majorant_scale(lambda);
        SampledSpectrum f(1.f), density(1.f);
        // Multiplies f and density by the majorant transmittance over dt and one collision's
        // factors, then divides both by the lane's density, so that the products of long chains
        // of null collisions neither overflow nor underflow (only their ratios matter).
        auto collide = [&](const SampledSpectrum &sigma_maj, float dt, const SampledSpectrum &f_event,
                           const SampledSpectrum &density_event) {
            const SampledSpectrum T_maj = exp(-sigma_maj * dt);
            f *= T_maj * f_event;
            density *= T_maj * density_event;
            const float norm = density[lane];
            if (norm > 0) {
                f /= norm;
                density /= norm;
            }
        };
        majorants_.traverse(o, d, 0, t_max, [&](const MajorantGrid::Segment &s) {
            const SampledSpectrum sigma_maj = scale * s.bound;
            float t = s.t0;
            while (true) {
                const float dt = sigma_maj[lane] > 0 ? exponential(rng, sigma_maj[lane]) : Infinity;
                if (t + dt >= s.t1) {
                    collide(sigma_maj, s.t1 - t, SampledSpectrum(1.f), SampledSpectrum(1.f));
                    return true;
                }
                t += dt;
                const Vec3f u = o + d * t;
                const MediumProperties mp = local(u, lambda);
                const SampledSpectrum sigma_t = mp.sigma_a + mp.sigma_s;
                if (rng.uniform() * sigma_maj[lane] < sigma_t[lane]) {
                    collide(sigma_maj, dt, SampledSpectrum(1.f), sigma_t);
                    if (is_emissive()) event.emitted = f * mp.sigma_a * local_Le(u, lambda);
                    f *= mp.sigma_s;
                    event.scattered = true;
                    event.t = t;
                    return false;
                }
                SampledSpectrum sigma_n = sigma_maj - sigma_t;
                for (int i = 0; i < NumWavelengths; ++i) sigma_n[i] = std::max(0.f, sigma_n[i]);
                collide(sigma_maj, dt, sigma_n, sigma_n);
            }
        });
        event.f = f;
        event.density = density;
    }
    for (int k = carried; k < NumWavelengths; ++k) event.f[k] = event.emitted[k] = 0;
    return event;
}

ScalarDensityMedium::ScalarDensityMedium(const Transform &render_from_medium, const Bounds3f &bounds, float g,
                                         MajorantGrid majorants, SpectrumPtr sigma_a, SpectrumPtr sigma_s, float scale)
    : HeterogeneousMedium(render_from_medium, bounds, g, std::move(majorants)), sigma_a_(std::move(sigma_a)),
      sigma_s_(std::move(sigma_s)), scale_(scale) {}

MediumProperties ScalarDensityMedium::local(Vec3f u, const SampledWavelengths &lambda) const {
    const float d = density_at(u) * scale_;
    return {sigma_a_->sample(lambda) * d, sigma_s_->sample(lambda) * d};
}

SampledSpectrum ScalarDensityMedium::majorant_scale(const SampledWavelengths &lambda) const {
    return (sigma_a_->sample(lambda) + sigma_s_->sample(lambda)) * scale_;
}

bool ScalarDensityMedium::may_scatter(const SampledWavelengths &lambda, int carried) const {
    const SampledSpectrum s = sigma_s_->sample(lambda);
    for (int i = 0; i < carried; ++i)
        if (s[i] * scale_ > 0) return true;
    return false;
}

} // namespace caustica
