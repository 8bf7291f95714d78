#include "integrators/common/visible_surfaces.h"

#include "camera/camera.h"
#include "camera/camera_footprint.h"
#include "core/rng.h"
#include "core/scratch_buffer.h"
#include "film/film.h"
#include "integrators/common/subpath_walk.h"
#include "integrators/common/tile_renderer.h"
#include "scene/scene.h"
#include "spectral/color_space.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <optional>

namespace caustica {

namespace {

struct VisibleSurface {
    Vec3f p, n, ns, dpdx, dpdy;
    Vec2f uv;
};

// The BSDF's directional albedo by its own sampling, as pbrt-v4's BSDF::rho, with 16 samples.
// pbrt-v4 uses one fixed set of 16 for every pixel, which leaves each pixel's estimate of a
// glossy lobe biased; these are drawn afresh for each camera sample (from the sampler), so
// that the pixel's average converges.
SampledSpectrum directional_albedo(const BSDF &bsdf, Vec3f wo, Vec3f ns, Sampler &sampler) {
    constexpr int Samples = 16;
    SampledSpectrum sum(0.f);
    for (int i = 0; i < Samples; ++i) {
        const float uc = sampler.get_1d();
        const Vec2f u = sampler.get_2d();
        if (auto bs = bsdf.sample_f(wo, uc, u)) sum += bs->f * (abs_dot(bs->wi, ns) / bs->pdf);
    }
    return sum / float(Samples);
}

// Output RGB of a reflectance lit by the colour space's white (pbrt-v4's albedo colour).
RGB albedo_rgb(const SampledSpectrum &albedo, const SampledWavelengths &lambda, const RGBColorSpace &space) {
    return space.rgb_from_xyz(sampled_spectrum_to_xyz(albedo * space.illuminant().sample(lambda), lambda));
}

// The first surface with a BSDF that a camera ray (with its differentials) reaches; dp/dx and
// dp/dy are where the differential rays meet its tangent plane (camera_footprint.h).
std::optional<VisibleSurface> trace_visible_surface(const Scene &scene, const CameraRay &camera_ray,
                                                    SampledWavelengths &lambda, Sampler &sampler,
                                                    ScratchBuffer &scratch, SampledSpectrum *albedo) {
    uint64_t rays = 0;
    SubpathWalk walk(scene, TransportMode::Radiance, lambda, sampler, scratch, rays, false);
    walk.start(camera_ray.ray, scene.camera_medium, SampledSpectrum(1.f), camera_ray.differential);
    while (true) {
        if (walk.advance() != WalkEvent::Vertex || walk.in_medium()) return {};
        const ScatteringPoint &point = walk.vertex();
        if (!point.bsdf) {
            walk.pass_through();
            continue;
        }
        const SurfaceInteraction &si = walk.hit();
        VisibleSurface v;
        v.p = si.p;
        v.n = face_forward(si.n, si.wo);
        v.ns = face_forward(si.shading.n, si.wo);
        v.uv = si.uv;
        v.dpdx = si.dpdx;
        v.dpdy = si.dpdy;
        *albedo = directional_albedo(point.bsdf, si.wo, si.shading.n, sampler);
        return v;
    }
}

struct PixelSums {
    double albedo[3] = {0, 0, 0};
    double p[3] = {0, 0, 0}, n[3] = {0, 0, 0}, ns[3] = {0, 0, 0};
    double dzdx = 0, dzdy = 0, u = 0, v = 0;
    double weight = 0, surface_weight = 0;
};

void add(double *sum, Vec3f v, float w) {
    for (int c = 0; c < 3; ++c) sum[c] += double(w) * v[c];
}

} // namespace

void add_visible_surface_layers(const Scene &scene, int samples, int render_samples, Image &image) {
    const Film &film = *scene.film;
    // pbrt-v4 scales camera ray differentials to the spacing of the render's samples, and its dz
    // layers with them.
    const float differential = differential_scale(render_samples);
    const PixelBounds &bounds = film.pixel_bounds();
    const Transform output_from_world = film.gbuffer_camera_space() ? scene.camera_from_world : Transform();
    const size_t pixels = size_t(bounds.width()) * bounds.height();
    std::vector<PixelSums> sums(pixels);
    struct ThreadState {
        std::unique_ptr<Sampler> sampler;
        std::unique_ptr<ScratchBuffer> scratch;
    };
    tbb::enumerable_thread_specific<ThreadState> states(
        [&] { return ThreadState{scene.sampler->clone(), std::make_unique<ScratchBuffer>()}; });
    tbb::parallel_for(bounds.min.y, bounds.max.y, [&](int y) {
        ThreadState &state = states.local();
        Sampler &sampler = *state.sampler;
        for (int x = bounds.min.x; x < bounds.max.x; ++x) {
            PixelSums &s = sums[size_t(y - bounds.min.y) * bounds.width() + (x - bounds.min.x)];
            for (int i = 0; i < samples; ++i) {
                sampler.start_pixel_sample({x, y}, i);
                // Visible wavelengths whatever the render samples, so that the albedo's colour
                // is estimated over the whole spectrum.
                SampledWavelengths lambda = SampledWavelengths::sample_visible(sampler.get_1d());
                const CameraSample cs = get_camera_sample(sampler, {x, y}, film.filter(), scene.motion_shutter());
                s.weight += cs.filter_weight;
                const std::optional<CameraRay> ray = generate_ray_differential(*scene.camera, cs, lambda, differential);
                if (!ray) continue;
                SampledSpectrum albedo(0.f);
                const std::optional<VisibleSurface> v =
                    trace_visible_surface(scene, *ray, lambda, sampler, *state.scratch, &albedo);
                state.scratch->reset();
                if (!v) continue;
                const float w = cs.filter_weight;
                const RGB a = albedo_rgb(albedo, lambda, film.color_space());
                for (int c = 0; c < 3; ++c) s.albedo[c] += double(w) * a[c];
                add(s.p, output_from_world.apply_point(v->p), w);
                add(s.n, normalize(output_from_world.apply_normal(v->n)), w);
                add(s.ns, normalize(output_from_world.apply_normal(v->ns)), w);
                s.dzdx += double(w) * output_from_world.apply_vector(v->dpdx).z;
                s.dzdy += double(w) * output_from_world.apply_vector(v->dpdy).z;
                s.u += double(w) * v->uv.x;
                s.v += double(w) * v->uv.y;
                s.surface_weight += w;
            }
        }
    });

    Image::Layer albedo{"Albedo", std::vector<float>(pixels * 3, 0.f)};
    const char *axes = "XYZ";
    std::vector<Image::Channel> channels;
    for (const char *name : {"P", "N", "Ns"})
        for (int c = 0; c < 3; ++c) channels.push_back({std::string(name) + "." + axes[c], std::vector<float>(pixels, 0.f)});
    for (const char *name : {"dzdx", "dzdy", "u", "v"}) channels.push_back({name, std::vector<float>(pixels, 0.f)});
    for (size_t i = 0; i < pixels; ++i) {
        const PixelSums &s = sums[i];
        if (s.weight != 0)
            for (int c = 0; c < 3; ++c) albedo.rgb[i * 3 + c] = float(s.albedo[c] / s.weight);
        if (s.surface_weight == 0) continue;
        const double w = s.surface_weight;
        auto unit = [](const double *v) {
            const double length = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
            return length > 0 ? Vec3f{float(v[0] / length), float(v[1] / length), float(v[2] / length)} : Vec3f{};
        };
        const Vec3f n = unit(s.n), ns = unit(s.ns);
        for (int c = 0; c < 3; ++c) {
            channels[c].values[i] = float(s.p[c] / w);
            channels[3 + c].values[i] = n[c];
            channels[6 + c].values[i] = ns[c];
        }
        channels[9].values[i] = float(std::abs(s.dzdx / w));
        channels[10].values[i] = float(std::abs(s.dzdy / w));
        channels[11].values[i] = float(s.u / w);
        channels[12].values[i] = float(s.v / w);
    }
    image.layers.push_back(std::move(albedo));
    for (Image::Channel &channel : channels) image.channels.push_back(std::move(channel));
}

} // namespace caustica
