// Phase 3 (phase3_tracing.h): tracing alternates between the operands at intersection vertices,
// and stops with ClipFailure, never loops, when the lists are not what phases 1 and 2 promise.
#include <gtest/gtest.h>

#include "arithmetic/paper_arithmetic.h"
#include "ghclip/errors.h"
#include "ghclip/measure.h"
#include "phase1_intersections.h"
#include "phase2_marking.h"
#include "phase3_tracing.h"
#include "search/all_pairs_search.h"

namespace gh::detail {
namespace {

Ring rect(double x0, double y0, double x1, double y1) { return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; }

// The square [0,4]^2 and a gate whose legs cross its top edge: four crossings, two pieces inside.
struct Gate {
  ExactCounters counters;
  Stats stats;
  Phase1Result crossings;
  VertexGraph graph;
  Gate()
      : crossings(findIntersections(
            Operand({rect(0, 0, 4, 4)}),
            Operand({{{0.5, 2}, {1.5, 2}, {1.5, 5}, {2.5, 5}, {2.5, 2}, {3.5, 2}, {3.5, 6}, {0.5, 6}}}),
            AllPairsSearch{}, PaperArithmetic(counters), stats)),
        graph(buildVertexGraph(crossings)) {
    locateRingStarts(graph, PaperArithmetic(counters));
    markEntryExit(graph);
  }
};

TEST(Tracing, EachOperationTracesItsPieces) {
  Gate g;
  ASSERT_EQ(g.crossings.crossingCount(), 4u);
  // Intersection: the two leg ends inside the square, 1 x 2 each.
  const Region both = traceResult(g.graph, Op::Intersection);
  EXPECT_EQ(both.size(), 2u);
  EXPECT_DOUBLE_EQ(evenOddArea(both), 4);
  EXPECT_DOUBLE_EQ(evenOddArea(traceResult(g.graph, Op::Union)), 21);
  EXPECT_DOUBLE_EQ(evenOddArea(traceResult(g.graph, Op::Difference)), 12);
  EXPECT_DOUBLE_EQ(evenOddArea(traceResult(g.graph, Op::ReverseDifference)), 5);
  // Xor is the two differences, one after the other.
  EXPECT_DOUBLE_EQ(evenOddArea(traceResult(g.graph, Op::Xor)), 17);
}

// Phase 3 must stop with ClipFailure, never loop, when the linked lists are not what phases 1-2
// promise. Corrupt them by hand: the clip's list becomes a cycle that never leads back to the
// intersection vertex a trace started from.
TEST(Tracing, BrokenListsRaiseClipFailureInsteadOfLooping) {
  Gate gate;
  VertexGraph& g = gate.graph;
  EXPECT_NO_THROW(traceResult(g, Op::Intersection));
  // Point every clip node's neighbour at one subject node: traces can no longer close.
  for (Node& n : *g.clipNodes) n.setNeighbor(1);
  EXPECT_THROW(traceResult(g, Op::Intersection), ClipFailure);
}

// Marks that disagree with the geometry (what inconsistent floating-point signs produce) make a
// trace arrive at an intersection vertex an earlier trace used: reported, not followed.
TEST(Tracing, ReusedIntersectionVertexRaisesClipFailure) {
  Gate gate;
  VertexGraph& g = gate.graph;
  int failures = 0;
  for (std::uint32_t n = 0; n < g.nodeCount(); ++n) {
    g.node(n).setEntry(!g.node(n).entry());
    try {
      traceResult(g, Op::Intersection);
    } catch (const ClipFailure& e) {
      ++failures;
      EXPECT_NE(std::string(e.what()).find("tracing"), std::string::npos);
    }
    g.node(n).setEntry(!g.node(n).entry());
  }
  EXPECT_GT(failures, 0);
}

}  // namespace
}  // namespace gh::detail
