// The diamond generator builds a closed, outward-facing round brilliant with 57 facets and
// Tolkowsky's proportions.
#include "../../scenes/generators/brilliant_cut.h"

#include <gtest/gtest.h>

#include <map>

using namespace caustica::diamond;

namespace {

TEST(BrilliantCut, HasTheFiftySevenFacetsOfARoundBrilliant) {
    std::map<FacetKind, int> count;
    for (const Face &f : build_faces(facet_planes(Proportions{}))) ++count[f.kind];
    EXPECT_EQ(count[FacetKind::Table], 1);
    EXPECT_EQ(count[FacetKind::Star], 8);
    EXPECT_EQ(count[FacetKind::Bezel], 8);
    EXPECT_EQ(count[FacetKind::UpperGirdle], 16);
    EXPECT_EQ(count[FacetKind::PavilionMain], 8);
    EXPECT_EQ(count[FacetKind::LowerGirdle], 16);
}

// Closed and outward: by the divergence theorem the signed volume sum over faces of
// (1/3) dot(centroid, area vector) is positive for outward faces, and the area vectors of a
// closed surface sum to zero.
TEST(BrilliantCut, IsClosedWithOutwardFaces) {
    Vec area_sum;
    double volume = 0;
    for (const Face &f : build_faces(facet_planes(Proportions{}))) {
        for (size_t i = 1; i + 1 < f.vertices.size(); ++i) {
            Vec a = f.vertices[0], b = f.vertices[i], c = f.vertices[i + 1];
            Vec area = cross(b - a, c - a) * 0.5;
            area_sum = area_sum + area;
            volume += dot((a + b + c) * (1.0 / 3), area) / 3;
        }
    }
    EXPECT_NEAR(area_sum.x, 0, 1e-9);
    EXPECT_NEAR(area_sum.y, 0, 1e-9);
    EXPECT_NEAR(area_sum.z, 0, 1e-9);
    EXPECT_GT(volume, 0.5);
}

// Tolkowsky: crown height about 16.2% and pavilion depth about 43.1% of the girdle diameter.
TEST(BrilliantCut, HasTolkowskyProportions) {
    double top = -1, bottom = 1;
    for (const Face &f : build_faces(facet_planes(Proportions{})))
        for (const Vec &v : f.vertices) {
            top = std::max(top, v.z);
            bottom = std::min(bottom, v.z);
        }
    const double girdle = Proportions{}.girdle_thickness;
    EXPECT_NEAR((top - girdle) / 2, 0.162, 0.01);
    EXPECT_NEAR((-bottom - girdle) / 2, 0.431, 0.01);
}

} // namespace
