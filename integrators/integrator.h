// The integrator interface and what all integrators report back.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

namespace caustica {

class Scene;

// How the processes of a distributed render (an MPI job: mpi/mpi_share.h) share one render.
// Every process renders the same scene under the same budget; the loops that drive integrators
// (tile_renderer.h, iteration_renderer.h) ask this which part of the work is theirs and agree
// with the other processes at every boundary between sweeps. The calls other than rank() and
// ranks() are collective: every process makes the same calls in the same order. A process on
// its own is rank 0 of 1, and agreeing is a no-op.
class RenderShare {
  public:
    virtual ~RenderShare() = default;
    virtual int rank() const { return 0; }
    virtual int ranks() const { return 1; }
    // Rank 0's value, on every rank: decisions that depend on a clock (a time budget).
    virtual int64_t agree(int64_t value) const { return value; }
    // The sum of every rank's value.
    virtual int64_t sum(int64_t value) const { return value; }
    bool any(bool value) const { return sum(value ? 1 : 0) > 0; }
    // The largest of every rank's value.
    float max(float value) const;
    // Every rank's bytes, concatenated in rank order.
    virtual std::vector<char> gather_all(std::vector<char> bytes) const { return bytes; }
    // The share of a process on its own.
    static const RenderShare &alone();
};

// Budget for one render: a fixed sample count, or as many samples as fit in a time limit.
struct RenderBudget {
    int spp = 16;
    double seconds = 0;   // > 0: render until this much wall time has passed (spp is then a cap)
    // Set asynchronously (by a signal handler) to stop the render as soon as possible; what was
    // accumulated stays in the film, correctly normalised.
    const std::atomic<bool> *cancel = nullptr;
    // Called on the rendering thread whenever the film and the integrator's state hold exactly
    // the samples the RenderStats count, which are then up to date: at every boundary between
    // sweeps of samples (photon mapping: between iterations), and when the render stops on
    // `cancel` if it can stop in such a state. Camera-sample renderers (pt, lt, bdpt) always can,
    // recording each pixel's own count in RenderStats::pixel_sample_counts; photon mapping can
    // when the interrupted iteration left no trace. These are the moments a checkpoint can be
    // taken (cli/checkpoint.h); the callback may be called twice for the same state.
    std::function<void()> at_boundary;
    // The processes sharing the render (see RenderShare); null: this process alone. A
    // distributed render calls at_boundary only where every rank's state is consistent, on
    // every rank at once.
    const RenderShare *share = nullptr;
    const RenderShare &sharing() const { return share ? *share : RenderShare::alone(); }
};

// What a render has done. A render continues from the stats it is given: a fresh RenderStats
// starts from nothing, while a render resumed from a checkpoint passes the saved stats, whose
// samples its film and integrator state already hold.
struct RenderStats {
    std::atomic<uint64_t> rays{0};              // camera, bounce and shadow rays traced
    std::atomic<uint64_t> non_finite_samples{0};// caught, counted and dropped
    int samples_per_pixel = 0;                  // completed for every pixel
    // Pixel samples actually taken, over the film's pixel bounds: differs from
    // samples_per_pixel * pixels when a render is interrupted part-way through a sweep.
    std::atomic<uint64_t> pixel_samples{0};
    // After an interruption part-way through a sweep of camera samples (pt, lt, bdpt): the
    // samples each pixel of the film's bounds has taken, row by row (each at least
    // samples_per_pixel). Empty when every pixel has taken samples_per_pixel.
    std::vector<int> pixel_sample_counts;
    bool interrupted = false;
    double seconds = 0;
    // sppm, bpm and vcm: the most light vertices kept at once for the camera pass (photons, and
    // with vcm's "lightvertices" "store" the vertices kept for connections), over iterations.
    std::atomic<uint64_t> stored_light_vertices{0};
};

// Progress callback: fraction done in [0,1] and samples taken so far.
using ProgressCallback = std::function<void(double fraction, uint64_t samples)>;

class Integrator {
  public:
    virtual ~Integrator() = default;
    // Renders into scene.film, continuing from `stats` (see RenderStats). Deterministic for a
    // seed and sample count, whatever the threads, and whether or not it was resumed.
    virtual void render(const Scene &scene, const RenderBudget &budget, RenderStats &stats,
                        const ProgressCallback &progress) = 0;
    // The factor the film's splats are scaled by when the image is made (Film::get_image) after
    // render() has filled in stats. Integrators that only add camera samples leave it at 1.
    virtual double splat_scale(const Scene &scene, const RenderStats &stats) const {
        (void)scene;
        (void)stats;
        return 1;
    }
    // Checkpoints: what the integrator carries from one iteration to the next beyond the film
    // and the RenderStats, written at a boundary (RenderBudget::at_boundary) and read back
    // before a resumed render() of the same scene. Most integrators carry nothing.
    // restore_state throws std::runtime_error if the data does not fit.
    virtual void save_state(std::ostream &out) const { (void)out; }
    virtual void restore_state(std::istream &in) { (void)in; }
};

// Creates the integrator named by scene.integrator_name; throws InputError for unknown names.
// Then warns about the Integrator parameters that neither it nor the scene builder read, unless
// the caller reports them itself (compare: those that no integrator of the comparison read).
enum class UnusedParameters { Report, LeaveToCaller };
std::unique_ptr<Integrator> create_integrator(const Scene &scene,
                                              UnusedParameters unused = UnusedParameters::Report);

} // namespace caustica
