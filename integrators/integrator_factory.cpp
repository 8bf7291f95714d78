#include "core/error.h"
#include "integrators/bdpt/bdpt.h"
#include "integrators/integrator.h"
#include "integrators/lt/light_tracer.h"
#include "integrators/pt/path_tracer.h"
#include "integrators/sppm/sppm.h"
#include "integrators/vcm/vcm.h"
#include "scene/scene.h"

namespace caustica {

namespace {

std::unique_ptr<Integrator> make_integrator(const Scene &scene) {
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

} // namespace

std::unique_ptr<Integrator> create_integrator(const Scene &scene, UnusedParameters unused) {
    std::unique_ptr<Integrator> integrator = make_integrator(scene);
    if (unused == UnusedParameters::Report) scene.integrator_params.report_unused();
    return integrator;
}

} // namespace caustica
