#include "integrators/sppm/sppm.h"

#include "core/error.h"
#include "core/octahedral.h"
#include "core/sampling.h"
#include "integrators/common/iteration_renderer.h"
#include "integrators/common/light_sampling.h"
#include "integrators/common/merge_radius.h"
#include "integrators/common/light_path_start.h"
#include "integrators/common/medium_photon.h"
#include "integrators/common/path_vertex.h"
#include "integrators/common/photon_search_parameter.h"
#include "integrators/common/photon_side.h"
#include "integrators/common/profile_subsurface.h"
#include "integrators/common/path_tracing.h"
#include "integrators/common/subpath_walk.h"
#include "integrators/common/wavelength_groups.h"
#include "materials/profile_subsurface_material.h"
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
      photon_search_(read_photon_search(params)),
      buckets_(scene.film->spectral() ? scene.film->spectral()->count() : 0) {
    if (max_depth_ < 0 || max_depth_ > StoredPhoton::MaxDepth)
        throw InputError(params.location("maxdepth"),
                         "\"maxdepth\" must lie in [0, " + std::to_string(StoredPhoton::MaxDepth) + "]");
    if (initial_radius_ < 0 || !std::isfinite(initial_radius_))
        throw InputError(params.location("radius"), "\"radius\" must be a positive distance (or 0 for the default)");
    // A radius given in the scene is used on surfaces and in media alike.
    initial_medium_radius_ = initial_radius_;
    if (initial_radius_ == 0) {
        initial_radius_ = default_merge_radius(scene);
        initial_medium_radius_ = default_medium_merge_radius(scene, initial_radius_);
    }
    if (photons_per_iteration_ == 0 || photons_per_iteration_ < -1)
        throw InputError(params.location("photonsperiteration"),
                         "\"photonsperiteration\" must be positive (or -1: one per pixel)");
    if (wavelength_groups_ < 1 || wavelength_groups_ > 64)
        throw InputError(params.location("wavelengthgroups"), "\"wavelengthgroups\" must lie in [1, 64]");
}

namespace {

constexpr int kPhotonDimension = 1 << 12;
// The fraction of newly gathered photons kept by the radius reduction (Hachisuka and Jensen
// 2009 use 0.7; pbrt-v4 2/3).
constexpr float kGamma = 2.f / 3.f;

} // namespace

float SPPM::KernelEstimate::update(const RGB &phi, float m, int dimension) {
    const float n_new = photons + kGamma * m;
    const float ratio = n_new / (photons + m);
    const float r_new = radius * (dimension == 2 ? std::sqrt(ratio) : std::cbrt(ratio));
    const float shrink = r_new / radius;
    const float scale = dimension == 2 ? sqr(shrink) : shrink * sqr(shrink);
    tau = (tau + phi) * scale;
    photons = n_new;
    radius = r_new;
    return scale;
}

namespace {

struct VisiblePoint {
    Vec3f p, ng, ns, wo;
    int depth = 0;             // scattering vertices on the camera path before this one
    BSDF bsdf;                 // surface points, in the iteration's scratch memory
    const Medium *medium = nullptr; // points inside a participating medium
    // The camera path's throughput up to the point, over the surface's coverage there: photons
    // land on a partly transparent cut-out only that often (SurfaceInteraction::coverage).
    SampledSpectrum beta;
    SampledWavelengths lambda; // the path's wavelengths (terminated if it crossed dispersion)

