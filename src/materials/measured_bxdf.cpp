#include "materials/measured_bxdf.h"

#include "core/error.h"
#include "materials/tensor_file.h"

#include <cmath>
#include <map>
#include <mutex>

namespace caustica {

namespace {

// The unit-square coordinates of spherical angles, and back.
float theta_to_u(float theta) { return std::sqrt(theta * (2 / Pi)); }
float phi_to_u(float phi) { return phi * (1 / (2 * Pi)) + 0.5f; }
float u_to_theta(float u) { return sqr(u) * (Pi / 2); }
float u_to_phi(float u) { return (2 * u - 1) * Pi; }

float azimuth(Vec3f w) { return std::atan2(w.y, w.x); }
// The polar angle, accurate near the pole (where acos(z) loses it).
float polar(Vec3f w) { return std::atan2(std::sqrt(sqr(w.x) + sqr(w.y)), w.z); }

// Jacobian of the map from u_wm to the reflected direction: 4 (wo . wm) for the reflection,
// times 2 pi^2 u_wm.x sin theta_m from the unit square to the sphere of normals.
float reflection_jacobian(float wo_dot_wm, float u_wm_x, float sin_theta_m) {
    return 4 * wo_dot_wm * std::max(2 * sqr(Pi) * u_wm_x * sin_theta_m, 1e-6f);
}

const TensorField &field(const std::map<std::string, TensorField> &fields, const std::string &name,
                         TensorField::Type type, size_t rank, const std::string &path) {
    auto it = fields.find(name);
    if (it == fields.end()) throw InputError("\"" + path + "\" is not an RGL BSDF file: it has no field \"" + name + "\"");
    if (it->second.type != type || it->second.shape.size() != rank)
        throw InputError("\"" + path + "\" is not an RGL BSDF file: field \"" + name + "\" should have rank " +
                         std::to_string(rank) + " and type " + (type == TensorField::Float32 ? "float32" : "uint8"));
    return it->second;
}

} // namespace

std::shared_ptr<const MeasuredBRDF> MeasuredBRDF::read(const std::string &path) {
    static std::mutex mutex;
    static std::map<std::string, std::weak_ptr<const MeasuredBRDF>> cache;
    std::lock_guard lock(mutex);
    if (auto cached = cache[path].lock()) return cached;

    const auto fields = read_tensor_file(path);
    using T = TensorField;
    const T &theta_i = field(fields, "theta_i", T::Float32, 1, path), &phi_i = field(fields, "phi_i", T::Float32, 1, path);
    const T &wavelengths = field(fields, "wavelengths", T::Float32, 1, path);
    const T &ndf = field(fields, "ndf", T::Float32, 2, path), &sigma = field(fields, "sigma", T::Float32, 2, path);
    const T &vndf = field(fields, "vndf", T::Float32, 4, path), &luminance = field(fields, "luminance", T::Float32, 4, path);
    const T &spectra = field(fields, "spectra", T::Float32, 5, path);
    field(fields, "description", T::UInt8, 1, path);
    const T &jacobian = field(fields, "jacobian", T::UInt8, 1, path);

    const uint64_t n_phi = phi_i.shape[0], n_theta = theta_i.shape[0], n_lambda = wavelengths.shape[0];
    const auto &v = vndf.shape, &l = luminance.shape, &s = spectra.shape;
    const bool consistent = jacobian.shape[0] == 1 && v[0] == n_phi && v[1] == n_theta && l[0] == n_phi &&
                            l[1] == n_theta && l[2] == l[3] && s[0] == n_phi && s[1] == n_theta && s[2] == n_lambda &&
                            s[3] == s[4] && l[2] == s[3] && l[3] == s[4];
    if (!consistent)
        throw InputError("\"" + path + "\" is not an RGL BSDF file: the shapes of its fields do not agree");
    const std::vector<float> phi_values = phi_i.floats();
    const bool isotropic = n_phi <= 2;
    if (!isotropic && std::rint(2 * Pi / (phi_values.back() - phi_values.front())) != 1)
        throw InputError("\"" + path + "\": anisotropic BSDF files must tabulate a whole turn of azimuths "
                         "(symmetry reductions are not supported, as in pbrt-v4)");

    // Each table is at least 2 x 2 and all its values finite (PiecewiseLinear2D checks the
    // densities and the parameters).
    for (const T *t : {&ndf, &sigma, &vndf, &luminance, &spectra}) {
        const size_t rank = t->shape.size();
        for (float x : t->floats())
            if (!std::isfinite(x)) throw InputError("\"" + path + "\" holds values that are not finite numbers");
        if (t->shape[rank - 1] < 2 || t->shape[rank - 2] < 2)
            throw InputError("\"" + path + "\": a table is smaller than 2 x 2");
    }
    auto table = [&](const T &t, std::vector<std::vector<float>> parameters, PiecewiseLinear2D::Kind kind) {
        const size_t rank = t.shape.size();
        return PiecewiseLinear2D(t.floats(), int(t.shape[rank - 1]), int(t.shape[rank - 2]), std::move(parameters), kind);
    };
    using K = PiecewiseLinear2D::Kind;
    try {
        const std::vector<float> theta_values = theta_i.floats(), lambda_values = wavelengths.floats();
        std::shared_ptr<const MeasuredBRDF> brdf(new MeasuredBRDF(
            table(ndf, {}, K::Interpolant), table(sigma, {}, K::Interpolant),
            table(vndf, {phi_values, theta_values}, K::Density), table(luminance, {phi_values, theta_values}, K::Density),
            table(spectra, {phi_values, theta_values, lambda_values}, K::Interpolant), isotropic));
        cache[path] = brdf;
        return brdf;
    } catch (const std::invalid_argument &e) {
        throw InputError("\"" + path + "\" is not a usable RGL BSDF file: " + e.what());
    }
}

MeasuredBxDF::Pair MeasuredBxDF::pair(Vec3f a, Vec3f b) const {
    Pair p;
    if (a.z * b.z <= 0) return p;
    if (a.z < 0) a = -a, b = -b;
    const Vec3f sum = a + b;
    if (dot(sum, sum) == 0) return p;
    p.a = a;
    p.b = b;
    p.wm = normalize(sum);
    p.theta_a = polar(a);
    p.phi_a = azimuth(a);
    const float phi_m = azimuth(p.wm) - (brdf_->isotropic() ? p.phi_a : 0);
    p.u_wm = {theta_to_u(polar(p.wm)), phi_to_u(phi_m)};
    p.u_wm.y -= std::floor(p.u_wm.y);
    const float condition[2] = {p.phi_a, p.theta_a};
    p.sample_space = brdf_->vndf_.invert(p.u_wm, condition);
    p.valid = true;
    return p;
}

SampledSpectrum MeasuredBxDF::value(const Pair &p) const {
    if (!p.valid) return {};
    const float sigma = brdf_->sigma_.evaluate({theta_to_u(p.theta_a), phi_to_u(p.phi_a)});
    const float scale = brdf_->ndf_.evaluate(p.u_wm) / (4 * sigma * p.b.z);
    if (!(scale > 0) || !std::isfinite(scale)) return {};
    SampledSpectrum f;
    for (int i = 0; i < NumWavelengths; ++i) {
        const float parameters[3] = {p.phi_a, p.theta_a, lambda_[i]};
        f[i] = std::max(0.f, brdf_->spectra_.evaluate(p.sample_space.p, parameters)) * scale;
    }
    return f;
}

float MeasuredBxDF::density(const Pair &p) const {
    if (!p.valid) return 0;
    const float condition[2] = {p.phi_a, p.theta_a};
    const float sin_theta_m = std::sqrt(sqr(p.wm.x) + sqr(p.wm.y));
    const float pdf = p.sample_space.pdf * brdf_->luminance_.evaluate(p.sample_space.p, condition) /
                      reflection_jacobian(dot(p.a, p.wm), p.u_wm.x, sin_theta_m);
    return std::isfinite(pdf) ? pdf : 0;
}

SampledSpectrum MeasuredBxDF::f(Vec3f wo, Vec3f wi, TransportMode mode) const {
    return mode == TransportMode::Radiance ? value(pair(wo, wi)) : value(pair(wi, wo));
}

float MeasuredBxDF::pdf(Vec3f wo, Vec3f wi, TransportMode, SampleFlags flags) const {
    if (!allows(flags, SampleFlags::Reflection)) return 0;
    return density(pair(wo, wi));
}

BxDFEvaluation MeasuredBxDF::evaluate(Vec3f wo, Vec3f wi, TransportMode mode) const {
    const Pair forward = pair(wo, wi), reverse = pair(wi, wo);
    return {value(mode == TransportMode::Radiance ? forward : reverse), density(forward), density(reverse)};
}

std::optional<BSDFSample> MeasuredBxDF::sample_f(Vec3f wo, float, Vec2f u, TransportMode mode,
                                                 SampleFlags flags) const {
    if (!allows(flags, SampleFlags::Reflection) || wo.z == 0) return std::nullopt;
    const bool flip = wo.z < 0;
    if (flip) wo = -wo;

    // The luminance warp, then the visible normals' warp, conditioned on wo.
    Pair p;
    p.a = wo;
    p.theta_a = polar(wo);
    p.phi_a = azimuth(wo);
    const float condition[2] = {p.phi_a, p.theta_a};
    const Vec2f sample_space = brdf_->luminance_.sample(u, condition).p;
    const PiecewiseLinear2D::Sample normal = brdf_->vndf_.sample(sample_space, condition);
    p.u_wm = normal.p;
    p.sample_space = {sample_space, normal.pdf};
    const float theta_m = u_to_theta(p.u_wm.x);
    const float phi_m = u_to_phi(p.u_wm.y) + (brdf_->isotropic() ? p.phi_a : 0);
    p.wm = spherical_direction(std::sin(theta_m), std::cos(theta_m), phi_m);
    p.b = reflect(wo, p.wm);
    if (p.b.z <= 0 || dot(wo, p.wm) <= 0) return std::nullopt;
    p.valid = true;

    BSDFSample s;
    s.f = mode == TransportMode::Radiance ? value(p) : value(pair(p.b, wo));
    s.pdf = density(p);
    if (!(s.pdf > 0)) return std::nullopt;
    s.wi = flip ? -p.b : p.b;
    s.flags = BxDFGlossyReflection;
    return s;
}

} // namespace caustica
