#include "arithmetic/paper_arithmetic.h"

#include <algorithm>
#include <cmath>

#include "predicates/even_odd_ray.h"

namespace gh::detail {
namespace {

// The paper's window-edge coordinate of p with respect to the line through q1, q2
// (a cross product: positive on one side, negative on the other, zero on the line).
inline double windowEdgeCoordinate(Point p, Point q1, Point q2) {
  return (p.x - q1.x) * (q2.y - q1.y) - (p.y - q1.y) * (q2.x - q1.x);
}

inline int signOf(double v) { return (v > 0) - (v < 0); }

// Collinear pair: the endpoints of each edge that lie within the other's extent along the line.
std::uint8_t collinearContacts(Point p1, Point p2, Point q1, Point q2) {
  const bool alongX = std::max(std::abs(p2.x - p1.x), std::abs(q2.x - q1.x)) >=
                      std::max(std::abs(p2.y - p1.y), std::abs(q2.y - q1.y));
  auto key = [alongX](Point a) { return alongX ? a.x : a.y; };
  auto within = [&](Point a, Point b, Point c) {
    return key(a) >= std::min(key(b), key(c)) && key(a) <= std::max(key(b), key(c));
  };
  std::uint8_t flags = 0;
  if (within(p1, q1, q2)) flags |= PairTest::kSubjectFrom;
  if (within(p2, q1, q2)) flags |= PairTest::kSubjectTo;
  if (within(q1, p1, p2)) flags |= PairTest::kClipFrom;
  if (within(q2, p1, p2)) flags |= PairTest::kClipTo;
  return flags;
}

PairTest degenerate(std::uint8_t flags) {
  PairTest t;
  t.kind = flags ? PairTest::Kind::Degenerate : PairTest::Kind::None;
  t.onOtherEdge = flags;
  return t;
}

// The library's ray test against every edge of an operand.
bool insideOperand(Point p, const Operand& other, ExactCounters& counters) {
  return insideByRay(
      p,
      [&other](auto&& visit) {
        for (std::uint32_t e = 0; e < other.size(); ++e) visit(other.from(e), other.to(e));
      },
      counters);
}

}  // namespace

PairTest PaperArithmetic::test(const Operand& subject, std::uint32_t subjectEdge, const Operand& clip,
                               std::uint32_t clipEdge, Crossing& out, Extra&) const {
  const Point p1 = subject.from(subjectEdge), p2 = subject.to(subjectEdge);
  const Point q1 = clip.from(clipEdge), q2 = clip.to(clipEdge);
  // The paper's early out (outcodes): disjoint bounding boxes cannot meet.
  if (std::max(p1.x, p2.x) < std::min(q1.x, q2.x) || std::max(q1.x, q2.x) < std::min(p1.x, p2.x) ||
      std::max(p1.y, p2.y) < std::min(q1.y, q2.y) || std::max(q1.y, q2.y) < std::min(p1.y, p2.y)) {
    return {};
  }
  const double wecP1 = windowEdgeCoordinate(p1, q1, q2);
  const double wecP2 = windowEdgeCoordinate(p2, q1, q2);
  const int sP1 = signOf(wecP1), sP2 = signOf(wecP2);
  if (sP1 == 0 && sP2 == 0) return degenerate(collinearContacts(p1, p2, q1, q2));
  if (sP1 * sP2 > 0) return {};
  const double wecQ1 = windowEdgeCoordinate(q1, p1, p2);
  const double wecQ2 = windowEdgeCoordinate(q2, p1, p2);
  const int sQ1 = signOf(wecQ1), sQ2 = signOf(wecQ2);
  if (sQ1 == 0 && sQ2 == 0) return degenerate(collinearContacts(p1, p2, q1, q2));
  if (sQ1 * sQ2 > 0) return {};
  if (sP1 == 0 || sP2 == 0 || sQ1 == 0 || sQ2 == 0) {
    std::uint8_t flags = 0;
    if (sP1 == 0) flags |= PairTest::kSubjectFrom;
    if (sP2 == 0) flags |= PairTest::kSubjectTo;
    if (sQ1 == 0) flags |= PairTest::kClipFrom;
    if (sQ2 == 0) flags |= PairTest::kClipTo;
    return degenerate(flags);
  }
  out.subjectEdge = subjectEdge;
  out.clipEdge = clipEdge;
  out.alphaSubject = wecP1 / (wecP1 - wecP2);
  out.alphaClip = wecQ1 / (wecQ1 - wecQ2);
  const double a = out.alphaSubject;
  out.point = {p1.x + a * (p2.x - p1.x), p1.y + a * (p2.y - p1.y)};
  return {PairTest::Kind::Crossing, 0};
}

bool PaperArithmetic::subjectVertexInsideClip(const Operand& subject, std::uint32_t v, const Operand& clip) const {
  return insideOperand(subject.vertices[v], clip, *counters_);
}

bool PaperArithmetic::clipVertexInsideSubject(const Operand& clip, std::uint32_t v, const Operand& subject) const {
  return insideOperand(clip.vertices[v], subject, *counters_);
}

}  // namespace gh::detail
