// Measurements of regions (measure.h): even-odd area, signed area, and the even-odd point test,
// which is the library's one ray test with exact orientations.
#include <gtest/gtest.h>

#include <cmath>

#include "common/hand_cases.h"
#include "ghclip/clip.h"
#include "ghclip/errors.h"
#include "ghclip/measure.h"
#include "ghoracle/exact_oracle.h"

namespace gh {
namespace {

TEST(Measure, EvenOddAreaOfEveryHandCaseOperand) {
  for (const test::HandCase& c : test::handCases()) {
    EXPECT_NEAR(evenOddArea(c.subject), c.areaSubject, 1e-12 * std::max(1.0, c.areaSubject)) << c.name;
    EXPECT_NEAR(evenOddArea(c.clip), c.areaClip, 1e-12 * std::max(1.0, c.areaClip)) << c.name;
  }
}

TEST(Measure, SignedAreaFollowsOrientation) {
  const Ring ccw{{0, 0}, {2, 0}, {2, 1}, {0, 1}};
  const Ring cw(ccw.rbegin(), ccw.rend());
  EXPECT_DOUBLE_EQ(signedArea(ccw), 2);
  EXPECT_DOUBLE_EQ(signedArea(cw), -2);
  EXPECT_EQ(vertexCount({ccw, cw}), 8u);
}

// The pentagram's centre has winding number 2: outside under the even-odd rule; its points are
// inside; and a ring drawn twice cancels.
TEST(Measure, InsideEvenOddFollowsTheEvenOddRule) {
  const Region star = test::handCase("pentagram_in_square").subject;
  EXPECT_FALSE(insideEvenOdd(star, {0, 0}));
  EXPECT_TRUE(insideEvenOdd(star, {0, 0.8}));
  const Ring square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  EXPECT_TRUE(insideEvenOdd({square}, {0.5, 0.5}));
  EXPECT_FALSE(insideEvenOdd({square, square}, {0.5, 0.5}));
}

// Decided exactly: a point one ulp beside a long slanted edge is on the right side of it, where
// the ray's crossing x in doubles would round onto the point itself.
TEST(Measure, InsideEvenOddIsExactBesideAnEdge) {
  const Region triangle{{{0, 0}, {3, 1}, {0, 1}}};  // the edge y = x / 3 from (0,0) to (3,1)
  const double y = 1.0 / 3;                          // rounded: (1, y) is off the edge
  for (double dy : {0.0, std::nextafter(y, 1.0) - y, std::nextafter(y, 0.0) - y}) {
    const Point p{1, y + dy};
    // Above the line y = x/3 (exactly: 3 * p.y > p.x) means inside the triangle.
    const bool inside = 3 * static_cast<long double>(p.y) > static_cast<long double>(p.x);
    EXPECT_EQ(insideEvenOdd(triangle, p), inside) << p.y;
  }
}

// Regression (fuzz_clip_exact, tests/regressions/fuzz/fuzz_clip_exact/evenodd-area-nan): the exact
// arithmetic's union of these rings is right (the exact oracle passes it), but the floating-point
// evenOddArea measured it as NaN: exact orientations said two nearly parallel edges cross while
// their double determinants cancelled, and the crossing's x became 0/0.
TEST(Measure, EvenOddAreaStaysFiniteWhereDeterminantsCancel) {
  const Region s{{{3, 4}, {1, 8}, {8, 7}, {0, 0}, {4, 6}},
                 {{5, 6}, {3, 3}, {8, 2}, {3, 5}, {7, 3}, {1, 4}, {4, 0}, {0, 6}, {7, 0}, {0, 8}, {2, 1}, {5, 2}, {8, 1}, {0, 2}},
                 {{4, 3}, {4, 2}, {5, 2}, {5, 0}}};
  const Region c{{{4, 0}, {6, 4}, {7, 1}, {3, 7}},
                 {{0, 8}, {2, 1}, {5, 2}, {8, 1}, {0, 2}, {8, 4}, {3, 4}, {2, 5}, {2, 5}, {0, 1}},
                 {{4, 0}, {6, 4}, {4, 1}, {4, 8}}};
  const Region r = clip(s, c, Op::Union);
  const auto v = oracle::exactCheck(s, c, Op::Union, r);
  EXPECT_TRUE(v.pass);
  const double area = evenOddArea(r);
  ASSERT_TRUE(std::isfinite(area));
  EXPECT_NEAR(area, v.expectedArea, 1e-9 * v.expectedArea);
}

// Regression (fuzz_clip_exact, tests/regressions/fuzz/fuzz_clip_exact/evenodd-area-one-ulp-slab):
// the exact arithmetic's union of an empty subject with a clip ring folded near (1, 1) is this
// triangle, one ulp of 1 wide and 1 high (the exact oracle passes it), but evenOddArea measured
// it and the clip as 0, and the union invariant trapped. Its slabs are one ulp wide, their
// middle rounded to a boundary, where the segments meeting there tie: the pairs were ordered by
// their heights there, half of them upside down.
TEST(Measure, EvenOddAreaOfSlabsOneUlpWide) {
  const double below = std::nextafter(1.0, 0.0), twoBelow = std::nextafter(below, 0.0);
  const Region triangle{{{below, below}, {twoBelow, below}, {1, 3.637978807091713e-12}}};
  // Exactly: ((below - twoBelow) * (below - 3.6e-12)) / 2, within an ulp.
  const double exact = (below - twoBelow) * (below - 3.637978807091713e-12) / 2;
  EXPECT_NEAR(evenOddArea(triangle), exact, 1e-15 * exact);
  const Region folded{{{1, 3.637978807091713e-12}, {twoBelow, below}, {std::nextafter(twoBelow, 0.0), below}, {below, below},
                       {below, twoBelow}, {below, below}, {below, below}, {below, below}}};
  const auto v = oracle::exactCheck({}, folded, Op::Union, triangle);
  EXPECT_TRUE(v.pass);
  EXPECT_NEAR(evenOddArea(folded), v.expectedArea, 1e-15 * v.expectedArea);
  EXPECT_GT(v.expectedArea, 0);
}

// GMP, behind the exact predicates, raises SIGFPE on NaN and infinity: refused with a message.
TEST(Measure, NonFiniteCoordinatesAreRefused) {
  const Region square{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
  for (double bad : {std::nan(""), double{INFINITY}, -double{INFINITY}}) {
    const Region broken{{{0, 0}, {bad, 0}, {1, 1}, {0, 1}}};
    EXPECT_THROW(evenOddArea(broken), InvalidInput);
    EXPECT_THROW(insideEvenOdd(broken, {0.5, 0.5}), InvalidInput);
    EXPECT_THROW(insideEvenOdd(square, {bad, 0.5}), InvalidInput);
    EXPECT_THROW(insideEvenOdd(square, {0.5, bad}), InvalidInput);
  }
  EXPECT_TRUE(insideEvenOdd(square, {0.5, 0.5}));
  EXPECT_EQ(evenOddArea(square), 1);
}

}  // namespace
}  // namespace gh
