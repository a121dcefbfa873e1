#include "arithmetic/exact_arithmetic.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "predicates/construction.h"
#include "predicates/crossing_position.h"
#include "predicates/difference_products.h"
#include "predicates/orientation.h"
#include "predicates/sos_predicates.h"

namespace gh::detail {

PairTest ExactArithmetic::test(const Operand& subject, std::uint32_t subjectEdge, const Operand& clip,
                               std::uint32_t clipEdge, Crossing& x, Extra& extra) const {
  const Point p1 = subject.from(subjectEdge), p2 = subject.to(subjectEdge);
  const Point q1 = clip.from(clipEdge), q2 = clip.to(clipEdge);
  // Boxes of p and of q translated by (eps, eps^2): a tie on q's low side or p's high side
  // separates them, a tie the other way round overlaps.
  if (std::max(p1.x, p2.x) <= std::min(q1.x, q2.x) || std::max(q1.x, q2.x) < std::min(p1.x, p2.x) ||
      std::max(p1.y, p2.y) <= std::min(q1.y, q2.y) || std::max(q1.y, q2.y) < std::min(p1.y, p2.y)) {
    return {};
  }
  // Each determinant is evaluated once: its sign (filtered, exact when needed) decides the
  // crossing, and its value and bound give the crossing's position along the edge. A pair whose
  // bounds came out infinite (coordinates near 1e-300 or 1e150) is evaluated again towards 1.
  FilteredDeterminant dP1 = orientationDeterminant(q1, q2, p1), dP2 = orientationDeterminant(q1, q2, p2);
  if (!(std::max(dP1.bound, dP2.bound) < std::numeric_limits<double>::infinity())) determinantsTowardsUnit(q1, q2, p1, p2, dP1, dP2);
  const Sign oP1 = orientation(dP1, q1, q2, p1, *counters_), oP2 = orientation(dP2, q1, q2, p2, *counters_);
  if (sos::clipEdgeSide(oP1, q1, q2) == sos::clipEdgeSide(oP2, q1, q2)) return {};
  FilteredDeterminant dQ1 = orientationDeterminant(p1, p2, q1), dQ2 = orientationDeterminant(p1, p2, q2);
  if (!(std::max(dQ1.bound, dQ2.bound) < std::numeric_limits<double>::infinity())) determinantsTowardsUnit(p1, p2, q1, q2, dQ1, dQ2);
  const Sign oQ1 = orientation(dQ1, p1, p2, q1, *counters_), oQ2 = orientation(dQ2, p1, p2, q2, *counters_);
  if (sos::subjectEdgeSide(oQ1, p1, p2) == sos::subjectEdgeSide(oQ2, p1, p2)) return {};

  x.subjectEdge = subjectEdge;
  x.clipEdge = clipEdge;
  // Positions along both edges (the limit values) with certified error bounds: the sort orders
  // most crossings by them and asks the exact predicate only when two intervals overlap. Where
  // the limit is an input vertex, the position is exact.
  extra.errSubject = extra.errClip = 0;
  x.alphaSubject = oP1 == Sign::Zero ? 0 : oP2 == Sign::Zero ? 1 : certifiedRatio(dP1, dP2, extra.errSubject);
  x.alphaClip = oQ1 == Sign::Zero ? 0 : oQ2 == Sign::Zero ? 1 : certifiedRatio(dQ1, dQ2, extra.errClip);
  // The point in the limit eps -> 0, once, from the original coordinates: that input vertex where
  // the limit is one, else the crossing faithfully rounded (construction.h).
  bool atInputVertex = true;
  if (oP1 == Sign::Zero) {
    x.point = p1;
  } else if (oP2 == Sign::Zero) {
    x.point = p2;
  } else if (oQ1 == Sign::Zero) {
    x.point = q1;
  } else if (oQ2 == Sign::Zero) {
    x.point = q2;
  } else {
    atInputVertex = false;
    x.point = constructCrossing(p1, p2, q1, q2, *counters_);
  }
  if (atInputVertex) extra.errSubject = -extra.errSubject;  // the sign bit says it (-0.0 too)
  return {PairTest::Kind::Crossing, 0};
}

void ExactArithmetic::testRow(const Operand& subject, std::uint32_t se, const Operand& clip,
                              const EdgeArrays* clipArrays, CrossingBuffer<Extra>& into) const {
  const auto m = static_cast<std::uint32_t>(clip.size());
  into.pairs += m;
  struct Context {
    const ExactArithmetic& arithmetic;
    const Operand &subject, &clip;
    std::uint32_t se;
    CrossingBuffer<Extra>& into;
  } context{*this, subject, clip, se, into};
  auto test = [](void* c, std::uint32_t ce) {
    Context& k = *static_cast<Context*>(c);
    Crossing crossing;
    Extra extra;
    if (k.arithmetic.test(k.subject, k.se, k.clip, ce, crossing, extra).kind == PairTest::Kind::Crossing) {
      k.into.add(crossing, extra);
    }
  };
  if (clipArrays) {
    const Point p1 = subject.from(se), p2 = subject.to(se);
    exactRowCandidates(p1.x, p1.y, p2.x, p2.y, *clipArrays, test, &context);
    return;
  }
  for (std::uint32_t ce = 0; ce < m; ++ce) test(&context, ce);
}

int ExactArithmetic::exactlyAlongSubject(std::uint32_t e, std::uint32_t a, std::uint32_t b, const Operand& subject,
                                         const Operand& clip, bool sameLimit) const {
  return sos::compareAlongSubject(subject.from(e), subject.to(e), clip.from(a), clip.to(a), clip.from(b), clip.to(b),
                                  *counters_, sameLimit);
}

int ExactArithmetic::exactlyAlongClip(std::uint32_t e, std::uint32_t a, std::uint32_t b, const Operand& subject,
                                      const Operand& clip, bool sameLimit) const {
  return sos::compareAlongClip(clip.from(e), clip.to(e), subject.from(a), subject.to(a), subject.from(b), subject.to(b),
                               *counters_, sameLimit);
}

bool ExactArithmetic::subjectPointInsideClip(Point p, const Operand& clip, const std::uint32_t* edges,
                                             std::size_t count) const {
  return sos::subjectPointInsideClip(p, clip.vertices.data(), clip.next.data(), edges, count, *counters_);
}

bool ExactArithmetic::clipPointInsideSubject(Point q, const Operand& subject, const std::uint32_t* edges,
                                             std::size_t count) const {
  return sos::clipPointInsideSubject(q, subject.vertices.data(), subject.next.data(), edges, count, *counters_);
}

}  // namespace gh::detail
