// The exact predicates: the filter decides exact computations without GMP, the fallback agrees
// with an independent rational computation, and the SoS expansions never return zero.
#include <gtest/gtest.h>
#include <gmpxx.h>
#include <rapidcheck/gtest.h>

#include <random>

#include "approx.h"
#include "orientation.h"
#include "sos_predicates.h"

namespace gh::detail {
namespace {

int rationalOrientation(Point a, Point b, Point c) {
  const mpq_class det = (mpq_class(b.x) - a.x) * (mpq_class(c.y) - a.y) - (mpq_class(b.y) - a.y) * (mpq_class(c.x) - a.x);
  return sgn(det);
}

TEST(Approx, ExactComputationsCarryNoError) {
  const Approx d = (Approx(3) - Approx(1)) * (Approx(7) - Approx(2)) - Approx(10);
  EXPECT_EQ(d.e, 0);
  EXPECT_EQ(certainSign(d), 0);  // a certain zero, no fallback needed
  const Approx t = Approx(0.1) * Approx(0.3);
  EXPECT_GT(t.e, 0);
  EXPECT_EQ(certainSign(Approx(1e-300) * Approx(1e-300)), 2);  // underflow: undecided
}

// Near-collinear points on a 2^-43 grid around a line: the classic failure of double orientation.
TEST(Orientation, AgreesWithRationalsOnNearCollinearFixtures) {
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<int> k(-64, 64);
  int fallbacks = 0;
  for (int i = 0; i < 20000; ++i) {
    const double h = std::ldexp(1.0, -43);
    const Point a{0.5 + k(rng) * h, 0.5 + k(rng) * h}, b{12 + k(rng) * h, 12 + k(rng) * h}, c{24 + k(rng) * h, 24 + k(rng) * h};
    const std::uint64_t before = exactFallbacks();
    EXPECT_EQ(static_cast<int>(orientation(a, b, c)), rationalOrientation(a, b, c)) << i;
    fallbacks += static_cast<int>(exactFallbacks() - before);
  }
  EXPECT_GT(fallbacks, 0);  // the fixture does reach the exact stage
}

TEST(SoS, SidesAreNeverZero) {
  const Point a{0, 0}, b{2, 0}, on{1, 0};
  EXPECT_NE(sos::clipEdgeSide(a, b, on), Sign::Zero);
  EXPECT_NE(sos::subjectEdgeSide(a, b, on), Sign::Zero);
  EXPECT_NE(sos::clipEdgeSide(a, a == b ? b : Point{0, 2}, a), Sign::Zero);
}

TEST(SoS, IdenticalEdgesDoNotCrossButShiftedOnesDo) {
  // Collinear overlapping edges never cross: the translated clip edge is parallel.
  EXPECT_FALSE(sos::cross({0, 0}, {2, 0}, {0, 0}, {2, 0}));
  EXPECT_FALSE(sos::cross({0, 0}, {2, 0}, {1, 0}, {3, 0}));
  // A clip edge through a subject vertex crosses one of the two subject edges there, not both.
  const bool first = sos::cross({0, -1}, {0, 0}, {-1, 0}, {1, 0});
  const bool second = sos::cross({0, 0}, {0, 1}, {-1, 0}, {1, 0});
  EXPECT_NE(first, second);
}

// Regression: the exact fallback of the ordering predicate crashed (a gmpxx expression template
// returned from a lambda referred to the lambda's own parameters). The pentagram's tip lies
// 6e-17 off the clip line x = 0, so the order along that line needs exact arithmetic.
TEST(SoS, OrderingFallsBackToExactArithmeticSafely) {
  const Point tip{6.123233995736766e-17, 1};
  const Point left{-0.58778525229247325, -0.80901699437494734}, right{0.58778525229247303, -0.80901699437494756};
  const Point q1{0, 2}, q2{0, -2};
  const std::uint64_t before = exactFallbacks();
  const int order = sos::compareAlongClip(q1, q2, tip, left, right, tip);
  EXPECT_NE(order, 0);
  EXPECT_EQ(order, -sos::compareAlongClip(q1, q2, right, tip, tip, left));
  EXPECT_GE(exactFallbacks(), before);
  // Two clip edges through one subject vertex are ordered along the subject edge, never tied.
  EXPECT_NE(sos::compareAlongSubject({-1, 0}, {1, 0}, {0, -1}, {0, 0}, {0, 0}, {1, 1}), 0);
}

// Found by the OGC conversion test at 2^-540: between 2^-900 and ~2^-537 the differences of
// coordinates are "safe" for the filter but their products underflow to exactly 0, which the
// running error bound took for an exact zero: orientation() said Zero for a plain right turn.
TEST(Orientation, ProductsThatUnderflowToZeroAreNotExactZeros) {
  for (int e : {-300, -540, -600, -700, -1000}) {
    const double s = std::ldexp(1.0, e);
    EXPECT_EQ(orientation({4 * s, 4 * s}, {6 * s, 4 * s}, {6 * s, 6 * s}), Sign::Positive) << "2^" << e;
    EXPECT_EQ(orientation({4 * s, 4 * s}, {6 * s, 6 * s}, {6 * s, 4 * s}), Sign::Negative) << "2^" << e;
    EXPECT_EQ(orientation({4 * s, 4 * s}, {6 * s, 6 * s}, {8 * s, 8 * s}), Sign::Zero) << "2^" << e;
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
  RC_ASSERT(static_cast<int>(orientation(a, b, c)) == rationalOrientation(a, b, c));
}

}  // namespace
}  // namespace gh::detail
