// Phase 1 (phase1_intersections.h): the sort along an edge gives the one sorted order of the
// arithmetic's total order, whatever the approximations it starts from (ties, unbounded and
// non-finite alphas included), and phase 1 gives the same result on one thread and on several.
#include <gmpxx.h>
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <limits>

#include "arithmetic/exact_arithmetic.h"
#include "arithmetic/paper_arithmetic.h"
#include "ghwork/generators.h"
#include "paper_perturbation.h"
#include "phase1_intersections.h"
#include "search/all_pairs_search.h"
#include "search/sweep_search.h"

namespace gh::detail {
namespace {

SortItem item(double alpha, double err, std::uint32_t other, std::uint32_t index) {
  SortItem i{};
  i.alpha = alpha, i.err = err, i.other = other, i.index = index;
  return i;
}

// Items whose true positions are `truth` (ties allowed), given to the sort as approximations
// alpha within err of the truth, or as NaN or infinity with an unbounded error. The comparison
// is the truth's, as an arithmetic's exact comparison would be; ties go to the other edge.
RC_GTEST_PROP(SortAlongEdge, GivesTheTotalOrderFromAnyApproximation, ()) {
  const int s = *rc::gen::inRange(0, 120);
  std::vector<double> truth(static_cast<std::size_t>(s));
  std::vector<SortItem> items;
  for (int i = 0; i < s; ++i) {
    truth[static_cast<std::size_t>(i)] = *rc::gen::inRange(0, 12) / 11.0;  // few values: many ties
    const int kind = *rc::gen::inRange(0, 6);
    double alpha = truth[static_cast<std::size_t>(i)], err = 0;
    if (kind == 1) err = 1e-3, alpha += *rc::gen::inRange(-1000, 1001) * 1e-6;
    if (kind == 2) err = 0.3, alpha += *rc::gen::inRange(-1000, 1001) * 3e-4;
    if (kind == 3) err = INFINITY, alpha = std::numeric_limits<double>::quiet_NaN();
    if (kind == 4) err = INFINITY, alpha = INFINITY;
    items.push_back(item(alpha, err, static_cast<std::uint32_t>(1000 - i), static_cast<std::uint32_t>(i)));
  }
  auto compare = [&truth](const SortItem& a, const SortItem& b) {
    const double x = truth[a.index], y = truth[b.index];
    return (x > y) - (x < y);
  };
  std::vector<SortItem> expected = items;
  std::sort(expected.begin(), expected.end(), [&](const SortItem& a, const SortItem& b) {
    if (const int c = compare(a, b)) return c < 0;
    return a.other < b.other;
  });
  std::vector<SortItem> scratch;
  std::vector<std::uint32_t> slots;
  sortAlongEdge<false>(items.data(), items.data() + items.size(), scratch, slots, compare);
  for (std::size_t i = 0; i < items.size(); ++i) RC_ASSERT(items[i].index == expected[i].index);
}

// Where alpha is the order itself (the paper's), the spread and the slots' sorts alone suffice.
RC_GTEST_PROP(SortAlongEdge, SortsByAlphaThenTheOtherEdge, ()) {
  const int s = *rc::gen::inRange(0, 300);
  std::vector<SortItem> items;
  for (int i = 0; i < s; ++i) {
    const double alpha = *rc::gen::element(0.0, -0.0, 1.0, 0.5, 1e-300) + *rc::gen::inRange(0, 50) / 64.0;
    items.push_back(item(alpha, 0, static_cast<std::uint32_t>(*rc::gen::inRange(0, 1 << 20)) * 512u + static_cast<std::uint32_t>(i),
                         static_cast<std::uint32_t>(i)));
  }
  std::vector<SortItem> expected = items;
  std::sort(expected.begin(), expected.end(), [](const SortItem& a, const SortItem& b) {
    if (a.alpha != b.alpha) return a.alpha < b.alpha;
    return a.other < b.other;
  });
  std::vector<SortItem> scratch;
  std::vector<std::uint32_t> slots;
  sortAlongEdge<true>(items.data(), items.data() + items.size(), scratch, slots,
                      [](const SortItem& a, const SortItem& b) { return (a.alpha > b.alpha) - (a.alpha < b.alpha); });
  for (std::size_t i = 0; i < items.size(); ++i) RC_ASSERT(items[i].index == expected[i].index);
}

bool samePhase1(const Phase1Result& a, const Phase1Result& b) {
  if (a.crossingCount() != b.crossingCount()) return false;
  for (std::size_t i = 0; i < a.crossingCount(); ++i) {
    if (a.subjectEdge(i) != b.subjectEdge(i) || a.clipEdge(i) != b.clipEdge(i) || !(a.point(i) == b.point(i)) ||
        a.clipOrder(i) != b.clipOrder(i)) {
      return false;
    }
  }
  return true;
}

// Where a crossing lies along an edge, exactly: alpha of the crossing of a->b with c->d.
mpq_class exactAlpha(Point a, Point b, Point c, Point d) {
  const mpq_class ax(a.x), ay(a.y), bx(b.x), by(b.y), cx(c.x), cy(c.y), dx(d.x), dy(d.y);
  const mpq_class numerator = (cx - ax) * (dy - cy) - (cy - ay) * (dx - cx);
  const mpq_class denominator = (bx - ax) * (dy - cy) - (by - ay) * (dx - cx);
  return numerator / denominator;
}

// A clip ring that zig-zags across the subject edge near one point, crossing it many times at
// places a few ulps apart (some exactly equal: edges through one point), or nearly parallel to it.
Region zigZagAcross(Point a, Point b, int kind) {
  const int k = *rc::gen::inRange(3, 24);
  // Where along the edge, about; for the fans exactly the edge's midpoint (the origin: a and b
  // are symmetric), so that every spike crosses the edge at one point.
  const double t = kind == 2 ? 0.5 : *rc::gen::inRange(1, 1000) / 1001.0;
  const Point p{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
  const double nx = a.y - b.y, ny = b.x - a.x;  // a normal of the edge
  Ring ring;
  for (int i = 0; i < 2 * k; ++i) {
    const double side = i % 2 == 0 ? 1 : -1;
    // kind 0: tall spikes whose feet are ulps apart; kind 1: flat spikes (near-parallel edges);
    // kind 2: exact fans through p (reflections of one vertex through p, both doubles).
    const double height = (kind == 1 ? std::ldexp(*rc::gen::inRange(1, 64), -40) : *rc::gen::inRange(1, 64) / 16.0) +
                          i * std::ldexp(1.0, kind == 1 ? -38 : -3);  // distinct: no repeated vertex
    const double shift = std::ldexp(*rc::gen::inRange(-4, 5), -50) * (kind == 1 ? 1e6 : 1);
    double x = p.x + side * height * nx + shift * (b.x - a.x), y = p.y + side * height * ny + shift * (b.y - a.y);
    if (kind == 2 && i % 2 == 1) x = 2 * p.x - ring.back().x, y = 2 * p.y - ring.back().y;
    ring.push_back({x, y});
  }
  return {ring};
}

// The exact arithmetic orders crossings along every edge as GMP's rationals do, wherever two
// alphas differ, on crossings a few ulps apart, nearly parallel edges and fans through a point.
RC_GTEST_PROP(Phase1Order, ExactOrderAlongEdgesIsTheRationalOrder, ()) {
  const double scale = std::ldexp(1.0, *rc::gen::inRange(-20, 21));
  const int kind = *rc::gen::inRange(0, 3);
  const double ya = *rc::gen::inRange(-1000, 1001) / 997.0 * scale;
  const Point a{-1.0 * scale, ya};
  const Point b{1.0 * scale, kind == 2 ? -ya : *rc::gen::inRange(-1000, 1001) / 991.0 * scale};
  const Region subject{{a, b, {0, 3 * scale}}};
  const Region clip = zigZagAcross(a, b, kind);
  ExactCounters counters;
  Stats stats;
  const Phase1Result r = findIntersections(Operand(subject, false), Operand(clip, false), AllPairsSearch{},
                                           ExactArithmetic(counters), stats);
  RC_TAG(kind);
  auto check = [&](const std::vector<Node>& nodes, const Operand& own, const Operand& other,
                   const std::vector<Node>& otherNodes) {
    for (std::size_t i = 0; i + 1 < nodes.size(); ++i) {
      if (nodes[i].edge != nodes[i + 1].edge) continue;
      const std::uint32_t e = nodes[i].edge;
      const std::uint32_t f = otherNodes[nodes[i].neighbor()].edge, g = otherNodes[nodes[i + 1].neighbor()].edge;
      const mpq_class first = exactAlpha(own.from(e), own.to(e), other.from(f), other.to(f));
      const mpq_class second = exactAlpha(own.from(e), own.to(e), other.from(g), other.to(g));
      RC_ASSERT(first <= second);  // equal alphas: Simulation of Simplicity decides
    }
  };
  check(r.subjectNodes, r.subject, r.clip, r.clipNodes);
  check(r.clipNodes, r.clip, r.subject, r.subjectNodes);
  RC_ASSERT(r.crossingCount() > 0);
}

// Threads split the search and the sorts; the answer is the one-thread answer, bit for bit.
TEST(Phase1, SameOnEveryNumberOfThreads) {
  for (const char* name : {"random", "circles", "grid", "bitset-grid"}) {
    const work::Workload w = work::generate(name, std::string(name) == "circles" ? 20000 : 400, 5);
    ExactCounters c1, c4;
    Stats s1, s4;
    const Phase1Result one = findIntersections(Operand(w.subject, false), Operand(w.clip, false), SweepSearch{},
                                               ExactArithmetic(c1), s1, nullptr, 1);
    const Phase1Result four = findIntersections(Operand(w.subject, false), Operand(w.clip, false), SweepSearch{},
                                                ExactArithmetic(c4), s4, nullptr, 4);
    EXPECT_TRUE(samePhase1(one, four)) << name;
    EXPECT_EQ(s1.candidatePairs, s4.candidatePairs) << name;
    EXPECT_EQ(c1.filterFailures, c4.filterFailures) << name;
    Stats p1, p4;
    const Phase1Result paperOne = findIntersectionsPerturbed(Operand(w.subject, false), Operand(w.clip, false),
                                                             AllPairsSearch{}, PaperArithmetic(c1), p1, 1);
    const Phase1Result paperFour = findIntersectionsPerturbed(Operand(w.subject, false), Operand(w.clip, false),
                                                              AllPairsSearch{}, PaperArithmetic(c4), p4, 4);
    EXPECT_TRUE(samePhase1(paperOne, paperFour)) << name;
    EXPECT_EQ(p1.perturbations, p4.perturbations) << name;
  }
}

}  // namespace
}  // namespace gh::detail
