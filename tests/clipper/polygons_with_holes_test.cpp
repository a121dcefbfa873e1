// Turning an even-odd region into OGC polygons with holes (polygons_with_holes.h): exact, at every
// magnitude, and refused with the reason wherever the region has no exact OGC form.
#include <gtest/gtest.h>

#include <cmath>

#include "ghclip/measure.h"
#include "ghclip/polygons_with_holes.h"

namespace gh {
namespace {

Ring rect(double x0, double y0, double x1, double y1) { return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; }

TEST(PolygonsWithHoles, NestingMakesShellsAndHoles) {
  // Square, hole, island in the hole: two polygons, the first with one hole.
  const Region r{rect(0, 0, 10, 10), rect(2, 2, 8, 8), rect(4, 4, 6, 6)};
  const PolygonsWithHoles p = toPolygonsWithHoles(r);
  ASSERT_FALSE(p.refusal) << *p.refusal;
  ASSERT_EQ(p.polygons.size(), 2u);
  EXPECT_EQ(p.polygons[0].holes.size(), 1u);
  EXPECT_GT(signedArea(p.polygons[0].shell), 0);
  EXPECT_LT(signedArea(p.polygons[0].holes[0]), 0);
  EXPECT_NEAR(evenOddArea(toRegion(p.polygons)), evenOddArea(r), 1e-12);
}

// Found by experiments/robustness (simple+tiny): rings near 1e-300 were refused as having zero
// area (their area underflows in doubles), so GEOS, Boost.Geometry and CGAL never saw them. The
// conversion must decide orientation exactly, at any magnitude.
TEST(PolygonsWithHoles, ConvertsAtEveryMagnitude) {
  for (int e : {-1000, -540, 0, 490}) {
    auto scaled = [](const Ring& ring, int k) {
      Ring out = ring;
      for (Point& p : out) p = {std::ldexp(p.x, k), std::ldexp(p.y, k)};
      return out;
    };
    const Region r{scaled(rect(0, 0, 10, 10), e), scaled(rect(2, 2, 8, 8), e), scaled(rect(4, 4, 6, 6), e)};
    const PolygonsWithHoles p = toPolygonsWithHoles(r);
    ASSERT_FALSE(p.refusal) << "2^" << e << ": " << *p.refusal;
    ASSERT_EQ(p.polygons.size(), 2u);
    EXPECT_EQ(p.polygons[0].holes.size(), 1u);
    EXPECT_GT(signedArea(scaled(p.polygons[0].shell, -e)), 0) << "2^" << e;
    EXPECT_LT(signedArea(scaled(p.polygons[0].holes[0], -e)), 0) << "2^" << e;
  }
  // A ring of collinear points still has zero area at any scale.
  EXPECT_TRUE(toPolygonsWithHoles({{{0, 0}, {std::ldexp(1.0, -1000), 0}, {std::ldexp(3.0, -1000), 0}}}).refusal);
}

TEST(PolygonsWithHoles, RefusesEveryContact) {
  EXPECT_TRUE(toPolygonsWithHoles({rect(0, 0, 1, 1), rect(1, 0, 2, 1)}).refusal);  // shared edge
  EXPECT_TRUE(toPolygonsWithHoles({rect(0, 0, 1, 1), rect(1, 1, 2, 2)}).refusal);  // shared vertex
  EXPECT_TRUE(toPolygonsWithHoles({{{0, 0}, {2, 0}, {1, 0}, {1, 1}}}).refusal);     // folds back
  EXPECT_TRUE(toPolygonsWithHoles({{{0, 0}, {4, 0}, {4, 4}, {2, 0}, {0, 4}}}).refusal);  // touches itself
  // A vertex 2^-60 away from another ring's edge is not a contact: decided exactly.
  EXPECT_FALSE(toPolygonsWithHoles({rect(0, 0, 1, 1), {{0.5, std::ldexp(1.0, -60)}, {0.9, 0.5}, {0.6, 0.5}}}).refusal);
}

}  // namespace
}  // namespace gh
