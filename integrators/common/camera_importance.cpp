#include "integrators/common/camera_importance.h"

#include "core/error.h"
#include "scene/scene.h"

namespace caustica {

void require_camera_importance(const Scene &scene, const std::string &integrator) {
    if (scene.camera->models_importance()) return;
    throw InputError(scene.camera_location, integrator + " connects light paths to the lens, which needs a camera "
                                                         "whose importance is modelled (perspective); this camera does not "
                                                         "model it (use pt or sppm)");
}

} // namespace caustica
