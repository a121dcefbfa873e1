// The rounding allowance (tolerance.h): what each constructed vertex of an answer is allowed, and
// nothing for the operands' vertices.
#include "ghoracle/tolerance.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "ulp.h"

namespace gh::oracle {
namespace {

// Operands whose vertices are far from sorted by x and y, with a NaN among them: a lookup that
// forgot to sort, or let the NaN in, misses some of them.
const Region kSubject{{{3, 0}, {5, 2}, {3, 4}, {1, 2}}, {{9, 9}, {-7, 8}, {2, -6}}};
const Region kClip{{{0, 1}, {6, 1}, {6, 3}, {std::numeric_limits<double>::quiet_NaN(), 3}, {0, 3}}};

TEST(RoundingAllowance, OperandVerticesGetNone) {
  EXPECT_EQ(roundingAllowance(kSubject, kClip, kSubject), 0);
  const Region clipWithoutNaN{{{0, 1}, {6, 1}, {6, 3}, {0, 3}}};
  EXPECT_EQ(roundingAllowance(kSubject, kClip, clipWithoutNaN), 0);
}

TEST(RoundingAllowance, EachConstructedVertexGetsItsDisplacementTimesItsEdges) {
  // Two vertices of S and two constructed ones, (4, 1) and (2, 1): each may move by 4 ulps of its
  // larger coordinate along both axes, sweeping half of its two edges.
  const Region answer{{{3, 0}, {4, 1}, {5, 2}, {2, 1}}};
  auto share = [](Point v, Point a, Point b, int ulps, double floor) {
    return ulps * ulpOf(std::max(v.x, v.y), floor) * std::sqrt(2.0) *
           (std::hypot(v.x - a.x, v.y - a.y) + std::hypot(b.x - v.x, b.y - v.y)) / 2;
  };
  const double expected = share({4, 1}, {3, 0}, {5, 2}, kComparisonUlps, 0) + share({2, 1}, {5, 2}, {3, 0}, kComparisonUlps, 0);
  EXPECT_EQ(roundingAllowance(kSubject, kClip, answer), expected);
  // The floor stands for a scaled copy's subnormal spacing: above both vertices' ulps, it is what
  // they move by.
  const double floor = 0x1p-20;
  const double floored = share({4, 1}, {3, 0}, {5, 2}, 1, floor) + share({2, 1}, {5, 2}, {3, 0}, 1, floor);
  EXPECT_EQ(floored, floor * std::sqrt(2.0) * std::hypot(1, 1) + floor * std::sqrt(2.0) * (std::hypot(3, 1) + std::hypot(1, 1)) / 2);
  EXPECT_EQ(roundingAllowance(kSubject, kClip, answer, 1, floor), floored);
}

}  // namespace
}  // namespace gh::oracle