    bool exists() const { return bsdf || medium; }
    bool in_medium() const { return medium != nullptr; }
};

// A pixel's camera path this iteration (its estimate is in SPPM::estimates_). A visible point
// on a profile-subsurface solid (diffusion, dipole) has a second one where the light that the
// camera sees there entered the solid: see trace_camera_path.
struct PixelState {
    RGB direct;
    std::vector<double> direct_buckets; // a spectral film's
    VisiblePoint vp, subsurface_vp;
    // The camera path's scattering events in media, where it gathers the photons of volumetric
    // caustics (see trace_camera_path).
    std::vector<VisiblePoint> medium_vps;
};

// The exit `at` (with its exit lobe) of a camera path's jump through a profile solid, reached
// with throughput beta, as the pixel's second visible point, with its direct lighting added to L.
// A profile solid has no interior medium: the exit lies in the medium the entry does.
void record_subsurface_exit(const Scene &scene, const SurfaceInteraction &at, const BSDF &exit_bsdf, int depth,
                            const SampledSpectrum &beta, const SampledWavelengths &lambda, const Medium *medium,
                            IterationPixelContext &ctx, SampledSpectrum &L, VisiblePoint &subsurface_vp) {
    L += beta * sample_direct_lighting(scene, at, exit_bsdf, LightSampleContext{at.p, at.n, at.shading.n}, lambda,
                                       ctx.sampler, ctx.rays, TransportMode::Radiance,
                                       DirectLighting::LightSamplingOnly, medium);
    subsurface_vp = VisiblePoint{at.p, at.n, at.shading.n, at.wo, depth, exit_bsdf, nullptr, beta / at.coverage, lambda};
}

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
    const ProfileSubsurfaceMaterial *material = profile_entry(si, *bs);
    if (!material) return;
    std::optional<ProfileExit> exit =
        sample_profile_exit(scene, *material, si, lambda, sampler, ctx.iteration_scratch, ctx.rays);
    if (!exit) return;
    beta *= bs->f * (abs_dot(bs->wi, si.shading.n) / bs->pdf) * exit->weight;
    if (beta.is_black()) return;
    record_subsurface_exit(scene, exit->si, exit->bsdf, depth, beta, lambda, medium, ctx, L, subsurface_vp);
}

