// The integrator interface and what all integrators report back.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

namespace caustica {

class Scene;

// Budget for one render: a fixed sample count, or as many samples as fit in a time limit.
struct RenderBudget {
    int spp = 16;
    double seconds = 0;   // > 0: render until this much wall time has passed (spp is then a cap)
    // Set asynchronously (by a signal handler) to stop the render as soon as possible; what was
    // accumulated stays in the film, correctly normalised.
    const std::atomic<bool> *cancel = nullptr;
};

struct RenderStats {
    std::atomic<uint64_t> rays{0};              // camera, bounce and shadow rays traced
    std::atomic<uint64_t> non_finite_samples{0};// caught, counted and dropped
    int samples_per_pixel = 0;                  // completed for every pixel
    // Pixel samples actually taken, over the film's pixel bounds: differs from
    // samples_per_pixel * pixels when a render is interrupted part-way through a sweep.
    std::atomic<uint64_t> pixel_samples{0};
    bool interrupted = false;
    double seconds = 0;
};

// Progress callback: fraction done in [0,1] and samples taken so far.
using ProgressCallback = std::function<void(double fraction, uint64_t samples)>;

class Integrator {
  public:
    virtual ~Integrator() = default;
    // Renders into scene.film. Deterministic for a seed and sample count, whatever the threads.
    virtual void render(const Scene &scene, const RenderBudget &budget, RenderStats &stats,
                        const ProgressCallback &progress) = 0;
    // The factor the film's splats are scaled by when the image is made (Film::get_image) after
    // render() has filled in stats. Integrators that only add camera samples leave it at 1.
    virtual double splat_scale(const Scene &scene, const RenderStats &stats) const {
        (void)scene;
        (void)stats;
        return 1;
    }
};

// Creates the integrator named by scene.integrator_name; throws InputError for unknown names.
std::unique_ptr<Integrator> create_integrator(const Scene &scene);

} // namespace caustica
