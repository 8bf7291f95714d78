// Checkpoints of a render (`caustica render --checkpoint SECONDS`, `--resume`): the state a long
// render can be continued from after the process was stopped or killed, giving the image an
// uninterrupted render would have given, bit for bit.
//
// A distributed render (cli/process_group.h) keeps every rank's state in one checkpoint, and
// resumes with the same number of ranks.
//
// A checkpoint is taken only where the film and the integrator's state hold exactly the samples
// the RenderStats count (RenderBudget::at_boundary): between sweeps of samples or photon-mapping
// iterations, and where an interrupted render stops if that state is consistent (for pt, lt and
// bdpt it always is: each pixel's own sample count is saved). It holds
//   - a text header: the format, then the render's fingerprint, one "name value" line each,
//     ending with an empty line;
//   - per process (one, or each MPI rank's): the RenderStats (sample counts, rays, time), the
//     film's accumulators (Film::save_state) and the integrator's own state
//     (Integrator::save_state), in this machine's binary representation;
//   - an end marker.
// The fingerprint names everything the result depends on: the caustica build, the contents of
// the scene's files, the integrator, seed, sample count or time budget, resolution, pixel
// bounds, wavelength options and the variance layer. A render resumes only from a checkpoint
// with the same fingerprint; the thread count may differ, as it does not change the result.
//
// A checkpoint is written to a temporary file, flushed to the disk and renamed over the
// previous one, so that a kill (or a power cut) at any moment leaves a complete checkpoint.
#pragma once

#include "cli/process_group.h"
#include "core/error.h"
#include "integrators/integrator.h"

#include <atomic>
#include <chrono>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

namespace caustica {

struct SceneDescription;
struct RenderSession;

// What determines a render's result, as (name, value) pairs in a fixed order.
struct RenderFingerprint {
    std::vector<std::pair<std::string, std::string>> fields;
};

// The fingerprint of rendering `description` (read from scene_path) as `scene` under `budget`,
// with or without the variance layer. Reads every file the scene consists of: the scene file,
// the files it includes and every existing file a parameter names (meshes, images, spectra).
RenderFingerprint render_fingerprint(const std::string &scene_path, const SceneDescription &description,
                                     const Scene &scene, const RenderBudget &budget, bool variance);

// The checkpoint of a render whose image goes to output_path: next to it, "OUT.exr.checkpoint".
std::string checkpoint_path(const std::string &output_path);

// A session's state: its RenderStats, its film's accumulators and its integrator's state.
std::string session_state(const RenderSession &session, const RenderStats &stats);
// Restores what session_state wrote into `session` (fresh, of the same render) and `stats`.
// Throws std::runtime_error if the data does not fit.
void restore_session_state(const std::string &state, RenderSession &session, RenderStats &stats);

// Writes a checkpoint of a render's processes at `path`, one state at a time (one for a render
// on its own, else each rank's in rank order): commit() replaces any previous checkpoint only
// once the new one is complete and on the disk; a file never committed is removed. Throws
// std::runtime_error when it cannot.
class CheckpointFile {
  public:
    CheckpointFile(const std::string &path, const RenderFingerprint &fingerprint, size_t states);
    ~CheckpointFile();
    void add(const std::string &state);
    void commit();

  private:
    std::string path_, temporary_;
    std::ofstream out_;
    size_t remaining_;
    bool committed_ = false;
};

// Reads the checkpoint at `path`: the constructor checks the header and the layout and throws
// InputError when there is no checkpoint, when it belongs to a different render (naming what
// differs) or is damaged; then next_state() gives the states in rank order.
class CheckpointReader {
  public:
    CheckpointReader(const std::string &path, const RenderFingerprint &fingerprint);
    size_t states() const { return states_; }
    std::string next_state();

  private:
    InputError damaged(const std::string &why) const;
    std::string path_;
    std::ifstream in_;
    size_t states_ = 0;
    std::streampos first_state_;
};

// Restores each rank's session and stats from the checkpoint at `path`, after which the render
// continues where the saved one stopped: rank 0 reads it and hands each rank its state. Throws
// InputError on every rank as read_checkpoint does, and when the checkpoint has another number
// of ranks; the session is then unchanged.
void resume_from_checkpoint(const std::string &path, const RenderFingerprint &fingerprint, const ProcessGroup &group,
                            RenderSession &session, RenderStats &stats);

// Takes the checkpoints of one render, as its RenderBudget::at_boundary: at the first boundary
// after `interval` seconds have passed since the last checkpoint (or the start), and at the
// boundary where an interrupted render stops (`interrupt` set). A checkpoint that cannot be
// written is a warning: the render goes on.
class CheckpointWriter {
  public:
    // With a group of several processes, every rank calls at_boundary() at the same boundaries,
    // and rank 0 writes every rank's state.
    CheckpointWriter(std::string path, RenderFingerprint fingerprint, double interval, const RenderSession &session,
                     const RenderStats &stats, const std::atomic<bool> *interrupt, const ProcessGroup &group);

    void at_boundary();

    const std::string &path() const { return path_; }
    // What the last checkpoint this writer wrote holds: its samples per pixel (-1: none
    // written), and whether some pixels had taken more (an interrupted sweep).
    int saved_samples_per_pixel() const { return saved_spp_; }
    bool saved_partial_sweep() const { return saved_partial_; }

  private:
    std::string path_;
    RenderFingerprint fingerprint_;
    double interval_;
    const RenderSession &session_;
    const RenderStats &stats_;
    const std::atomic<bool> *interrupt_;
    const ProcessGroup &group_;
    std::chrono::steady_clock::time_point last_;
    int saved_spp_ = -1;
    uint64_t saved_pixel_samples_ = 0;
    bool saved_partial_ = false;
};

} // namespace caustica
