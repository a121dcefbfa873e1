// The predicates (clipper/src/predicates/): error-free transforms, the filter's number type, the
// one filtered-predicate helper, orientation, the SoS expansions, the one ray test and the one
// segment-meeting test. The filter decides exact computations without GMP, the fallback agrees
// with an independent rational computation, and the SoS expansions never return zero.
#include <gtest/gtest.h>
#include <gmpxx.h>
#include <rapidcheck/gtest.h>

#include <limits>
#include <optional>
#include <random>
#include <vector>

#include "arithmetic/exact_arithmetic.h"
#include "predicates/approx.h"
#include "predicates/error_free.h"
#include "predicates/even_odd_ray.h"
#include "predicates/filtered_predicate.h"
#include "predicates/integer_stage.h"
#include "predicates/orientation.h"
#include "predicates/segment_meeting.h"
#include "predicates/sos_predicates.h"

namespace gh::detail {
namespace {

// The sign of (b - a) x (d - c) in rationals.
int rationalCross(Point a, Point b, Point c, Point d) {
  return sgn((mpq_class(b.x) - a.x) * (mpq_class(d.y) - c.y) - (mpq_class(b.y) - a.y) * (mpq_class(d.x) - c.x));
}

int rationalOrientation(Point a, Point b, Point c) { return rationalCross(a, b, a, c); }

mpq_class exactly(TwoTerm t) { return mpq_class(t.hi) + mpq_class(t.lo); }

TEST(ErrorFree, TransformsAreExact) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1e6, 1e6);
  for (int i = 0; i < 10000; ++i) {
    const double a = u(rng) * std::ldexp(1.0, static_cast<int>(rng() % 200) - 100), b = u(rng);
    ASSERT_EQ(exactly(twoSum(a, b)), mpq_class(a) + mpq_class(b));
    ASSERT_EQ(exactly(twoDiff(a, b)), mpq_class(a) - mpq_class(b));
    ASSERT_EQ(exactly(twoProduct(a, b)), mpq_class(a) * mpq_class(b));
    ASSERT_EQ(exactly(twoProductBySplitting(a, b)), mpq_class(a) * mpq_class(b));
  }
}

TEST(Approx, ExactComputationsCarryNoError) {
  const Approx d = (Approx(3) - Approx(1)) * (Approx(7) - Approx(2)) - Approx(10);
  EXPECT_EQ(d.e, 0);
  EXPECT_EQ(certainSign(d), Sign::Zero);  // a certain zero, no fallback needed
  const Approx t = Approx(0.1) * Approx(0.3);
  EXPECT_GT(t.e, 0);
  EXPECT_EQ(certainSign(Approx(1e-300) * Approx(1e-300)), std::nullopt);  // underflow: undecided
}

TEST(CertainSign, DecidesOnlyWhatTheBoundDecides) {
  EXPECT_EQ(certainSign(1.0, 0.5), Sign::Positive);
  EXPECT_EQ(certainSign(-1.0, 0.5), Sign::Negative);
  EXPECT_EQ(certainSign(0.0, 0.0), Sign::Zero);
  EXPECT_EQ(certainSign(0.4, 0.5), std::nullopt);
  EXPECT_EQ(certainSign(1.0, 1.0), std::nullopt);  // on the bound: the bound's own rounding
  EXPECT_EQ(certainSign(1.0, INFINITY), std::nullopt);
  EXPECT_EQ(certainSign(NAN, 1.0), std::nullopt);
}

// The helper runs the filter stage; only when a sign it needed was not certain the stage in
// doubles, counted as an expansion decision; only when that gives nothing the exact stage,
// counted as a filter failure.
TEST(FilteredPredicate, GoesOnOnlyWhenUncertainAndCounts) {
  ExactCounters counters;
  int filters = 0, inDoubles = 0, exacts = 0;
  auto predicate = [&](double a, double b, std::optional<Sign> decidedInDoubles) {
    return filteredPredicate(
        [&](auto numbers) {
          using N = typename decltype(numbers)::Number;
          ++filters;
          const N d = N(a) * N(b) - N(1);
          return numbers.sign(d);
        },
        [&] {
          ++inDoubles;
          return decidedInDoubles;
        },
        [&] {
          ++exacts;
          return toSign(sgn(mpq_class(a) * b - 1));
        },
        counters);
  };
  EXPECT_EQ(predicate(2, 3, std::nullopt), Sign::Positive);
  EXPECT_EQ(filters, 1);
  EXPECT_EQ(inDoubles + exacts, 0);
  // 1/3 rounded times 3 is 1 - 2^-54 exactly: tiny, but the filter's bound covers it.
  const Sign truth = toSign(sgn(mpq_class(1.0 / 3) * 3 - 1));
  EXPECT_EQ(predicate(1.0 / 3, 3, truth), truth);
  EXPECT_EQ(inDoubles, 1);
  EXPECT_EQ(exacts, 0);
  EXPECT_EQ(counters.expansionDecisions, 1u);
  EXPECT_EQ(counters.filterFailures, 0u);
  EXPECT_EQ(predicate(1.0 / 3, 3, std::nullopt), truth);
  EXPECT_EQ(exacts, 1);
  EXPECT_EQ(counters.filterFailures, 1u);
}

