// Input checking (validate.h): every class of bad input is refused with gh::InvalidInput and a
// message naming the problem; consecutive duplicates are dropped.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "ghclip/clip.h"
#include "ghclip/errors.h"
#include "ghclip/measure.h"
#include "ghclip/validate.h"

namespace gh {
namespace {

Ring rect(double x0, double y0, double x1, double y1) { return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; }

std::string messageOf(const Region& s, const Region& c) {
  try {
    clip(s, c, Op::Intersection);
  } catch (const InvalidInput& e) {
    return e.what();
  }
  return "";
}

TEST(BadInput, NaNIsRefused) {
  Region s{{{0, 0}, {1, 0}, {std::nan(""), 1}}};
  EXPECT_NE(messageOf(s, {rect(0, 0, 1, 1)}).find("not finite"), std::string::npos);
  EXPECT_NE(messageOf({rect(0, 0, 1, 1)}, s).find("ring 1, vertex 3"), std::string::npos);
}

// The refusal says which operand: a tool names that operand's file.
TEST(BadInput, TheRefusedOperandIsNamed) {
  const Region bad{rect(0, 0, 1, 1), {{0, 0}, {1, 1}}};
  for (const bool subjectIsBad : {true, false}) {
    try {
      clip(subjectIsBad ? bad : Region{rect(0, 0, 1, 1)}, subjectIsBad ? Region{rect(0, 0, 1, 1)} : bad, Op::Union);
      ADD_FAILURE() << "not refused";
    } catch (const InvalidInput& e) {
      EXPECT_EQ(e.operand(), subjectIsBad ? "subject" : "clip");
      EXPECT_EQ(e.problem(), "ring 2 has fewer than 3 distinct vertices");
      EXPECT_EQ(std::string(e.what()), e.operand() + ": " + e.problem());
    }
  }
}

TEST(BadInput, InfinityIsRefused) {
  Region s{{{0, 0}, {std::numeric_limits<double>::infinity(), 0}, {0, 1}}};
  EXPECT_NE(messageOf(s, {rect(0, 0, 1, 1)}).find("not finite"), std::string::npos);
}

TEST(BadInput, CoordinatesWhoseProductsOverflowAreRefused) {
  Region huge{{{0, 0}, {1e200, 0}, {0, 1e200}}};
  EXPECT_NE(messageOf(huge, {rect(0, 0, 1, 1)}).find("exceeds"), std::string::npos);
  // 1e150 is inside the limit, and clipping at that scale works.
  Region big{rect(0, 0, 2e150, 2e150)};
  Region big2{rect(1e150, 1e150, 3e150, 3e150)};
  EXPECT_NEAR(evenOddArea(clip(big, big2, Op::Intersection)), 1e300, 1e291);
}

TEST(BadInput, TwoVertexRingIsRefused) {
  Region s{{{0, 0}, {1, 1}}};
  EXPECT_NE(messageOf(s, {rect(0, 0, 1, 1)}).find("fewer than 3 distinct"), std::string::npos);
}

TEST(BadInput, RingWithTwoDistinctVerticesIsRefused) {
  Region s{{{0, 0}, {1, 1}, {0, 0}, {1, 1}}};
  EXPECT_NE(messageOf(s, {rect(0, 0, 1, 1)}).find("fewer than 3 distinct"), std::string::npos);
  Region closedTriangleOfTwo{{{0, 0}, {1, 1}, {1, 1}, {0, 0}}};
  EXPECT_NE(messageOf(closedTriangleOfTwo, {rect(0, 0, 1, 1)}).find("fewer than 3"),
            std::string::npos);
}

TEST(BadInput, SanitizeDropsDegenerateRingsInstead) {
  Region s{rect(0, 0, 2, 2), {{5, 5}, {6, 6}}};
  Options options;
  options.sanitize = true;
  EXPECT_NEAR(evenOddArea(clip(s, {rect(1, 1, 3, 3)}, Op::Intersection, options)), 1, 1e-12);
}

TEST(Normalisation, ConsecutiveDuplicatesAndClosingVertexAreDropped) {
  const Region messy{{{0, 0}, {0, 0}, {2, 0}, {2, 2}, {2, 2}, {2, 2}, {0, 2}, {0, 0}}};
  const Region n = normalized(messy);
  ASSERT_EQ(n.size(), 1u);
  EXPECT_EQ(n[0].size(), 4u);
  EXPECT_NEAR(evenOddArea(clip(messy, {rect(1, 1, 3, 3)}, Op::Intersection)), 1, 1e-12);
}

TEST(Normalisation, EmptyRegionIsTheEmptySet) {
  EXPECT_TRUE(clip({}, {}, Op::Union).empty());
  EXPECT_NEAR(evenOddArea(clip({}, {rect(0, 0, 1, 1)}, Op::Union)), 1, 1e-15);
}

}  // namespace
}  // namespace gh
