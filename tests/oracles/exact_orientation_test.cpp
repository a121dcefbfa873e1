// The judges' orientation against the plain rational determinant (GMP's mpq, no filter, no
// shortcut) on inputs built to reach each of its stages: the double filter, the exact-double
// comparison of collinear grid points, the exact expansions of doubles (points ulps off the grid
// or off a line), and the integer stage (huge and subnormal coordinates, differences that
// overflow, products that underflow).
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "ghoracle/exact_orientation.h"
#include "rational_orientation.h"

namespace gh::oracle {
namespace {

// (b - a) x (p - a) in rationals.
mpq_class rationalDeterminant(Point a, Point b, Point p) {
  const mpq_class ax(a.x), ay(a.y), bx(b.x), by(b.y), px(p.x), py(p.y);
  return (bx - ax) * (py - ay) - (by - ay) * (px - ax);
}

int rationalOrientation(Point a, Point b, Point p) { return sgn(rationalDeterminant(a, b, p)); }

// A coordinate from a family chosen by the generator: grid integers, grid values moved by an
// ulp or by 2^-k, halves and quarters of huge and tiny powers of two, subnormals, and raw random
// doubles across the whole exponent range.
double coordinate(std::mt19937_64& rng) {
  std::uniform_int_distribution<int> family(0, 6), small(-4, 4), bit(1, 60);
  const double base = small(rng);
  switch (family(rng)) {
    case 0: return base;
    case 1: return std::nextafter(base, small(rng) > 0 ? 10.0 : -10.0);
    case 2: return base + std::ldexp(1.0, -bit(rng));
    case 3: return base * std::ldexp(1.0, 1000);
    case 4: return base * std::ldexp(1.0, -1000);
    case 5: return base * std::numeric_limits<double>::denorm_min() * (1 + bit(rng));
    default: {
      std::uniform_real_distribution<double> mantissa(-1, 1);
      std::uniform_int_distribution<int> exponent(-1074, 1023);
      return std::ldexp(mantissa(rng), exponent(rng));
    }
  }
}

// Three points a, b, p (case i of a run): from the coordinate families, and every third time p on
// the line through a and b, or an ulp off it, where the filter gives up. False when p is not finite
// (the judges see finite points only).
bool triple(std::mt19937_64& rng, int i, Point& a, Point& b, Point& p) {
  a = {coordinate(rng), coordinate(rng)}, b = {coordinate(rng), coordinate(rng)};
  p = {coordinate(rng), coordinate(rng)};
  if (i % 3 == 0) {
    const double t = std::uniform_int_distribution<int>(-3, 3)(rng) * 0.5;
    p = {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
    if (i % 2 == 0) p.y = std::nextafter(p.y, 1e300);
  }
  return std::isfinite(p.x) && std::isfinite(p.y);
}

std::string describe(Point a, Point b, Point p) {
  std::ostringstream s;
  s << std::hexfloat << "a=(" << a.x << ", " << a.y << ") b=(" << b.x << ", " << b.y << ") p=(" << p.x << ", " << p.y
    << ")";
  return s.str();
}

TEST(ExactOrientation, AgreesWithTheRationalDeterminantOnEveryStage) {
  std::mt19937_64 rng(20261124);
  int zeros = 0, nonzeros = 0;
  for (int i = 0; i < 200000; ++i) {
    Point a, b, p;
    if (!triple(rng, i, a, b, p)) continue;
    const int expected = rationalOrientation(a, b, p);
    ASSERT_EQ(orientation(a, b, p), expected) << describe(a, b, p);
    (expected == 0 ? zeros : nonzeros) += 1;
  }
  // Both answers were reached often: the test says something about the exact stages.
  EXPECT_GT(zeros, 5000);
  EXPECT_GT(nonzeros, 10000);
}

// |(b - a) x (p - a)| <= bound against the rationals, with bounds at the determinant itself, an
// ulp either side of it, far above and below, zero and subnormal, on the same inputs.
// A rational point against a line through doubles (the exact oracle's zone edges): on the line
// at rational parameters, a tiny rational step off it either way, and anywhere; coordinates from
// every family, so that a and b lie over very different powers of two.
TEST(ExactOrientation, RationalPointAgreesWithTheRationalDeterminant) {
  std::mt19937_64 rng(20261127);
  std::uniform_int_distribution<int> numerator(-7, 7), denominator(1, 9), kind(0, 2);
  int zeros = 0, lefts = 0, rights = 0;
  for (int i = 0; i < 50000; ++i) {
    Point a, b, q;
    if (!triple(rng, i, a, b, q)) continue;
    const mpq_class ax(a.x), ay(a.y), bx(b.x), by(b.y);
    const mpq_class t(numerator(rng), denominator(rng));
    mpq_class px = ax + t * (bx - ax), py = ay + t * (by - ay);
    switch (kind(rng)) {
      case 0: break;  // on the line
      case 1: py += mpq_class(numerator(rng), 1) * mpq_class(q.y) / mpq_class(denominator(rng)) / 1024; break;
      default: px = mpq_class(q.x) / denominator(rng), py = mpq_class(q.y) / denominator(rng); break;
    }
    px.canonicalize(), py.canonicalize();
    const int expected = sgn(mpq_class((bx - ax) * (py - ay) - (by - ay) * (px - ax)));
    ASSERT_EQ(orientationOfRational(a, b, px.get_mpq_t(), py.get_mpq_t()), expected) << describe(a, b, q) << " " << px << " " << py;
    (expected == 0 ? zeros : expected > 0 ? lefts : rights) += 1;
  }
  EXPECT_GT(zeros, 5000);
  EXPECT_GT(lefts, 5000);
  EXPECT_GT(rights, 5000);
}

TEST(ExactOrientation, CrossAtMostAgreesWithTheRationalDeterminant) {
  std::mt19937_64 rng(20261126);
  int within = 0, beyond = 0;
  for (int i = 0; i < 100000; ++i) {
    Point a, b, p;
    if (!triple(rng, i, a, b, p)) continue;
    const mpq_class cross = abs(rationalDeterminant(a, b, p));
    const double near = cross.get_d();  // within an ulp of the exact value
    const double bounds[] = {near, std::nextafter(near, 0.0), std::nextafter(near, 1e308), 2 * near, near / 2, 0.0,
                             std::numeric_limits<double>::denorm_min(), std::numeric_limits<double>::max()};
    for (double bound : bounds) {
      if (!std::isfinite(bound) || bound < 0) continue;
      const bool expected = cross <= mpq_class(bound);
      ASSERT_EQ(crossAtMost(a, b, p, bound), expected) << describe(a, b, p) << " bound " << std::hexfloat << bound;
      (expected ? within : beyond) += 1;
    }
  }
  EXPECT_GT(within, 50000);
  EXPECT_GT(beyond, 50000);
}

// Points a few ulps off a line through points off the grid, so that neither the filter nor the
// exact-double comparison decides: the expansion stage's work, at scales across its range
// ([2^-480, 2^500]) and just beyond it on either side (the integer stage's), against the rationals.
TEST(ExactOrientation, NearlyCollinearPointsOffTheGridAtEveryScale) {
  std::mt19937_64 rng(20261128);
  std::uniform_real_distribution<double> unit(-1, 1);
  std::uniform_int_distribution<int> ulps(-2, 2), step(-4, 4);
  const int scales[] = {-532, -481, -480, -479, -300, -60, 0, 60, 300, 499, 500, 501, 520};
  int zeros = 0, nonzeros = 0;
  for (int scale : scales) {
    for (int i = 0; i < 4000; ++i) {
      const Point a{std::ldexp(unit(rng), scale), std::ldexp(unit(rng), scale)};
      const Point b{std::ldexp(unit(rng), scale), std::ldexp(unit(rng), scale)};
      const double t = step(rng) / 4.0;
      Point p{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
      for (int k = ulps(rng); k != 0; k += k > 0 ? -1 : 1) p.y = std::nextafter(p.y, k > 0 ? 1e308 : -1e308);
      if (!std::isfinite(p.x) || !std::isfinite(p.y)) continue;
      const int expected = rationalOrientation(a, b, p);
      ASSERT_EQ(orientation(a, b, p), expected) << "scale 2^" << scale << " " << describe(a, b, p);
      (expected == 0 ? zeros : nonzeros) += 1;
      const mpq_class cross = abs(rationalDeterminant(a, b, p));
      const double near = cross.get_d();
      for (double bound : {near, std::nextafter(near, 0.0), std::nextafter(near, 1e308)}) {
        ASSERT_EQ(crossAtMost(a, b, p, bound), cross <= mpq_class(bound)) << describe(a, b, p) << " bound " << std::hexfloat << bound;
      }
    }
  }
  EXPECT_GT(zeros, 1000);
  EXPECT_GT(nonzeros, 20000);
}

TEST(ExactOrientation, CasesNearTheStagesLimits) {
  const double tiny = std::numeric_limits<double>::denorm_min(), big = std::numeric_limits<double>::max();
  const std::vector<std::array<Point, 3>> cases = {
      {{{0, 0}, {1, 1}, {2, 2}}},                                        // collinear on the grid
      {{{0, 0}, {3, 1}, {6, std::nextafter(2.0, 3.0)}}},                  // an ulp off the line
      {{{0, 0}, {0x1p-500, 0x1p-500}, {0x1p-450, 0x1p-450}}},             // products below 2^-900
      {{{0, 0}, {0x1p-540, 0x1p-530}, {0x1p-530, 0x1p-540}}},             // they underflow to zero
      {{{0, 0}, {tiny, tiny}, {2 * tiny, 3 * tiny}}},                     // subnormal coordinates
      {{{-big, -big}, {big, big}, {0, 0}}},                               // differences overflow
      {{{-big, 0}, {big, 0}, {0, tiny}}},                                 // both at once
      {{{1e300, 1e-300}, {-1e300, 1e300}, {1e-300, -1e300}}},             // 2,000 bits of range
      {{{0, 0}, {0, 0}, {0, 0}}},
  };
  for (const auto& [a, b, p] : cases) {
    EXPECT_EQ(orientation(a, b, p), rationalOrientation(a, b, p)) << describe(a, b, p);
  }
}

}  // namespace
}  // namespace gh::oracle
