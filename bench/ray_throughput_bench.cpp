// Ray throughput of the renderer's intersection path against raw Embree rtcIntersect1 on the
// same rays (camera rays plus one cosine-distributed bounce from each hit) of the Cornell box.
// The ratio tells how much the SurfaceInteraction setup costs over bare traversal.
#include "core/rng.h"
#include "core/sampling.h"
#include "geometry/interaction.h"
#include "parser/scene_description.h"
#include "scene/scene.h"

#include <benchmark/benchmark.h>

#include <memory>
#include <vector>

namespace caustica {
namespace {

struct BenchScene {
    std::unique_ptr<Scene> scene;
    std::vector<Ray> rays;
};

const BenchScene &cornell_box() {
    static const BenchScene bench = [] {
        BenchScene b;
        set_warnings_enabled(false);
        SceneDescription d = parse_scene_file(std::string(CAUSTICA_SOURCE_DIR) + "/scenes/cornell-box.pbrt");
        b.scene = build_scene(d, RenderOverrides{});
        const Scene &s = *b.scene;
        Vec2i res = s.film->resolution();
        Rng rng(7, 0);
        SampledWavelengths lambda = SampledWavelengths::sample_visible(0.5f);
        for (int y = 0; y < res.y; ++y)
            for (int x = 0; x < res.x; ++x) {
                CameraSample cs;
                cs.p_film = {x + rng.uniform(), y + rng.uniform()};
                cs.p_lens = rng.uniform2();
                auto cr = s.camera->generate_ray(cs, lambda);
                if (!cr) continue;
                b.rays.push_back(cr->ray);
                SurfaceInteraction si;
                if (!s.intersect(cr->ray, &si)) continue;
                Frame frame = Frame::from_z(si.n);
                Vec3f d = frame.from_local(sample_cosine_hemisphere(rng.uniform2()));
                b.rays.push_back(si.spawn_ray(dot(d, si.wo) > 0 ? d : -d));
            }
        return b;
    }();
    return bench;
}

void BM_RendererIntersect(benchmark::State &state) {
    const BenchScene &b = cornell_box();
    size_t hits = 0;
    for (auto _ : state) {
        for (const Ray &ray : b.rays) {
            SurfaceInteraction si;
            hits += b.scene->intersect(ray, &si);
        }
    }
    benchmark::DoNotOptimize(hits);
    state.SetItemsProcessed(int64_t(state.iterations()) * b.rays.size());
}
BENCHMARK(BM_RendererIntersect)->Unit(benchmark::kMillisecond);

void BM_EmbreeIntersect1(benchmark::State &state) {
    const BenchScene &b = cornell_box();
    RTCScene rtc = b.scene->geometry.handle();
    size_t hits = 0;
    for (auto _ : state) {
        for (const Ray &ray : b.rays) {
            RTCIntersectContext context;
            rtcInitIntersectContext(&context);
            RTCRayHit rh{};
            rh.ray.org_x = ray.o.x; rh.ray.org_y = ray.o.y; rh.ray.org_z = ray.o.z;
            rh.ray.dir_x = ray.d.x; rh.ray.dir_y = ray.d.y; rh.ray.dir_z = ray.d.z;
            rh.ray.tnear = 0;
            rh.ray.tfar = ray.t_max;
            rh.ray.mask = ~0u;
            rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
            rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
            rtcIntersect1(rtc, &context, &rh);
            hits += rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
        }
    }
    benchmark::DoNotOptimize(hits);
    state.SetItemsProcessed(int64_t(state.iterations()) * b.rays.size());
}
BENCHMARK(BM_EmbreeIntersect1)->Unit(benchmark::kMillisecond);

} // namespace
} // namespace caustica

BENCHMARK_MAIN();