// Direct lighting and the visible points of one pixel's camera path.
// lambda is terminated in place if the path crosses dispersion: L is in its measure.
//
// Participating media (which pbrt-v4's SPPM does not handle). Every light-carrying path is
// counted by exactly one of these estimators:
//   - the camera path reaching an emitter, or next-event estimation at a camera vertex that
//     continues (glossy surfaces: the two weighted by MIS; specular ones: the hit alone);
//   - at each camera vertex in a medium, next-event estimation for the light that arrives
//     unscattered, and, for delta lights (point, spot, distant), the caustic photons: the light
//     that arrives through specular surfaces only (a spot light focused by glass into fog),
//     which no camera path can find, as no camera path can hit a delta light. They are photons
//     deposited in media straight after one or more specular bounces (trace_photon), gathered
//     within a sphere. The camera path then goes on by sampling the phase function, so that
//     light scattered any further is found at its later vertices; an emitter that it hits
//     straight from the medium vertex belongs to that vertex's light sampling, and one that it
//     reaches through specular surfaces is counted (only lights that can be hit emit there);
//   - at the visible point (the first diffuse surface), next-event estimation for light that
//     arrives unscattered, and the photons for all the rest: a photon is deposited at a surface
//     after at least one scattering event, on a surface or in a medium.
// Only the volumetric caustics of delta lights are density estimates in media; the rest of the
// light in a medium is found by the camera path, without the blur of a kernel that a boundary
// cuts.
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
void trace_camera_path(const Scene &scene, int max_depth, const CameraRay &camera_ray, SampledWavelengths &lambda,
                       IterationPixelContext &ctx, SampledSpectrum &L, PixelState &state) {
    Sampler &sampler = ctx.sampler;
    // The visible points' BSDFs must outlive the camera pass.
    SubpathWalk walk(scene, TransportMode::Radiance, lambda, sampler, ctx.iteration_scratch, ctx.rays, false);
    walk.allow_reradiation();
    walk.start(camera_ray.ray, scene.camera_medium, camera_ray.weight, camera_ray.differential);
    bool specular_bounce = false;
    bool medium_scatter = false; // the last scattering event was in a medium
    float bsdf_pdf = 0;
    LightSampleContext previous{};
    // Emission reached by BSDF sampling, weighted against next-event estimation as in the path
    // tracer (only glossy bounces can precede it: the path stops at diffuse surfaces).
    auto add_emission = [&](const Light &light, const SampledSpectrum &Le, int depth, Vec3f wi) {
        if (medium_scatter) return;
        float w = 1;
        if (depth > 0 && !specular_bounce) w = power_heuristic(1, bsdf_pdf, 1, light_pdf(scene, light, previous, wi));
        L += walk.beta * Le * w;
    };
    for (int depth = 0;; ++depth) {
        const WalkEvent event = walk.advance();
        // Emissive media along the way, as the path tracer counts them: photons from the media
        // bring only the light they send to the visible points.
        if (depth < max_depth) L += walk.emitted();
        if (event == WalkEvent::Ended) return;
        if (event == WalkEvent::Escaped) {
            for (const Light *light : scene.infinite_lights)
                add_emission(*light, light->Le(walk.ray(), lambda), depth, normalize(walk.ray().d));
            return;
        }
        const ScatteringPoint &point = walk.vertex();
        if (point.in_medium()) {
            if (depth == max_depth) return;
            L += walk.beta * sample_direct_lighting_in_medium(scene, point.p, point.time, point.wo, *point.medium, lambda, sampler,
                                                             ctx.rays, DirectLighting::LightSamplingOnly);
            state.medium_vps.push_back(
                VisiblePoint{point.p, Vec3f{}, Vec3f{}, point.wo, depth, BSDF(), point.medium, walk.beta, lambda});
            if (!walk.scatter()) return;
            medium_scatter = true;
            continue;
        }
        const SurfaceInteraction &si = walk.hit();
        if (si.area_light)
            add_emission(*si.area_light, si.area_light->L(si.p, si.n, si.uv, si.wo, lambda), depth, -si.wo);
        if (!point.bsdf) {
            walk.pass_through();
            --depth;
            continue;
        }
        if (depth == max_depth) return;
        const BSDF &bsdf = point.bsdf;
        const LightSampleContext here{si.p, si.n, si.shading.n};
        const BxDFFlags flags = bsdf.flags();
        // The path ends at its visible point, so there the light is found by light sampling
        // alone; where it goes on, BSDF-sampled hits on lights take their share by MIS.
        const bool visible_point = is_diffuse(flags) || (is_glossy(flags) && depth == max_depth - 1);
        if (is_non_specular(flags))
            L += walk.beta * sample_direct_lighting(scene, si, bsdf, here, lambda, sampler, ctx.rays,
                                                    TransportMode::Radiance,
                                                    visible_point ? DirectLighting::LightSamplingOnly
                                                                  : DirectLighting::WeightedAgainstBsdfSampling,
                                                    walk.medium());
        const auto *profile_solid = dynamic_cast<const ProfileSubsurfaceMaterial *>(si.material);
        if (visible_point && profile_solid && profile_solid->reflects_only_specularly(si)) {
            // A smooth boundary over a profile solid: no photon can be gathered at the surface.
            // One BSDF sample either enters (the light below the surface, found at the exit as
            // at any subsurface visible point) or reflects, and the path follows the reflection.
            const std::optional<WalkScatter> s = walk.scatter();
            if (!s) return;
            if (s->profile) {
                if (walk.jump(*s->profile))
                    record_subsurface_exit(scene, walk.hit(), walk.vertex().bsdf, depth, walk.beta, lambda,
                                           walk.medium(), ctx, L, state.subsurface_vp);
                return;
            }
            bsdf_pdf = s->pdf_fwd;
            specular_bounce = s->specular;
            medium_scatter = false;
            previous = here;
            if (walk.beta.is_black()) return;
            continue;
        }
        if (visible_point) {
            state.vp = VisiblePoint{si.p, si.n, si.shading.n, si.wo, depth, bsdf, nullptr, walk.beta / si.coverage,
                                    lambda};
            if (si.material->has_profile_subsurface())
                find_subsurface_visible_point(scene, si, bsdf, depth, walk.beta, lambda, walk.medium(), ctx, L,
                                              state.subsurface_vp);
            // Light re-radiated by fluorescent surfaces, here or further on: photons carry none of
            // it (reradiation.h), so the path goes on beyond its visible point to gather it with
            // the path tracer's strategies (path_tracing.h).
            if (scene.features.fluorescence) {
                L += reradiated_light_at(scene, walk, sampler, ctx.rays);
                std::optional<WalkScatter> s = walk.scatter();
                LightSampleContext from = here;
                if (s && s->profile) { // on from the exit of the profile solid it enters
                    s = walk.jump(*s->profile) ? walk.scatter() : std::nullopt;
                    from = LightSampleContext{walk.hit().p, walk.hit().n, walk.hit().shading.n};
                }
                if (s) L += reradiated_beyond(scene, walk, from, s->pdf_fwd, depth + 1, max_depth, sampler, ctx.rays);
            }
            return;
        }
        // Specular and glossy surfaces have no subsurface entry (that is a diffuse lobe).
        const std::optional<WalkScatter> s = walk.scatter();
        if (!s || s->profile) return;
        bsdf_pdf = s->pdf_fwd;
        specular_bounce = s->specular;
        medium_scatter = false;
        previous = here;
        if (walk.beta.is_black()) return;
    }
}

