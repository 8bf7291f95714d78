#include "core/error.h"
#include "integrators/bdpt/bdpt.h"
#include "integrators/integrator.h"
#include "integrators/lt/light_tracer.h"
#include "integrators/pt/path_tracer.h"
#include "integrators/sppm/sppm.h"
#include "integrators/vcm/vcm.h"
#include "scene/scene.h"

#include <algorithm>
#include <cstring>

namespace caustica {

float RenderShare::max(float value) const {
    if (ranks() == 1) return value;
    std::vector<char> bytes(sizeof value);
    std::memcpy(bytes.data(), &value, sizeof value);
    bytes = gather_all(std::move(bytes));
    for (size_t offset = 0; offset + sizeof value <= bytes.size(); offset += sizeof value) {
        float v;
        std::memcpy(&v, &bytes[offset], sizeof v);
        value = std::max(value, v);
    }
    return value;
}

const RenderShare &RenderShare::alone() {
    static const RenderShare share;
    return share;
}

std::unique_ptr<Integrator> create_integrator(const Scene &scene) {
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
