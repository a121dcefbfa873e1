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
                              const EdgeArrays* clipArrays, CrossingBuffer<Extra>& into) const {
  const Point p1 = subject.from(se), p2 = subject.to(se);
  const auto m = static_cast<std::uint32_t>(clip.size());
  const Point* v = clip.vertices.data();
  const std::uint32_t* next = clip.next.data();
  into.pairs += m;
  if (clipArrays) {
    struct Context {
      const Operand &subject, &clip;
      std::uint32_t se;
      Point p1, p2;
      CrossingBuffer<Extra>& into;
    } context{subject, clip, se, p1, p2, into};
    paperRow(
        p1.x, p1.y, p2.x, p2.y, *clipArrays,
        [](void* c, std::uint32_t ce, double alphaS, double alphaC, double x, double y) {
          static_cast<Context*>(c)->into.crossings.push_back({static_cast<Context*>(c)->se, ce, {x, y}, alphaS, alphaC});
        },
        [](void* c, std::uint32_t ce) {
          Context& k = *static_cast<Context*>(c);
          Crossing crossing;
          const PairTest t = paper::intersect(k.p1, k.p2, k.se, k.clip.from(ce), k.clip.to(ce), ce, crossing);
          if (t.kind == PairTest::Kind::Crossing) {
            k.into.crossings.push_back(crossing);
          } else if (t.kind == PairTest::Kind::Degenerate) {
            k.into.addDegenerate(t, k.se, ce, k.subject, k.clip);
          }
        },
        &context);
    return;
  }
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

// The library's ray test against the listed edges of an operand (all when `edges` is null).
bool insideOperand(Point p, const Operand& other, const std::uint32_t* edges, std::size_t count,
                   ExactCounters& counters) {
  return insideByRay(
      p,
      [&](auto&& visit) {
        for (std::size_t i = 0; i < count; ++i) {
          const std::uint32_t e = edges ? edges[i] : static_cast<std::uint32_t>(i);
          visit(other.from(e), other.to(e));
        }
      },
      counters);
}

}  // namespace

bool PaperArithmetic::subjectPointInsideClip(Point p, const Operand& clip, const std::uint32_t* edges,
                                             std::size_t count) const {
  return insideOperand(p, clip, edges, count, *counters_);
}

bool PaperArithmetic::clipPointInsideSubject(Point q, const Operand& subject, const std::uint32_t* edges,
                                             std::size_t count) const {
  return insideOperand(q, subject, edges, count, *counters_);
}

}  // namespace gh::detail
