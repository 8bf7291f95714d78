#include "textures/texture_factory.h"

#include "params/constant_textures.h"
#include "params/parameters.h"
#include "spectral/color_space.h"
#include "textures/bilerp_texture.h"
#include "textures/checkerboard_texture.h"
#include "textures/image_texture.h"
#include "textures/mix_texture.h"
#include "textures/noise_textures.h"
#include "textures/scale_texture.h"

#include <algorithm>
#include <array>

namespace caustica {

namespace {

TextureMapping2D create_mapping_2d(const Transform &render_from_texture,
                                   const ParameterDictionary &params) {
    std::string kind = params.get_one_string("mapping", "uv");
    if (kind == "uv")
        return TextureMapping2D::uv(params.get_one_float("uscale", 1), params.get_one_float("vscale", 1),
                                    params.get_one_float("udelta", 0), params.get_one_float("vdelta", 0));
    Transform texture_from_render = render_from_texture.inverse();
    if (kind == "spherical") return TextureMapping2D::spherical(texture_from_render);
    if (kind == "cylindrical") return TextureMapping2D::cylindrical(texture_from_render);
    if (kind == "planar")
        return TextureMapping2D::planar(texture_from_render,
                                        params.get_one_vector3("v1", Vec3f(1, 0, 0)),
                                        params.get_one_vector3("v2", Vec3f(0, 1, 0)),
                                        params.get_one_float("udelta", 0),
                                        params.get_one_float("vdelta", 0));
    throw InputError(params.location("mapping"),
                     "unknown texture mapping \"" + kind + "\" (expected \"uv\", \"spherical\", "
                     "\"cylindrical\" or \"planar\")");
}

// The "octaves" of the noise textures; pbrt-v4's default is 8.
int octaves(const ParameterDictionary &params) {
    int n = params.get_one_int("octaves", 8);
    if (n < 0 || n > 64)
        throw InputError(params.location("octaves"), "\"octaves\" must lie in [0, 64], not " +
                                                         std::to_string(n));
    return n;
}

// Reads a child texture of either flavour with a constant default.
struct FloatChildren {
    const ParameterDictionary &params;
    const NamedTextures &textures;
    TexturePtr<FloatTexture> get(const std::string &name, float def) const {
        return params.get_float_texture(name, def, textures);
    }
    TexturePtr<FloatTexture> constant(float v) const { return std::make_shared<ConstantFloatTexture>(v); }
};
struct SpectrumChildren {
    const ParameterDictionary &params;
    const NamedTextures &textures;
    SpectrumType type;
    TexturePtr<SpectrumTexture> get(const std::string &name, float def) const {
        return params.get_spectrum_texture(name, std::make_shared<ConstantSpectrum>(def), type, textures);
    }
    TexturePtr<SpectrumTexture> constant(float v) const {
        return std::make_shared<ConstantSpectrumTexture>(std::make_shared<ConstantSpectrum>(v));
    }
};

// The types shared by both flavours; null for "constant", handled by the callers.
template <typename Base, typename Children>
TexturePtr<Base> create_composite(const std::string &type, const Transform &render_from_texture,
                                  const ParameterDictionary &params, const Children &children,
                                  const NamedTextures &textures, const SourceLocation &loc) {
    if (type == "scale")
        return std::make_shared<ScaleTexture<Base>>(children.get("tex", 1),
                                                    params.get_float_texture("scale", 1, textures));
    if (type == "mix")
        return std::make_shared<MixTexture<Base>>(children.get("tex1", 0), children.get("tex2", 1),
                                                  params.get_float_texture("amount", 0.5f, textures));
    if (type == "checkerboard") {
        int dimension = params.get_one_int("dimension", 2);
        auto tex1 = children.get("tex1", 1), tex2 = children.get("tex2", 0);
        if (dimension == 2)
            return std::make_shared<CheckerboardTexture<Base>>(
                create_mapping_2d(render_from_texture, params), tex1, tex2);
        if (dimension == 3)
            return std::make_shared<CheckerboardTexture<Base>>(
                TextureMapping3D(render_from_texture.inverse()), tex1, tex2);
        throw InputError(params.location("dimension"),
                         "checkerboard \"dimension\" must be 2 or 3, not " + std::to_string(dimension));
    }
    if (type == "bilerp")
        return std::make_shared<BilerpTexture<Base>>(create_mapping_2d(render_from_texture, params),
                                                     children.get("v00", 0), children.get("v10", 0),
                                                     children.get("v01", 1), children.get("v11", 1));
    if (type == "directionmix") {
        Vec3f dir = render_from_texture.apply_vector(params.get_one_vector3("dir", Vec3f(0, 1, 0)));
        if (!(length(dir) > 0))
            throw InputError(params.location("dir"), "directionmix: \"dir\" must not be zero");
        return std::make_shared<MixTexture<Base>>(children.get("tex1", 0), children.get("tex2", 1),
                                                  std::make_shared<DirectionMixAmount>(normalize(dir)));
    }
    if (type == "dots")
        return std::make_shared<DotsTexture<Base>>(create_mapping_2d(render_from_texture, params),
                                                   children.get("outside", 0), children.get("inside", 1));
    throw InputError(loc, "unknown texture type \"" + type + "\"");
}

} // namespace

FloatTexturePtr create_float_texture(const std::string &type, const Transform &render_from_texture,
                                     const ParameterDictionary &params, const NamedTextures &textures,
                                     const SourceLocation &loc) {
    FloatTexturePtr result;
    TextureMapping3D mapping_3d(render_from_texture.inverse());
    if (type == "constant")
        result = std::make_shared<ConstantFloatTexture>(params.get_one_float("value", 1));
    else if (type == "fbm" || type == "wrinkled")
        result = std::make_shared<OctaveNoiseTexture>(
            mapping_3d, type == "fbm" ? fractional_brownian_motion : turbulence,
            params.get_one_float("roughness", 0.5f), octaves(params));
    else if (type == "windy")
        result = std::make_shared<WindyTexture>(mapping_3d);
    else if (type == "imagemap")
        result = std::make_shared<FloatImageTexture>(
            read_image_lookup(create_mapping_2d(render_from_texture, params), params, 1, loc));
    else
        result = create_composite<FloatTexture>(type, render_from_texture, params,
                                                FloatChildren{params, textures}, textures, loc);
    params.report_unused();
    return result;
}

SpectrumTexturePtr create_spectrum_texture(const std::string &type,
                                           const Transform &render_from_texture,
                                           const ParameterDictionary &params,
                                           SpectrumType spectrum_type,
                                           const NamedTextures &textures, const SourceLocation &loc) {
    SpectrumTexturePtr result;
    if (type == "marble")
        result = std::make_shared<MarbleTexture>(
            TextureMapping3D(render_from_texture.inverse()), params.get_one_float("roughness", 0.5f),
            octaves(params), params.get_one_float("scale", 1), params.get_one_float("variation", 0.2f));
    else if (type == "constant")
        result = std::make_shared<ConstantSpectrumTexture>(params.get_one_spectrum(
            "value", std::make_shared<ConstantSpectrum>(1.f), spectrum_type));
    else if (type == "imagemap")
        // Image files carry no colour space Caustica reads; nearly all are sRGB (as pbrt-v4
        // assumes without metadata).
        result = std::make_shared<SpectrumImageTexture>(
            read_image_lookup(create_mapping_2d(render_from_texture, params), params, 3, loc), spectrum_type,
            RGBColorSpace::srgb());
    else
        result = create_composite<SpectrumTexture>(type, render_from_texture, params,
                                                   SpectrumChildren{params, textures, spectrum_type},
                                                   textures, loc);
    params.report_unused();
    return result;
}

} // namespace caustica