// A coordinate for the integer stage: zero, or any finite double from the subnormals to 2^1000,
// either sign, often a few ulps off a small integer or a power of two.
double integerStageCoordinate() {
  switch (*rc::gen::inRange(0, 4)) {
    case 0: return 0.0;
    case 1: {
      double x = *rc::gen::inRange(-8, 9);
      for (int k = *rc::gen::inRange(-3, 4); k != 0; k += k > 0 ? -1 : 1) x = std::nextafter(x, k > 0 ? 9.0 : -9.0);
      return x;  // near 0 these are subnormal
    }
    case 2: return std::ldexp(*rc::gen::inRange(-(1 << 20), 1 << 20), *rc::gen::inRange(-1074, 980));
    default: {
      const double x = std::ldexp(1.0 + std::ldexp(*rc::gen::inRange(0, 1 << 30), -30), *rc::gen::inRange(-1074, 980));
      return *rc::gen::arbitrary<bool>() ? -x : x;
    }
  }
}

// The integer stage against rationals, over every magnitude a double has (subnormals beside
// 2^980 in one predicate, where the stages in doubles give up), exact zeros included (points
// repeated): the cross product's sign and the SoS order's F0.
RC_GTEST_PROP(IntegerStage, AgreesWithRationalsAtEveryMagnitude, ()) {
  std::vector<Point> pool;
  for (int i = 0; i < 4; ++i) pool.push_back({integerStageCoordinate(), integerStageCoordinate()});
  const auto point = [&] { return pool[static_cast<std::size_t>(*rc::gen::inRange(0, 4))]; };
  const Point a = point(), b = point(), c = point(), d = point();
  RC_ASSERT(static_cast<int>(integerCrossSign(a, b, c, d)) == rationalCross(a, b, c, d));
  const Point m1 = point(), m2 = point(), n1 = point(), n2 = point();
  const mpq_class mx = mpq_class(m2.x) - m1.x, my = mpq_class(m2.y) - m1.y, nx = mpq_class(n2.x) - n1.x, ny = mpq_class(n2.y) - n1.y;
  const mpq_class ax = mpq_class(a.x) - b.x, ay = mpq_class(a.y) - b.y;
  const mpq_class aM = mx * (mpq_class(a.y) - m1.y) - my * (mpq_class(a.x) - m1.x);
  const mpq_class aN = nx * (mpq_class(a.y) - n1.y) - ny * (mpq_class(a.x) - n1.x);
  RC_ASSERT(static_cast<int>(integerOrderTerm(a, b, m1, m2, n1, n2)) == sgn(aM * (nx * ay - ny * ax) - aN * (mx * ay - my * ax)));
}

// Near-collinear points on a 2^-43 grid around a line: the classic failure of double orientation.
TEST(Orientation, AgreesWithRationalsOnNearCollinearFixtures) {
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<int> k(-64, 64);
  ExactCounters counters;
  for (int i = 0; i < 20000; ++i) {
    const double h = std::ldexp(1.0, -43);
    const Point a{0.5 + k(rng) * h, 0.5 + k(rng) * h}, b{12 + k(rng) * h, 12 + k(rng) * h}, c{24 + k(rng) * h, 24 + k(rng) * h};
    EXPECT_EQ(static_cast<int>(orientation(a, b, c, counters)), rationalOrientation(a, b, c)) << i;
  }
  EXPECT_GT(counters.expansionDecisions, 0u);  // the fixture does reach the exact stages
}

