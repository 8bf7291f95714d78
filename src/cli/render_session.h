// What the commands that render (`render`, `compare`) share: reading --resolution, building a
// scene with its integrator, running one render and taking its image, and the metadata the
// image's EXR carries.
#pragma once

#include "film/image.h"
#include "integrators/integrator.h"
#include "scene/scene.h"

#include <cstdint>
#include <map>
#include <memory>
#include <string>

namespace caustica {

struct SceneDescription;

// "WxH" with 1 <= W, H <= 65536; throws InputError otherwise.
void parse_resolution(const std::string &text, int *width, int *height);

// The worker threads to use: `requested` when > 0, else all cores.
int worker_thread_count(int requested);

// A scene built from a description and the integrator it names, ready for one render: the
// film accumulates, so every render needs a session of its own.
struct RenderSession {
    std::unique_ptr<Scene> scene;
    std::unique_ptr<Integrator> integrator;

    // Renders the scene under `budget` into its film, filling in `stats`.
    void render(const RenderBudget &budget, RenderStats &stats, const ProgressCallback &progress);
    // The film's image after render() (light-tracing splats scaled as the integrator says),
    // with a G-buffer film's visible-surface layers; the film's own metadata (a spectral film's
    // layout) are added to `metadata` when given.
    Image image(const RenderStats &stats, std::map<std::string, std::string> *metadata = nullptr) const;
};

// Which warnings creating a session prints: building the scene and creating the integrator.
// A command that builds one description several times shows each warning once. Muted warnings
// are switched back on afterwards (the commands run with warnings on).
struct SessionWarnings {
    bool scene = true, integrator = true;
    // The Integrator parameters that nothing read (off: the caller reports them, see
    // create_integrator).
    bool unused_integrator_parameters = true;
};

// Throws InputError for anything the description or the overrides get wrong.
RenderSession create_render_session(const SceneDescription &description, const RenderOverrides &overrides,
                                    SessionWarnings warnings = {});

// The string attributes written into a rendered EXR (caustica:integrator, spp, seed, scene,
// partial).
std::map<std::string, std::string> render_metadata(const Scene &scene, const RenderStats &stats, uint64_t seed,
                                                   const std::string &scene_path);

} // namespace caustica
