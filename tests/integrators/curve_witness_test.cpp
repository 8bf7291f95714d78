// pbrt-v4's "curve" shape and "hair" material against pbrt-v4's images of scenes/shapes/*.pbrt
// (made by scenes/generators/make_curve_scenes.py): thin flat, cylinder, ribbon and B-spline
// curves on diffuse materials; three tufts of hair coloured by melanin, by "color" and by
// "sigma_a"; and a hair fibre and a cylinder curve many pixels wide, across which the hair's
// offset h and the cylinder's normal change in blocks of pixels, not only within a pixel. All
// under the sun and the sky, with the hard-transport suite's check (render_test_support.h).
// pt only: curves are ray-facing ribbons, which light paths meet turned towards themselves, so
// the light-path integrators render them differently (docs/pbrt-v4-coverage.md), as pbrt-v4's
// own do. Negative controls (one run each, then undone): the cylinder's normal turned the other
// way across its width fails wide-fibres with |z| 301; the hair's h taken as 1 - 2 v with |z|
// 129; ribbons not narrowed by the cosine of their normal fail curves with a mean error of 1.8%
// and |z| 14.
#include "render_test_support.h"

#include <gtest/gtest.h>

using namespace caustica::testing;

namespace {

INSTANTIATE_TEST_SUITE_P(Curves, PbrtWitness,
                         ::testing::Values(RenderCase{"shapes/curves", "pt", 64},
                                           RenderCase{"shapes/hair", "pt", 64},
                                           RenderCase{"shapes/wide-fibres", "pt", 64}),
                         witness_case_name);

} // namespace