// The turn between two edge directions, four points a few of their own ulps off one line (the
// differences round too). The eight fixed quadruples were found by a search of 3*10^6 such random
// ones: their rounded determinants have the wrong sign and exceed u*(|left| + |right|) by up to
// 1.87 times, so only the whole of Shewchuk's stage-A bound, (3 + 16u)u, sends them on.
TEST(CrossSign, AgreesWithRationalsOnNearCollinearFixtures) {
  ExactCounters counters;
  const Point found[][4] = {
      {{0x1.9d6fe69abdc2cp+0, 0x1.852c90919d5dap+0}, {0x1.532e8e11caf68p+3, 0x1.02d6f204d9e75p+3}, {-0x1.4205810ccf967p+2, -0x1.ab679ca3beab3p+1}, {0x1.36b5df688adp+4, 0x1.d12f40be2b8fap+3}},
      {{0x1.f049932ef3a2fp+1, 0x1.964a736b809f2p+1}, {-0x1.0f08ebc2b128p+1, -0x1.35659e3f1003dp+0}, {0x1.d52522595a5f4p-1, 0x1.0267fb9bcbc3bp+0}, {-0x1.1fed930f2748ep+3, -0x1.8f47e2ee4e2ap+2}},
      {{0x1.ed61a217252e1p+2, 0x1.7e704d3d7bdcap+2}, {-0x1.025125486dbfp-1, -0x1.e11fbd7896374p-6}, {-0x1.69a67e3dd229ap+2, -0x1.e5599d659f2e2p+1}, {-0x1.99cf80b3ff40bp+4, -0x1.262e3c801f56cp+4}},
      {{-0x1.b2e8b3101cfc6p+2, -0x1.283c01f66fe9p+2}, {0x1.c26186e72df08p-2, 0x1.527509982990cp-1}, {0x1.58b84426156a1p+2, 0x1.11c08f8c59089p+2}, {-0x1.18567c282163ap+0, -0x1.d82ddb0f7b5b5p-2}},
      {{-0x1.ff10ffe48efc9p+1, -0x1.4a2f7fd6b4317p+1}, {0x1.7d62f405834fap+1, 0x1.42496bc119066p+1}, {-0x1.63bfbc6841092p+2, -0x1.dcb895f0c64aap+1}, {0x1.42cd44574a97dp+1, 0x1.17749ccc8d9ddp+1}},
      {{0x1.582eedcce473ep+1, 0x1.27166820a994bp+1}, {0x1.ab8aeb99d34fap+4, 0x1.3e0221946bed9p+4}, {0x1.4c755f3726aa8p+0, 0x1.49f8799e2e238p+0}, {-0x1.2791ee6b10877p+4, -0x1.a551991e83073p+3}},
      {{-0x1.c9a71de78ec0ap-2, 0x1.a1a0b9de0d204p-7}, {-0x1.b0b28234a0d02p+2, -0x1.269e10c7056d5p+2}, {0x1.d2fe294e0cab2p+2, 0x1.6b2560536c3ebp+2}, {0x1.a3c2d06c7437p+4, 0x1.3851b3cda4e2bp+4}},
      {{0x1.afb4267ae3217p+2, 0x1.51589c5dc0a2fp+2}, {-0x1.7b9595e958ed8p+2, -0x1.ff92b5d187444p+1}, {0x1.82d3ff4651554p+0, 0x1.71b861c937a95p+0}, {-0x1.b467292e1f0ep+3, -0x1.3430c07928de8p+3}},
  };
  for (const auto& [a, b, c, d] : found) {
    const double left = (b.x - a.x) * (d.y - c.y), right = (b.y - a.y) * (d.x - c.x);
    ASSERT_NE((left - right > 0) - (left - right < 0), rationalCross(a, b, c, d));  // the doubles are wrong
    EXPECT_EQ(static_cast<int>(crossSign(a, b, c, d, counters)), rationalCross(a, b, c, d)) << a.x;
  }
  std::mt19937_64 rng(11);
  std::uniform_int_distribution<int> k(-64, 64);
  std::uniform_real_distribution<double> t(-1, 1);
  const auto near = [&](double scale) {
    const double x = 0.37 + scale * t(rng), y = 0.61 + 0.7311 * (x - 0.37);
    return Point{x + k(rng) * (std::nextafter(x, 1e9) - x), y + k(rng) * (std::nextafter(y, 1e9) - y)};
  };
  for (int i = 0; i < 20000; ++i) {
    const Point a = near(8), b = near(32), c = near(8), d = near(32);
    EXPECT_EQ(static_cast<int>(crossSign(a, b, c, d, counters)), rationalCross(a, b, c, d)) << i;
  }
  EXPECT_GT(counters.expansionDecisions, 0u);
}

// Found by the OGC conversion test at 2^-540: between 2^-900 and ~2^-537 the differences of
// coordinates are "safe" for the filter but their products underflow to exactly 0, which the
// running error bound took for an exact zero: orientation() said Zero for a plain right turn.
TEST(Orientation, ProductsThatUnderflowToZeroAreNotExactZeros) {
  ExactCounters c;
  for (int e : {-300, -540, -600, -700, -1000}) {
    const double s = std::ldexp(1.0, e);
    EXPECT_EQ(orientation({4 * s, 4 * s}, {6 * s, 4 * s}, {6 * s, 6 * s}, c), Sign::Positive) << "2^" << e;
    EXPECT_EQ(orientation({4 * s, 4 * s}, {6 * s, 6 * s}, {6 * s, 4 * s}, c), Sign::Negative) << "2^" << e;
    EXPECT_EQ(orientation({4 * s, 4 * s}, {6 * s, 6 * s}, {8 * s, 8 * s}, c), Sign::Zero) << "2^" << e;
  }
}

