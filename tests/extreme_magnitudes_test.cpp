// Inputs at the ends of the double range: the exact variant must stay exact there, and the judges
// must judge there. Each case was a finding (the fuzz campaign of 2026-11-22, and what followed
// from it); see fuzz/regressions/ for the fuzzers' own reproducers.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "ghclip/clip.h"
#include "ghio/formats.h"
#include "ghoracle/exact_oracle.h"
#include "ghoracle/invariants.h"
#include "ghoracle/sampling_oracle.h"

namespace gh {
namespace {

Region square(double x0, double y0, double size) {
  return {{{x0, y0}, {x0 + size, y0}, {x0 + size, y0 + size}, {x0, y0 + size}}};
}
Region kite(double s) { return {{{2 * s, 1 * s}, {6 * s, 2 * s}, {6 * s, 6 * s}, {1 * s, 5 * s}}}; }

// Every operation of the exact variant on a square and a kite at scale s, judged by all three
// judges. Subnormal scales used to crash (NaN crossing points reached GMP), 1e-300 scales gave
// points computed from underflowed products, and the judges' own floating-point measures
// underflowed (areas) or overflowed (tolerances) at either end.
void expectExactEverywhere(double s) {
  const Region a = square(0, 0, 4 * s), b = kite(s);
  Options o;
  o.variant = Variant::Exact;
  for (Op op : kAllOps) {
    SCOPED_TRACE(std::string(name(op)) + " at scale " + std::to_string(std::log2(s)));
    const Region r = clip(a, b, op, o);
    EXPECT_TRUE(oracle::exactCheck(a, b, op, r).pass);
    EXPECT_TRUE(oracle::sampleCheck(a, b, op, r).pass());
    EXPECT_TRUE(oracle::invariantViolations(a, b, op, r).empty());
  }
}

TEST(ExtremeMagnitudes, SubnormalCoordinates) { expectExactEverywhere(std::numeric_limits<double>::denorm_min() * 2); }
TEST(ExtremeMagnitudes, TinyCoordinates) { expectExactEverywhere(1e-300); }
// Differences near 2^-540: products underflow to exactly 0 (see Orientation.ProductsThatUnderflow...).
TEST(ExtremeMagnitudes, CoordinatesWhoseProductsUnderflow) {
  expectExactEverywhere(std::ldexp(1.0, -540));
  expectExactEverywhere(std::ldexp(1.0, -620));
}
// The library accepts |coordinates| up to 2^500 (~3.3e150): squares of them still fit a double.
TEST(ExtremeMagnitudes, HugeCoordinates) { expectExactEverywhere(1e149); }

// fuzz_clip_exact_oracle: the exact answer is a sliver whose constructed vertices, rounded to the
// nearest doubles, all lie on one line; the rounded ring bounds nothing and is dropped. That is a
// rounding-level error: the tolerance must count the exact answer's constructed vertices, not
// only the result's (there are none).
TEST(ExtremeMagnitudes, AnswerFlattenedByRoundingIsWithinTolerance) {
  const Region s = io::readWkt("MULTIPOLYGON(((0 0,0 4,3 5,0 2.0000000000000013,0 0)))");
  const Region c = io::readWkt(
      "MULTIPOLYGON(((0 2,4.0000000000001137 0,1 0,5 3,3 3,3 2,4 -9.8813129168249309e-324,0 2)),"
      "((0 4,4.9406564584124654e-324 0,0 0,0 0,0 0,0 4)))");
  Options o;
  o.variant = Variant::Exact;
  const Region r = clip(s, c, Op::Intersection, o);
  const auto v = oracle::exactCheck(s, c, Op::Intersection, r);
  EXPECT_NE(v.errorAreaExact, "0");  // not exactly right: the answer has area ~2.5e-323
  EXPECT_TRUE(v.pass);
  // A real error of that size still fails: drop the answer of a normal-sized problem.
  const Region big = square(0, 0, 1);
  EXPECT_FALSE(oracle::exactCheck(big, big, Op::Intersection, {}).pass);
}

// fuzz_clip_exact: areas of ~1e-323 measured in doubles are off by denormals; the union
// invariant must allow for the measurement's own error.
TEST(ExtremeMagnitudes, InvariantsAllowForDenormalAreaMeasurement) {
  const Region s = io::readWkt(
      "MULTIPOLYGON(((4.0000000000001137 5,-9.8813129168249309e-324 0,0 0,0 0,0 0,0 0,0.5 0.5,0 0,0 0,0 0,"
      "0 -1.4821969375237396e-323,0 3,0 1,0 0,4.0000000000001137 5)),((0 -1.4821969375237396e-323,0 0,"
      "2.001953125 0,0 -1.4821969375237396e-323)))");
  Options o;
  o.variant = Variant::Exact;
  const Region r = clip(s, {}, Op::Union, o);
  EXPECT_TRUE(oracle::exactCheck(s, {}, Op::Union, r).pass);
  EXPECT_TRUE(oracle::invariantViolations(s, {}, Op::Union, r).empty());
}

}  // namespace
}  // namespace gh