// One photon path: every non-specular surface reached after at least one scattering event, and,
// from a delta light, every medium event reached through specular surfaces only (at least one),
// is a photon; see trace_camera_path for why. The emitted flux is kept apart from the walk's throughput, on which
// Russian roulette acts as in every other integrator.
void trace_photon(const Scene &scene, int max_depth, SampledWavelengths lambda, float time, IterationPixelContext &ctx,
                  SppmPhotonMap &surface_photons, SppmPhotonMap &medium_photons) {
    Sampler &sampler = ctx.sampler;
    const std::optional<LightPathStart> start = start_light_path(scene, sampler, lambda, time);
    if (!start) return;
    // Area lights' paths leave into the medium outside their shape (the side they emit to).
    SubpathWalk walk(scene, TransportMode::Importance, lambda, sampler, ctx.sample_scratch, ctx.rays, false);
    walk.start(start->les.ray, start->light->medium(), SampledSpectrum(1.f));
    // Every scattering vertex so far was a specular bounce, from a light no camera path can hit.
    bool delta_caustic = is_delta_light(start->light->type());
    // A path from an emissive medium starts at an event of the medium, which counts as a
    // scattering vertex (towards maxdepth, and as the one before its first photon): next-event
    // estimation does not sample media, so its photons carry their direct light too.
    const int first_depth = start->light->type() == LightType::Volume ? 1 : 0;
    for (int depth = first_depth; depth < max_depth && walk.advance() == WalkEvent::Vertex;) {
        const ScatteringPoint &point = walk.vertex();
        if (!point.in_medium() && !point.bsdf) {
            walk.pass_through();
            continue;
        }
        // The vertex, then (not a photon) the exit of a profile solid that its direction enters.
        while (true) {
            const bool photon = point.in_medium() ? delta_caustic : is_non_specular(point.bsdf.flags());
            if (depth > 0 && !walk.after_jump() && photon) {
                SampledSpectrum beta = start->flux * walk.beta;
                if (point.in_medium()) beta = over_sigma_s(beta, *point.medium, point.p, lambda);
                const StoredPhoton photon{{beta[0], beta[1], beta[2], beta[3]},
                                          encode_octahedral(point.wo),
                                          point.in_medium() ? uint16_t(0) : encode_octahedral_coarse(point.ng),
                                          uint16_t(depth),
                                          lambda.secondary_terminated()};
                (point.in_medium() ? medium_photons : surface_photons).add(point.p, photon);
            }
            const std::optional<WalkScatter> s = walk.scatter();
            if (!s) return;
            delta_caustic = delta_caustic && s->specular;
            if (!s->profile) break;
            if (!walk.jump(*s->profile)) return;
        }
        ++depth;
        if (!walk.russian_roulette(depth)) return;
    }
}

} // namespace

