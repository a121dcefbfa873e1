// Every class of bad input is refused with gh::InvalidInput and a message naming the problem;
// the algorithm's own failure modes (unclosed traces) raise gh::ClipFailure, never hang.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "ghclip/clip.h"
#include "ghclip/errors.h"
#include "ghclip/measure.h"
#include "ghclip/validate.h"
#include "hand_cases.h"
#include "naive_arithmetic.h"
#include "all_pairs_search.h"
#include "phase1_intersections.h"
#include "phase3_tracing.h"
#include "vertex_graph.h"

namespace gh {
namespace {

using test::rect;

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

// Phase 3 must stop with ClipFailure, never loop, when the linked lists are not what phases 1-2
// promise. Corrupt them by hand: the clip's list becomes a cycle that never leads back to the
// intersection vertex a trace started from.
TEST(Tracing, BrokenListsRaiseClipFailureInsteadOfLooping) {
  using namespace detail;
  Stats stats;
  Phase1Result r = findIntersections(
      Operand({rect(0, 0, 4, 4)}),
      Operand({{{0.5, 2}, {1.5, 2}, {1.5, 5}, {2.5, 5}, {2.5, 2}, {3.5, 2}, {3.5, 6}, {0.5, 6}}}),
      AllPairsSearch{}, NaiveArithmetic{}, stats);
  ASSERT_EQ(r.crossings.size(), 4u);
  VertexGraph g = buildVertexGraph(r);
  markEntryExit(g);
  EXPECT_NO_THROW(traceResult(g, Op::Intersection));
  // Point every clip node's neighbour at one subject node: traces can no longer close.
  for (std::uint32_t n = g.firstClipNode; n < g.nodes.size(); ++n) g.nodes[n].neighbor = 1;
  EXPECT_THROW(traceResult(g, Op::Intersection), ClipFailure);
}

// Marks that disagree with the geometry (what inconsistent floating-point signs produce) make a
// trace arrive at an intersection vertex an earlier trace used: reported, not followed.
TEST(Tracing, ReusedIntersectionVertexRaisesClipFailure) {
  using namespace detail;
  Stats stats;
  // Gate-shaped clip: four crossings with the square's top edge.
  Phase1Result r = findIntersections(
      Operand({rect(0, 0, 4, 4)}),
      Operand({{{0.5, 2}, {1.5, 2}, {1.5, 5}, {2.5, 5}, {2.5, 2}, {3.5, 2}, {3.5, 6}, {0.5, 6}}}),
      AllPairsSearch{}, NaiveArithmetic{}, stats);
  ASSERT_EQ(r.crossings.size(), 4u);
  VertexGraph g = buildVertexGraph(r);
  markEntryExit(g);
  int failures = 0;
  for (std::uint32_t n = 0; n < g.nodes.size(); ++n) {
    VertexGraph corrupt = g;
    corrupt.nodes[n].entry = !corrupt.nodes[n].entry;
    try {
      traceResult(corrupt, Op::Intersection);
    } catch (const ClipFailure& e) {
      ++failures;
      EXPECT_NE(std::string(e.what()).find("tracing"), std::string::npos);
    }
  }
  EXPECT_GT(failures, 0);
}

}  // namespace
}  // namespace gh
