// A scene ready to render: camera, film, sampler, geometry, lights and materials, built once from
// a parsed scene description and then shared read-only by all render threads.
#pragma once

#include "camera/camera.h"
#include "camera/camera_footprint.h"
#include "film/film.h"
#include "film/filter.h"
#include "geometry/embree_scene.h"
#include "geometry/shape_factory.h"
#include "lights/light.h"
#include "lights/light_sampler.h"
#include "scene/scene_probe.h"
#include "materials/material.h"
#include "media/medium_interface.h"
#include "params/parameters.h"
#include "sampler/sampler.h"
#include "spectral/wavelength_density.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace caustica {

struct SceneDescription;

// What the scene contains, derived once so integrators can skip what it does not need.
struct SceneFeatures {
    bool dispersive_materials = false;   // some dielectric's IOR varies with wavelength
    bool specular_surfaces = false;      // delta lobes
    // Surfaces that focus light (specular or near-specular: Material::forms_caustics) and
    // non-specular ones that can receive what they focus: caustic (light - specular - diffuse)
    // paths, which camera paths find only by chance.
    bool caustic_paths = false;
    bool media = false;
    bool emissive_media = false;         // a medium emits (Le or temperature)
    bool medium_boundaries = false;      // shapes without a material, which rays pass through
    bool subsurface = false;
    bool fluorescence = false;           // a material re-radiates at other wavelengths
    // Curves are pbrt-v4's ray-facing ribbons: each ray sees one turned towards it, so light
    // paths meet other surfaces than camera paths do, and only pt renders them as pbrt-v4's
    // path tracer does (geometry/curves.h).
    bool curves = false;
    SceneProbe probe;                    // what camera and lights see (scene_probe.h)
    bool absorbing_interiors = false;
    // Every material and medium scatters all wavelengths alike, and every light emits the same
    // colour (multiples of one spectrum). A path's radiance is then that colour times a factor
    // that does not depend on wavelength, so the scene is rendered at one wavelength, and the
    // film gives each sample the colour's exact sensor value: faster, and without the colour
    // noise of sampling wavelengths (Scene::achromatic_wavelength, Film::set_achromatic).
    bool achromatic = false;
};

// Command-line choices that override the scene file.
struct RenderOverrides {
    std::string integrator;     // empty: the scene's
    int spp = 0;                // 0: the scene's
    int width = 0, height = 0;  // 0: the scene's
    uint64_t seed = 0;
    float wavelength = 0;       // > 0: monochromatic rendering at this wavelength (nm)
    bool single_wavelength = false; // one wavelength per path instead of hero sampling
    bool spectral = false;      // sample wavelengths even for an achromatic scene
    std::vector<float> crop_window; // x0 x1 y0 y1 in [0, 1]; empty: the Film's
    std::vector<int> pixel_bounds;  // x0 x1 y0 y1 in pixels; empty: the Film's
};

class Scene {
  public:
    CameraPtr camera;
    std::unique_ptr<Film> film;
    std::unique_ptr<Sampler> sampler;
    GeometryScene geometry;
    std::vector<LightPtr> lights;
    std::vector<const Light *> infinite_lights;
    std::unique_ptr<LightSampler> light_sampler;
    // Emissive media as the starts of light paths (lights/medium_emitter.h), and the choice by
    // power among them and the lights, for the integrators that start paths there (lt, sppm);
    // null without emissive media.
    std::vector<LightPtr> medium_emitters;
    std::unique_ptr<LightSampler> light_and_medium_sampler;
    // The Camera directive's placement (identity for pbrt-v4's default camera).
    Transform camera_from_world;
    // The camera's approximate texture footprint at any point (camera_footprint.h); none in
    // scenes without textures (nothing reads it) or assembled without a film, whose texture
    // lookups then use their finest level.
    std::optional<CameraFootprint> camera_footprint;
    // The medium around the camera (the outside medium in effect at the Camera directive).
    const Medium *camera_medium = nullptr;
    Shutter shutter;
    // The shutter when the camera or some geometry moves during it (motion blur), else null:
    // paths then draw a time, and without motion they draw none, so that still scenes keep
    // their samples.
    const Shutter *motion_shutter() const { return geometry.moves() || camera->moves() ? &shutter : nullptr; }

    std::string integrator_name;         // Caustica's name: "pt", "lt", ...
    std::string integrator_reason;       // why `auto` chose it (empty when it was named)
    ParameterDictionary integrator_params;
    SourceLocation integrator_location;
    SourceLocation camera_location; // of the Camera directive (empty for pbrt-v4's default camera)
    std::string output_filename;         // Film "filename"
    SceneFeatures features;
    RenderOverrides overrides;
    // > 0: every path is traced at this wavelength (nm), the achromatic scene's (see
    // SceneFeatures::achromatic) where its lights' colour is largest; 0: wavelengths are sampled.
    float achromatic_wavelength = 0;
    // The density sampled wavelengths are drawn from: fitted to the lights' and emissive media's
    // spectral power and to what fluorescent dyes would re-emit of it (spectral/
    // wavelength_density.h); a spectral film samples its own range.
    std::optional<WavelengthDensity> wavelength_density;
    // lt's light paths, which splat at their own wavelengths, carry only what the lights emit:
    // when dyes add to the density above, the density fitted to the lights alone.
    std::optional<WavelengthDensity> light_path_wavelength_density;

    // Scene statistics for `caustica info`.
    size_t shape_count = 0, triangle_count = 0, material_count = 0, medium_count = 0,
           instance_count = 0, texture_count = 0;

    bool intersect(const Ray &ray, SurfaceInteraction *si) const { return geometry.intersect(ray, si); }
    bool occluded(const Ray &ray) const { return geometry.occluded(ray); }
    // The camera ray for a sample, with its differentials when textures read the footprint; spp
    // is the sampler's samples per pixel, which sets their step (differential_scale).
    std::optional<CameraRay> generate_camera_ray(const CameraSample &cs, const SampledWavelengths &lambda,
                                                 int spp) const {
        if (!camera_footprint) return camera->generate_ray(cs, lambda);
        return generate_ray_differential(*camera, cs, lambda, differential_scale(spp));
    }

    // Keeps what the lights and primitives point to alive for the scene's lifetime.
    std::vector<MaterialPtr> materials;
    std::vector<std::shared_ptr<const ShapeGroup>> shape_groups;
    std::vector<MediumPtr> media;
    std::vector<std::unique_ptr<MediumInterface>> medium_interfaces;
};

// The integrator `--integrator auto` picks for a scene with these features, and why.
struct IntegratorChoice {
    std::string name, reason;
};
IntegratorChoice choose_auto_integrator(const SceneFeatures &features, bool camera_models_importance);

// Maps the pbrt-v4 integrator names onto Caustica's; empty when unknown.
std::string caustica_integrator_name(const std::string &pbrt_name);

// Builds the scene; throws InputError for anything the description gets wrong.
std::unique_ptr<Scene> build_scene(const SceneDescription &description, const RenderOverrides &overrides);

} // namespace caustica
