// Phase 2 (phase2_marking.h): every ring's start is located in the other operand by the
// arithmetic's ray test, and intersection vertices alternate entry and exit from there.
#include <gtest/gtest.h>

#include "arithmetic/exact_arithmetic.h"
#include "arithmetic/paper_arithmetic.h"
#include "phase1_intersections.h"
#include "phase2_marking.h"
#include "search/all_pairs_search.h"

namespace gh::detail {
namespace {

Ring rect(double x0, double y0, double x1, double y1) { return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; }

template <class Arithmetic>
VertexGraph marked(Phase1Result& r, const Arithmetic& a) {
  VertexGraph g = buildVertexGraph(r);
  locateRingStarts(g, a);
  markEntryExit(g);
  return g;
}

TEST(Phase2, LocatesRingStartsAndAlternatesEntryAndExit) {
  ExactCounters counters;
  const PaperArithmetic paper(counters);
  Stats stats;
  // The square [0,4]^2 (first vertex (0,0), outside the gate), the gate (first vertex (0.5, 2),
  // inside the square), and a ring far away that crosses nothing.
  Phase1Result r = findIntersections(
      Operand({rect(0, 0, 4, 4)}),
      Operand({{{0.5, 2}, {1.5, 2}, {1.5, 5}, {2.5, 5}, {2.5, 2}, {3.5, 2}, {3.5, 6}, {0.5, 6}}, rect(10, 10, 11, 11)}),
      AllPairsSearch{}, paper, stats);
  const VertexGraph g = marked(r, paper);
  ASSERT_EQ(g.subjectRings.size(), 1u);
  ASSERT_EQ(g.clipRings.size(), 2u);
  EXPECT_FALSE(g.subjectRings[0].startsInside);
  EXPECT_TRUE(g.clipRings[0].startsInside);
  EXPECT_FALSE(g.clipRings[1].startsInside);
  EXPECT_EQ(g.clipRings[1].head, kNone);
  // Along each ring with crossings: entry, exit, entry, exit... from an outside start, and the
  // opposite from an inside one.
  for (const RingInfo* ring : {&g.subjectRings[0], &g.clipRings[0]}) {
    bool expected = !ring->startsInside;
    std::uint32_t n = ring->head;
    int count = 0;
    do {
      EXPECT_EQ(g.node(n).entry(), expected);
      expected = !expected;
      n = g.next(n);
      ++count;
    } while (n != ring->head);
    EXPECT_EQ(count, 4);
  }
}

// Under Simulation of Simplicity the clip is moved by (eps, eps^2): a subject vertex on the clip's
// lower-left corner is outside it, the clip's copy of that corner is inside the subject.
TEST(Phase2, DecidesStartsOnTheOtherBoundaryBySimulationOfSimplicity) {
  ExactCounters counters;
  const ExactArithmetic exact(counters);
  Stats stats;
  Phase1Result r =
      findIntersections(Operand({rect(0, 0, 2, 2)}), Operand({rect(0, 0, 2, 2)}), AllPairsSearch{}, exact, stats);
  const VertexGraph g = marked(r, exact);
  EXPECT_FALSE(g.subjectRings[0].startsInside);
  EXPECT_TRUE(g.clipRings[0].startsInside);
}

}  // namespace
}  // namespace gh::detail
