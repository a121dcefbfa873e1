#include "exact_arithmetic.h"

#include <algorithm>

#include "orientation.h"
#include "sos_predicates.h"

namespace gh::detail {
namespace {

int signOfDifference(double a, double b) { return (a > b) - (a < b); }

// SoS sides from exact orientations (the expansions of sos_predicates.h, with O computed once).
Sign clipSide(Sign o, Point q1, Point q2) {
  if (o != Sign::Zero) return o;
  const int dy = signOfDifference(q2.y, q1.y);
  return toSign(dy != 0 ? dy : -signOfDifference(q2.x, q1.x));
}
Sign subjectSide(Sign o, Point p1, Point p2) {
  if (o != Sign::Zero) return o;
  const int ey = signOfDifference(p2.y, p1.y);
  return toSign(ey != 0 ? -ey : signOfDifference(p2.x, p1.x));
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
  if (clipSide(oP1, q1, q2) == clipSide(oP2, q1, q2)) return {};
  const Sign oQ1 = orientation(p1, p2, q1), oQ2 = orientation(p1, p2, q2);
  if (subjectSide(oQ1, p1, p2) == subjectSide(oQ2, p1, p2)) return {};

  PairTest t;
  t.kind = PairTest::Kind::Crossing;
  t.crossing.subjectEdge = subjectEdge;
  t.crossing.clipEdge = clipEdge;
  // The point in the limit eps -> 0, from the original coordinates. Where the limit is an input
  // vertex, that vertex exactly; otherwise the crossing of the original segments in doubles.
  if (oP1 == Sign::Zero) {
    t.crossing.point = p1, t.crossing.alphaSubject = 0;
  } else if (oP2 == Sign::Zero) {
    t.crossing.point = p2, t.crossing.alphaSubject = 1;
  } else if (oQ1 == Sign::Zero) {
    t.crossing.point = q1, t.crossing.alphaClip = 0;
  } else if (oQ2 == Sign::Zero) {
    t.crossing.point = q2, t.crossing.alphaClip = 1;
  } else {
    const double w1 = (p1.x - q1.x) * (q2.y - q1.y) - (p1.y - q1.y) * (q2.x - q1.x);
    const double w2 = (p2.x - q1.x) * (q2.y - q1.y) - (p2.y - q1.y) * (q2.x - q1.x);
    const double a = std::clamp(w1 / (w1 - w2), 0.0, 1.0);
    t.crossing.alphaSubject = a;
    t.crossing.point = {p1.x + a * (p2.x - p1.x), p1.y + a * (p2.y - p1.y)};
  }
  return t;
}

bool ExactArithmetic::lessAlongSubject(const Crossing& a, const Crossing& b, const Operand& subject,
                                       const Operand& clip) const {
  const std::uint32_t e = a.subjectEdge;
  return sos::compareAlongSubject(subject.from(e), subject.to(e), clip.from(a.clipEdge), clip.to(a.clipEdge),
                                  clip.from(b.clipEdge), clip.to(b.clipEdge)) < 0;
}

bool ExactArithmetic::lessAlongClip(const Crossing& a, const Crossing& b, const Operand& subject,
                                    const Operand& clip) const {
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