// Small integers times 2^e, e anywhere from the subnormal range to 2^480: the filtered
// orientation agrees with rationals (collinear triples included, by construction half the time).
RC_GTEST_PROP(Orientation, AgreesWithRationalsAtEveryScale, ()) {
  const int e = *rc::gen::inRange(-1074, 480);
  const auto coord = rc::gen::map(rc::gen::inRange(-64, 65), [e](int m) { return std::ldexp(m, e); });
  const Point a{*coord, *coord}, b{*coord, *coord};
  Point c{*coord, *coord};
  if (*rc::gen::arbitrary<bool>()) c = {a.x + 2 * (b.x - a.x), a.y + 2 * (b.y - a.y)};  // on the line ab
  RC_PRE(std::isfinite(c.x) && std::isfinite(c.y));
  ExactCounters counters;
  RC_ASSERT(static_cast<int>(orientation(a, b, c, counters)) == rationalOrientation(a, b, c));
  RC_ASSERT(static_cast<int>(crossSign(a, b, a, c, counters)) == rationalOrientation(a, b, c));
}

// The exact sum in doubles between the filter and GMP: nearly parallel directions (a direction
// and its rounded opposite, as the pie workload's edges through the origin are) are decided
// without rationals, and right.
RC_GTEST_PROP(CrossSign, DecidesNearlyParallelDirectionsInDoubles, ()) {
  const double angle = *rc::gen::inRange(0, 1 << 20) * (6.283185307179586 / (1 << 20));
  const int e = *rc::gen::inRange(-400, 400);
  const Point o{std::ldexp(*rc::gen::inRange(-8, 9), e), std::ldexp(*rc::gen::inRange(-8, 9), e)};
  const Point m{o.x + std::ldexp(std::cos(angle), e), o.y + std::ldexp(std::sin(angle), e)};
  const Point n{o.x + std::ldexp(std::cos(angle + 3.141592653589793), e), o.y + std::ldexp(std::sin(angle + 3.141592653589793), e)};
  ExactCounters counters;
  const Sign s = crossSign(o, m, o, n, counters);
  const mpq_class exact = (mpq_class(m.x) - o.x) * (mpq_class(n.y) - o.y) - (mpq_class(m.y) - o.y) * (mpq_class(n.x) - o.x);
  RC_ASSERT(static_cast<int>(s) == sgn(exact));
  RC_ASSERT(counters.filterFailures == 0u);
}

// Coordinates of every magnitude at once: each a small integer times its own power of two, from
// the subnormals to 2^480, so that one difference may span hundreds of binades (its rounding
// error is then tiny beside it) and products of such errors underflow. Half the time d - c is
// b - a scaled by a power of two (parallel: an exact zero to decide). The sign is the rationals'.
RC_GTEST_PROP(CrossSign, AgreesWithRationalsAtMixedMagnitudes, ()) {
  const auto coord = [] { return std::ldexp(*rc::gen::inRange(-64, 65), *rc::gen::inRange(-1074, 481)); };
  const Point a{coord(), coord()}, b{coord(), coord()}, c{coord(), coord()};
  Point d{coord(), coord()};
  if (*rc::gen::arbitrary<bool>()) {
    const int k = *rc::gen::inRange(-20, 21);
    d = {c.x + std::ldexp(b.x - a.x, k), c.y + std::ldexp(b.y - a.y, k)};
  }
  RC_PRE(std::isfinite(d.x) && std::isfinite(d.y) && std::abs(d.x) <= 0x1p500 && std::abs(d.y) <= 0x1p500);
  ExactCounters counters;
  const int exact = rationalCross(a, b, c, d);
  RC_ASSERT(static_cast<int>(crossSign(a, b, c, d, counters)) == exact);
}

// Found by the property above: the filter's error bound underflowed. (b - a) and (d - c) are
// near 2^-343 and 2^-556 with rounding errors near 2^-898, so the products of a value and an error
// (2^-1241, 2^-1451) flush to 0: the filter carried a zero bound, took the rounded determinant
// (0) for exact and said Zero for a clockwise turn.
TEST(CrossSign, AnErrorBoundThatUnderflowsDecidesNothing) {
  ExactCounters counters;
  const Point a{-0x1p-898, -0x1p-898}, b{-0x1p-556, -0x1p-343}, c{-0x1p-899, -0x1p-895}, d{-0x1p-556, -0x1p-343};
  const int exact = rationalCross(a, b, c, d);
  ASSERT_EQ(exact, -1);
  EXPECT_EQ(static_cast<int>(crossSign(a, b, c, d, counters)), exact);
  const Approx u = Approx(b.x) - Approx(a.x), v = Approx(d.y) - Approx(c.y);
  EXPECT_EQ(certainSign(u * v - Approx(u.v * v.v)), std::nullopt);
}

