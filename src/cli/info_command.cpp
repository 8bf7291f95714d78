#include "cli/commands.h"
#include "parser/scene_description.h"
#include "scene/scene.h"

#include <cstdio>

namespace caustica {

int run_info(const std::string &scene_path) {
    SceneDescription description;
    std::unique_ptr<Scene> scene;
    {
        SceneWarningOrder in_file_order;
        description = parse_scene_file(scene_path);
        scene = build_scene(description, RenderOverrides{});
    }
    const SceneFeatures &f = scene->features;
    Vec2i res = scene->film->resolution();
    auto yes_no = [](bool b) { return b ? "yes" : "no"; };
    std::printf("scene:            %s\n", scene_path.c_str());
    std::printf("resolution:       %d x %d\n", res.x, res.y);
    std::printf("integrator:       %s\n", scene->integrator_name.c_str());
    IntegratorChoice automatic = choose_auto_integrator(f, scene->camera->models_importance());
    std::printf("auto would use:   %s (%s)\n", automatic.name.c_str(), automatic.reason.c_str());
    std::printf("samples/pixel:    %d\n", scene->sampler->samples_per_pixel());
    std::printf("shapes:           %zu\n", scene->shape_count);
    std::printf("triangles:        %zu\n", scene->triangle_count);
    std::printf("instances:        %zu\n", scene->instance_count);
    std::printf("lights:           %zu (%zu infinite)\n", scene->lights.size(), scene->infinite_lights.size());
    std::printf("materials:        %zu\n", scene->material_count);
    std::printf("textures:         %zu\n", scene->texture_count);
    std::printf("media:            %zu\n", scene->medium_count);
    std::printf("features:\n");
    std::printf("  dispersive materials:      %s\n", yes_no(f.dispersive_materials));
    std::printf("  delta-specular surfaces:   %s\n", yes_no(f.specular_surfaces));
    std::printf("  caustic paths:             %s\n", yes_no(f.caustic_paths));
    std::printf("  absorbing interiors:       %s\n", yes_no(f.absorbing_interiors));
    std::printf("  participating media:       %s\n", yes_no(f.media));
    std::printf("  emissive media:            %s\n", yes_no(f.emissive_media));
    std::printf("  subsurface scattering:     %s\n", yes_no(f.subsurface));
    if (f.achromatic)
        std::printf("  achromatic:                yes (rendered at %.0f nm, no colour noise)\n",
                    scene->achromatic_wavelength);
    else
        std::printf("  achromatic:                no\n");
    std::printf("  image showing emitters:    %.0f%%\n", 100 * f.probe.view_emitters);
    std::printf("  image showing specular:    %.0f%%\n", 100 * f.probe.view_specular);
    std::printf("  light meeting specular:    %.0f%%\n", 100 * f.probe.lights_behind_specular);
    return 0;
}

} // namespace caustica
