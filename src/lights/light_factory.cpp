#include "lights/light_factory.h"

#include "lights/diffuse_area_light.h"
#include "lights/distant_light.h"
#include "lights/goniometric_light.h"
#include "lights/image_infinite_light.h"
#include "spectral/photometric.h"
#include "lights/point_light.h"
#include "lights/portal_infinite_light.h"
#include "lights/projection_light.h"
#include "lights/rgb_image.h"
#include "lights/spot_light.h"
#include "lights/uniform_infinite_light.h"
#include "spectral/color_space.h"


namespace caustica {

namespace {

// Emission must not be negative anywhere: a negative spectrum or scale would give the light a
// negative power, which the power-proportional light sampler cannot sample, and radiance that
// subtracts light. (RGB and blackbody emission cannot be negative; inline spectra and
// constants can.)
SpectrumPtr checked_emission(const ParameterDictionary &params, const std::string &name,
                             SpectrumPtr s) {
    if (!s) return s;
    for (int lambda = int(LambdaMin); lambda <= int(LambdaMax); ++lambda)
        if (!((*s)(float(lambda)) >= 0))
            throw InputError(params.location(name), "\"" + name + "\": emission must not be "
                             "negative (it is " + std::to_string((*s)(float(lambda))) + " at " +
                             std::to_string(lambda) + " nm)");
    return s;
}

float read_scale(const ParameterDictionary &params) {
    float scale = params.get_one_float("scale", 1);
    if (!(scale >= 0))
        throw InputError(params.location("scale"), "\"scale\" must not be negative");
    return scale;
}

// The light's spectrum, or the colour space's illuminant (pbrt-v4's default for every light).
SpectrumPtr light_spectrum(const ParameterDictionary &params, const std::string &name) {
    SpectrumPtr s = checked_emission(params, name,
                                     params.get_one_spectrum(name, nullptr, SpectrumType::Illuminant));
    return s ? s : std::make_shared<DenselySampledSpectrum>(params.color_space().illuminant());
}

// Divides scale by the spectrum's luminance integral so that the light emits 1 nit (or 1 cd)
// times scale; a spectrum without luminance emits nothing.
float photometric_scale(float scale, const Spectrum &s) {
    float y = spectrum_to_photometric(s);
    return y > 0 ? scale / y : 0.f;
}

// Lights evaluate their spectrum at every sample: a 1 nm table is fast whatever the source.
SpectrumPtr tabulated(const SpectrumPtr &s) { return std::make_shared<DenselySampledSpectrum>(*s); }

// The transform taking light-space +z to unit direction z (x and y completing a frame).
Transform transform_from_z(Vec3f z) {
    Frame f = Frame::from_z(z);
    const float m[16] = {f.x.x, f.y.x, f.z.x, 0, f.x.y, f.y.y, f.z.y, 0,
                         f.x.z, f.y.z, f.z.z, 0, 0,     0,     0,     1};
    return Transform(Matrix4::from_row_major(m), Matrix4::from_row_major(m).transposed());
}

Vec3f direction_between(const ParameterDictionary &params, Vec3f from, Vec3f to) {
    Vec3f d = to - from;
    if (!(length_squared(d) > 0))
        throw InputError(params.location("to"), "\"from\" and \"to\" must be different points");
    return normalize(d);
}

LightPtr create_point(const Transform &render_from_light, const ParameterDictionary &params) {
    SpectrumPtr I = light_spectrum(params, "I");
    float scale = photometric_scale(read_scale(params), *I);
    float power = params.get_one_float("power", -1);
    // Intensity 1 over the sphere of directions gives power 4 pi.
    if (power > 0) scale *= power / (4 * Pi);
    Vec3f from = params.get_one_point3("from", {0, 0, 0});
    return std::make_shared<PointLight>(render_from_light * Transform::translate(from),
                                        tabulated(I), scale);
}

LightPtr create_spot(const Transform &render_from_light, const ParameterDictionary &params) {
    SpectrumPtr I = light_spectrum(params, "I");
    float scale = photometric_scale(read_scale(params), *I);
    float cone_angle = params.get_one_float_checked("coneangle", 30, 0, 180);
    float cone_delta = params.get_one_float_checked("conedeltaangle", 5, 0, 180);
    Vec3f from = params.get_one_point3("from", {0, 0, 0});
    Vec3f to = params.get_one_point3("to", {0, 0, 1});
    Transform light_frame =
        Transform::translate(from) * transform_from_z(direction_between(params, from, to));
    float power = params.get_one_float("power", -1);
    if (power > 0) {
        // Power of unit intensity: 2 pi times the profile integrated over cos theta.
        float cos_end = std::cos(radians(cone_angle));
        float cos_start = std::cos(radians(cone_angle - cone_delta));
        float k_e = 2 * Pi * ((1 - cos_start) + (cos_start - cos_end) / 2);
        if (k_e > 0) scale *= power / k_e;
    }
    return std::make_shared<SpotLight>(render_from_light * light_frame, tabulated(I), scale,
                                       cone_angle, cone_angle - cone_delta);
}

// The image file of an image light's "filename" parameter, read as linear RGB; errors at the
// parameter.
RGBImage read_light_image(const ParameterDictionary &params, const std::string &filename) {
    try {
        return read_rgb_image(params.file_path("filename", filename));
    } catch (const std::runtime_error &e) {
        throw InputError(params.location("filename"), e.what());
    }
}

LightPtr create_goniometric(const Transform &render_from_light, const ParameterDictionary &params) {
    SpectrumPtr I = light_spectrum(params, "I");
    float scale = photometric_scale(read_scale(params), *I);
    const std::string filename = params.get_one_string("filename", "");
    if (filename.empty())
        throw InputError(params.location("filename"), "goniometric: no \"filename\" (the diagram image) given");
    RGBImage image = read_light_image(params, filename);
    if (image.width != image.height)
        throw InputError(params.location("filename"),
                         "\"" + filename + "\": resolution " + std::to_string(image.width) + "x" +
                             std::to_string(image.height) +
                             " is not square (a goniometric diagram is an equal-area octahedral map)");
    auto light = std::make_shared<GoniometricLight>(render_from_light, tabulated(I), scale, image);
    float power = params.get_one_float("power", -1);
    // Intensity scale * mean over the sphere of directions gives power 4 pi scale * mean.
    if (power > 0 && light->mean() > 0)
        light = std::make_shared<GoniometricLight>(render_from_light, tabulated(I),
                                                   scale * power / (4 * Pi * light->mean()), image);
    return light;
}

LightPtr create_projection(const Transform &render_from_light, const ParameterDictionary &params) {
    float scale = photometric_scale(read_scale(params), RGBColorSpace::srgb().illuminant());
    const float fov = params.get_one_float_checked("fov", 90, 0, 180);
    if (!(fov > 0 && fov < 180))
        throw InputError(params.location("fov"), "\"fov\" must lie strictly between 0 and 180 degrees");
    const std::string filename = params.get_one_string("filename", "");
    if (filename.empty())
        throw InputError(params.location("filename"), "projection: no \"filename\" (the projected image) given");
    RGBImage image = read_light_image(params, filename);
    auto light = std::make_shared<ProjectionLight>(render_from_light, image, scale, fov);
    const float power = params.get_one_float("power", -1);
    if (power > 0 && light->unit_luminous_power() > 0)
        light = std::make_shared<ProjectionLight>(render_from_light, std::move(image),
                                                  scale * power / light->unit_luminous_power(), fov);
    return light;
}

LightPtr create_distant(const Transform &render_from_light, const ParameterDictionary &params) {
    SpectrumPtr L = light_spectrum(params, "L");
    float scale = photometric_scale(read_scale(params), *L);
    Vec3f from = params.get_one_point3("from", {0, 0, 0});
    Vec3f to = params.get_one_point3("to", {0, 0, 1});
    // Light-space +z points back towards the light, from "to" to "from".
    Transform frame = transform_from_z(direction_between(params, to, from));
    // Illuminance on a surface perpendicular to the light: 1 per unit of normalised L.
    float illuminance = params.get_one_float("illuminance", -1);
    if (illuminance > 0) scale *= illuminance;
    return std::make_shared<DistantLight>(render_from_light * frame, tabulated(L), scale);
}

EnvironmentMapping environment_mapping(const RGBImage &image, const ParameterDictionary &params,
                                       const std::string &filename) {
    if (image.width == image.height) return EnvironmentMapping::EqualArea;
    if (image.width == 2 * image.height) return EnvironmentMapping::Equirectangular;
    throw InputError(params.location("filename"),
                     "\"" + filename + "\": resolution " + std::to_string(image.width) + "x" +
                         std::to_string(image.height) +
                         " is neither square (pbrt-v4's equal-area octahedral environment map) "
                         "nor 2:1 (an equirectangular map)");
}

LightPtr create_infinite(const Transform &render_from_light, const ParameterDictionary &params) {
    SpectrumPtr L = checked_emission(params, "L",
                                     params.get_one_spectrum("L", nullptr, SpectrumType::Illuminant));
    float scale = read_scale(params);
    std::string filename = params.get_one_string("filename", "");
    float illuminance = params.get_one_float("illuminance", -1);
    const std::vector<Vec3f> portal = params.get_point3_array("portal");
    if (!portal.empty() && portal.size() != 4)
        throw InputError(params.location("portal"), "\"portal\" needs the 4 corners of a rectangle, got " +
                                                        std::to_string(portal.size()) + " points");
    const RGBColorSpace &cs = params.color_space();

    if (filename.empty() && portal.empty()) {
        if (!L) L = std::make_shared<DenselySampledSpectrum>(cs.illuminant());
        scale = photometric_scale(scale, *L);
        // A uniform sky of luminance 1 sheds illuminance pi on a surface.
        if (illuminance > 0) scale *= illuminance / Pi;
        return std::make_shared<UniformInfiniteLight>(tabulated(L), scale);
    }
    if (L && !filename.empty())
        throw InputError(params.location("L"),
                         "an infinite light takes either \"L\" or \"filename\", not both");

    RGBImage image;
    if (!filename.empty()) {
        image = read_light_image(params, filename);
    } else {
        // A portal with a uniform sky: pbrt-v4 turns "L" (or the colour space's illuminant)
        // into a one-texel sRGB image.
        const RGB rgb = L ? RGBColorSpace::srgb().rgb_from_xyz(spectrum_to_xyz(*L)) : RGB{1, 1, 1};
        image.width = image.height = 1;
        image.pixels = {rgb.r, rgb.g, rgb.b};
    }
    EnvironmentMapping mapping = environment_mapping(image, params, filename);
    // Image values are RGB in sRGB (pbrt-v4 reads the file's colour space; files without one,
    // nearly all, are sRGB).
    const RGBColorSpace &image_cs = RGBColorSpace::srgb();
    scale = photometric_scale(scale, image_cs.illuminant());
    if (illuminance > 0) {
        float k_e = ImageInfiniteLight::pbrt_illuminance_normalization(image, mapping,
                                                                       luminance_weights(image_cs));
        if (k_e > 0) scale *= illuminance / k_e;
    }
    if (!portal.empty()) {
        if (mapping != EnvironmentMapping::EqualArea)
            throw InputError(params.location("filename"), "\"" + filename +
                                                              "\": a portal needs a square (equal-area) environment map");
        // The corners are world-space points, not transformed by the light's own transform.
        try {
            return std::make_shared<PortalInfiniteLight>(render_from_light, image, image_cs, scale,
                                                         std::array<Vec3f, 4>{portal[0], portal[1], portal[2], portal[3]});
        } catch (const std::invalid_argument &e) {
            throw InputError(params.location("portal"), e.what());
        }
    }
    return std::make_shared<ImageInfiniteLight>(render_from_light, std::move(image), mapping,
                                                image_cs, scale);
}

}  // namespace

LightPtr create_light(const std::string &type, const Transform &render_from_light,
                      const ParameterDictionary &params, const SourceLocation &loc) {
    LightPtr light;
    if (type == "point")
        light = create_point(render_from_light, params);
    else if (type == "spot")
        light = create_spot(render_from_light, params);
    else if (type == "distant")
        light = create_distant(render_from_light, params);
    else if (type == "infinite")
        light = create_infinite(render_from_light, params);
    else if (type == "goniometric")
        light = create_goniometric(render_from_light, params);
    else if (type == "projection")
        light = create_projection(render_from_light, params);
    else
        throw InputError(loc, "unknown light type \"" + type + "\"");
    params.report_unused();
    return light;
}

std::vector<LightPtr> create_area_lights(const std::string &type, const ParameterDictionary &params,
                                         const std::vector<std::shared_ptr<Shape>> &shapes,
                                         const SourceLocation &loc,
                                         std::shared_ptr<const AlphaMask> alpha) {
    if (type != "diffuse") throw InputError(loc, "unknown area light type \"" + type + "\"");
    const std::string filename = params.get_one_string("filename", "");
    if (!filename.empty() && params.has("L"))
        throw InputError(params.location("filename"), "both \"L\" and \"filename\" given for a diffuse area light");
    // An emission image (sRGB values) or a spectrum; either way "scale" 1 means the colour
    // space's white at 1 nit.
    std::shared_ptr<const EmissionImage> image;
    if (!filename.empty()) image = std::make_shared<EmissionImage>(read_light_image(params, filename));
    SpectrumPtr L = light_spectrum(params, "L");
    float scale = photometric_scale(read_scale(params), *L);
    bool two_sided = params.get_one_bool("twosided", false);
    float power = params.get_one_float("power", -1);
    const float image_luminance = image ? image->mean_luminance() : 1;
    SpectrumPtr radiance = tabulated(L);  // shared by all the shapes' lights
    std::vector<LightPtr> lights;
    lights.reserve(shapes.size());
    for (const std::shared_ptr<Shape> &shape : shapes) {
        float shape_scale = scale;
        // Radiance 1 over the hemisphere and the area gives power pi A per side.
        float k_e = (two_sided ? 2 : 1) * shape->area() * Pi * image_luminance;
        if (power > 0 && k_e > 0) shape_scale *= power / k_e;
        lights.push_back(
            std::make_shared<DiffuseAreaLight>(shape, radiance, shape_scale, two_sided, alpha, image));
    }
    params.report_unused();
    return lights;
}

}  // namespace caustica