// Small coordinates (every point near 2^e, e down to the subnormals) are decided in doubles: the
// differences are scaled up before their products, which would otherwise underflow and send
// every such predicate to GMP. Collinear and parallel cases included.
RC_GTEST_PROP(CrossSign, DecidesSmallCoordinatesInDoubles, ()) {
  const int e = *rc::gen::inRange(-1074, -400);
  const auto coord = [e] { return std::ldexp(*rc::gen::inRange(-64, 65), e); };
  const Point a{coord(), coord()}, b{coord(), coord()}, c{coord(), coord()};
  Point d{coord(), coord()};
  if (*rc::gen::arbitrary<bool>()) d = {c.x + 2 * (b.x - a.x), c.y + 2 * (b.y - a.y)};
  ExactCounters counters;
  const int exact = rationalCross(a, b, c, d);
  RC_ASSERT(static_cast<int>(crossSign(a, b, c, d, counters)) == exact);
  RC_ASSERT(counters.filterFailures == 0u);
}

// Random turns at 2^-700 and 2^-1000 (subnormal) are decided as at 1, by Shewchuk's stage A on
// differences scaled up by a power of two: not one in a hundred goes on to a later stage (without
// the scaling every one did: the products fall below 2^-900). All agree with the rationals.
TEST(CrossSign, DecidesRandomTurnsAtSmallScalesInStageA) {
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> t(0, 1);
  for (const int e : {-700, -1000}) {
    ExactCounters counters;
    const int n = 10000;
    for (int i = 0; i < n; ++i) {
      const auto p = [&] { return Point{std::ldexp(t(rng), e), std::ldexp(t(rng), e)}; };
      const Point a = p(), b = p(), c = p(), d = p();
      const int exact = rationalCross(a, b, c, d);
      ASSERT_EQ(static_cast<int>(crossSign(a, b, c, d, counters)), exact) << e << " " << i;
    }
    EXPECT_LT(counters.expansionDecisions + counters.filterFailures, n / 100u) << "2^" << e;
  }
}

// Axis-parallel directions are decided inline: each product has a factor that is exactly 0 (two
// vertical directions, a vertical and a horizontal one...), so the sign is zero with no stage
// run. A factor of 0 in only one product decides nothing: the other product may be all there is,
// even a subnormal one.
TEST(CrossSign, ZeroFactorInEachProductIsAnExactZero) {
  ExactCounters counters;
  const double sub = std::numeric_limits<double>::denorm_min();
  EXPECT_EQ(crossSign({1, 2}, {1, 5}, {3, 4}, {3, -7}, counters), Sign::Zero);          // both vertical
  EXPECT_EQ(crossSign({1, 2}, {6, 2}, {-3, sub}, {9, sub}, counters), Sign::Zero);      // both horizontal
  EXPECT_EQ(crossSign({0, 0}, {0, 0}, {sub, 1e300}, {-1e300, sub}, counters), Sign::Zero);  // a zero direction
  EXPECT_EQ(counters.expansionDecisions + counters.filterFailures, 0u);
  const Point a{0, 0}, b{0, 1}, c{0, 0}, d{sub, 0};  // vertical against horizontal, d a subnormal away
  EXPECT_EQ(static_cast<int>(crossSign(a, b, c, d, counters)), rationalCross(a, b, c, d));
  EXPECT_EQ(crossSign(a, b, c, d, counters), Sign::Negative);
  const Point e{sub, 3}, f{sub, -2}, g{0, 0}, h{2 * sub, sub};  // ux = 0 only: (b - a) x (d - c) = 5 * 2 sub
  EXPECT_EQ(static_cast<int>(crossSign(e, f, g, h, counters)), rationalCross(e, f, g, h));
  EXPECT_EQ(crossSign(e, f, g, h, counters), Sign::Positive);
}

