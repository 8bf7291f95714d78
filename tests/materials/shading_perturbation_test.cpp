// Bump and normal mapping (src/materials/shading_perturbation.h) in closed form: on the plane
// z = 0 with u = x and v = y, a displacement a u tilts the shading normal to (-a, 0, 1) / |.|,
// and a normal map of constant texel 0.5 (n + 1) makes the shading normal n; both through the
// material factory's "displacement" and "normalmap" and shade().
#include "param_helpers.h"

#include "core/scratch_buffer.h"
#include "geometry/interaction.h"
#include "materials/material_factory.h"
#include "textures/texture_factory.h"

#include <ImfRgbaFile.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <unistd.h>

namespace caustica {
namespace {

using namespace caustica::testing;

SurfaceInteraction plane_point(const Material &material) {
    SurfaceInteraction si;
    si.p = {0.3f, 0.4f, 0};
    si.uv = {0.3f, 0.4f};
    si.n = {0, 0, 1};
    si.wo = {0, 0, 1};
    si.dpdu = {1, 0, 0};
    si.dpdv = {0, 1, 0};
    si.set_shading({0, 0, 1}, {1, 0, 0}, {0, 1, 0});
    si.material = &material;
    return si;
}

Vec3f shaded_normal(const MaterialPtr &material) {
    SurfaceInteraction si = plane_point(*material);
    ScratchBuffer scratch;
    SampledWavelengths lambda = SampledWavelengths::sample_visible(0.5f);
    BSDF bsdf = shade(si, lambda, scratch);
    EXPECT_TRUE(bsdf);
    // The BSDF's frame follows the new shading normal.
    EXPECT_NEAR(dot(bsdf.frame().z, si.shading.n), 1, 1e-6f);
    return si.shading.n;
}

TEST(ShadingPerturbation, BumpMapTiltsTheNormalByTheDisplacementGradient) {
    set_warnings_enabled(false);
    for (float a : {0.f, 0.5f, -2.f}) {
        // bilerp with v00 = v01 = 0 and v10 = v11 = a is d(u, v) = a u.
        NamedTextures textures;
        textures.float_textures["ramp"] = create_float_texture(
            "bilerp", {},
            dictionary({numbers("float", "v10", {a}, 2), numbers("float", "v11", {a}, 3),
                        numbers("float", "v01", {0}, 4)}),
            textures, directive_location());
        MaterialPtr bumped = create_material(
            "diffuse", dictionary({strings("texture", "displacement", {"ramp"}, 2)}), textures,
            directive_location());
        Vec3f n = shaded_normal(bumped);
        Vec3f expected = normalize(Vec3f(-a, 0, 1));
        EXPECT_NEAR(n.x, expected.x, 1e-3f) << a;
        EXPECT_NEAR(n.y, expected.y, 1e-3f) << a;
        EXPECT_NEAR(n.z, expected.z, 1e-3f) << a;
    }
    set_warnings_enabled(true);
}

TEST(ShadingPerturbation, NormalMapSetsTheTangentSpaceNormal) {
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("caustica-normalmap-" + std::to_string(getpid()));
    std::filesystem::create_directories(dir);
    const Vec3f tangent_space(0.6f, 0, 0.8f);
    const std::string path = (dir / "normals.exr").string();
    {
        Imf::Rgba pixels[4];
        for (Imf::Rgba &p : pixels)
            p = Imf::Rgba(0.5f * (tangent_space.x + 1), 0.5f * (tangent_space.y + 1),
                          0.5f * (tangent_space.z + 1), 1);
        Imf::RgbaOutputFile file(path.c_str(), 2, 2, Imf::WRITE_RGB);
        file.setFrameBuffer(pixels, 1, 2);
        file.writePixels(2);
    }
    MaterialPtr mapped = create_material("diffuse", dictionary({strings("string", "normalmap", {path}, 2)}),
                                         {}, directive_location());
    // The tangent frame is dp/du = x, shading normal = z: the map's normal as it is.
    Vec3f n = shaded_normal(mapped);
    EXPECT_NEAR(n.x, 0.6f, 2e-3f);
    EXPECT_NEAR(n.y, 0, 2e-3f);
    EXPECT_NEAR(n.z, 0.8f, 2e-3f);
    // A missing file is an error at the parameter.
    try {
        create_material("diffuse", dictionary({strings("string", "normalmap", {(dir / "none.png").string()}, 7)}),
                        {}, directive_location());
        ADD_FAILURE() << "no error";
    } catch (const InputError &e) {
        EXPECT_EQ(e.location().line, 7);
    }
    std::filesystem::remove_all(dir);
}

} // namespace
} // namespace caustica
