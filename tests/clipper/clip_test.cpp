// The public entry point (clip.h, options.h): the hand-checked cases of tests/data/hand_cases.txt
// through every operation of every combination of arithmetic and search, the two axes and their
// names, the default (exact), and inputs at the ends of the double range judged by every judge.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "common/hand_cases.h"
#include "ghclip/clip.h"
#include "ghclip/errors.h"
#include "ghclip/measure.h"
#include "ghoracle/exact_oracle.h"
#include "ghoracle/invariants.h"
#include "ghoracle/sampling_oracle.h"
#include "ghwork/generators.h"

namespace gh {
namespace {

using test::HandCase;

void expectNear(double actual, double expected, const std::string& what) {
  const double tolerance = 1e-9 * std::max(1.0, std::abs(expected));
  EXPECT_NEAR(actual, expected, tolerance) << what;
}

struct CaseParam {
  HandCase c;
  Options options;
};

void PrintTo(const CaseParam& p, std::ostream* os) { *os << p.c.name << " (" << name(p.options) << ")"; }

class HandCaseTest : public testing::TestWithParam<CaseParam> {};

TEST_P(HandCaseTest, EveryOperationGivesTheHandComputedArea) {
  const HandCase& c = GetParam().c;
  expectNear(evenOddArea(c.subject), c.areaSubject, "subject area");
  expectNear(evenOddArea(c.clip), c.areaClip, "clip area");
  for (int k = 0; k < 5; ++k) {
    const Op op = kAllOps[k];
    const Region r = clip(c.subject, c.clip, op, GetParam().options);
    expectNear(evenOddArea(r), c.expected[k], std::string(name(op)));
    for (const Ring& ring : r) {
      EXPECT_GE(ring.size(), 3u);
      for (std::size_t i = 0; i < ring.size(); ++i) {
        EXPECT_NE(ring[i], ring[(i + 1) % ring.size()]) << "zero-length edge in " << name(op);
      }
    }
  }
}

TEST_P(HandCaseTest, IntersectionPlusUnionEqualsSubjectPlusClip) {
  const HandCase& c = GetParam().c;
  const double both = evenOddArea(clip(c.subject, c.clip, Op::Intersection, GetParam().options));
  const double either = evenOddArea(clip(c.subject, c.clip, Op::Union, GetParam().options));
  expectNear(both + either, evenOddArea(c.subject) + evenOddArea(c.clip), "identity");
}

TEST_P(HandCaseTest, SwappingOperandsSwapsTheDifferences) {
  const HandCase& c = GetParam().c;
  expectNear(evenOddArea(clip(c.clip, c.subject, Op::Difference, GetParam().options)), c.expected[3],
             "C \\ S via swapped operands");
  expectNear(evenOddArea(clip(c.clip, c.subject, Op::Intersection, GetParam().options)), c.expected[0], "C n S");
}

// Every combination of the two axes.
std::vector<Options> everyCombination() {
  std::vector<Options> out;
  for (Arithmetic a : {Arithmetic::Exact, Arithmetic::Paper}) {
    for (Search s : {Search::Auto, Search::AllPairs, Search::Sweep}) {
      Options o;
      o.arithmetic = a, o.search = s;
      out.push_back(o);
    }
  }
  return out;
}

std::vector<CaseParam> params() {
  std::vector<CaseParam> out;
  for (const Options& o : everyCombination()) {
    for (const HandCase& c : test::handCases()) out.push_back({c, o});
  }
  return out;
}

INSTANTIATE_TEST_SUITE_P(Hand, HandCaseTest, testing::ValuesIn(params()),
                         [](const testing::TestParamInfo<CaseParam>& info) {
                           std::string n = std::string(name(info.param.options.arithmetic)) + "_" +
                                           std::string(name(info.param.options.search)) + "_" + info.param.c.name;
                           for (char& ch : n) {
                             if (ch == '-') ch = '_';
                           }
                           return n;
                         });

// The default options are exact: the hand cases' ring counts hold as worked out (no slivers left
// by perturbation), and a region minus itself is empty, exactly.
TEST(Defaults, AreTheExactArithmetic) {
  EXPECT_EQ(Options{}.arithmetic, Arithmetic::Exact);
  EXPECT_EQ(Options{}.search, Search::Auto);
  EXPECT_EQ(name(Options{}), "exact");
  int checked = 0;
  for (const HandCase& c : test::handCases()) {
    if (c.intersectionRings < 0) continue;  // count not worked out for this case
    EXPECT_EQ(static_cast<int>(clip(c.subject, c.clip, Op::Intersection).size()), c.intersectionRings) << c.name;
    ++checked;
  }
  EXPECT_GE(checked, 5);
  const HandCase& square = test::handCase("identical");
  EXPECT_TRUE(clip(square.subject, square.subject, Op::Difference).empty());
  // The paper arithmetic leaves a sliver there: the default is not it.
  Options paper;
  paper.arithmetic = Arithmetic::Paper;
  const Region sliver = clip(square.subject, square.subject, Op::Difference, paper);
  EXPECT_GT(evenOddArea(sliver), 0);
}

// The named combinations map onto the two axes and back.
TEST(Options, NamesOfCombinations) {
  EXPECT_EQ(optionsOf(Variant::Naive).arithmetic, Arithmetic::Paper);
  EXPECT_EQ(optionsOf(Variant::Naive).search, Search::AllPairs);
  EXPECT_EQ(optionsOf(Variant::Sweep).search, Search::Sweep);
  EXPECT_EQ(optionsOf(Variant::Exact).arithmetic, Arithmetic::Exact);
  for (Variant v : kAllVariants) {
    EXPECT_EQ(name(optionsOf(v)), name(v));
    EXPECT_EQ(parseVariant(name(v)), v);
  }
  for (const Options& o : everyCombination()) {
    const auto back = parseOptions(name(o));
    ASSERT_TRUE(back.has_value()) << name(o);
    EXPECT_EQ(name(*back), name(o));
    EXPECT_EQ(back->arithmetic, o.arithmetic);
  }
  EXPECT_EQ(name(*parseOptions("exact-allpairs")), "exact-allpairs");
  EXPECT_EQ(parseOptions("exact-allpairs")->search, Search::AllPairs);
  EXPECT_FALSE(parseOptions("fast").has_value());
  EXPECT_EQ(parseArithmetic("paper"), Arithmetic::Paper);
  EXPECT_EQ(parseSearch("all-pairs"), Search::AllPairs);
  EXPECT_FALSE(parseSearch("allpairs").has_value());
}

// Search::Auto with the exact arithmetic: all pairs where nearly every pair of edge boxes overlaps
// (the paper's random workload: the sweep would only add bookkeeping), the sweep where edges are
// short against the extent (two circles: the sweep skips almost every pair). The paper arithmetic
// tests all pairs, as in the paper.
TEST(Options, AutoSearchTestsAllPairsOnRandomPolygonsAndSweepsCircles) {
  Stats stats;
  const work::Workload random = work::generate("random", 100, 1);
  clip(random.subject, random.clip, Op::Intersection, {}, &stats);
  EXPECT_EQ(stats.candidatePairs, 100u * 100u);
  const work::Workload circles = work::generate("circles", 1000, 1);
  clip(circles.subject, circles.clip, Op::Intersection, {}, &stats);
  EXPECT_LT(stats.candidatePairs, 1000u * 1000u / 50);
  Options paper;
  paper.arithmetic = Arithmetic::Paper;
  clip(circles.subject, circles.clip, Op::Intersection, paper, &stats);
  EXPECT_EQ(stats.candidatePairs, 1000u * 1000u);
}

// The region with every coordinate times 2^k (exact while nothing over- or underflows).
Region scaledBy(Region r, int k) {
  for (Ring& ring : r) {
    for (Point& p : ring) p = {std::ldexp(p.x, k), std::ldexp(p.y, k)};
  }
  return r;
}

// The exact stages past the filter are counted: the pentagram's tip lies 6e-17 off the clip's
// edge x = 0, and ordering the crossings along that edge needs exact arithmetic, in doubles at
// this scale (or scaled down from 2^300), in rationals (GMP) at 2^300 with that edge moved to
// x = 2^-1000: differences beyond 2^240 beside a coordinate no common scaling keeps exact, where
// the doubles stage does not go. (Clean-up's own fallbacks: tests/clipper/cleanup_test.cpp.)
TEST(Stats, CountTheExactFallbacks) {
  const HandCase& c = test::handCase("pentagram_half_square");
  Stats stats;
  clip(c.subject, c.clip, Op::Intersection, {}, &stats);
  EXPECT_GT(stats.expansionDecisions, 0u);
  EXPECT_EQ(stats.filterFailures, 0u);
  const Region farSubject = scaledBy(c.subject, 300), farClip = scaledBy(c.clip, 300);
  Stats far;
  clip(farSubject, farClip, Op::Intersection, {}, &far);
  EXPECT_GT(far.expansionDecisions, 0u);
  EXPECT_EQ(far.filterFailures, 0u);
  Region mixedClip = farClip;
  for (Ring& ring : mixedClip) {
    for (Point& p : ring) {
      if (p.x == 0) p.x = 0x1p-1000;
    }
  }
  Stats mixed;
  clip(farSubject, mixedClip, Op::Intersection, {}, &mixed);
  EXPECT_GT(mixed.filterFailures, 0u);
  Stats paper;
  clip(c.subject, c.clip, Op::Intersection, optionsOf(Variant::Naive), &paper);
  EXPECT_EQ(paper.filterFailures + paper.expansionDecisions, 0u);
}

// The exact arithmetic at 2^-900 and 2^400 works as at 1: the problem scaled by a power of two
// takes the same decisions at the same stages (points far from 1 are scaled back towards it
// before the filters, difference_products.h), so as many predicates pass the filter and none more
// need GMP, and the answer is the unit-scale answer scaled, vertex for vertex. (Before, every
// predicate near 1e-300 went to GMP: a 1000-gon pair took 130 s instead of 0.1 s.)
TEST(Scale, FarFromOneTheExactArithmeticDecidesAsAtOne) {
  const std::pair<const char*, std::size_t> cases[] = {{"random", 60}, {"grid", 60}, {"pie", 40}, {"bitset-grid", 60}, {"flower", 60}};
  for (const auto& [workload, n] : cases) {
    const work::Workload w = work::generate(workload, n, 5);
    for (const int k : {-900, 400}) {
      for (Op op : {Op::Intersection, Op::Union}) {
        Stats unit, far;
        const Region a = clip(w.subject, w.clip, op, {}, &unit);
        const Region b = clip(scaledBy(w.subject, k), scaledBy(w.clip, k), op, {}, &far);
        EXPECT_EQ(far.expansionDecisions, unit.expansionDecisions) << workload << " 2^" << k;
        EXPECT_EQ(far.filterFailures, unit.filterFailures) << workload << " 2^" << k;
        EXPECT_EQ(scaledBy(b, -k), a) << workload << " 2^" << k;
      }
    }
  }
}

// Threads split phases 1, 2 and 3 into pieces; the answer must be the one-thread answer, bit for
// bit, for both arithmetics and every operation, on inputs large enough to be split.
TEST(Threads, SameAnswerOnEveryNumberOfThreads) {
  const std::pair<const char*, std::size_t> cases[] = {
      {"random", 600}, {"circles", 40000}, {"archipelago", 40000}, {"pie", 200}, {"bitset-grid", 400}};
  for (const auto& [workload, n] : cases) {
    const work::Workload w = work::generate(workload, n, 3);
    for (Arithmetic a : {Arithmetic::Exact, Arithmetic::Paper}) {
      for (Op op : kAllOps) {
        Options one, four;
        one.arithmetic = four.arithmetic = a;
        four.threads = 4;
        Region r1, r4;
        try {
          r1 = clip(w.subject, w.clip, op, one);
        } catch (const ClipFailure&) {
          EXPECT_THROW(clip(w.subject, w.clip, op, four), ClipFailure);
          continue;
        }
        r4 = clip(w.subject, w.clip, op, four);
        EXPECT_EQ(r1.size(), r4.size()) << workload << " " << name(op) << " " << name(a);
        EXPECT_TRUE(r1 == r4) << workload << " " << name(op) << " " << name(a);
      }
    }
  }
}

Region square(double x0, double y0, double size) {
  return {{{x0, y0}, {x0 + size, y0}, {x0 + size, y0 + size}, {x0, y0 + size}}};
}
Region kite(double s) { return {{{2 * s, 1 * s}, {6 * s, 2 * s}, {6 * s, 6 * s}, {1 * s, 5 * s}}}; }

// Every operation of the exact arithmetic on a square and a kite at scale s, judged by all three
// judges. Findings of the fuzz campaign of 2026-11-22 and after: subnormal scales crashed (NaN
// crossing points reached GMP), 1e-300 scales gave points computed from underflowed products,
// and the judges' own floating-point measures underflowed (areas) or overflowed (tolerances).
void expectExactEverywhere(double s) {
  const Region a = square(0, 0, 4 * s), b = kite(s);
  for (Op op : kAllOps) {
    SCOPED_TRACE(std::string(name(op)) + " at scale " + std::to_string(std::log2(s)));
    const Region r = clip(a, b, op);
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

}  // namespace
}  // namespace gh