// A difference that spans 1000 binades (2^500 minus a subnormal) has a rounding error so small
// that its products with the other pair's errors underflow: they are bounded, not computed, and
// the sign is still decided in doubles unless the rest cancels.
TEST(CrossSign, BoundsProductsTooSmallToMakeExact) {
  ExactCounters counters;
  const double big = 0x1p500, tiny = 0x1p-1070;
  const Point a{tiny, tiny}, b{big, 3 * tiny}, c{-tiny, 5 * tiny}, d{big, big};
  const int exact = rationalCross(a, b, c, d);
  EXPECT_EQ(static_cast<int>(crossSign(a, b, c, d, counters)), exact);
  EXPECT_EQ(counters.filterFailures, 0u);
  // Everything computed cancels: what was left out could be all there is, so GMP decides. The
  // same direction twice is a zero; (2^500 + 2t)^2 - (2^500 + t)(2^500 + 3t) = t^2 is not.
  const Point e{-tiny, -tiny}, f{big, big};
  EXPECT_EQ(crossSign(e, f, e, f, counters), Sign::Zero);
  EXPECT_EQ(counters.filterFailures, 1u);
  EXPECT_EQ(crossSign({-2 * tiny, -tiny}, f, {-3 * tiny, -2 * tiny}, f, counters), Sign::Positive);
  EXPECT_EQ(counters.filterFailures, 2u);
}

// The SoS order of two crossings along an edge, term by term in rationals (sos_predicates.cpp):
// the sign of F0 + b F1 eps + c F2 eps^2, times the signs of D_M and D_N.
int rationalOrder(Point a1, Point a2, Point m1, Point m2, Point n1, Point n2, int b, int c) {
  const mpq_class mx = mpq_class(m2.x) - m1.x, my = mpq_class(m2.y) - m1.y, nx = mpq_class(n2.x) - n1.x, ny = mpq_class(n2.y) - n1.y;
  const mpq_class ax = mpq_class(a1.x) - a2.x, ay = mpq_class(a1.y) - a2.y;
  const mpq_class dM = mx * ay - my * ax, dN = nx * ay - ny * ax;
  const mpq_class aM = mx * (mpq_class(a1.y) - m1.y) - my * (mpq_class(a1.x) - m1.x);
  const mpq_class aN = nx * (mpq_class(a1.y) - n1.y) - ny * (mpq_class(a1.x) - n1.x);
  const int f0 = sgn(aM * dN - aN * dM), f1 = sgn(my * dN - ny * dM), f2 = sgn(mx * dN - nx * dM);
  const int s = f0 != 0 ? f0 : f1 != 0 ? b * f1 : c * f2;
  return s * sgn(dM) * sgn(dN);
}

// Near-grid points (grid points moved by a few ulps or by 2^-k, at any scale), three edges through
// one point v or not: the order agrees with the rationals along subject and clip edges, and a tie
// in F0 (crossings at one point, F0 exactly 0 while the filter carries rounding errors) is
// decided in doubles, not GMP, unless a coordinate is far smaller than the rest.
RC_GTEST_PROP(SoS, OrderAgreesWithRationalsOnNearGridPoints, ()) {
  const int e = *rc::gen::inRange(-1000, 480);
  const auto coord = [e] {
    double x = *rc::gen::inRange(-8, 9);
    switch (*rc::gen::inRange(0, 3)) {
      case 0: for (int k = *rc::gen::inRange(-3, 4); k != 0; k += k > 0 ? -1 : 1) x = std::nextafter(x, k > 0 ? 9.0 : -9.0); break;
      case 1: x += std::ldexp(1.0, -*rc::gen::inRange(1, 60)); break;
      default: break;
    }
    return std::ldexp(x, e);
  };
  const auto point = [&] { return Point{coord(), coord()}; };
  const Point v = point(), a = point(), m = point(), n = point();
  const bool shared = *rc::gen::arbitrary<bool>();  // M and N through v, an end of the edge
  const Point m1 = shared ? v : point(), n1 = shared ? v : point();
  RC_PRE(!(a == v) && !(m == m1) && !(n == n1));
  const bool reverse = *rc::gen::arbitrary<bool>();
  const Point a1 = reverse ? a : v, a2 = reverse ? v : a;
  ExactCounters counters;
  RC_ASSERT(sos::compareAlongSubject(a1, a2, m1, m, n1, n, counters) == rationalOrder(a1, a2, m1, m, n1, n, +1, -1));
  RC_ASSERT(sos::compareAlongClip(a1, a2, m1, m, n1, n, counters) == rationalOrder(a1, a2, m1, m, n1, n, -1, +1));
  // 0 moved by an ulp is subnormal: beside the others' ~2^e its products with rounding errors
  // underflow, and GMP decides (rightly); every other case is decided in doubles.
  bool subnormal = false;
  for (const Point& p : {a1, a2, m1, m, n1, n}) {
    for (const double x : {p.x, p.y}) subnormal |= x != 0 && std::abs(x) < std::ldexp(1.0, e - 100);
  }
  RC_ASSERT(subnormal || counters.filterFailures == 0u);
}

