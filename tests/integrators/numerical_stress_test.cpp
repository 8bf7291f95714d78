// The numerical stress suite: small scenes at the edges of what the models handle (grazing
// angles, total internal reflection, eta exactly 1 and 1 +/- 1e-6, roughness from 1e-4 to 1, scene
// scales from 1e-4 to 1e5, a light inside glass, long specular chains, zero and extremely bright
// emitters, the camera inside a medium, dense media and subsurface scattering), each rendered by
// every integrator. The renderer counts the samples it had to drop
// because they were not finite (--stats-json "non_finite_samples"); a non-finite sample is a bug
// to fix where it arises, so the count must be zero, and every pixel of the image finite.
#include "render_test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

using namespace caustica::testing;

namespace {

struct StressScene {
    const char *name;
    std::string text;
};

// A floor, a slab of `material` above it and a square light, at scale s (every length times s).
std::string slab_scene(const std::string &material, double s, const std::string &light = "\"blackbody L\" [ 5000 ]",
                       const std::string &integrator_params = "\"integer maxdepth\" [ 8 ]",
                       const std::string &camera = "") {
    auto n = [s](double v) { return std::to_string(v * s); };
    std::string cam = camera.empty() ? "LookAt 0 " + n(1.5) + " " + n(2.5) + "  0 " + n(0.3) + " 0  0 1 0\n" : camera;
    return cam + "Camera \"perspective\" \"float fov\" [ 45 ]\n"
                 "Film \"rgb\" \"integer xresolution\" [ 16 ] \"integer yresolution\" [ 16 ]\n"
                 "Sampler \"independent\" \"integer pixelsamples\" [ 4 ]\n"
                 "Integrator \"path\" " + integrator_params + "\n"
                 "WorldBegin\n"
                 "AttributeBegin\n Material \"diffuse\"\n"
                 " Shape \"bilinearmesh\" \"point3 P\" [ " + n(-2) + " 0 " + n(-2) + "  " + n(2) + " 0 " + n(-2) +
           "  " + n(-2) + " 0 " + n(2) + "  " + n(2) + " 0 " + n(2) + " ]\nAttributeEnd\n"
                 "AttributeBegin\n " + material + "\n"
                 " Shape \"trianglemesh\" \"integer indices\" [ 0 1 2  0 2 3  4 6 5  4 7 6  0 4 5  0 5 1  1 5 6  1 6 2"
                 "  2 6 7  2 7 3  3 7 4  3 4 0 ]\n"
                 "  \"point3 P\" [ " + n(-0.6) + " " + n(0.3) + " " + n(-0.6) + "  " + n(0.6) + " " + n(0.3) + " " +
           n(-0.6) + "  " + n(0.6) + " " + n(0.3) + " " + n(0.6) + "  " + n(-0.6) + " " + n(0.3) + " " + n(0.6) +
           "  " + n(-0.6) + " " + n(0.5) + " " + n(-0.6) + "  " + n(0.6) + " " + n(0.5) + " " + n(-0.6) + "  " +
           n(0.6) + " " + n(0.5) + " " + n(0.6) + "  " + n(-0.6) + " " + n(0.5) + " " + n(0.6) + " ]\n"
                 "AttributeEnd\n"
                 "AttributeBegin\n AreaLightSource \"diffuse\" " + light + "\n Material \"diffuse\" \"rgb reflectance\" [ 0 0 0 ]\n"
                 " Shape \"bilinearmesh\" \"point3 P\" [ " + n(-0.5) + " " + n(2) + " " + n(-0.5) + "  " + n(0.5) + " " +
           n(2) + " " + n(-0.5) + "  " + n(-0.5) + " " + n(2) + " " + n(0.5) + "  " + n(0.5) + " " + n(2) + " " + n(0.5) +
           " ]\n  \"normal N\" [ 0 -1 0  0 -1 0  0 -1 0  0 -1 0 ]\nAttributeEnd\n";
}

std::vector<StressScene> stress_scenes() {
    const std::string glass = "Material \"dielectric\" \"float eta\" [ 1.5 ]";
    const std::string fog = "MakeNamedMedium \"fog\" \"string type\" \"homogeneous\" \"rgb sigma_a\" [ 0.1 0.2 0.3 ] "
                            "\"rgb sigma_s\" [ 0.8 0.5 0.2 ] \"float g\" [ 0.7 ]\n";
    const std::string dense = "MakeNamedMedium \"dense\" \"string type\" \"homogeneous\" \"rgb sigma_a\" [ 1 10 100 ] "
                              "\"rgb sigma_s\" [ 5000 2000 1 ] \"float g\" [ -0.9 ]\n";
    return {
        {"eta_exactly_one", slab_scene("Material \"dielectric\" \"float eta\" [ 1 ]", 1)},
        {"eta_one_plus_1e-6", slab_scene("Material \"dielectric\" \"float eta\" [ 1.000001 ]", 1)},
        {"eta_one_minus_1e-6", slab_scene("Material \"dielectric\" \"float eta\" [ 0.999999 ]", 1)},
        {"rough_eta_one_plus_1e-6",
         slab_scene("Material \"dielectric\" \"float eta\" [ 1.000001 ] \"float roughness\" [ 0.2 ]", 1)},
        {"roughness_1e-4",
         slab_scene("Material \"dielectric\" \"float eta\" [ 1.5 ] \"float roughness\" [ 0.0001 ] "
                    "\"bool remaproughness\" false", 1)},
        {"roughness_1",
         slab_scene("Material \"dielectric\" \"float eta\" [ 1.5 ] \"float roughness\" [ 1 ] "
                    "\"bool remaproughness\" false", 1)},
        {"rough_conductor_1e-4", slab_scene("Material \"conductor\" \"float roughness\" [ 0.0001 ]", 1)},
        {"dispersive_dense_flint", slab_scene("Material \"dielectric\" \"spectrum eta\" \"glass-SF11\"", 1)},
        {"scale_1e-4", slab_scene(glass, 1e-4)},
        {"scale_1e5", slab_scene(glass, 1e5)},
        // The camera level with the slab's top: its faces are seen at grazing angles, and total
        // internal reflection traps light inside it.
        {"grazing_total_internal_reflection",
         slab_scene(glass, 1, "\"blackbody L\" [ 5000 ]", "\"integer maxdepth\" [ 8 ]",
                    "LookAt 0 0.5 3  0 0.5 0  0 1 0\n")},
        {"long_specular_chains_maxdepth_100", slab_scene(glass, 1, "\"blackbody L\" [ 5000 ]", "\"integer maxdepth\" [ 100 ]")},
        {"zero_radiance_emitter", slab_scene(glass, 1, "\"rgb L\" [ 0 0 0 ]")},
        {"extremely_bright_emitter", slab_scene(glass, 1, "\"blackbody L\" [ 5000 ] \"float scale\" [ 1e15 ]")},
        // The light inside the glass slab.
        {"light_inside_glass",
         slab_scene(glass, 1, "\"blackbody L\" [ 5000 ]", "\"integer maxdepth\" [ 8 ]") +
             "AttributeBegin\n AreaLightSource \"diffuse\" \"blackbody L\" [ 3000 ]\n Translate 0 0.4 0\n"
             " Shape \"sphere\" \"float radius\" [ 0.05 ]\nAttributeEnd\n"},
        // The camera, the light and the scene inside a chromatic, strongly forward-scattering fog.
        {"camera_inside_medium",
         slab_scene(glass, 1, "\"blackbody L\" [ 5000 ]", "\"integer maxdepth\" [ 8 ]",
                    fog + "MediumInterface \"\" \"fog\"\nLookAt 0 1.5 2.5  0 0.3 0  0 1 0\n")},
        // Glass filled with a medium whose coefficients span five orders of magnitude across the
        // spectrum, backscattering strongly.
        {"dense_chromatic_medium_in_glass",
         dense + slab_scene("MediumInterface \"dense\" \"\"\n " + glass, 1)},
        // Random-walk subsurface with a vanishing and with a huge scatter distance.
        {"subsurface_scatter_distance_1e-6",
         slab_scene("Material \"disney\" \"rgb scatterDistance\" [ 1e-6 1e-6 1e-6 ]", 1)},
        {"subsurface_scatter_distance_1e4",
         slab_scene("Material \"disney\" \"rgb scatterDistance\" [ 1e4 1 1e-3 ] \"float specTrans\" [ 0.3 ]", 1)},
    };
}

class NumericalStress : public ::testing::TestWithParam<std::tuple<int, const char *>> {};

TEST_P(NumericalStress, NoNonFiniteSampleAndAFiniteImage) {
    const StressScene scene = stress_scenes()[std::get<0>(GetParam())];
    const std::string integrator = std::get<1>(GetParam());
    const std::string dir = scratch_dir(std::string("stress-") + scene.name + "-" + integrator);
    const std::string path = dir + "/scene.pbrt", out = dir + "/out.exr", stats = dir + "/stats.json";
    std::FILE *f = std::fopen(path.c_str(), "wb");
    ASSERT_NE(f, nullptr);
    std::fwrite(scene.text.data(), 1, scene.text.size(), f);
    std::fclose(f);
    ASSERT_EQ(run_caustica("render " + path + " --quiet --integrator " + integrator + " --spp 4 --seed 1 -o " + out +
                           " --stats-json " + stats),
              0)
        << scene.name;
    const std::string json = read_text(stats);
    const size_t key = json.find("\"non_finite_samples\"");
    ASSERT_NE(key, std::string::npos) << json;
    const long dropped = std::stol(json.substr(json.find(':', key) + 1));
    EXPECT_EQ(dropped, 0) << scene.name << " with " << integrator;
    const RgbImage image = read_rgb(out);
    for (float v : image.rgb) ASSERT_TRUE(std::isfinite(v)) << scene.name << " with " << integrator;
}

INSTANTIATE_TEST_SUITE_P(
    EdgeCases, NumericalStress,
    ::testing::Combine(::testing::Range(0, int(stress_scenes().size())),
                       ::testing::Values("pt", "lt", "bdpt", "sppm", "bpm", "vcm")),
    [](const ::testing::TestParamInfo<std::tuple<int, const char *>> &info) {
        std::string name = std::string(stress_scenes()[std::get<0>(info.param)].name) + "_" + std::get<1>(info.param);
        for (char &c : name)
            if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
        return name;
    });

} // namespace
