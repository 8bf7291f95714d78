#include "camera/camera_factory.h"

#include "camera/orthographic_camera.h"
#include "camera/perspective_camera.h"
#include "camera/realistic_camera.h"
#include "camera/spherical_camera.h"
#include "params/float_file.h"

#include <cmath>

namespace caustica {

namespace {

struct ProjectiveParameters {
    ScreenWindow screen;
    float lens_radius, focal_distance;
};

ProjectiveParameters read_projective(const ParameterDictionary &params, Vec2i resolution) {
    ProjectiveParameters p;
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

std::shared_ptr<Camera> create_perspective(const Transform &world_from_camera, const FilmExtent &film,
                             const ParameterDictionary &params) {
    ProjectiveParameters p = read_projective(params, film.full_resolution);
    float fov = params.get_one_float("fov", 90);
    if (!(fov > 0 && fov < 180))
        throw InputError(params.location("fov"), "\"fov\" must lie strictly between 0 and 180 degrees");
    return std::make_shared<PerspectiveCamera>(world_from_camera, film, fov, p.screen,
                                               p.lens_radius, p.focal_distance);
}

// pbrt-v4's "realistic" camera: "lensfile" (required), "aperturediameter" (mm, default 1),
// "focusdistance" (m from the film, default 10), "aperture" (a built-in shape or an image file).
std::shared_ptr<Camera> create_realistic(const Transform &world_from_camera, const FilmExtent &film,
                           const ParameterDictionary &params, const SourceLocation &loc) {
    const std::string lens_file = params.get_one_string("lensfile", "");
    if (lens_file.empty()) throw InputError(loc, "the \"realistic\" camera needs a lens description (\"lensfile\")");
    const float aperture_diameter = params.get_one_float("aperturediameter", 1);
    if (!(aperture_diameter > 0) || !std::isfinite(aperture_diameter))
        throw InputError(params.location("aperturediameter"), "\"aperturediameter\" must be positive");
    const float focus_distance = params.get_one_float("focusdistance", 10);
    if (!(focus_distance > 0) || !std::isfinite(focus_distance))
        throw InputError(params.location("focusdistance"), "\"focusdistance\" must be positive");

    LensSystem lens;
    bool clamped = false;
    try {
        lens = LensSystem::from_description(read_float_file(params.file_path("lensfile", lens_file), "lens file"),
                                            aperture_diameter, &clamped);
    } catch (const InputError &e) {
        throw InputError(params.location("lensfile"), e.message());
    }
    if (clamped)
        warning(params.location("aperturediameter"),
                "\"aperturediameter\" is larger than the lens's aperture stop; the stop's own diameter is used");
    try {
        lens.focus(focus_distance, film.diagonal);
    } catch (const InputError &e) {
        throw InputError(params.location("focusdistance"), e.message());
    }

    std::optional<ApertureMask> mask;
    const std::string aperture = params.get_one_string("aperture", "");
    if (!aperture.empty()) {
        mask = ApertureMask::builtin(aperture);
        if (!mask) {
            const std::string path = params.file_path("aperture", aperture);
            try {
                mask = ApertureMask::from_image(path);
            } catch (const std::runtime_error &e) {
                throw InputError(params.location("aperture"),
                                 "\"aperture\" is neither gaussian, square, pentagon nor star, and as an image: " +
                                     std::string(e.what()));
            }
        }
    }
    auto camera = std::make_shared<RealisticCamera>(world_from_camera, film, std::move(lens), std::move(mask));
    if (!camera->transmits())
        warning(loc, "no ray from the film passes the lens system: the image will be black");
    return camera;
}

} // namespace

std::shared_ptr<Camera> create_still_camera(const std::string &type, const Transform &world_from_camera,
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
    if (type == "realistic") return create_realistic(world_from_camera, film, params, loc);
    throw InputError(loc, "\"" + type + "\": unknown camera type");
}

CameraPtr create_camera(const std::string &type, const Transform &world_from_camera, const FilmExtent &film,
                        const ParameterDictionary &params, const SourceLocation &loc, const CameraMotion *motion) {
    std::shared_ptr<Camera> camera = create_still_camera(type, world_from_camera, film, params, loc);
    if (motion && !camera->set_motion({world_from_camera, motion->world_from_camera_end}, motion->times))
        warning(loc, "the camera's motion changes its scale, which Caustica does not support: the "
                     "camera stays at its start transform");
    return camera;
}

CameraPtr create_camera(const std::string &type, const Transform &world_from_camera,
                        Vec2i resolution, const ParameterDictionary &params,
                        const SourceLocation &loc) {
    return create_camera(type, world_from_camera, FilmExtent::whole_image(resolution), params, loc);
}

Shutter camera_shutter(const ParameterDictionary &params, const SourceLocation &loc) {
    float open = params.get_one_float("shutteropen", 0), close = params.get_one_float("shutterclose", 1);
    if (!(close - open > 0) || !std::isfinite(close - open))
        throw InputError(loc, "the camera's shutter times (\"shutteropen\" " + std::to_string(open) +
                                  ", \"shutterclose\" " + std::to_string(close) +
                                  ") imply that the shutter never opens");
    return {open, close};
}

} // namespace caustica