// The order of crossings that tend to one point (many edges through one vertex) from the eps terms
// alone, factored (sos_predicates.cpp), against the expansion evaluated term by term in rationals.
RC_GTEST_PROP(SoS, OrderAtASharedLimitAgreesWithRationals, ()) {
  auto coord = [] { return static_cast<double>(*rc::gen::inRange(-6, 7)); };
  const Point v{coord(), coord()};
  Point a{coord(), coord()}, m{coord(), coord()}, n{coord(), coord()};
  RC_PRE(!(a == v) && !(m == v) && !(n == v));
  const bool reverse = *rc::gen::arbitrary<bool>();
  const Point a1 = reverse ? a : v, a2 = reverse ? v : a;  // the edge along which we order
  // (t_M - t_N) D_M D_N = F0 + F1 eps - F2 eps^2 along a subject edge (bSign +1, cSign -1).
  const mpq_class mx = mpq_class(m.x) - v.x, my = mpq_class(m.y) - v.y, nx = mpq_class(n.x) - v.x, ny = mpq_class(n.y) - v.y;
  const mpq_class ax = mpq_class(a1.x) - a2.x, ay = mpq_class(a1.y) - a2.y;
  const mpq_class dM = mx * ay - my * ax, dN = nx * ay - ny * ax;
  RC_PRE(sgn(dM) != 0 && sgn(dN) != 0);
  const mpq_class aM = mx * (mpq_class(a1.y) - v.y) - my * (mpq_class(a1.x) - v.x);
  const mpq_class aN = nx * (mpq_class(a1.y) - v.y) - ny * (mpq_class(a1.x) - v.x);
  const int f0 = sgn(aM * dN - aN * dM), f1 = sgn(my * dN - ny * dM), f2 = -sgn(mx * dN - nx * dM);
  RC_ASSERT(f0 == 0);  // both crossings are at v
  const int expected = (f1 != 0 ? f1 : f2) * sgn(dM) * sgn(dN);
  ExactCounters counters;
  RC_ASSERT(sos::compareAlongSubject(a1, a2, v, m, v, n, counters, true) == expected);
  RC_ASSERT(sos::compareAlongSubject(a1, a2, v, m, v, n, counters, false) == expected);
}

TEST(SoS, SidesAreNeverZero) {
  const Point a{0, 0}, b{2, 0}, vertical{0, 2};
  EXPECT_NE(sos::clipEdgeSide(Sign::Zero, a, b), Sign::Zero);
  EXPECT_NE(sos::subjectEdgeSide(Sign::Zero, a, b), Sign::Zero);
  EXPECT_NE(sos::clipEdgeSide(Sign::Zero, a, vertical), Sign::Zero);
  EXPECT_NE(sos::subjectEdgeSide(Sign::Zero, a, vertical), Sign::Zero);
  // A nonzero sign is the sign: the eps terms only break ties.
  EXPECT_EQ(sos::clipEdgeSide(Sign::Negative, a, b), Sign::Negative);
}

// The exact arithmetic's pair test under SoS: collinear overlapping edges never cross (the
// translated clip edge is parallel), and a clip edge through a subject vertex crosses exactly one
// of the two subject edges there.
TEST(SoS, IdenticalEdgesDoNotCrossButShiftedOnesDo) {
  ExactCounters counters;
  const ExactArithmetic exact(counters);
  auto crosses = [&](Point p1, Point p2, Point q1, Point q2) {
    const Operand s({{p1, p2, {p1.x - 7, p1.y - 5}}}), c({{q1, q2, {q1.x + 11, q1.y - 13}}});
    Crossing crossing;
    ExactArithmetic::Extra extra;
    return exact.test(s, 0, c, 0, crossing, extra).kind == PairTest::Kind::Crossing;
  };
  EXPECT_FALSE(crosses({0, 0}, {2, 0}, {0, 0}, {2, 0}));
  EXPECT_FALSE(crosses({0, 0}, {2, 0}, {1, 0}, {3, 0}));
  EXPECT_NE(crosses({0, -1}, {0, 0}, {-1, 0}, {1, 0}), crosses({0, 0}, {0, 1}, {-1, 0}, {1, 0}));
}

