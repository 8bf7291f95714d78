// Integrators that connect light paths to the lens (lt, bdpt, bpm, vcm) need the camera's
// importance; a camera that does not model it (orthographic, spherical) is refused at its Camera
// directive, as pbrt-v4 refuses it.
#pragma once

#include <string>

namespace caustica {

class Scene;

// Throws InputError at the scene's Camera directive when its camera models no importance;
// `integrator` names the integrator in the message.
void require_camera_importance(const Scene &scene, const std::string &integrator);

} // namespace caustica
