#include "core/error.h"
#include "integrators/bdpt/bdpt.h"
#include "integrators/integrator.h"
#include "integrators/lt/light_tracer.h"
#include "integrators/pt/path_tracer.h"
#include "integrators/sppm/sppm.h"
#include "integrators/vcm/vcm.h"
#include "materials/disney_material.h"
#include "scene/scene.h"

namespace caustica {

namespace {

// Profile subsurface (the Disney material's diffusion and dipole models) is a BSSRDF sampled by
// probe rays, which pt, lt and bdpt follow (profile_subsurface.h; bdpt with the jump from entry
// to exit as an edge no strategy splits, PathVertex::after_jump); the photon-mapping integrators
// have no way to merge across it, so a scene that needs it and names one of them is an error
// rather than a silent change of model.
void check_profile_subsurface(const Scene &scene) {
    if (scene.integrator_name == "pt" || scene.integrator_name == "lt" || scene.integrator_name == "bdpt" ||
        !scene.features.subsurface)
        return;
    for (const MaterialPtr &material : scene.materials) {
        auto *disney = dynamic_cast<const DisneyMaterial *>(material.get());
        if (disney && disney->has_profile_subsurface())
            throw InputError(disney->subsurface_location(),
                             "profile subsurface (diffusion, dipole) is rendered by pt, lt and bdpt only; use "
                             "randomwalk (or one of those integrators; this scene is rendered with \"" +
                                 scene.integrator_name + "\")");
    }
}

} // namespace

std::unique_ptr<Integrator> create_integrator(const Scene &scene) {
    check_profile_subsurface(scene);
    if (scene.integrator_name == "pt") return std::make_unique<PathTracer>(scene.integrator_params);
    if (scene.integrator_name == "lt")
        return std::make_unique<LightTracer>(scene.integrator_params, scene);
    if (scene.integrator_name == "bdpt") return std::make_unique<BDPT>(scene.integrator_params, scene);
    if (scene.integrator_name == "sppm") return std::make_unique<SPPM>(scene.integrator_params, scene);
    if (scene.integrator_name == "vcm")
        return std::make_unique<VCM>(VCM::Mode::VertexConnectionMerging, scene.integrator_params, scene);
    if (scene.integrator_name == "bpm")
        return std::make_unique<VCM>(VCM::Mode::BidirectionalPhotonMapping, scene.integrator_params, scene);
    throw InputError(scene.integrator_location,
                     "integrator \"" + scene.integrator_name + "\" is not available in this build");
}

} // namespace caustica
