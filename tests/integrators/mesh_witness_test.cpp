// pbrt-v4's displacement of a "plymesh" (src/geometry/mesh_displacement.h) against pbrt-v4's
// image of scenes/shapes/displaced-plymesh.pbrt: a grid of quads refined to short render-space
// edges, moved along its normals by an fbm height field and shaded with the normals recomputed
// from the moved triangles, lit at a grazing angle so that the relief decides every pixel; with
// the hard-transport suite's check (render_test_support.h), by a camera path and a light path
// integrator. Negative controls (one run each, then undone), pt:
// - the normals of the refined, undisplaced mesh kept for shading: 29% dark, |z| 892;
// - edge lengths measured in object space (the mesh is scaled by 1.5): 1.1% dark, |z| 45.
#include "render_test_support.h"

#include <gtest/gtest.h>

using namespace caustica::testing;

namespace {

INSTANTIATE_TEST_SUITE_P(DisplacedMesh, PbrtWitness,
                         ::testing::Values(RenderCase{"shapes/displaced-plymesh", "pt", 64},
                                           RenderCase{"shapes/displaced-plymesh", "lt", 64}),
                         witness_case_name);

// Curved bilinear patches (src/geometry/bilinear_patch.h) against pbrt-v4's image of
// scenes/shapes/bilinear-patches.pbrt: intersected exactly, textured through their own (u, v),
// shaded with interpolated normals, instanced, and sampled as an area light, by a camera path,
// a light path and a bidirectional integrator (which weighs the light's area density at points
// that camera paths reach). Negative control: the patches split into two triangles each, as
// before, make the image mean 5.7% dark and single blocks up to 42% off (pt, 256 spp).
INSTANTIATE_TEST_SUITE_P(BilinearPatches, PbrtWitness,
                         ::testing::Values(RenderCase{"shapes/bilinear-patches", "pt", 256},
                                           RenderCase{"shapes/bilinear-patches", "lt", 256},
                                           RenderCase{"shapes/bilinear-patches", "bdpt", 256}),
                         witness_case_name);

} // namespace
