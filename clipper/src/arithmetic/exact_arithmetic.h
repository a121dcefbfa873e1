// The exact arithmetic policy: every decision of phase 1 (and of phase 2's starting status) is an
// exact predicate under Simulation of Simplicity (predicates/sos_predicates.h; why it is complete
// and what the output is in the limit: EXACT.md). No degeneracy exists for it, so nothing is
// perturbed and no input coordinate ever moves. Only intersection points are constructed, once
// each, from the original coordinates. Every fallback to rational arithmetic is counted in the
// ExactCounters the policy is given.
#pragma once

#include <cmath>
#include <cstdint>

#include "arithmetic/pair_test.h"
#include "arithmetic/row_kernels.h"
#include "operand.h"
#include "phase1_buffers.h"
#include "phase1_result.h"
#include "predicates/exact_counters.h"
#include "predicates/sign.h"

namespace gh::detail {

class ExactArithmetic {
 public:
  // Alpha is only an approximation of the order along an edge: it is decided exactly.
  static constexpr bool kAlphaOrderIsExact = false;
  static constexpr bool kReportsDegeneracies = false;
  // The limit eps -> 0 leaves zero-width parts (slivers, spikes, seams) for clean-up to remove.
  static constexpr bool kLeavesZeroWidthParts = true;

  // What the ordering needs beside the Crossing: certified bounds |true alpha - alpha| <= err on
  // its positions (infinite: no bound), and whether the crossing's point is exactly an input
  // vertex (the limit of the crossing is that vertex, so its position is known exactly), kept in
  // the sign bit of errSubject (bounds are never negative): 16 bytes per crossing.
  struct Extra {
    double errSubject = 0;
    double errClip = 0;
  };

  explicit ExactArithmetic(ExactCounters& counters) : counters_(&counters) {}
  ExactCounters& counters() const { return *counters_; }

  PairTest test(const Operand& subject, std::uint32_t subjectEdge, const Operand& clip, std::uint32_t clipEdge,
                Crossing& out, Extra& extra) const;
  void testPair(const Operand& subject, std::uint32_t se, const Operand& clip, std::uint32_t ce,
                CrossingBuffer<Extra>& into) const {
    ++into.pairs;
    Crossing c;
    Extra e;
    if (test(subject, se, clip, ce, c, e).kind == PairTest::Kind::Crossing) into.add(c, e);
  }
  // Subject edge se against every clip edge; the vectorized filter rejects most pairs first when
  // `clipArrays` is given (row_kernels.h), with the same answers.
  void testRow(const Operand& subject, std::uint32_t se, const Operand& clip, const EdgeArrays* clipArrays,
               CrossingBuffer<Extra>& into) const;

  // Exact order of two crossings on one edge: -1 (a first), +1, or 0 (one point in the limit,
  // only when the two other edges lie on one line). Most pairs are decided by their certified
  // position intervals (inline, for the sort); the rest by the exact predicate.
  double errorAlongSubject(const Extra& e) const { return std::abs(e.errSubject); }
  double errorAlongClip(const Extra& e) const { return e.errClip; }
  bool atInputVertex(const Extra& e) const { return std::signbit(e.errSubject); }
  //
  // Crossings whose limits are input vertices (many edges through one point) are ordered without
  // the full predicate: two different vertices by their positions along the edge, which is
  // exact; the same vertex by the eps terms alone (sos_predicates.h, sameLimit), which the
  // floating-point filter decides, where the eps-free term would need rationals to show it is 0.
  template <class Item>
  int compareAlongSubject(const Item& a, const Item& b, std::uint32_t edge, const Operand& subject,
                          const Operand& clip) const {
    if (const int quick = byIntervals(a.alpha, a.err, b.alpha, b.err)) return quick;
    const bool bothAtVertices = a.atInputVertex && b.atInputVertex;
    if (bothAtVertices && !(a.point == b.point)) return alongLine(subject.from(edge), subject.to(edge), a.point, b.point);
    return exactlyAlongSubject(edge, a.other, b.other, subject, clip, bothAtVertices);
  }
  template <class Item>
  int compareAlongClip(const Item& a, const Item& b, std::uint32_t edge, const Operand& subject,
                       const Operand& clip) const {
    if (const int quick = byIntervals(a.alpha, a.err, b.alpha, b.err)) return quick;
    const bool bothAtVertices = a.atInputVertex && b.atInputVertex;
    if (bothAtVertices && !(a.point == b.point)) return alongLine(clip.from(edge), clip.to(edge), a.point, b.point);
    return exactlyAlongClip(edge, a.other, b.other, subject, clip, bothAtVertices);
  }

  // Even-odd test of a point of one operand (a ring's first vertex) against the other operand,
  // counting the `count` edges listed in `edges` (null: all of them), which must include every
  // edge whose y-range holds the point's y (search/edge_slabs.h): phase 2's start.
  bool subjectPointInsideClip(Point p, const Operand& clip, const std::uint32_t* edges, std::size_t count) const;
  bool clipPointInsideSubject(Point q, const Operand& subject, const std::uint32_t* edges, std::size_t count) const;

 private:
  // a < b from certified intervals a +- ea, b +- eb when they are disjoint: -1 (a first), +1, or
  // 0 (undecided).
  static int byIntervals(double a, double ea, double b, double eb) {
    if (a + ea < b - eb) return -1;
    if (b + eb < a - ea) return 1;
    return 0;
  }
  // Along subject edge `edge`, the crossings with clip edges a and b (and the other way round);
  // sameLimit: both tend to one point.
  int exactlyAlongSubject(std::uint32_t edge, std::uint32_t a, std::uint32_t b, const Operand& subject,
                          const Operand& clip, bool sameLimit) const;
  int exactlyAlongClip(std::uint32_t edge, std::uint32_t a, std::uint32_t b, const Operand& subject,
                       const Operand& clip, bool sameLimit) const;
  // The order of two distinct points u, v that lie on the line from e1 to e2 (both the limits of
  // crossings with the edge e1e2): -1 if u comes first going from e1 to e2. Exact: comparisons
  // along an axis on which e1 and e2 differ.
  static int alongLine(Point e1, Point e2, Point u, Point v) {
    if (e1.x != e2.x) return signOfDifference(u.x, v.x) * signOfDifference(e2.x, e1.x);
    return signOfDifference(u.y, v.y) * signOfDifference(e2.y, e1.y);
  }

  ExactCounters* counters_;
};

}  // namespace gh::detail
