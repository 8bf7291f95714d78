#include "integrators/sppm/sppm.h"

#include "core/error.h"
#include "core/octahedral.h"
#include "core/sampling.h"
#include "integrators/common/iteration_renderer.h"
#include "integrators/common/light_sampling.h"
#include "integrators/common/merge_radius.h"
#include "integrators/common/path_segment.h"
#include "integrators/common/path_vertex.h"
#include "integrators/common/photon_search_parameter.h"
#include "integrators/common/photon_side.h"
#include "integrators/common/profile_subsurface.h"
#include "integrators/common/wavelength_groups.h"
#include "materials/disney_material.h"
#include "media/medium_interface.h"
#include "scene/scene.h"
#include "spatial/photon_map.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <istream>
#include <ostream>
#include <stdexcept>

namespace caustica {

namespace {

// What a photon leaves in its wavelength group's map: 24 bytes, 36 with its position.
struct StoredPhoton {
    // Unaligned (SampledSpectrum's 16-byte alignment would pad the record).
    std::array<float, NumWavelengths> beta_values;
    uint32_t wi;                  // octahedral, towards where the photon came from
    uint16_t normal;              // coarse octahedral geometric normal, see photon_side.h
    uint16_t depth : 15;          // scattering vertices on the light path before this one
    uint16_t secondary_terminated : 1;