void SPPM::render(const Scene &scene, const RenderBudget &budget, RenderStats &stats,
                  const ProgressCallback &progress) {
    Film &film = *scene.film;
    const PixelBounds &bounds = film.pixel_bounds();
    std::vector<PixelState> pixels(size_t(bounds.width()) * bounds.height());
    auto pixel_at = [&](size_t index) {
        return Vec2i{bounds.min.x + int(index % size_t(bounds.width())), bounds.min.y + int(index / size_t(bounds.width()))};
    };
    // A resumed render continues from the restored estimates.
    if (stats.samples_per_pixel == 0) {
        PixelEstimate initial;
        initial.surface.radius = initial_radius_;
        initial.medium.radius = initial_medium_radius_;
        estimates_.assign(pixels.size(), initial);
        bucket_estimates_.assign(pixels.size() * 3 * buckets_, 0.0);
    }
    const int buckets = buckets_;
    if (estimates_.size() != pixels.size())
        throw std::runtime_error("sppm: resumed without the estimates of the pixels");
    const size_t photon_count = photons_per_iteration_ > 0 ? size_t(photons_per_iteration_) : pixels.size();
    WavelengthGroups groups(wavelength_groups_, seed_);
    // Per wavelength group: the photons on surfaces and those in media, gathered by visible
    // points of the same kind only.
    std::deque<SppmPhotonMap> surface_maps, medium_maps;
    auto photon_blocks = std::make_shared<SppmPhotonMap::Pool>();
    for (int g = 0; g < wavelength_groups_; ++g) {
        surface_maps.emplace_back(photon_search_, photon_blocks);
        medium_maps.emplace_back(photon_search_, photon_blocks);
    }
    int iterations = 0;
    std::vector<bool> owned(pixels.size()); // whether this rank's passes visit a pixel

    {
        // A pixel's statistics depend on the iterations before, so a distributed render shares
        // each iteration: its pixels and its photons, which every rank then gathers.
        IterationRenderer renderer(scene, budget, stats, progress, IterationRenderer::Sharing::PixelsAndPaths);
        for (size_t index = 0; index < pixels.size(); ++index) owned[index] = renderer.owns(pixel_at(index));
        renderer.run([&](int iteration) {
            groups.start_iteration(scene, iteration, pixels.size(), photon_count);
            // Visible points and photons of one iteration share its time, so that they meet.
            const float time = renderer.time(iteration);
            // Camera pass: visible points and direct lighting.
            bool completed = renderer.for_each_pixel(iteration, 0, [&](Vec2i pixel, size_t index, IterationPixelContext &ctx) {
                PixelState &state = pixels[index];
                SampledWavelengths lambda = groups.wavelengths(groups.group_of_pixel(index));
                ctx.sampler.get_1d(); // the hero wavelength is the group's
                CameraSample cs = get_camera_sample(ctx.sampler, pixel, film.filter());
                cs.time = time;
                state.vp = state.subsurface_vp = VisiblePoint{};
                state.medium_vps.clear();
                SampledSpectrum L(0.f);
                if (auto camera_ray = scene.generate_camera_ray(cs, lambda, ctx.sampler.samples_per_pixel()))
                    trace_camera_path(scene, max_depth_, *camera_ray, lambda, ctx, L, state);
                if (L.has_non_finite()) {
                    ++ctx.non_finite;
                    L = SampledSpectrum(0.f);
                }
                state.direct = film.sensor_value(L, lambda);
                if (buckets > 0) {
                    state.direct_buckets.assign(buckets, 0.0);
                    film.add_bucket_values(L, lambda, state.direct_buckets.data());
                }
            });
            if (renderer.share().any(!completed)) return false;

            // Photon pass, then the groups' maps, independent of each other: indexed in parallel
            // (one after another, they kept the second thread idle for a tenth of the render).
            for (int g = 0; g < groups.count(); ++g) {
                surface_maps[g].clear();
                medium_maps[g].clear();
            }
            completed = renderer.for_each_path(iteration, photon_count, kPhotonDimension,
                                               [&](size_t index, IterationPixelContext &ctx) {
                const int g = groups.group_of_light_path(index);
                trace_photon(scene, max_depth_, groups.wavelengths(g), time, ctx, surface_maps[g], medium_maps[g]);
            });
            if (renderer.share().any(!completed)) return false;
            std::vector<SppmPhotonMap *> maps;
            for (int g = 0; g < groups.count(); ++g) {
                maps.push_back(&surface_maps[g]);
                maps.push_back(&medium_maps[g]);
            }
            SppmPhotonMap::gather(maps, renderer.share());
            // The grids are laid out for the largest radius (of every rank's pixels).
            float max_surface_radius = 0, max_medium_radius = 0;
            for (size_t index = 0; index < estimates_.size(); ++index) {
                if (!owned[index]) continue;
                max_surface_radius = std::max(max_surface_radius, estimates_[index].surface.radius);
                max_medium_radius = std::max(max_medium_radius, estimates_[index].medium.radius);
            }
            max_surface_radius = renderer.share().max(max_surface_radius);
            max_medium_radius = renderer.share().max(max_medium_radius);
            tbb::parallel_for(0, groups.count(), [&](int g) {
                surface_maps[g].build(max_surface_radius);
                medium_maps[g].build(max_medium_radius);
            });
            uint64_t stored = 0;
            for (int g = 0; g < groups.count(); ++g) stored += surface_maps[g].size() + medium_maps[g].size();
            stats.stored_light_vertices = std::max<uint64_t>(stats.stored_light_vertices, stored);

            // Gather pass: each visible point's photons, then the progressive update. It traces
            // no rays and is not interrupted, so that every pixel's statistics describe the same
            // number of completed iterations.
            // The sensor value of the photons of group g within radius of vp; gathered counts them.
            // A spectral film's buckets are added to bucket_phi.
            auto gather = [&](const VisiblePoint &vp, int g, float radius, int &gathered, double *bucket_phi) -> RGB {
                SampledSpectrum phi(0.f);
                int count = 0;
                // A photon and a visible point of the same group share wavelengths; if either
                // crossed dispersion, only the hero is valid, in the terminated set's measure.
                auto add = [&](SampledSpectrum contribution, const StoredPhoton &photon) {
                    if (photon.secondary_terminated && !vp.lambda.secondary_terminated()) {
                        SampledWavelengths terminated = vp.lambda;
                        terminated.terminate_secondary();
                        contribution *= vp.lambda.pdf()[0] / terminated.pdf()[0];
                        for (int c = 1; c < NumWavelengths; ++c) contribution[c] = 0;
                    }
                    phi += contribution;
                };
                if (vp.in_medium()) {
                    // The volumetric photon map's estimate (Jensen and Christensen 1998): the
                    // phase function times each photon's flux, which was divided by sigma_s at
                    // its own point when stored, as both the camera path's and the photon's
                    // throughputs hold sigma_s (vcm.cpp's merge_in_medium derives it); the final
                    // division is by the sphere's volume.
                    const HenyeyGreenstein &phase = vp.medium->phase();
                    medium_maps[g].for_each_within(vp.p, radius, [&](const StoredPhoton &photon) {
                        if (photon.depth + 1 + vp.depth > max_depth_) return;
                        ++count;
                        add(SampledSpectrum(phase.p(vp.wo, decode_octahedral(photon.wi))) * photon.beta(), photon);
                    });
                } else {
                    surface_maps[g].for_each_within(vp.p, radius, [&](const StoredPhoton &photon) {
                        // "maxdepth" bounds the scattering vertices of the whole path, as for the
                        // other integrators (pbrt-v4 bounds each subpath separately instead).
                        if (photon.depth + 1 + vp.depth > max_depth_) return;
                        if (!same_surface(decode_octahedral_coarse(photon.normal), vp.ng)) return;
                        ++count;
                        const Vec3f wi = decode_octahedral(photon.wi);
                        const float cos_ng = abs_dot(wi, vp.ng);
                        if (cos_ng == 0) return;
                        add(vp.bsdf.f(vp.wo, wi, TransportMode::Radiance) * (abs_dot(wi, vp.ns) / cos_ng) * photon.beta(),
                            photon);
                    });
                }
                SampledSpectrum flux = vp.beta * phi;
                if (flux.has_non_finite()) return RGB{};
                gathered += count;
                // All photons of the iteration over the group's: the final normalisation divides
                // by the total photon count.
                const float group_scale = float(photon_count) / float(groups.light_path_count(g));
                // A density estimate, not a sample: the film's clamp leaves it alone.
                if (buckets > 0)
                    film.add_bucket_values(flux * group_scale, vp.lambda, bucket_phi, Film::ValueKind::PhotonEstimate);
                return film.sensor_value(flux, vp.lambda, Film::ValueKind::PhotonEstimate) * group_scale;
            };
            tbb::parallel_for(size_t(0), pixels.size(), [&](size_t index) {
                if (!owned[index]) return;
                const PixelState &state = pixels[index];
                PixelEstimate &estimate = estimates_[index];
                estimate.direct_sum += state.direct;
                const int g = groups.group_of_pixel(index);
                // A surface visible point may have a second one below the surface; both gather
                // within the pixel's surface radius, so their photons are counted together, as
                // are those of all the camera path's medium vertices within its medium radius.
                RGB surface_phi, medium_phi;
                int surface_gathered = 0, medium_gathered = 0;
                // A spectral film's buckets of the two gathers.
                std::vector<double> phi_buckets(2 * size_t(buckets), 0.0);
                double *surface_phi_buckets = phi_buckets.data(), *medium_phi_buckets = surface_phi_buckets + buckets;
                for (const VisiblePoint *vp : {&state.vp, &state.subsurface_vp})
                    if (vp->exists()) surface_phi += gather(*vp, g, estimate.surface.radius, surface_gathered, surface_phi_buckets);
                for (const VisiblePoint &vp : state.medium_vps)
                    medium_phi += gather(vp, g, estimate.medium.radius, medium_gathered, medium_phi_buckets);
                float surface_scale = 1, medium_scale = 1;
                if (surface_gathered > 0) surface_scale = estimate.surface.update(surface_phi, float(surface_gathered), 2);
                if (medium_gathered > 0) medium_scale = estimate.medium.update(medium_phi, float(medium_gathered), 3);
                if (buckets > 0) {
                    double *b = &bucket_estimates_[index * 3 * buckets];
                    for (int i = 0; i < buckets; ++i) {
                        b[i] += state.direct_buckets[i];
                        if (surface_gathered > 0) b[buckets + i] = (b[buckets + i] + surface_phi_buckets[i]) * surface_scale;
                        if (medium_gathered > 0) b[2 * buckets + i] = (b[2 * buckets + i] + medium_phi_buckets[i]) * medium_scale;
                    }
                }
            });
            return true;
        });
        iterations = stats.samples_per_pixel;
    }
    // An interrupted iteration changed no estimate (the gather pass is not interrupted) and
    // the film is only written below, so the state is still that of the completed iterations.
    if (stats.interrupted && budget.at_boundary) budget.at_boundary();

    // The image: direct lighting averaged over the iterations, plus the photon estimates
    // tau / (N_emitted |kernel|), |kernel| = pi r^2 on surfaces and 4/3 pi r^3 in media.
    if (iterations == 0) return;
    const double emitted = double(iterations) * double(photon_count);
    size_t index = 0;
    for (int y = bounds.min.y; y < bounds.max.y; ++y)
        for (int x = bounds.min.x; x < bounds.max.x; ++x, ++index) {
            if (!owned[index]) continue; // another rank's pixel, added by that rank
            const PixelEstimate &estimate = estimates_[index];
            const float r_surface = estimate.surface.radius, r_medium = estimate.medium.radius;
            const double surface_measure = emitted * Pi * sqr(r_surface);
            const double medium_measure = emitted * 4 / 3 * Pi * r_medium * sqr(r_medium);
            RGB value = estimate.direct_sum / float(iterations) + estimate.surface.tau / float(surface_measure) +
                        estimate.medium.tau / float(medium_measure);
            std::vector<double> value_buckets(buckets);
            const double *b = buckets > 0 ? &bucket_estimates_[index * 3 * buckets] : nullptr;
            for (int i = 0; i < buckets; ++i) {
                value_buckets[i] = b[i] / iterations + (r_surface > 0 ? b[buckets + i] / surface_measure : 0) +
                                   (r_medium > 0 ? b[2 * buckets + i] / medium_measure : 0);
            }
            film.add_sensor_value({x, y}, value, 1, buckets > 0 ? value_buckets.data() : nullptr);
        }
}

void SPPM::save_state(std::ostream &out) const {
    const uint64_t count = estimates_.size();
    out.write(reinterpret_cast<const char *>(&count), sizeof count);
    out.write(reinterpret_cast<const char *>(estimates_.data()), std::streamsize(count * sizeof(PixelEstimate)));
    out.write(reinterpret_cast<const char *>(bucket_estimates_.data()),
              std::streamsize(bucket_estimates_.size() * sizeof(double)));
}

void SPPM::restore_state(std::istream &in) {
    uint64_t count = 0;
    in.read(reinterpret_cast<char *>(&count), sizeof count);
    if (!in || count > (uint64_t(1) << 32)) throw std::runtime_error("sppm: damaged pixel estimates");
    estimates_.resize(count);
    bucket_estimates_.assign(count * 3 * buckets_, 0.0);
    in.read(reinterpret_cast<char *>(estimates_.data()), std::streamsize(count * sizeof(PixelEstimate)));
    in.read(reinterpret_cast<char *>(bucket_estimates_.data()), std::streamsize(bucket_estimates_.size() * sizeof(double)));
    if (!in) throw std::runtime_error("sppm: damaged pixel estimates");
}

} // namespace caustica
