// The exact arithmetic's only constructed points: every coordinate of a crossing must be a faithful
// rounding of the exact one (strictly within one ulp), at every magnitude, subnormal and huge
// included, and for nearly parallel segments.
#include "predicates/construction.h"

#include <gmpxx.h>
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace gh {
namespace {

// The construction with a counter of exact constructions (thread-local: the tests are serial).
detail::ExactCounters& counters() {
  thread_local detail::ExactCounters c;
  return c;
}
Point constructCrossing(Point p1, Point p2, Point q1, Point q2) {
  return detail::constructCrossing(p1, p2, q1, q2, counters());
}

mpq_class q(double v) {
  return mpq_class(v);
}

mpq_class orient(Point a, Point b, Point c) {
  return (q(b.x) - q(a.x)) * (q(c.y) - q(a.y)) - (q(b.y) - q(a.y)) * (q(c.x) - q(a.x));
}

// Do the segments cross at one point interior to both? (Exact.)
bool properlyCross(Point p1, Point p2, Point q1, Point q2) {
  return sgn(orient(q1, q2, p1)) * sgn(orient(q1, q2, p2)) < 0 &&
         sgn(orient(p1, p2, q1)) * sgn(orient(p1, p2, q2)) < 0;
}

// Is d one of the two doubles that bracket the exact value v (or v itself)?
bool faithful(double d, const mpq_class& v) {
  const double inf = std::numeric_limits<double>::infinity();
  return q(std::nextafter(d, -inf)) < v && v < q(std::nextafter(d, inf));
}

// Checks the construction against the exact rational crossing; "" when faithful.
std::string check(Point p1, Point p2, Point q1, Point q2) {
  const mpq_class w1 = orient(q1, q2, p1), w2 = orient(q1, q2, p2);
  const mpq_class t = w1 / (w1 - w2);
  const mpq_class x = q(p1.x) + t * (q(p2.x) - q(p1.x)), y = q(p1.y) + t * (q(p2.y) - q(p1.y));
  // Both compiled paths: the one this processor uses, and the one for processors without fma.
  for (const Point c : {constructCrossing(p1, p2, q1, q2),
                        detail::constructCrossingWithoutFmaInstruction(p1, p2, q1, q2, counters())}) {
    if (!faithful(c.x, x)) return "x " + std::to_string(c.x) + " is not a faithful rounding";
    if (!faithful(c.y, y)) return "y " + std::to_string(c.y) + " is not a faithful rounding";
  }
  return "";
}

// Small integers times 2^e: every magnitude from the subnormal range to near overflow.
rc::Gen<double> scaledInteger(int e) {
  return rc::gen::map(rc::gen::inRange(-(1 << 20), 1 << 20),
                      [e](int m) { return std::ldexp(m, e); });
}

RC_GTEST_PROP(Construction, CrossingsAreFaithfullyRoundedAtEveryMagnitude, ()) {
  const int e = *rc::gen::inRange(-1074, 980);
  const auto coord = scaledInteger(e);
  const Point p1{*coord, *coord}, p2{*coord, *coord}, q1{*coord, *coord}, q2{*coord, *coord};
  RC_PRE(properlyCross(p1, p2, q1, q2));
  const std::string problem = check(p1, p2, q1, q2);
  RC_ASSERT(problem == "");
}

// Random doubles: the fast path decides these; nearly parallel pairs stress its bound.
RC_GTEST_PROP(Construction, CrossingsOfNearlyParallelSegmentsAreFaithfullyRounded, ()) {
  const auto unit =
      rc::gen::map(rc::gen::inRange(0, 1 << 30), [](int m) { return std::ldexp(m, -30); });
  const Point p1{*unit, *unit}, p2{*unit, *unit};
  // q runs along p, tilted by a tiny angle about a point of p.
  const double s = *unit, tilt = std::ldexp(1.0, -*rc::gen::inRange(1, 50));
  const Point m{p1.x + s * (p2.x - p1.x), p1.y + s * (p2.y - p1.y)};
  const double dx = p2.x - p1.x, dy = p2.y - p1.y;
  const Point q1{m.x - dx - tilt * dy, m.y - dy + tilt * dx},
      q2{m.x + dx + tilt * dy, m.y + dy - tilt * dx};
  RC_PRE(properlyCross(p1, p2, q1, q2));
  const std::string problem = check(p1, p2, q1, q2);
  RC_ASSERT(problem == "");
}

// Every coordinate at its own magnitude (2^-60..2^60): the determinants' terms and the
// interpolation's terms differ widely, which is where a wrong error bound would show.
RC_GTEST_PROP(Construction, CrossingsOfMixedMagnitudesAreFaithfullyRounded, ()) {
  const auto coord =
      rc::gen::mapcat(rc::gen::inRange(-60, 61), [](int e) { return scaledInteger(e - 20); });
  const Point p1{*coord, *coord}, p2{*coord, *coord}, q1{*coord, *coord}, q2{*coord, *coord};
  RC_PRE(properlyCross(p1, p2, q1, q2));
  const std::string problem = check(p1, p2, q1, q2);
  RC_ASSERT(problem == "");
}

// The properties above test the certified fast path only if it decides most points: on random
// crossings in a square it must (about 1 in 10^4 needs rationals), or they would test GMP. Tiny
// squares take it too, at a power-of-two scale (below 2^-1022 the coordinates lose bits, and
// the crossing of segments with few-bit coordinates may itself need rounding).
TEST(Construction, CertifiedPathDecidesRandomCrossingsAtEveryScale) {
  for (const int scale : {0, -1000, -600, 400}) {
    std::mt19937_64 rng(20261122);  // its output is fixed by the standard, unlike distributions'
    auto unit = [&rng, scale] { return std::ldexp(static_cast<double>(rng() >> 11), -53 + scale); };
    const std::uint64_t before = counters().exactConstructions;
    int crossings = 0;
    while (crossings < 10000) {
      const Point p1{unit(), unit()}, p2{unit(), unit()}, q1{unit(), unit()}, q2{unit(), unit()};
      if (!properlyCross(p1, p2, q1, q2)) continue;
      ++crossings;
      ASSERT_EQ(check(p1, p2, q1, q2), "") << "scale 2^" << scale;
    }
    EXPECT_LT(counters().exactConstructions - before, 100u)
        << "at scale 2^" << scale << ", of " << crossings << " crossings took the exact path";
  }
}

// Is d the double nearest to v (either of two equally near)?
bool nearest(double d, const mpq_class& v) {
  const double inf = std::numeric_limits<double>::infinity();
  const mpq_class error = abs(v - q(d));
  return error <= abs(v - q(std::nextafter(d, -inf))) && error <= abs(v - q(std::nextafter(d, inf)));
}

// Where the doubles cannot certify a coordinate, the rationals decide and round to the nearest
// double. A crossing on the axis x = 0 always goes there (0 has no certificate: the exact value
// might be a tiny non-zero one), at every magnitude of the other coordinate, its lifting of values
// below 2^-1000 included; so a fallback that kept a wrong neighbour, or a faithful but not
// nearest one, fails here where the faithfulness properties above would not see it.
TEST(Construction, RationalFallbackRoundsToTheNearestDouble) {
  std::mt19937_64 rng(20261129);
  auto magnitude = [&rng](int lo, int hi) {
    const double m = static_cast<double>(rng() >> 11) + 1;  // 53 random bits, never 0
    return std::ldexp(m, lo + static_cast<int>(rng() % static_cast<std::uint64_t>(hi - lo + 1)) - 53);
  };
  int fallbacks = 0;
  for (int i = 0; i < 3000; ++i) {
    // q from the left half-plane to the right one; p along x = 0, long enough to meet it.
    const int e = -1070 + static_cast<int>(rng() % 2000);  // the scale of q's heights
    const Point q1{-magnitude(-40, 40), magnitude(e, e + 20) * (rng() % 2 ? 1 : -1)},
        q2{magnitude(-40, 40), magnitude(e, e + 20) * (rng() % 2 ? 1 : -1)};
    const double reach = 2 * std::max(std::abs(q1.y), std::abs(q2.y)) + 1;
    const Point p1{0, -reach}, p2{0, reach};
    if (!properlyCross(p1, p2, q1, q2)) continue;
    const mpq_class t = q(q1.x) / (q(q1.x) - q(q2.x));  // q's parameter at x = 0
    const mpq_class y = q(q1.y) + t * (q(q2.y) - q(q1.y));
    for (const bool fma : {true, false}) {
      const std::uint64_t before = counters().exactConstructions;
      const Point c = fma ? constructCrossing(p1, p2, q1, q2)
                          : detail::constructCrossingWithoutFmaInstruction(p1, p2, q1, q2, counters());
      ASSERT_EQ(counters().exactConstructions - before, 1u) << "the crossing on x = 0 was certified in doubles";
      EXPECT_EQ(c.x, 0.0);
      ASSERT_TRUE(nearest(c.y, y)) << "y " << c.y << " is not the nearest double, for q " << q1.x << " " << q1.y
                                   << " to " << q2.x << " " << q2.y;
    }
    ++fallbacks;
  }
  EXPECT_GT(fallbacks, 2500);
}

TEST(Construction, SubnormalCrossingIsExact) {
  const double u = std::numeric_limits<double>::denorm_min();
  // (4u, 2u)-(12u, 4u) crosses x = 8u at y = 3u exactly.
  const Point c = constructCrossing({4 * u, 2 * u}, {12 * u, 4 * u}, {8 * u, 0}, {8 * u, 8 * u});
  EXPECT_EQ(c.x, 8 * u);
  EXPECT_EQ(c.y, 3 * u);
}

TEST(Construction, AxisParallelSegmentsGiveExactCoordinates) {
  const Point c = constructCrossing({0.1, 0.3}, {0.7, 0.3}, {0.2, 0.9}, {0.2, -0.4});
  EXPECT_EQ(c.x, 0.2);
  EXPECT_EQ(c.y, 0.3);
}

}  // namespace
}  // namespace gh