    static constexpr int MaxDepth = (1 << 15) - 1; // sppm's "maxdepth" is at most this
    SampledSpectrum beta() const { return {beta_values[0], beta_values[1], beta_values[2], beta_values[3]}; }
};
static_assert(sizeof(StoredPhoton) == 24, "photons are kept compact");

using SppmPhotonMap = PhotonMap<StoredPhoton>;

} // namespace

SPPM::SPPM(const ParameterDictionary &params, const Scene &scene)
    : max_depth_(params.get_one_int("maxdepth", 5)), initial_radius_(params.get_one_float("radius", 0)),
      photons_per_iteration_(params.get_one_int("photonsperiteration", -1)),
      wavelength_groups_(params.get_one_int("wavelengthgroups", 16)),
      seed_(uint64_t(params.get_one_int("seed", 0)) + scene.overrides.seed),
      photon_search_(read_photon_search(params)) {
    if (max_depth_ < 0 || max_depth_ > StoredPhoton::MaxDepth)
        throw InputError(params.location("maxdepth"),
                         "\"maxdepth\" must lie in [0, " + std::to_string(StoredPhoton::MaxDepth) + "]");
    if (initial_radius_ < 0 || !std::isfinite(initial_radius_))
        throw InputError(params.location("radius"), "\"radius\" must be a positive distance (or 0 for the default)");
    if (initial_radius_ == 0) initial_radius_ = default_merge_radius(scene);
    if (photons_per_iteration_ == 0 || photons_per_iteration_ < -1)
        throw InputError(params.location("photonsperiteration"),
                         "\"photonsperiteration\" must be positive (or -1: one per pixel)");
    if (wavelength_groups_ < 1 || wavelength_groups_ > 64)
        throw InputError(params.location("wavelengthgroups"), "\"wavelengthgroups\" must lie in [1, 64]");
    params.report_unused();
}

namespace {

constexpr int kPhotonDimension = 1 << 12;
// The fraction of newly gathered photons kept by the radius reduction (Hachisuka and Jensen
// 2009 use 0.7; pbrt-v4 2/3).
constexpr float kGamma = 2.f / 3.f;

struct VisiblePoint {
    Vec3f p, ng, ns, wo;
    int depth = 0;             // scattering vertices on the camera path before this one
    BSDF bsdf;                 // in the iteration's scratch memory; null: no visible point
    SampledSpectrum beta;      // camera path throughput up to the point
    SampledWavelengths lambda; // the path's wavelengths (terminated if it crossed dispersion)
};

// A pixel's camera path this iteration (its estimate is in SPPM::estimates_). A visible point
// on a profile-subsurface solid (diffusion, dipole) has a second one where the light that the
// camera sees there entered the solid: see trace_camera_path.
struct PixelState {
    RGB direct;
    VisiblePoint vp, subsurface_vp;
};

// The second visible point of a camera path that reached the profile-subsurface solid at si
// with throughput beta (see trace_camera_path): where one BSDF sample, if it enters the solid,
// leads through the profile, with its direct lighting added to L. Left empty otherwise.
void find_subsurface_visible_point(const Scene &scene, const SurfaceInteraction &si, const BSDF &bsdf, int depth,
                                   SampledSpectrum beta, const SampledWavelengths &lambda, const Medium *medium,
                                   IterationPixelContext &ctx, SampledSpectrum &L, VisiblePoint &subsurface_vp) {
    Sampler &sampler = ctx.sampler;
    const float u = sampler.get_1d();
    auto bs = bsdf.sample_f(si.wo, u, sampler.get_2d(), TransportMode::Radiance);
    if (!bs) return;
    const DisneyMaterial *material = profile_entry(si, *bs);
    if (!material) return;
    std::optional<ProfileExit> exit =
        sample_profile_exit(scene, *material, si, lambda, sampler, ctx.iteration_scratch, ctx.rays);
    if (!exit) return;
    beta *= bs->f * (abs_dot(bs->wi, si.shading.n) / bs->pdf) * exit->weight;
    if (beta.is_black()) return;
    const SurfaceInteraction &at = exit->si;
    // A profile solid has no interior medium: the exit lies in the medium the entry does.
    L += beta * sample_direct_lighting(scene, at, exit->bsdf, LightSampleContext{at.p, at.n, at.shading.n}, lambda,
                                       sampler, ctx.rays, TransportMode::Radiance, DirectLighting::LightSamplingOnly,
                                       medium);
    subsurface_vp = VisiblePoint{at.p, at.n, at.shading.n, at.wo, depth, exit->bsdf, beta, lambda};
}

// Direct lighting and the visible point of one pixel's camera path.
// lambda is terminated in place if the path crosses dispersion: L is in its measure.
//
// Participating media (which pbrt-v4's SPPM does not handle). Every light-carrying path is
// counted by exactly one of three estimators:
//   - the camera path reaching an emitter, or next-event estimation at a camera vertex that
//     continues (glossy surfaces: the two weighted by MIS; specular ones: the hit alone);
//   - at a camera vertex in a medium, next-event estimation ALONE: the emitter hit right after
//     a medium scattering event (through medium boundaries only) is not counted, and the camera
//     path goes on by sampling the phase function, so that light scattered any further is found
//     at its later vertices;
//   - at the visible point (the first diffuse surface), next-event estimation for light that
//     arrives unscattered, and the photons for all the rest: a photon is deposited at a surface
//     only after at least one scattering event, on a surface or in a medium (trace_photon).
// Photons are never deposited in media: the camera path resolves the media between the camera
// and its visible point itself, and the light paths those beyond it.
//
// Profile subsurface (profile_subsurface.h). The BSDF at a visible point on such a solid leaves
// the subsurface entry out of f (disney_bxdf.h), so its photons give the surface reflection
// alone. The light scattered below the surface is found from the camera's end: one BSDF sample
// there, when it is the entry, jumps through the profile to an exit point, which becomes the
// pixel's second visible point, with the exit lobe as its BSDF and next-event estimation of
// its own. (The sample's f |cos| / pdf includes the chance of choosing the entry, so the
// estimate is unbiased though it is taken only that often.) Photons jump through profiles too
// but are not deposited at exits: the light arriving at an exit through the interior is
// exactly what the camera's jump gathers at the other end.
void trace_camera_path(const Scene &scene, int max_depth, Ray ray, SampledSpectrum beta,
                       SampledWavelengths &lambda, IterationPixelContext &ctx, SampledSpectrum &L,
                       VisiblePoint &vp, VisiblePoint &subsurface_vp) {
    bool specular_bounce = false;
    bool medium_scatter = false;   // the last scattering event was in a medium
    float bsdf_pdf = 0;
    LightSampleContext previous{};
    const Medium *medium = scene.camera_medium;
    const Material *absorbing_interior = nullptr;
    FreeFlightMIS free_flight;
    Sampler &sampler = ctx.sampler;
    // Emission reached by BSDF sampling, weighted against next-event estimation as in the path
    // tracer (only glossy bounces can precede it: the path stops at diffuse surfaces), and left
    // to next-event estimation alone after a medium scattering event.
    auto add_emission = [&](const Light &light, const SampledSpectrum &Le, int depth, Vec3f wi) {
        if (medium_scatter) return;
        float w = 1;
        if (depth > 0 && !specular_bounce)
            w = power_heuristic(1, bsdf_pdf, 1, light_pdf(scene, light, previous, wi));
        L += beta * Le * w;
    };
    for (int depth = 0;; ++depth) {
        SurfaceInteraction si;
        ++ctx.rays;
        bool hit = scene.intersect(ray, &si);
        PathSegment segment = traverse_segment(medium, absorbing_interior, hit ? si.t * length(ray.d) : Infinity,
                                               lambda, sampler, free_flight);
        beta *= segment.weight;
        if (beta.is_black()) return;
        if (segment.scattered) {
            if (depth == max_depth) return;
            const Vec3f wo = -normalize(ray.d), p = ray.o - wo * segment.t;
            L += beta * sample_direct_lighting_in_medium(scene, p, wo, *medium, lambda, sampler, ctx.rays,
                                                         DirectLighting::LightSamplingOnly);
            // The phase function is sampled exactly: beta is unchanged.
            PhaseSample ps = medium->phase().sample_p(wo, sampler.get_2d());
            medium_scatter = true;
            ray = Ray{p, ps.wi, Infinity};
            continue;
        }
        if (!hit) {
            for (const Light *light : scene.infinite_lights)
                add_emission(*light, light->Le(ray, lambda), depth, normalize(ray.d));
            return;
        }
        if (si.area_light)
            add_emission(*si.area_light, si.area_light->L(si.p, si.n, si.uv, si.wo, lambda), depth, -si.wo);
        BSDF bsdf = si.material ? shade(si, lambda, ctx.iteration_scratch) : BSDF();
        if (!bsdf) {
            medium = medium_after(si, ray.d, medium);
            ray = si.spawn_ray(ray.d);
            --depth;
            continue;
        }
        if (depth == max_depth) return;
        const LightSampleContext here{si.p, si.n, si.shading.n};
        const BxDFFlags flags = bsdf.flags();
        // The path ends at its visible point, so there the light is found by light sampling
        // alone; where it goes on, BSDF-sampled hits on lights take their share by MIS.
        const bool visible_point = is_diffuse(flags) || (is_glossy(flags) && depth == max_depth - 1);
        if (is_non_specular(flags))
            L += beta * sample_direct_lighting(scene, si, bsdf, here, lambda, sampler, ctx.rays,
                                               TransportMode::Radiance,
                                               visible_point ? DirectLighting::LightSamplingOnly
                                                             : DirectLighting::WeightedAgainstBsdfSampling,
                                               medium);
        if (visible_point) {
            vp = VisiblePoint{si.p, si.n, si.shading.n, si.wo, depth, bsdf, beta, lambda};
            if (si.material->has_profile_subsurface())
                find_subsurface_visible_point(scene, si, bsdf, depth, beta, lambda, medium, ctx, L, subsurface_vp);
            return;
        }
        float u = sampler.get_1d();
        auto bs = bsdf.sample_f(si.wo, u, sampler.get_2d(), TransportMode::Radiance);
        if (!bs) return;
        if (bs->dispersive && !lambda.secondary_terminated()) {
            lambda.terminate_secondary();
            for (int i = 1; i < NumWavelengths; ++i) beta[i] = 0;
        }
        beta *= bs->f * (abs_dot(bs->wi, si.shading.n) / bs->pdf);
        bsdf_pdf = bs->pdf_is_proportional ? bsdf.pdf(si.wo, bs->wi) : bs->pdf;
        specular_bounce = bs->is_specular();
        medium_scatter = false;
        previous = here;
        if (bs->is_transmission() && si.material->has_interior_absorption())
            absorbing_interior = dot(bs->wi, si.n) < 0 ? si.material : nullptr;
        medium = medium_after(si, bs->wi, medium);
        ray = si.spawn_ray(bs->wi);
        if (beta.is_black()) return;
    }
}

// One photon path: every non-specular surface reached after at least one scattering event
// (on a surface or in a medium) is a photon; see trace_camera_path for why.
void trace_photon(const Scene &scene, int max_depth, SampledWavelengths lambda, IterationPixelContext &ctx,
                  SppmPhotonMap &photons) {
    Sampler &sampler = ctx.sampler;
    auto chosen = scene.light_sampler->sample(sampler.get_1d());
    Vec2f u_position = sampler.get_2d(), u_direction = sampler.get_2d();
    if (!chosen) return;
    auto les = chosen->light->sample_le(u_position, u_direction, lambda);
    if (!les || les->L.is_black() || !(les->pdf_pos > 0) || !(les->pdf_dir > 0)) return;
    const float cos_light = les->n == Vec3f{} ? 1.f : abs_dot(les->n, normalize(les->ray.d));
    SampledSpectrum beta = les->L * (cos_light / (chosen->pmf * les->pdf_pos * les->pdf_dir));
    Ray ray = les->ray;
    // Area lights' paths leave into the medium outside their shape (the side they emit to).
    const Medium *medium = chosen->light->medium();
    const Material *absorbing_interior = nullptr;
    FreeFlightMIS free_flight;
    for (int depth = 0; depth < max_depth; ++depth) {
        SurfaceInteraction si;
        ++ctx.rays;
        bool hit = scene.intersect(ray, &si);
        PathSegment segment = traverse_segment(medium, absorbing_interior, hit ? si.t * length(ray.d) : Infinity,
                                               lambda, sampler, free_flight);
        if (segment.scattered) {
            // Scattering in the medium: the event's weight sigma_s T / density stands where a
            // surface has f |cos| / pdf (the phase function is sampled exactly), and Russian
            // roulette keeps the photon's power as at a surface.
            const Vec3f wo = -normalize(ray.d), p = ray.o - wo * segment.t;
            PhaseSample ps = medium->phase().sample_p(wo, sampler.get_2d());
            SampledSpectrum next = beta * segment.weight;
            float q = std::max(0.f, 1 - next.max_value() / beta.max_value());
            if (sampler.get_1d() < q) return;
            beta = next / (1 - q);
            ray = Ray{p, ps.wi, Infinity};
            if (beta.is_black()) return;
            continue;
        }
        beta *= segment.weight;
        if (!hit || beta.is_black()) return;
        BSDF bsdf = si.material ? shade(si, lambda, ctx.sample_scratch) : BSDF();
        if (!bsdf) {
            medium = medium_after(si, ray.d, medium);
            ray = si.spawn_ray(ray.d);
            --depth;
            continue;
        }
        if (depth > 0 && is_non_specular(bsdf.flags())) {
            photons.add(si.p, StoredPhoton{{beta[0], beta[1], beta[2], beta[3]},
                                           encode_octahedral(si.wo),
                                           encode_octahedral_coarse(si.n),
                                           uint16_t(depth),
                                           lambda.secondary_terminated()});
        }
        float u = sampler.get_1d();
        auto bs = bsdf.sample_f(si.wo, u, sampler.get_2d(), TransportMode::Importance);
        if (!bs) return;
        if (bs->dispersive && !lambda.secondary_terminated()) {
            lambda.terminate_secondary();
            for (int i = 1; i < NumWavelengths; ++i) beta[i] = 0;
        }
        SampledSpectrum next = beta * bs->f * (importance_cosine(si, si.wo, bs->wi) / bs->pdf);
        // Where the photon leaves the surface, and in which direction: through a profile solid
        // (see trace_camera_path), at the exit the profile samples, by its exit lobe.
        const SurfaceInteraction *leaving = &si;
        Vec3f wi = bs->wi;
        std::optional<ProfileExit> exit;
        if (const DisneyMaterial *material = profile_entry(si, *bs)) {
            exit = sample_profile_exit(scene, *material, si, lambda, sampler, ctx.sample_scratch, ctx.rays);
            if (!exit) return;
            auto exit_sample = exit->bsdf.sample_f(exit->si.wo, 0, sampler.get_2d(), TransportMode::Importance);
            if (!exit_sample) return;
            leaving = &exit->si;
            wi = exit_sample->wi;
            next *= exit->weight * exit_sample->f * (importance_cosine(*leaving, leaving->wo, wi) / exit_sample->pdf);
        } else if (bs->is_transmission() && si.material->has_interior_absorption()) {
            absorbing_interior = dot(bs->wi, si.n) < 0 ? si.material : nullptr;
        }
        // Russian roulette keeps the photons' power roughly constant (pbrt-v4 15.4.2).
        float q = std::max(0.f, 1 - next.max_value() / beta.max_value());
        if (sampler.get_1d() < q) return;
        beta = next / (1 - q);
        medium = medium_after(*leaving, wi, medium);
        ray = leaving->spawn_ray(wi);
        if (beta.is_black()) return;
    }
}

} // namespace

void SPPM::render(const Scene &scene, const RenderBudget &budget, RenderStats &stats,
                  const ProgressCallback &progress) {
    Film &film = *scene.film;
    const PixelBounds &bounds = film.pixel_bounds();
    std::vector<PixelState> pixels(size_t(bounds.width()) * bounds.height());
    // A resumed render continues from the restored estimates.
    if (stats.samples_per_pixel == 0) {
        PixelEstimate initial;
        initial.radius = initial_radius_;
        estimates_.assign(pixels.size(), initial);
    }
    if (estimates_.size() != pixels.size())
        throw std::runtime_error("sppm: resumed without the estimates of the pixels");
    const size_t photon_count = photons_per_iteration_ > 0 ? size_t(photons_per_iteration_) : pixels.size();
    WavelengthGroups groups(wavelength_groups_, seed_);
    std::deque<SppmPhotonMap> maps; // per wavelength group
    auto photon_blocks = std::make_shared<SppmPhotonMap::Pool>();
    for (int g = 0; g < wavelength_groups_; ++g) maps.emplace_back(photon_search_, photon_blocks);
    int iterations = 0;

    {
        IterationRenderer renderer(scene, budget, stats, progress);
        renderer.run([&](int iteration) {
            groups.start_iteration(scene, iteration, pixels.size(), photon_count);
            // Camera pass: visible points and direct lighting.
            bool completed = renderer.for_each_pixel(iteration, 0, [&](Vec2i pixel, size_t index, IterationPixelContext &ctx) {
                PixelState &state = pixels[index];
                SampledWavelengths lambda = groups.wavelengths(groups.group_of_pixel(index));
                ctx.sampler.get_1d(); // the hero wavelength is the group's
                CameraSample cs = get_camera_sample(ctx.sampler, pixel, film.filter());
                state.vp = state.subsurface_vp = VisiblePoint{};
                SampledSpectrum L(0.f);
                if (auto camera_ray = scene.camera->generate_ray(cs, lambda))
                    trace_camera_path(scene, max_depth_, camera_ray->ray, camera_ray->weight, lambda, ctx, L,
                                      state.vp, state.subsurface_vp);
                if (L.has_non_finite()) {
                    ++ctx.non_finite;
                    L = SampledSpectrum(0.f);
                }
                state.direct = film.sensor_value(L, lambda);
            });
            if (!completed) return false;

            // Photon pass, then the groups' maps, independent of each other: indexed in parallel
            // (one after another, they kept the second thread idle for a tenth of the render).
            for (SppmPhotonMap &map : maps) map.clear();
            completed = renderer.for_each_path(iteration, photon_count, kPhotonDimension,
                                               [&](size_t index, IterationPixelContext &ctx) {
                const int g = groups.group_of_light_path(index);
                trace_photon(scene, max_depth_, groups.wavelengths(g), ctx, maps[g]);
            });
            if (!completed) return false;
            float max_radius = 0;
            for (const PixelEstimate &estimate : estimates_) max_radius = std::max(max_radius, estimate.radius);
            tbb::parallel_for(0, groups.count(), [&](int g) { maps[g].build(max_radius); });
            uint64_t stored = 0;
            for (const SppmPhotonMap &map : maps) stored += map.size();
            stats.stored_light_vertices = std::max<uint64_t>(stats.stored_light_vertices, stored);

            // Gather pass: each visible point's photons, then the progressive update. It traces
            // no rays and is not interrupted, so that every pixel's statistics describe the same
            // number of completed iterations.
            // The sensor value of the photons of group g within radius of vp; gathered counts them.
            auto gather = [&](const VisiblePoint &vp, int g, float radius, int &gathered) -> RGB {
                SampledSpectrum phi(0.f);
                int count = 0;
                maps[g].for_each_within(vp.p, radius, [&](const StoredPhoton &photon) {
                    // "maxdepth" bounds the scattering vertices of the whole path, as for the
                    // other integrators (pbrt-v4 bounds each subpath separately instead).
                    if (photon.depth + 1 + vp.depth > max_depth_) return;
                    if (!same_surface(decode_octahedral_coarse(photon.normal), vp.ng)) return;
                    ++count;
                    const Vec3f wi = decode_octahedral(photon.wi);
                    const float cos_ng = abs_dot(wi, vp.ng);
                    if (cos_ng == 0) return;
                    SampledSpectrum f = vp.bsdf.f(vp.wo, wi, TransportMode::Radiance) * (abs_dot(wi, vp.ns) / cos_ng);
                    SampledSpectrum contribution = f * photon.beta();
                    // A photon and a visible point of the same group share wavelengths; if
                    // either crossed dispersion, only the hero is valid, in the terminated
                    // set's measure.
                    if (photon.secondary_terminated && !vp.lambda.secondary_terminated()) {
                        SampledWavelengths terminated = vp.lambda;
                        terminated.terminate_secondary();
                        contribution *= vp.lambda.pdf()[0] / terminated.pdf()[0];
                        for (int c = 1; c < NumWavelengths; ++c) contribution[c] = 0;
                    }
                    phi += contribution;
                });
                SampledSpectrum flux = vp.beta * phi;
                if (flux.has_non_finite()) return RGB{};
                gathered += count;
                // All photons of the iteration over the group's: the final normalisation divides
                // by the total photon count.
                const float group_scale = float(photon_count) / float(groups.light_path_count(g));
                return film.sensor_value(flux, vp.lambda) * group_scale;
            };
            tbb::parallel_for(size_t(0), pixels.size(), [&](size_t index) {
                const PixelState &state = pixels[index];
                PixelEstimate &estimate = estimates_[index];
                estimate.direct_sum += state.direct;
                const int g = groups.group_of_pixel(index);
                // Both visible points gather within the pixel's radius, so their photons are
                // counted together by the radius reduction.
                RGB phi_rgb;
                int gathered = 0;
                for (const VisiblePoint *vp : {&state.vp, &state.subsurface_vp})
                    if (vp->bsdf) phi_rgb += gather(*vp, g, estimate.radius, gathered);
                if (gathered == 0) return;
                const float m = float(gathered);
                const float n_new = estimate.photons + kGamma * m;
                const float r_new = estimate.radius * std::sqrt(n_new / (estimate.photons + m));
                estimate.tau = (estimate.tau + phi_rgb) * sqr(r_new / estimate.radius);
                estimate.photons = n_new;
                estimate.radius = r_new;
            });
            return true;
        });
        iterations = stats.samples_per_pixel;
    }
    // An interrupted iteration changed no estimate (the gather pass is not interrupted) and
    // the film is only written below, so the state is still that of the completed iterations.
    if (stats.interrupted && budget.at_boundary) budget.at_boundary();

    // The image: direct lighting averaged over the iterations, plus the photon estimate
    // tau / (N_emitted pi r^2).
    if (iterations == 0) return;
    const double emitted = double(iterations) * double(photon_count);
    size_t index = 0;
    for (int y = bounds.min.y; y < bounds.max.y; ++y)
        for (int x = bounds.min.x; x < bounds.max.x; ++x, ++index) {
            const PixelEstimate &estimate = estimates_[index];
            RGB value = estimate.direct_sum / float(iterations) +
                        estimate.tau / float(emitted * Pi * sqr(estimate.radius));
            film.add_sensor_value({x, y}, value, 1);
        }
}

void SPPM::save_state(std::ostream &out) const {
    const uint64_t count = estimates_.size();
    out.write(reinterpret_cast<const char *>(&count), sizeof count);
    out.write(reinterpret_cast<const char *>(estimates_.data()), std::streamsize(count * sizeof(PixelEstimate)));
}

void SPPM::restore_state(std::istream &in) {
    uint64_t count = 0;
    in.read(reinterpret_cast<char *>(&count), sizeof count);
    if (!in || count > (uint64_t(1) << 32)) throw std::runtime_error("sppm: damaged pixel estimates");
    estimates_.resize(count);
    in.read(reinterpret_cast<char *>(estimates_.data()), std::streamsize(count * sizeof(PixelEstimate)));
    if (!in) throw std::runtime_error("sppm: damaged pixel estimates");
}

} // namespace caustica
