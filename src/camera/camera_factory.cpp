#include "camera/camera_factory.h"

#include "camera/orthographic_camera.h"
#include "camera/perspective_camera.h"
#include "camera/spherical_camera.h"

namespace caustica {

namespace {

struct ProjectiveParameters {
    ScreenWindow screen;
    float lens_radius, focal_distance;
};

ProjectiveParameters read_projective(const ParameterDictionary &params, Vec2i resolution) {
    ProjectiveParameters p;
    // Shutter times only matter for motion blur (not rendered) and for the exposure time
    // (camera_exposure_time()); they are read here so they count as used.
    params.get_one_float("shutteropen", 0);
    params.get_one_float("shutterclose", 1);

    p.lens_radius = params.get_one_float("lensradius", 0);
    if (!(p.lens_radius >= 0))
        throw InputError(params.location("lensradius"), "\"lensradius\" must not be negative");
    p.focal_distance = params.get_one_float("focaldistance", 1e6f);
    if (!(p.focal_distance > 0))
        throw InputError(params.location("focaldistance"), "\"focaldistance\" must be positive");
    float frame = params.get_one_float("frameaspectratio", float(resolution.x) / float(resolution.y));
    if (!(frame > 0) || !std::isfinite(frame))
        throw InputError(params.location("frameaspectratio"), "\"frameaspectratio\" must be positive");
    p.screen = default_screen_window(frame);
    std::vector<float> sw = params.get_float_array("screenwindow");
    if (!sw.empty()) {
        if (sw.size() != 4)
            throw InputError(params.location("screenwindow"),
                             "\"screenwindow\" needs 4 values (xmin xmax ymin ymax), got " +
                                 std::to_string(sw.size()));
        if (!(sw[0] != sw[1]) || !(sw[2] != sw[3]))
            throw InputError(params.location("screenwindow"), "\"screenwindow\" has zero area");
        p.screen = {{sw[0], sw[2]}, {sw[1], sw[3]}};
    }
    return p;
}

CameraPtr create_perspective(const Transform &world_from_camera, const FilmExtent &film,
                             const ParameterDictionary &params) {
    ProjectiveParameters p = read_projective(params, film.full_resolution);
    float fov = params.get_one_float("fov", 90);
    if (!(fov > 0 && fov < 180))
        throw InputError(params.location("fov"), "\"fov\" must lie strictly between 0 and 180 degrees");
    return std::make_shared<PerspectiveCamera>(world_from_camera, film, fov, p.screen,
                                               p.lens_radius, p.focal_distance);
}

} // namespace

CameraPtr create_camera(const std::string &type, const Transform &world_from_camera,
                        const FilmExtent &film, const ParameterDictionary &params,
                        const SourceLocation &loc) {
    if (film.full_resolution.x < 1 || film.full_resolution.y < 1)
        throw InputError(loc, "the film resolution must be positive");
    if (type == "perspective") return create_perspective(world_from_camera, film, params);
    if (type == "orthographic") {
        ProjectiveParameters p = read_projective(params, film.full_resolution);
        return std::make_shared<OrthographicCamera>(world_from_camera, film, p.screen,
                                                    p.lens_radius, p.focal_distance);
    }
    if (type == "spherical") {
        params.get_one_float("shutteropen", 0);
        params.get_one_float("shutterclose", 1);
        const std::string mapping = params.get_one_string("mapping", "equalarea");
        if (mapping != "equalarea" && mapping != "equirectangular")
            throw InputError(params.location("mapping"), "\"mapping\" must be \"equalarea\" or "
                                                         "\"equirectangular\", not \"" + mapping + "\"");
        if (mapping == "equalarea" && film.full_resolution.x != film.full_resolution.y)
            throw InputError(loc, "the \"equalarea\" spherical camera needs a square film, not " +
                                      std::to_string(film.full_resolution.x) + "x" +
                                      std::to_string(film.full_resolution.y));
        return std::make_shared<SphericalCamera>(world_from_camera, film,
                                                 mapping == "equalarea" ? SphericalCamera::Mapping::EqualArea
                                                                        : SphericalCamera::Mapping::Equirectangular);
    }
    if (type == "realistic") {
        warning(loc, "the \"" + type + "\" camera is not supported; rendering with a "
                     "perspective camera instead");
        // The replaced camera's own parameters are acknowledged so that only the warning above
        // reports them, not one warning each.
        for (const char *name : {"lensfile", "apertureimage"})
            if (params.has(name)) params.get_one_string(name, "");
        for (const char *name : {"aperturediameter", "focusdistance"})
            if (params.has(name)) params.get_one_float(name, 0);
        return create_perspective(world_from_camera, film, params);
    }
    throw InputError(loc, "\"" + type + "\": unknown camera type");
}

CameraPtr create_camera(const std::string &type, const Transform &world_from_camera,
                        Vec2i resolution, const ParameterDictionary &params,
                        const SourceLocation &loc) {
    return create_camera(type, world_from_camera, FilmExtent::whole_image(resolution), params, loc);
}

float camera_exposure_time(const ParameterDictionary &params, const SourceLocation &loc) {
    float open = params.get_one_float("shutteropen", 0), close = params.get_one_float("shutterclose", 1);
    float t = close - open;
    if (!(t > 0))
        throw InputError(loc, "the camera's shutter times (\"shutteropen\" " + std::to_string(open) +
                                  ", \"shutterclose\" " + std::to_string(close) +
                                  ") imply that the shutter never opens");
    return t;
}

} // namespace caustica
