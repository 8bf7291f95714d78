// Integrators that connect light paths to the lens (lt, bdpt, bpm, vcm) need the camera's
// importance; a camera that does not model it (orthographic, spherical) is refused at its Camera
// directive, as pbrt-v4 refuses it. Emissive media are refused by the integrators that would
// miss their light.
#pragma once

#include <string>

namespace caustica {

class Scene;

// Throws InputError at the scene's Camera directive when its camera models no importance;
// `integrator` names the integrator in the message.
void require_camera_importance(const Scene &scene, const std::string &integrator);

// Throws InputError at the first emissive medium's MakeNamedMedium when the scene has one: for
// integrators whose light reaches surfaces only through light subpaths (lt, sppm), which no
// emissive medium starts yet.
void refuse_emissive_media(const Scene &scene, const std::string &integrator);

} // namespace caustica
