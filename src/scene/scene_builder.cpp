// Turns a parsed scene description into renderable objects, resolving names (textures,
// materials, instances) in declaration order and reporting errors at their source locations.
#include "camera/camera_factory.h"
#include "core/error.h"
#include "film/film.h"
#include "film/filter.h"
#include "lights/bvh_light_sampler.h"
#include "lights/light.h"
#include "lights/light_factory.h"
#include "lights/medium_emitter.h"
#include "lights/spectral_power.h"
#include "materials/fluorophore.h"
#include "materials/material_factory.h"
#include "media/medium.h"
#include "media/medium_factory.h"
#include "parser/scene_description.h"
#include "sampler/sampler_factory.h"
#include "geometry/shape_factory.h"
#include "scene/scene.h"
#include "spectral/spectrum.h"
#include "textures/texture_factory.h"

#include <map>
#include <set>

namespace caustica {

std::string caustica_integrator_name(const std::string &name) {
    static const std::map<std::string, std::string> names = {
        {"pt", "pt"},     {"path", "pt"},   {"volpath", "pt"}, {"lt", "lt"},
        {"lightpath", "lt"}, {"bdpt", "bdpt"}, {"sppm", "sppm"}, {"bpm", "bpm"}, {"vcm", "vcm"},
    };
    auto it = names.find(name);
    return it == names.end() ? std::string() : it->second;
}

namespace {

// Sizes that decide allocations are checked before anything is allocated, so that an absurd
// value is an error at its parameter instead of an out-of-memory failure or an integer
// overflow. The limits lie far beyond what a render on one machine can use.
constexpr int MaxFilmSide = 1 << 16;
// The film keeps about 60 bytes per pixel (sums, weights and splats in double precision):
// 2^27 pixels (e.g. 16384 x 8192) already take 8 GB.
constexpr int64_t MaxFilmPixels = int64_t(1) << 27;
constexpr int64_t MaxSamplesPerPixel = int64_t(1) << 24;
// Bidirectional integrators allocate maxdepth + 2 path vertices per sample.
constexpr int MaxPathDepth = 1 << 16;

void check_film_size(const SceneEntity &film, const RenderOverrides &ov) {
    const ParameterDictionary &params = film.params;
    int64_t side[2];
    const char *names[2] = {"xresolution", "yresolution"};
    const int overrides[2] = {ov.width, ov.height};
    for (int i = 0; i < 2; ++i) {
        side[i] = overrides[i] > 0 ? overrides[i] : params.get_one_int(names[i], i == 0 ? 1280 : 720);
        if (side[i] <= MaxFilmSide) continue;
        std::string message = std::to_string(side[i]) + " pixels exceed the largest film side (" +
                              std::to_string(MaxFilmSide) + ")";
        if (overrides[i] > 0) throw InputError("--resolution: " + message);
        throw InputError(params.location(names[i]), "\"" + std::string(names[i]) + "\": " + message);
    }
    if (side[0] * side[1] > MaxFilmPixels) {
        std::string message = std::to_string(side[0]) + " x " + std::to_string(side[1]) +
                              " pixels exceed the largest film (" + std::to_string(MaxFilmPixels) +
                              " pixels)";
        if (ov.width > 0 || ov.height > 0) throw InputError("--resolution: " + message);
        throw InputError(params.location("xresolution"), message);
    }
}

void check_sample_count(const SceneEntity &sampler, const RenderOverrides &ov) {
    auto too_many = [](int64_t n) {
        return std::to_string(n) + " samples per pixel exceed the limit (" +
               std::to_string(MaxSamplesPerPixel) + ")";
    };
    if (ov.spp > 0) {
        if (ov.spp > MaxSamplesPerPixel) throw InputError("--spp: " + too_many(ov.spp));
        return;
    }
    const ParameterDictionary &params = sampler.params;
    if (sampler.type == "stratified") {
        // Each count alone fits an int; their product need not.
        int64_t n = int64_t(params.get_one_int("xsamples", 4)) * params.get_one_int("ysamples", 4);
        if (n > MaxSamplesPerPixel)
            throw InputError(params.location("xsamples"), "\"xsamples\" x \"ysamples\": " + too_many(n));
    } else if (params.has("pixelsamples")) {
        int n = params.get_one_int("pixelsamples", 1);
        if (n > MaxSamplesPerPixel)
            throw InputError(params.location("pixelsamples"), "\"pixelsamples\": " + too_many(n));
    }
}

// Integrators this build can run; the others arrive with the bidirectional work.
const std::set<std::string> available_integrators = {"bdpt", "bpm", "lt", "pt", "sppm", "vcm"};

std::string available_integrator_list() {
    std::string list;
    for (const std::string &name : available_integrators) list += (list.empty() ? "" : ", ") + name;
    return list;
}

// The Integrator's "lightsampler", with pbrt-v4's names, for next-event estimation: "bvh" (the
// default, BVHLightSampler) and "exhaustive" (ExhaustiveLightSampler) choose by each light's
// importance at the receiving point, "power" and "uniform" without regard to it. Light subpaths
// take the same sampler's choice without a position (by power for all but "uniform"), or by
// power when emissive media start them too.
std::unique_ptr<LightSampler> create_light_sampler(const ParameterDictionary &params, const std::vector<LightPtr> &lights) {
    const std::string name = params.get_one_string("lightsampler", "bvh");
    if (name == "bvh") return std::make_unique<BVHLightSampler>(lights);
    if (name == "exhaustive") return std::make_unique<ExhaustiveLightSampler>(lights);
    if (name == "power") return std::make_unique<PowerLightSampler>(lights);
    if (name == "uniform") return std::make_unique<UniformLightSampler>(lights);
    throw InputError(params.location("lightsampler"),
                     "\"lightsampler\": unknown light sampler \"" + name + "\" (bvh, exhaustive, power or uniform)");
}

void choose_integrator(const SceneDescription &d, const RenderOverrides &ov, Scene &scene) {
    if (d.integrator.params.has("maxdepth")) {
        int depth = d.integrator.params.get_one_int("maxdepth", 5);
        if (depth > MaxPathDepth)
            throw InputError(d.integrator.params.location("maxdepth"),
                             "\"maxdepth\" " + std::to_string(depth) + " exceeds the limit (" +
                                 std::to_string(MaxPathDepth) + ")");
    }
    scene.integrator_params = d.integrator.params;
    scene.integrator_location = d.integrator.loc;
    if (!ov.integrator.empty()) {
        if (ov.integrator == "auto") {
            scene.integrator_name = "auto";
            return;
        }
        std::string name = caustica_integrator_name(ov.integrator);
        if (name.empty() || !available_integrators.count(name))
            throw InputError("--integrator: \"" + ov.integrator + "\" is not an available integrator (available: " +
                             available_integrator_list() + ", auto)");
        scene.integrator_name = name;
        return;
    }
    // A scene without an Integrator directive gets the automatic choice (pbrt-v4 would use
    // volpath); one that names an integrator gets it.
    if (d.integrator.type.empty()) {
        scene.integrator_name = "auto";
        return;
    }
    std::string name = caustica_integrator_name(d.integrator.type);
    if (name.empty() || !available_integrators.count(name)) {
        warning(d.integrator.loc, "integrator \"" + d.integrator.type +
                                      "\" is not supported yet; rendering with the path tracer (pt)");
        name = "pt";
    }
    scene.integrator_name = name;
}

void create_textures(const SceneDescription &d, NamedTextures &textures) {
    for (const TextureEntity &t : d.textures) {
        if (t.type == "ptex")
            throw InputError(t.loc, "texture \"" + t.name + "\": \"ptex\" textures are not supported "
                                    "(Debian 12 packages no Ptex library); convert the Ptex file to an "
                                    "image and use \"imagemap\"");
        if (t.texture_class == "float") {
            textures.float_textures[t.name] =
                create_float_texture(t.type, t.render_from_object, t.params, textures, t.loc);
            continue;
        }
        // An RGB texel means a different spectrum as a reflectance, an unbounded quantity or an
        // emission; like pbrt-v4, keep one texture per use. Reflectance is only defined for
        // values in [0, 1]: a texture outside that range is simply not usable as one.
        try {
            textures.albedo[t.name] = create_spectrum_texture(t.type, t.render_from_object, t.params,
                                                              SpectrumType::Albedo, textures, t.loc);
        } catch (const InputError &) {
        }
        textures.unbounded[t.name] = create_spectrum_texture(t.type, t.render_from_object, t.params,
                                                             SpectrumType::Unbounded, textures, t.loc);
        textures.illuminant[t.name] = create_spectrum_texture(t.type, t.render_from_object, t.params,
                                                              SpectrumType::Illuminant, textures, t.loc);
    }
}

using MediumTable = std::map<std::string, const Medium *>;

MediumTable create_media(const SceneDescription &d, Scene &scene) {
    MediumTable table;
    for (const MediumEntity &m : d.media) {
        scene.media.push_back(create_medium(m.type, m.params, m.loc, m.render_from_object));
        table[m.name] = scene.media.back().get();
        scene.features.emissive_media |= scene.media.back()->is_emissive();
    }
    scene.medium_count = d.media.size();
    return table;
}

// An empty name is vacuum; the parser has checked that every other name is defined.
const Medium *find_medium(const MediumTable &media, const std::string &name) {
    return name.empty() ? nullptr : media.at(name);
}

// The interface of a shape, or null when both sides are the same medium (see medium_interface.h).
const MediumInterface *interface_for(const ShapeEntity &s, const MediumTable &media, Scene &scene) {
    MediumInterface mi{find_medium(media, s.inside_medium), find_medium(media, s.outside_medium)};
    if (!mi.is_transition()) return nullptr;
    scene.medium_interfaces.push_back(std::make_unique<MediumInterface>(mi));
    return scene.medium_interfaces.back().get();
}

struct MaterialTable {
    std::vector<MaterialPtr> anonymous;
    std::map<std::string, MaterialPtr> named;
};

MaterialTable create_materials(const SceneDescription &d, const NamedTextures &textures, Scene &scene) {
    MaterialTable table;
    for (const auto &[name, entity] : d.named_materials) {
        table.named[name] = create_material(entity.type, entity.params, textures, entity.loc, &table.named);
        if (table.named[name]) scene.materials.push_back(table.named[name]);
    }
    for (const SceneEntity &m : d.materials) {
        table.anonymous.push_back(create_material(m.type, m.params, textures, m.loc, &table.named));
        if (table.anonymous.back()) scene.materials.push_back(table.anonymous.back());
    }
    scene.material_count = d.named_materials.size() + d.materials.size();
    return table;
}

const Material *material_for(const ShapeEntity &s, const MaterialTable &table) {
    if (!s.material_name.empty()) {
        auto it = table.named.find(s.material_name);
        if (it == table.named.end())
            throw InputError(s.loc, "named material \"" + s.material_name + "\" is not defined");
        return it->second.get();
    }
    if (s.material_index >= 0) return table.anonymous.at(s.material_index).get();
    // pbrt-v4's default material: diffuse with reflectance 0.5.
    static const MaterialPtr default_material = [] {
        ParameterDictionary none;
        return create_material("diffuse", none, NamedTextures{}, SourceLocation{});
    }();
    return default_material.get();
}

// The shape's "alpha" (a float or a float texture), or null when it is opaque. Parameters that
// no part of the renderer read are then reported, as for the other directives.
// A plymesh's "displacement" texture (mesh_displacement.h), or null.
FloatTexturePtr displacement_for(const ShapeEntity &s, const NamedTextures &textures) {
    return s.type == "plymesh" ? s.params.get_float_texture_or_null("displacement", textures) : nullptr;
}

std::shared_ptr<const AlphaMask> alpha_for(const ShapeEntity &s, const NamedTextures &textures) {
    auto alpha = make_alpha_mask(s.params.get_float_texture_or_null("alpha", textures));
    s.params.report_unused();
    return alpha;
}

void add_shapes(const SceneDescription &d, const NamedTextures &textures, const MaterialTable &materials,
                const MediumTable &media, Scene &scene) {
    for (const ShapeEntity &s : d.shapes) {
        // A moving shape is built in its own space and placed by Embree at each ray's time.
        auto groups = create_shapes(s.type, s.render_from_object_end ? Transform() : s.render_from_object,
                                    s.reverse_orientation, s.params, s.loc, displacement_for(s, textures).get());
        if (groups.empty()) continue;
        PrimitiveAttributes shared;
        shared.alpha = alpha_for(s, textures);
        shared.material = material_for(s, materials);
        shared.medium_interface = interface_for(s, media, scene);
        scene.features.medium_boundaries |= shared.material == nullptr;
        scene.shape_count += 1;
        for (std::shared_ptr<ShapeGroup> &group : groups) {
            PrimitiveAttributes attrs = shared;
            scene.features.curves |= group->curves != nullptr;
            if (s.area_light_index >= 0) {
                // pbrt-v4 cannot sample points on curves either (Curve::Sample aborts).
                if (group->curves) throw InputError(s.loc, "curves cannot be area lights");
                const SceneEntity &area = d.area_lights.at(s.area_light_index);
                for (LightPtr &light :
                     create_area_lights(area.type, area.params, group->shapes(), area.loc, attrs.alpha)) {
                    light->set_medium(find_medium(media, s.outside_medium));
                    attrs.area_lights.push_back(light.get());
                    scene.lights.push_back(std::move(light));
                }
            }
            scene.triangle_count += group->triangle_count();
            if (s.render_from_object_end)
                scene.geometry.add_moving(group, std::move(attrs), {s.render_from_object, *s.render_from_object_end});
            else
                scene.geometry.add(group, std::move(attrs));
            scene.shape_groups.push_back(std::move(group));
        }
    }
}

void add_instances(const SceneDescription &d, const NamedTextures &textures,
                   const MaterialTable &materials, const MediumTable &media, Scene &scene) {
    std::map<std::string, int> prototypes;
    for (const InstanceDefinition &def : d.instances) {
        std::vector<std::pair<std::shared_ptr<const ShapeGroup>, PrimitiveAttributes>> members;
        for (const ShapeEntity &s : def.shapes) {
            auto groups = create_shapes(s.type, s.render_from_object, s.reverse_orientation, s.params, s.loc,
                                        displacement_for(s, textures).get());
            if (groups.empty()) continue;
            if (s.area_light_index >= 0)
                warning(s.loc, "area lights inside object instances are not supported; the shape "
                               "is instanced without emission");
            PrimitiveAttributes attrs;
            attrs.alpha = alpha_for(s, textures);
            attrs.material = material_for(s, materials);
            attrs.medium_interface = interface_for(s, media, scene);
            scene.features.medium_boundaries |= attrs.material == nullptr;
            for (std::shared_ptr<ShapeGroup> &group : groups) {
                scene.features.curves |= group->curves != nullptr;
                scene.triangle_count += group->triangle_count();
                scene.shape_groups.push_back(group);
                members.emplace_back(std::move(group), attrs);
            }
        }
        prototypes[def.name] = scene.geometry.add_prototype(std::move(members));
    }
    for (const InstanceUse &use : d.instance_uses) {
        auto it = prototypes.find(use.name);
        if (it == prototypes.end())
            throw InputError(use.loc, "object instance \"" + use.name + "\" is not defined");
        scene.geometry.add_instance(it->second, use.render_from_instance);
        ++scene.instance_count;
    }
}

void add_lights(const SceneDescription &d, const MediumTable &media, Scene &scene) {
    for (const LightEntity &l : d.lights) {
        LightPtr light = create_light(l.type, l.render_from_object, l.params, l.loc);
        if (!light) continue;
        light->set_medium(find_medium(media, l.medium));
        scene.lights.push_back(std::move(light));
    }
    for (const LightPtr &light : scene.lights)
        if (light->type() == LightType::Infinite) scene.infinite_lights.push_back(light.get());
}

// Every emissive medium becomes a start of light paths, chosen with the lights by power.
void add_medium_emitters(const Bounds3f &bounds, Scene &scene) {
    for (const MediumPtr &m : scene.media)
        if (m->is_emissive()) {
            scene.medium_emitters.push_back(std::make_shared<MediumEmitter>(*m));
            scene.medium_emitters.back()->preprocess(bounds);
        }
    if (scene.medium_emitters.empty()) return;
    std::vector<LightPtr> all = scene.lights;
    all.insert(all.end(), scene.medium_emitters.begin(), scene.medium_emitters.end());
    scene.light_and_medium_sampler = std::make_unique<PowerLightSampler>(all);
}

// The colour all the scene's light is emitted in when the scene is achromatic (see
// SceneFeatures::achromatic), else null. Lights that emit nothing have no colour to agree on,
// and with no light at all there is no colour either (the film could not be given one).
const Spectrum *achromatic_colour(const Scene &scene) {
    for (const MaterialPtr &m : scene.materials)
        if (!m->is_wavelength_independent()) return nullptr;
    // Emissive media are light sources with colours of their own (a blackbody's varies).
    for (const MediumPtr &m : scene.media)
        if (!m->is_wavelength_independent() || m->is_emissive()) return nullptr;
    const Spectrum *colour = nullptr, *dark = nullptr;
    for (const LightPtr &light : scene.lights) {
        const Spectrum *emitted = light->emission_spectrum();
        if (!emitted) return nullptr;
        // The lights of one emissive shape share its spectrum: one test each.
        if (emitted == colour || emitted == dark) continue;
        if (!((*emitted)(peak_wavelength(*emitted)) > 0)) {
            dark = emitted;
            continue;
        }
        if (!colour) colour = emitted;
        else if (!is_multiple_of(*emitted, *colour)) return nullptr;
    }
    return colour;
}

void analyse_features(const SceneDescription &d, Scene &scene) {
    SceneFeatures &f = scene.features;
    bool caustic_forming = false;
    for (const MaterialPtr &m : scene.materials) {
        f.dispersive_materials |= m->is_dispersive();
        f.specular_surfaces |= m->has_specular_lobe();
        caustic_forming |= m->forms_caustics();
        f.subsurface |= m->has_subsurface();
        f.fluorescence |= m->is_fluorescent();
        f.absorbing_interiors |= m->has_interior_absorption();
    }
    f.media = !scene.media.empty();
    for (const MaterialPtr &m : scene.materials) f.media |= m->has_interior_medium();
    bool non_specular_surfaces = false;
    for (const MaterialPtr &m : scene.materials) non_specular_surfaces |= m->has_non_specular_lobe();
    f.caustic_paths = caustic_forming && non_specular_surfaces && !scene.lights.empty();
    f.probe = probe_scene(scene);
}

} // namespace

namespace {

// A light path that re-radiates lands at a wavelength of its own, which a monochromatic film
// (one fixed wavelength) does not record: lt cannot render a fluorescent scene at one wavelength.
// The other integrators gather re-radiated light from the camera's end (path_tracing.h).
void refuse_unrendered_fluorescence(const Scene &scene, const RenderOverrides &ov) {
    if (scene.features.fluorescence && scene.integrator_name == "lt" && ov.wavelength > 0)
        throw InputError("--wavelength: lt renders a fluorescent scene's light at the wavelengths it is re-radiated "
                         "at, not at one; use another integrator");
}

std::string percent(float fraction) { return std::to_string(int(std::lround(100 * fraction))) + "%"; }
} // namespace

IntegratorChoice choose_auto_integrator(const SceneFeatures &features, bool camera_models_importance) {
    if (features.curves)
        return {"pt", "the scene has curves, which camera paths alone see as pbrt-v4 does (ray-facing "
                      "ribbons, turned towards each ray)"};
    if (!features.caustic_paths)
        return {"pt", "no specular surface can focus light onto a diffuse one, so camera paths with "
                      "light sampling find every path; path tracing is the cheapest per sample"};
    if (!camera_models_importance)
        return {"sppm", "the scene has caustic paths, and its camera (orthographic, spherical or realistic) "
                        "cannot receive light paths: sppm renders caustics from camera rays and photons"};
    // Both ends of most paths behind specular surfaces (a pool seen and lit through its water):
    // the paths that matter are specular-diffuse-specular, which connections cannot sample and
    // only merging renders, so vcm's connections would be cost without benefit.
    constexpr float SpecularDominated = 0.5f;
    if (features.probe.view_specular >= SpecularDominated &&
        features.probe.lights_behind_specular >= SpecularDominated)
        return {"sppm", "most of the image (" + percent(features.probe.view_specular) +
                            ") shows purely specular surfaces and most emitted light (" +
                            percent(features.probe.lights_behind_specular) +
                            ") first meets one, so specular-diffuse-specular paths dominate; "
                            "only photon merging renders them, and sppm spends nothing on "
                            "connections that cannot"};
    return {"vcm", std::string("specular surfaces focus light onto diffuse ones (caustics") +
                       (features.dispersive_materials ? ", with dispersion" : "") +
                       "), which camera paths find only by chance; vertex connection and merging "
                       "adds light paths and photon merging"};
}

std::unique_ptr<Scene> build_scene(const SceneDescription &d, const RenderOverrides &ov) {
    auto scene = std::make_unique<Scene>();
    scene->overrides = ov;
    choose_integrator(d, ov, *scene);

    // pbrt-v4's default camera: perspective, at the origin of world space, looking along +z.
    if (!d.has_camera)
        warning("the scene has no Camera directive; using pbrt-v4's default, a perspective camera "
                "at the origin looking along +z");
    check_film_size(d.film, ov);
    check_sample_count(d.sampler, ov);
    std::unique_ptr<Filter> filter =
        create_filter(d.filter.type.empty() ? "gaussian" : d.filter.type, d.filter.params, d.filter.loc);
    scene->shutter = camera_shutter(d.camera.params, d.camera.loc);
    scene->film = create_film(d.film.type.empty() ? "rgb" : d.film.type, d.film.params, d.color_space,
                              std::move(filter), d.film.loc,
                              FilmOverrides{Vec2i{ov.width, ov.height}, ov.crop_window, ov.pixel_bounds},
                              scene->shutter.close - scene->shutter.open);
    scene->film->set_monochromatic(ov.wavelength > 0);
    scene->output_filename = scene->film->filename();
    std::optional<CameraMotion> camera_motion;
    if (d.camera.world_from_camera_end) camera_motion = CameraMotion{*d.camera.world_from_camera_end, d.transform_times};
    scene->camera = create_camera(d.camera.type.empty() ? "perspective" : d.camera.type,
                                  d.camera.world_from_camera, scene->film->extent(), d.camera.params,
                                  d.camera.loc, camera_motion ? &*camera_motion : nullptr);
    scene->camera_location = d.camera.loc;
    scene->camera_from_world = d.camera.world_from_camera.inverse();
    if (!d.textures.empty())
        scene->camera_footprint.emplace(*scene->camera, scene->camera_from_world, scene->film->extent().full_resolution);
    scene->sampler = d.sampler.type.empty()
                         ? create_default_sampler(int(ov.seed), ov.spp)
                         : create_sampler(d.sampler.type, d.sampler.params, d.sampler.loc, int(ov.seed), ov.spp,
                                          scene->film->resolution());
    // What pbrt-v4 refuses as unused parameters, named here as for the other directives. Those
    // that the command line overrode were not left unused by mistake.
    if (ov.spp > 0) (void)d.sampler.params.get_one_int("pixelsamples", 0);
    if (!ov.crop_window.empty() || !ov.pixel_bounds.empty()) {
        (void)d.film.params.get_float_array("cropwindow");
        (void)d.film.params.get_int_array("pixelbounds");
    }
    for (const SceneEntity *e : {&d.filter, &d.film, static_cast<const SceneEntity *>(&d.camera), &d.sampler})
        e->params.report_unused();

    NamedTextures textures;
    create_textures(d, textures);
    scene->texture_count = d.textures.size();
    MaterialTable materials = create_materials(d, textures, *scene);
    MediumTable media = create_media(d, *scene);
    scene->camera_medium = find_medium(media, d.camera.medium);
    scene->geometry.set_transform_times(d.transform_times);
    add_shapes(d, textures, materials, media, *scene);
    add_instances(d, textures, materials, media, *scene);
    add_lights(d, media, *scene);

    scene->geometry.commit();
    Bounds3f bounds = scene->geometry.bounds();
    for (const LightPtr &light : scene->lights) light->preprocess(bounds);
    scene->light_sampler = create_light_sampler(scene->integrator_params, scene->lights);
    add_medium_emitters(bounds, *scene);
    analyse_features(d, *scene);
    std::vector<const Light *> emitters;
    for (const std::vector<LightPtr> *list : {&scene->lights, &scene->medium_emitters})
        for (const LightPtr &light : *list) emitters.push_back(light.get());
    // Wavelengths fitted to the light the scene emits, and to what its fluorescent dyes would
    // re-emit of it if all of it reached each of them: under a blacklight, half of the fitted
    // wavelengths then fall where the dyes glow rather than in the invisible line.
    const EmittedSpectralPower emitted(emitters);
    std::vector<std::vector<float>> reemitted;
    for (const MaterialPtr &m : scene->materials)
        if (const Fluorophore *dye = m->fluorophore()) reemitted.push_back(dye->reemitted(emitted));
    if (!reemitted.empty()) scene->light_path_wavelength_density.emplace(emitted);
    // A film that clamps samples ("maxcomponentvalue") clamps each sample's colour, so its image
    // depends on how the wavelengths were drawn: they are drawn as pbrt-v4 draws them (visible
    // wavelengths, SampledWavelengths::sample_visible), and the clamp cuts what it cuts there.
    if (!scene->film->clamps_samples())
        scene->wavelength_density.emplace([&](float lambda) {
            float power = emitted(lambda);
            const size_t nm = size_t(std::clamp(std::lround(lambda - LambdaMin), 0L, long(LambdaMax - LambdaMin)));
            for (const std::vector<float> &r : reemitted) power += r[nm];
            return power;
        });
    const Spectrum *colour = achromatic_colour(*scene);
    scene->features.achromatic = colour != nullptr;
    // Overrides that ask for wavelengths (monochromatic, single or sampled) come first. A film
    // that clamps samples keeps sampled wavelengths too, as above: one wavelength would give each
    // sample the light's exact colour, where pbrt-v4's samples carry colour noise into its clamp.
    if (colour && ov.wavelength <= 0 && !ov.single_wavelength && !ov.spectral && !scene->film->clamps_samples()) {
        scene->achromatic_wavelength = peak_wavelength(*colour);
        scene->film->set_achromatic(*colour, scene->achromatic_wavelength);
    }
    if (scene->integrator_name == "auto") {
        IntegratorChoice choice = choose_auto_integrator(scene->features, scene->camera->models_importance());
        scene->integrator_name = choice.name;
        scene->integrator_reason = choice.reason;
        note("--integrator auto chose " + choice.name + ": " + choice.reason);
    }
    refuse_unrendered_fluorescence(*scene, ov);
    if (scene->features.curves && scene->integrator_name != "pt")
        warning("curves are ray-facing ribbons (pbrt-v4's model): light paths meet them turned "
                "towards themselves, not towards the camera, so " + scene->integrator_name +
                " renders them a few percent differently from pt and pbrt-v4's path tracer "
                "(pbrt-v4's own bdpt and lightpath differ likewise); use pt for scenes with curves");
    return scene;
}

} // namespace caustica
