// The hand-checked cases through every operation of every implemented variant.
#include <gtest/gtest.h>

#include <cmath>

#include "ghclip/clip.h"
#include "ghclip/measure.h"
#include "ghwork/generators.h"
#include "hand_cases.h"

namespace gh {
namespace {

using test::HandCase;

void expectNear(double actual, double expected, const std::string& what) {
  const double tolerance = 1e-9 * std::max(1.0, std::abs(expected));
  EXPECT_NEAR(actual, expected, tolerance) << what;
}

struct CaseParam {
  HandCase c;
  Variant variant;
};

void PrintTo(const CaseParam& p, std::ostream* os) {
  *os << p.c.name << " (" << name(p.variant) << ")";
}

class HandCaseTest : public testing::TestWithParam<CaseParam> {};

TEST_P(HandCaseTest, EveryOperationGivesTheHandComputedArea) {
  const HandCase& c = GetParam().c;
  Options options;
  options.variant = GetParam().variant;
  expectNear(evenOddArea(c.subject), c.areaSubject, "subject area");
  expectNear(evenOddArea(c.clip), c.areaClip, "clip area");
  for (int k = 0; k < 5; ++k) {
    const Op op = kAllOps[k];
    const Region r = clip(c.subject, c.clip, op, options);
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
  Options options;
  options.variant = GetParam().variant;
  const double both = evenOddArea(clip(c.subject, c.clip, Op::Intersection, options));
  const double either = evenOddArea(clip(c.subject, c.clip, Op::Union, options));
  expectNear(both + either, evenOddArea(c.subject) + evenOddArea(c.clip), "identity");
}

TEST_P(HandCaseTest, SwappingOperandsSwapsTheDifferences) {
  const HandCase& c = GetParam().c;
  Options options;
  options.variant = GetParam().variant;
  expectNear(evenOddArea(clip(c.clip, c.subject, Op::Difference, options)), c.expected[3],
             "C \\ S via swapped operands");
  expectNear(evenOddArea(clip(c.clip, c.subject, Op::Intersection, options)), c.expected[0],
             "C n S");
}

TEST(HandCases, IntersectionsHaveTheExpectedRingCounts) {
  int checked = 0;
  for (const HandCase& c : test::handCases()) {
    if (c.intersectionRings < 0) continue;  // count not worked out for this case
    EXPECT_EQ(static_cast<int>(clip(c.subject, c.clip, Op::Intersection).size()),
              c.intersectionRings)
        << c.name;
    ++checked;
  }
  EXPECT_GE(checked, 5);
}

std::vector<CaseParam> params() {
  std::vector<CaseParam> out;
  for (Variant v : {Variant::Naive, Variant::Sweep, Variant::Exact}) {
    if (!isImplemented(v)) continue;
    for (const HandCase& c : test::handCases()) out.push_back({c, v});
  }
  return out;
}

INSTANTIATE_TEST_SUITE_P(Hand, HandCaseTest, testing::ValuesIn(params()),
                         [](const testing::TestParamInfo<CaseParam>& info) {
                           return std::string(name(info.param.variant)) + "_" + info.param.c.name;
                         });

// The exact variant's default search: all pairs where nearly every pair of edge boxes overlaps
// (the paper's random workload: the sweep would only add bookkeeping), the sweep where edges are
// short against the extent (two circles: the sweep skips almost every pair).
TEST(SearchChoice, ExactTestsAllPairsOnRandomPolygonsAndSweepsCircles) {
  Options o;
  o.variant = Variant::Exact;
  Stats stats;
  const work::Workload random = work::generate("random", 100, 1);
  clip(random.subject, random.clip, Op::Intersection, o, &stats);
  EXPECT_EQ(stats.candidatePairs, 100u * 100u);
  const work::Workload circles = work::generate("circles", 1000, 1);
  clip(circles.subject, circles.clip, Op::Intersection, o, &stats);
  EXPECT_LT(stats.candidatePairs, 1000u * 1000u / 50);
}

}  // namespace
}  // namespace gh