// Regression: the exact fallback of the ordering predicate crashed (a gmpxx expression template
// returned from a lambda referred to the lambda's own parameters). The pentagram's tip lies
// 6e-17 off the clip line x = 0, so the order along that line needs exact arithmetic: in doubles
// at this scale; at 2^300 with the line at x = 2^-1000 (differences beyond what the doubles stage
// takes, beside a coordinate no common scaling keeps exact) in GMP, the fallback that crashed.
// Both give the rationals' order.
TEST(SoS, OrderingFallsBackToExactArithmeticSafely) {
  for (const int scale : {0, 300}) {
    ExactCounters counters;
    const auto at = [scale](Point p) { return Point{scale && p.x == 0 ? 0x1p-1000 : std::ldexp(p.x, scale), std::ldexp(p.y, scale)}; };
    const Point tip = at({6.123233995736766e-17, 1});
    const Point left = at({-0.58778525229247325, -0.80901699437494734}), right = at({0.58778525229247303, -0.80901699437494756});
    const Point q1 = at({0, 2}), q2 = at({0, -2});
    const int order = sos::compareAlongClip(q1, q2, tip, left, right, tip, counters);
    EXPECT_NE(order, 0);
    EXPECT_EQ(order, rationalOrder(q1, q2, tip, left, right, tip, -1, +1)) << scale;
    EXPECT_EQ(order, -sos::compareAlongClip(q1, q2, right, tip, tip, left, counters));
    EXPECT_GT(scale == 0 ? counters.expansionDecisions : counters.filterFailures, 0u) << scale;
    // Two clip edges through one subject vertex are ordered along the subject edge, never tied.
    EXPECT_NE(sos::compareAlongSubject(at({-1, 0}), at({1, 0}), at({0, -1}), at({0, 0}), at({0, 0}), at({1, 1}), counters), 0);
  }
}

// The one ray test: a vertex on the ray's line counts on one side only, so a ray through a vertex
// is counted once; with the SoS rules a point on an edge is decided consistently (the clip moved
// up and right).
TEST(EvenOddRay, VerticesOnTheRayCountOnce) {
  ExactCounters counters;
  const Ring diamond{{0, -1}, {1, 0}, {0, 1}, {-1, 0}};  // vertices (1,0), (-1,0) on the ray of (0,0)
  auto edges = [&diamond](auto&& visit) {
    for (std::size_t i = 0; i < diamond.size(); ++i) visit(diamond[i], diamond[(i + 1) % diamond.size()]);
  };
  EXPECT_TRUE(insideByRay(Point{0, 0}, edges, counters));
  EXPECT_FALSE(insideByRay(Point{2, 0}, edges, counters));
  EXPECT_FALSE(insideByRay(Point{-2, 0}, edges, counters));
  const Point v[] = {{0, 0}, {2, 0}, {2, 2}, {0, 2}};
  const std::uint32_t next[] = {1, 2, 3, 0};
  // A subject point on the clip's edges, the clip moved up and right: below its bottom edge and
  // left of its left edge it is outside; on its top and right edges, inside.
  EXPECT_FALSE(sos::subjectPointInsideClip({1, 0}, v, next, nullptr, 4, counters));
  EXPECT_FALSE(sos::subjectPointInsideClip({0, 1}, v, next, nullptr, 4, counters));
  EXPECT_TRUE(sos::subjectPointInsideClip({1, 2}, v, next, nullptr, 4, counters));
  EXPECT_TRUE(sos::subjectPointInsideClip({2, 1}, v, next, nullptr, 4, counters));
  // A clip point on the subject's bottom edge, moved up: inside; on its top edge: outside.
  EXPECT_TRUE(sos::clipPointInsideSubject({1, 0}, v, next, nullptr, 4, counters));
  EXPECT_FALSE(sos::clipPointInsideSubject({1, 2}, v, next, nullptr, 4, counters));
  // On the left edge, moved right: inside; on the right edge: outside.
  EXPECT_TRUE(sos::clipPointInsideSubject({0, 1}, v, next, nullptr, 4, counters));
  EXPECT_FALSE(sos::clipPointInsideSubject({2, 1}, v, next, nullptr, 4, counters));
}

TEST(SegmentMeeting, EveryKindOfContact) {
  ExactCounters c;
  EXPECT_EQ(meeting({0, 0}, {2, 2}, {0, 2}, {2, 0}, c), Meeting::Crossing);
  EXPECT_EQ(meeting({0, 0}, {2, 2}, {3, 0}, {3, 3}, c), Meeting::Disjoint);
  EXPECT_EQ(meeting({0, 0}, {2, 0}, {1, 0}, {1, 1}, c), Meeting::Touching);  // endpoint on the other
  EXPECT_EQ(meeting({0, 0}, {2, 0}, {2, 0}, {3, 1}, c), Meeting::Touching);  // shared endpoint
  EXPECT_EQ(meeting({0, 0}, {2, 0}, {1, 0}, {3, 0}, c), Meeting::Touching);  // collinear overlap
  EXPECT_EQ(meeting({0, 0}, {1, 0}, {2, 0}, {3, 0}, c), Meeting::Disjoint);  // collinear, apart
  // 2^-60 above an edge is not on it.
  EXPECT_EQ(meeting({0, 0}, {1, 0}, {0.5, std::ldexp(1.0, -60)}, {0.5, 1}, c), Meeting::Disjoint);
}

}  // namespace
}  // namespace gh::detail
