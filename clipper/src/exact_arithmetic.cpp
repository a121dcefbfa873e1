#include "exact_arithmetic.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "orientation.h"
#include "sos_predicates.h"

namespace gh::detail {
namespace {

// The parameter along a1a2 of its crossing with line b1b2 in the limit,
// t = O(b1,b2,a1) / (O(b1,b2,a1) - O(b1,b2,a2)), with a certified bound on its error (infinite
// when the bound does not apply). Only called for crossing edges, where the denominator is not 0.
// Each orientation is evaluated in doubles with Shewchuk's stage-A bound
// |error| <= (3 + 16u) u (|left| + |right|), valid while nothing under- or overflows.
double certifiedRatio(Point a1, Point a2, Point b1, Point b2, double& err) {
  constexpr double u = 0x1p-53, kBound = (3.0 + 16.0 * u) * u;
  const double bx = b2.x - b1.x, by = b2.y - b1.y;
  const double l1 = bx * (a1.y - b1.y), r1 = by * (a1.x - b1.x);
  const double l2 = bx * (a2.y - b1.y), r2 = by * (a2.x - b1.x);
  const double w1 = l1 - r1, w2 = l2 - r2, d = w1 - w2, t = w1 / d;
  const double s1 = std::abs(l1) + std::abs(r1), s2 = std::abs(l2) + std::abs(r2);
  const double e1 = kBound * s1, e2 = kBound * s2, ed = e1 + e2 + u * std::abs(d);
  const double margin = std::abs(d) - ed;
  const bool safe = s1 + s2 > 0x1p-900 && s1 + s2 < 0x1p900;
  if (!safe || !(margin > 0) || !std::isfinite(t)) {
    err = std::numeric_limits<double>::infinity();
    return t;
  }
  // |w1/d - t| <= (e1 + |t| ed) / (|d| - ed), plus the division's rounding; the last factor
  // covers the rounding of this bound itself.
  err = ((e1 + std::abs(t) * ed) / margin + 2 * u * std::abs(t)) * (1 + 0x1p-20);
  return t;
}

// Decides a < b from certified intervals when they are disjoint: -1 (a first), +1, or 0.
int byIntervals(double a, double ea, double b, double eb) {
  if (a + ea < b - eb) return -1;
  if (b + eb < a - ea) return 1;
  return 0;
}

}  // namespace

PairTest ExactArithmetic::test(const Operand& subject, std::uint32_t subjectEdge, const Operand& clip,
                               std::uint32_t clipEdge) const {
  const Point p1 = subject.from(subjectEdge), p2 = subject.to(subjectEdge);
  const Point q1 = clip.from(clipEdge), q2 = clip.to(clipEdge);
  // Boxes of p and of q translated by (eps, eps^2): a tie on q's low side or p's high side
  // separates them, a tie the other way round overlaps.
  if (std::max(p1.x, p2.x) <= std::min(q1.x, q2.x) || std::max(q1.x, q2.x) < std::min(p1.x, p2.x) ||
      std::max(p1.y, p2.y) <= std::min(q1.y, q2.y) || std::max(q1.y, q2.y) < std::min(p1.y, p2.y)) {
    return {};
  }
  const Sign oP1 = orientation(q1, q2, p1), oP2 = orientation(q1, q2, p2);
  if (sos::clipEdgeSide(oP1, q1, q2) == sos::clipEdgeSide(oP2, q1, q2)) return {};
  const Sign oQ1 = orientation(p1, p2, q1), oQ2 = orientation(p1, p2, q2);
  if (sos::subjectEdgeSide(oQ1, p1, p2) == sos::subjectEdgeSide(oQ2, p1, p2)) return {};

  PairTest t;
  t.kind = PairTest::Kind::Crossing;
  t.crossing.subjectEdge = subjectEdge;
  t.crossing.clipEdge = clipEdge;
  // The point in the limit eps -> 0, from the original coordinates. Where the limit is an input
  // vertex, that vertex exactly; otherwise the crossing of the original segments in doubles.
  if (oP1 == Sign::Zero) {
    t.crossing.point = p1;
  } else if (oP2 == Sign::Zero) {
    t.crossing.point = p2;
  } else if (oQ1 == Sign::Zero) {
    t.crossing.point = q1;
  } else if (oQ2 == Sign::Zero) {
    t.crossing.point = q2;
  }
  // Parameters along both edges (the limit values) with certified error bounds: the sort orders
  // most crossings by them and asks the exact predicate only when two intervals overlap.
  double errS = 0, errC = 0;
  const double aS = certifiedRatio(p1, p2, q1, q2, errS);
  const double aC = certifiedRatio(q1, q2, p1, p2, errC);
  if (oP1 == Sign::Zero) {
    t.crossing.alphaSubject = 0, t.crossing.errSubject = 0;
  } else if (oP2 == Sign::Zero) {
    t.crossing.alphaSubject = 1, t.crossing.errSubject = 0;
  } else {
    t.crossing.alphaSubject = aS, t.crossing.errSubject = errS;
  }
  if (oQ1 == Sign::Zero) {
    t.crossing.alphaClip = 0, t.crossing.errClip = 0;
  } else if (oQ2 == Sign::Zero) {
    t.crossing.alphaClip = 1, t.crossing.errClip = 0;
  } else {
    t.crossing.alphaClip = aC, t.crossing.errClip = errC;
  }
  if (oP1 != Sign::Zero && oP2 != Sign::Zero && oQ1 != Sign::Zero && oQ2 != Sign::Zero) {
    const double a = std::clamp(aS, 0.0, 1.0);
    t.crossing.point = {p1.x + a * (p2.x - p1.x), p1.y + a * (p2.y - p1.y)};
  }
  return t;
}

bool ExactArithmetic::lessAlongSubject(const Crossing& a, const Crossing& b, const Operand& subject,
                                       const Operand& clip) const {
  if (const int quick = byIntervals(a.alphaSubject, a.errSubject, b.alphaSubject, b.errSubject)) return quick < 0;
  const std::uint32_t e = a.subjectEdge;
  return sos::compareAlongSubject(subject.from(e), subject.to(e), clip.from(a.clipEdge), clip.to(a.clipEdge),
                                  clip.from(b.clipEdge), clip.to(b.clipEdge)) < 0;
}

bool ExactArithmetic::lessAlongClip(const Crossing& a, const Crossing& b, const Operand& subject,
                                    const Operand& clip) const {
  if (const int quick = byIntervals(a.alphaClip, a.errClip, b.alphaClip, b.errClip)) return quick < 0;
  const std::uint32_t e = a.clipEdge;
  return sos::compareAlongClip(clip.from(e), clip.to(e), subject.from(a.subjectEdge), subject.to(a.subjectEdge),
                               subject.from(b.subjectEdge), subject.to(b.subjectEdge)) < 0;
}

bool ExactArithmetic::subjectVertexInsideClip(const Operand& subject, std::uint32_t v, const Operand& clip) const {
  return sos::subjectPointInsideClip(subject.vertices[v], clip.vertices.data(), clip.next.data(), clip.size());
}

bool ExactArithmetic::clipVertexInsideSubject(const Operand& clip, std::uint32_t v, const Operand& subject) const {
  return sos::clipPointInsideSubject(clip.vertices[v], subject.vertices.data(), subject.next.data(), subject.size());
}

}  // namespace gh::detail
