// Creates the camera a scene's Camera directive asks for (pbrt-v4 names and parameters).
#pragma once

#include "camera/camera.h"
#include "core/error.h"
#include "params/parameters.h"

#include <string>

namespace caustica {

// "perspective" ("fov" in degrees across the shorter image axis, default 90; "lensradius",
// default 0; "focaldistance", default 1e6; "frameaspectratio"; "screenwindow"), "orthographic"
// (the same without "fov"), "spherical" ("mapping") and "realistic" ("lensfile",
// "aperturediameter", "focusdistance", "aperture"), with pbrt-v4's parameters and defaults.
// Unknown types and invalid values are InputErrors. `film` is the film's extent (Film::extent()):
// importance and splats then cover exactly the pixels the filter reaches, as in pbrt-v4.
// With `motion`, the camera moves from world_from_camera to motion's end placement over its
// TransformTimes (Camera::set_motion; a motion that changes the camera's scale warns and stays).
struct CameraMotion {
    Transform world_from_camera_end;
    TransformTimes times;
};
CameraPtr create_camera(const std::string &type, const Transform &world_from_camera,
                        const FilmExtent &film, const ParameterDictionary &params,
                        const SourceLocation &loc, const CameraMotion *motion = nullptr);

// The same for an uncropped film whose splats reach only the pixel they land in (a box filter
// of radius 0.5); prefer the FilmExtent overload when a Film exists.
CameraPtr create_camera(const std::string &type, const Transform &world_from_camera,
                        Vec2i resolution, const ParameterDictionary &params,
                        const SourceLocation &loc);

// The camera's "shutteropen" (default 0) and "shutterclose" (default 1). An InputError unless the
// shutter is open for a positive time, which is also the exposure time pbrt-v4 hands to the film's
// sensor.
Shutter camera_shutter(const ParameterDictionary &camera_params, const SourceLocation &loc);

} // namespace caustica
