#include "arithmetic/paper_arithmetic.h"

#include <algorithm>
#include <cmath>

#include "predicates/even_odd_ray.h"

namespace gh::detail {

PairTest paper::collinearContacts(Point p1, Point p2, Point q1, Point q2) {
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
  return {flags ? PairTest::Kind::Degenerate : PairTest::Kind::None, flags};
}

void PaperArithmetic::testRow(const Operand& subject, std::uint32_t se, const Operand& clip,
                              CrossingBuffer<Extra>& into) const {
  const Point p1 = subject.from(se), p2 = subject.to(se);
  const auto m = static_cast<std::uint32_t>(clip.size());
  const Point* v = clip.vertices.data();
  const std::uint32_t* next = clip.next.data();
  into.pairs += m;
  Crossing c;
  for (std::uint32_t ce = 0; ce < m; ++ce) {
    const PairTest t = paper::intersect(p1, p2, se, v[ce], v[next[ce]], ce, c);
    if (t.kind == PairTest::Kind::Crossing) {
      into.crossings.push_back(c);
    } else if (t.kind == PairTest::Kind::Degenerate) {
      into.addDegenerate(t, se, ce, subject, clip);
    }
  }
}

namespace {

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

bool PaperArithmetic::subjectVertexInsideClip(const Operand& subject, std::uint32_t v, const Operand& clip) const {
  return insideOperand(subject.vertices[v], clip, *counters_);
}

bool PaperArithmetic::clipVertexInsideSubject(const Operand& clip, std::uint32_t v, const Operand& subject) const {
  return insideOperand(clip.vertices[v], subject, *counters_);
}

}  // namespace gh::detail
