// pbrt-v4's "measured" material against pbrt-v4's image of scenes/materials/measured.pbrt: a
// rough isotropic and a brushed anisotropic metal, tabulated in RGL BSDF files (made by
// scenes/generators/make_measured_bsdfs.py), under a small lamp and a dim sky, with the
// hard-transport suite's check (render_test_support.h), in every integrator: light paths
// evaluate the tables with the directions exchanged (measured_bxdf.h), so that they render the
// reflectance camera paths do. (Whether they exchange them does not show here: the files'
// asymmetry lies away from the mirror direction, where these glossy lobes carry little light;
// tests/materials/measured_bxdf_test.cpp checks the exchange itself.)
// Negative control (one run, then undone): sigma 3% high on the anisotropic file darkens its
// sphere 3% and fails pt with |z| 18.6 and bdpt with |z| 6.7.
#include "render_test_support.h"

#include <gtest/gtest.h>

using namespace caustica::testing;

namespace {

INSTANTIATE_TEST_SUITE_P(Measured, PbrtWitness,
                         ::testing::Values(RenderCase{"materials/measured", "pt", 256},
                                           RenderCase{"materials/measured", "lt", 2048},
                                           RenderCase{"materials/measured", "bdpt", 64},
                                           RenderCase{"materials/measured", "sppm", 256},
                                           RenderCase{"materials/measured", "bpm", 256},
                                           RenderCase{"materials/measured", "vcm", 64}),
                         witness_case_name);

} // namespace
