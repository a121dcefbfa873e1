// The paper's arithmetic policy: doubles and alpha values (Greiner & Hormann 1998, Figure 11).
//
// intersect() is Figure 11: window-edge coordinates (WEC) of each endpoint against the other edge,
// a crossing when both pairs change sign, alpha = WEC ratio. A WEC of exactly zero on a touching
// pair is the paper's degeneracy ("P1 lies on Q1Q2 iff alphaP = 0 and 0 <= alphaQ <= 1"): the
// vertex that lies on the other operand's edge is reported, and paper_perturbation.h moves it and
// runs phase 1 again (Section 5, Figure 12).
//
// Every decision of phase 1 here is a floating-point sign: near-degenerate inputs can be decided
// inconsistently. That is the paper as written; the exact arithmetic exists to do better. Only
// phase 2's starting status uses the library's one ray test (exact orientations): the paper leaves
// that test open, and a vertex on an edge has been perturbed away by then.
#pragma once

#include <algorithm>
#include <cstdint>

#include "arithmetic/pair_test.h"
#include "arithmetic/row_kernels.h"
#include "operand.h"
#include "phase1_buffers.h"
#include "phase1_result.h"
#include "predicates/exact_counters.h"
#include "predicates/sign.h"

namespace gh::detail {

struct SortItem;

namespace paper {

// The paper's window-edge coordinate of p with respect to the line through q1, q2
// (a cross product: positive on one side, negative on the other, zero on the line).
inline double windowEdgeCoordinate(Point p, Point q1, Point q2) {
  return (p.x - q1.x) * (q2.y - q1.y) - (p.y - q1.y) * (q2.x - q1.x);
}

inline int signOf(double v) { return (v > 0) - (v < 0); }

// The degenerate verdict of a collinear pair: the endpoints of each edge that lie within the
// other's extent along the line.
PairTest collinearContacts(Point p1, Point p2, Point q1, Point q2);

// intersect(), Figure 11: writes the crossing to `out` when there is one.
inline PairTest intersect(Point p1, Point p2, std::uint32_t subjectEdge, Point q1, Point q2, std::uint32_t clipEdge,
                          Crossing& out) {
  // The paper's early out (outcodes): disjoint bounding boxes cannot meet.
  if (std::max(p1.x, p2.x) < std::min(q1.x, q2.x) || std::max(q1.x, q2.x) < std::min(p1.x, p2.x) ||
      std::max(p1.y, p2.y) < std::min(q1.y, q2.y) || std::max(q1.y, q2.y) < std::min(p1.y, p2.y)) {
    return {};
  }
  const double wecP1 = windowEdgeCoordinate(p1, q1, q2);
  const double wecP2 = windowEdgeCoordinate(p2, q1, q2);
  const int sP1 = signOf(wecP1), sP2 = signOf(wecP2);
  if (sP1 == 0 && sP2 == 0) return collinearContacts(p1, p2, q1, q2);
  if (sP1 * sP2 > 0) return {};
  const double wecQ1 = windowEdgeCoordinate(q1, p1, p2);
  const double wecQ2 = windowEdgeCoordinate(q2, p1, p2);
  const int sQ1 = signOf(wecQ1), sQ2 = signOf(wecQ2);
  if (sQ1 == 0 && sQ2 == 0) return collinearContacts(p1, p2, q1, q2);
  if (sQ1 * sQ2 > 0) return {};
  if (sP1 == 0 || sP2 == 0 || sQ1 == 0 || sQ2 == 0) {
    std::uint8_t flags = 0;
    if (sP1 == 0) flags |= PairTest::kSubjectFrom;
    if (sP2 == 0) flags |= PairTest::kSubjectTo;
    if (sQ1 == 0) flags |= PairTest::kClipFrom;
    if (sQ2 == 0) flags |= PairTest::kClipTo;
    return {PairTest::Kind::Degenerate, flags};
  }
  out.subjectEdge = subjectEdge;
  out.clipEdge = clipEdge;
  out.alphaSubject = wecP1 / (wecP1 - wecP2);
  out.alphaClip = wecQ1 / (wecQ1 - wecQ2);
  const double a = out.alphaSubject;
  out.point = {p1.x + a * (p2.x - p1.x), p1.y + a * (p2.y - p1.y)};
  return {PairTest::Kind::Crossing, 0};
}

}  // namespace paper

class PaperArithmetic {
 public:
  // Crossings are ordered along an edge by alpha alone (ties: the other edge).
  static constexpr bool kAlphaOrderIsExact = true;
  static constexpr bool kReportsDegeneracies = true;
  // Perturbed answers have no zero-width parts to dissolve (cleanup.h).
  static constexpr bool kLeavesZeroWidthParts = false;

  // The ordering needs nothing beside the alpha values.
  struct Extra {};

  explicit PaperArithmetic(ExactCounters& counters) : counters_(&counters) {}
  ExactCounters& counters() const { return *counters_; }

  // The paper's intersect(): a crossing is written to `out`.
  PairTest test(const Operand& subject, std::uint32_t subjectEdge, const Operand& clip, std::uint32_t clipEdge,
                Crossing& out, Extra&) const {
    return paper::intersect(subject.from(subjectEdge), subject.to(subjectEdge), subjectEdge, clip.from(clipEdge),
                            clip.to(clipEdge), clipEdge, out);
  }
  void testPair(const Operand& subject, std::uint32_t se, const Operand& clip, std::uint32_t ce,
                CrossingBuffer<Extra>& into) const {
    ++into.pairs;
    Crossing c;
    const PairTest t = paper::intersect(subject.from(se), subject.to(se), se, clip.from(ce), clip.to(ce), ce, c);
    if (t.kind == PairTest::Kind::Crossing) {
      into.crossings.push_back(c);
    } else if (t.kind == PairTest::Kind::Degenerate) {
      into.addDegenerate(t, se, ce, subject, clip);
    }
  }
  // Subject edge se against every clip edge; vectorized when `clipArrays` is given (the clip's
  // edges as arrays, row_kernels.h), with the same answers.
  void testRow(const Operand& subject, std::uint32_t se, const Operand& clip, const EdgeArrays* clipArrays,
               CrossingBuffer<Extra>& into) const;

  // Order of two crossings on the same subject (clip) edge: by alpha, as in the paper.
  // -1: a first, +1: b first, 0: tied.
  double errorAlongSubject(const Extra&) const { return 0; }
  double errorAlongClip(const Extra&) const { return 0; }
  bool atInputVertex(const Extra&) const { return false; }
  template <class Item>
  int compareAlongSubject(const Item& a, const Item& b, std::uint32_t, const Operand&, const Operand&) const {
    return signOfDifference(a.alpha, b.alpha);
  }
  template <class Item>
  int compareAlongClip(const Item& a, const Item& b, std::uint32_t, const Operand&, const Operand&) const {
    return signOfDifference(a.alpha, b.alpha);
  }

  // Even-odd test of a vertex of one operand against the other operand (phase 2's start).
  // Even-odd test of a point of one operand (a ring's first vertex) against the other operand,
  // counting the `count` edges listed in `edges` (null: all of them), which must include every
  // edge whose y-range holds the point's y (search/edge_slabs.h): phase 2's start.
  bool subjectPointInsideClip(Point p, const Operand& clip, const std::uint32_t* edges, std::size_t count) const;
  bool clipPointInsideSubject(Point q, const Operand& subject, const std::uint32_t* edges, std::size_t count) const;

 private:
  ExactCounters* counters_;
};

}  // namespace gh::detail
