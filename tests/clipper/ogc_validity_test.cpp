// The exact OGC validity check (ogc_validity.h): every rule of GEOS's IsValidOp caught on a
// polygon that breaks it and only it, at 1 and at scales where GEOS's arithmetic underflows.
#include <gtest/gtest.h>

#include <cmath>

#include "ghclip/ogc_validity.h"

namespace gh {
namespace {

Ring rect(double x0, double y0, double x1, double y1) { return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; }
Ring reversed(Ring r) {
  std::reverse(r.begin(), r.end());
  return r;
}
PolygonWithHoles scaled(PolygonWithHoles p, int k) {
  auto s = [k](Ring& r) {
    for (Point& q : r) q = {std::ldexp(q.x, k), std::ldexp(q.y, k)};
  };
  s(p.shell);
  for (Ring& h : p.holes) s(h);
  return p;
}
std::vector<PolygonWithHoles> scaled(std::vector<PolygonWithHoles> ps, int k) {
  for (PolygonWithHoles& p : ps) p = scaled(p, k);
  return ps;
}

// Each case at 1, near 1e-300 and near 1e150: the same verdict, the same rule named.
void expectInvalid(const std::vector<PolygonWithHoles>& polygons, const std::string& rule) {
  for (const int k : {0, -1000, 480}) {
    const auto why = ogcInvalidity(scaled(polygons, k));
    ASSERT_TRUE(why.has_value()) << "2^" << k << ": valid, expected " << rule;
    EXPECT_NE(why->find(rule), std::string::npos) << "2^" << k << ": " << *why << " (expected " << rule << ")";
  }
}
void expectValid(const std::vector<PolygonWithHoles>& polygons) {
  for (const int k : {0, -1000, 480}) {
    const auto why = ogcInvalidity(scaled(polygons, k));
    EXPECT_FALSE(why.has_value()) << "2^" << k << ": " << *why;
  }
}

TEST(OgcValidity, ValidPolygonsPass) {
  expectValid({});
  expectValid({{rect(0, 0, 10, 10), {reversed(rect(2, 2, 4, 4)), reversed(rect(5, 5, 8, 8))}}});
  // Holes touching the shell and each other at single points; shells touching at points; an
  // island inside a hole.
  expectValid({{rect(0, 0, 10, 10), {reversed(Ring{{0, 5}, {3, 3}, {3, 7}}), reversed(Ring{{3, 5}, {6, 4}, {6, 6}})}},
               {rect(10, 10, 12, 12), {}},
               {rect(4.4, 4.9, 4.6, 5.1), {}}});
  expectValid({{rect(0, 0, 10, 10), {reversed(rect(2, 2, 8, 8))}}, {rect(4, 4, 6, 6), {}}});
  // A hole vertex on the shell's edge (not a shell vertex).
  expectValid({{rect(0, 0, 10, 10), {reversed(Ring{{5, 0}, {6, 3}, {4, 3}})}}});
  // Repeated points are allowed.
  expectValid({{{{0, 0}, {1, 0}, {1, 0}, {1, 1}, {0, 1}}, {}}});
}

TEST(OgcValidity, EachRuleIsCaught) {
  expectInvalid({{{{0, 0}, {1, 0}, {0, 0}}, {}}}, "fewer than 3 distinct points");
  expectInvalid({{{{0, 0}, {2, 2}, {2, 0}, {0, 2}}, {}}}, "crosses itself");              // a bowtie
  expectInvalid({{{{0, 0}, {4, 0}, {4, 4}, {2, 0}, {0, 4}}, {}}}, "touches itself");        // at (2 0)
  expectInvalid({{{{0, 0}, {2, 0}, {1, 0}, {1, 1}}, {}}}, "folds back");
  expectInvalid({{rect(0, 0, 10, 10), {reversed(rect(8, 8, 12, 12))}}}, "cross");
  expectInvalid({{rect(0, 0, 10, 10), {reversed(rect(20, 20, 22, 22))}}}, "outside its shell");
  expectInvalid({{rect(0, 0, 10, 10), {reversed(rect(1, 1, 9, 9)), reversed(rect(3, 3, 5, 5))}}}, "inside polygon 1 hole");
  expectInvalid({{rect(0, 0, 10, 10), {reversed(rect(0, 2, 5, 4))}}}, "share an edge");
  // A hole touching the shell at two points cuts the interior in two.
  expectInvalid({{rect(0, 0, 10, 10), {reversed(Ring{{0, 5}, {5, 3}, {10, 5}, {5, 7}})}}}, "disconnected");
  // Two holes touching each other at two points enclose a pocket.
  expectInvalid({{rect(0, 0, 10, 10),
                  {reversed(Ring{{2, 5}, {5, 2}, {8, 5}, {5, 4}}), reversed(Ring{{2, 5}, {5, 6}, {8, 5}, {5, 8}})}}},
                "disconnected");
  expectInvalid({{rect(0, 0, 10, 10), {}}, {rect(2, 2, 4, 4), {}}}, "lies inside polygon 1");
  expectInvalid({{rect(0, 0, 10, 10), {}}, {rect(10, 0, 12, 10), {}}}, "share an edge");
}

TEST(OgcValidity, RingsCrossingAtCommonVerticesAreCaught) {
  // Two triangles with a common apex touch: valid; so does a triangle in the notch of a pentagon.
  expectValid({{{{0, 0}, {4, 0}, {2, 2}}, {}}, {{{2, 2}, {4, 4}, {0, 4}}, {}}});
  expectValid({{{{0, 0}, {4, 0}, {2, 2}, {4, 4}, {0, 4}}, {}}, {{{2, 2}, {6, 1}, {6, 3}}, {}}});
  // A square and a quadrilateral through three of its corners, along its diagonal: their edges
  // only touch, at those corners, but the rings cross at (0 0) and (4 4).
  expectInvalid({{rect(0, 0, 4, 4), {}}, {{{0, 0}, {2, -2}, {6, 2}, {4, 4}}, {}}}, "cross at");
}

TEST(OgcValidity, OrientationIsRfc7946sOnRequest) {
  const std::vector<PolygonWithHoles> clockwise{{reversed(rect(0, 0, 1, 1)), {}}};
  expectInvalid(clockwise, "clockwise");
  EXPECT_FALSE(ogcInvalidity(clockwise, RingOrientation::Any));
  const std::vector<PolygonWithHoles> ccwHole{{rect(0, 0, 10, 10), {rect(2, 2, 4, 4)}}};
  expectInvalid(ccwHole, "counter-clockwise");
  EXPECT_FALSE(ogcInvalidity(ccwHole, RingOrientation::Any));
}

TEST(OgcValidity, NonFiniteIsInvalid) {
  EXPECT_TRUE(ogcInvalidity({{{{0, 0}, {1, 0}, {NAN, 1}}, {}}}));
}

}  // namespace
}  // namespace gh
