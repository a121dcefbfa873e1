#include "phase3_tracing.h"

#include <algorithm>

#include "ghclip/errors.h"

namespace gh::detail {
namespace {

// Which pieces of each operand's boundary bound op(S, C): a piece of S's boundary lies on the
// result's boundary iff crossing it changes op's truth value, i.e. iff the clip status beside it
// is the one given here (and symmetrically for C). Xor keeps every piece: it is traced as the
// two differences.
bool keepsSubjectPiecesInsideClip(Op op) {
  return op == Op::Intersection || op == Op::ReverseDifference;
}
bool keepsClipPiecesInsideSubject(Op op) {
  return op == Op::Intersection || op == Op::Difference;
}

Ring copyRing(const Operand& op, const RingInfo& ring) {
  return Ring(op.vertices.begin() + ring.firstVertex, op.vertices.begin() + ring.endVertex);
}

void traceOneOp(VertexGraph& g, Op op, Region& out) {
  const bool flipSubject = !keepsSubjectPiecesInsideClip(op);
  const bool flipClip = !keepsClipPiecesInsideSubject(op);
  auto forward = [&](std::uint32_t n) { return (g.entry[n] != 0) != (g.isSubjectNode(n) ? flipSubject : flipClip); };
  std::fill(g.visited.begin(), g.visited.end(), 0);
  // Every step moves to another intersection vertex; a closed trace visits each at most once.
  const std::size_t bound = g.nodeCount() + 4;

  for (std::uint32_t first = 0; first < g.firstClipNode; ++first) {
    if (g.visited[first]) continue;
    Ring traced;
    std::uint32_t current = first;
    for (std::size_t steps = 0;; ++steps) {
      if (steps > bound) throw ClipFailure("tracing did not close within its bound");
      g.visited[g.crossingOf(current)] = 1;
      traced.push_back(g.point(current));
      // Along this operand to the next intersection vertex, then over to the other operand.
      if (forward(current)) {
        g.appendRunForward(current, traced);
        current = g.next(current);
      } else {
        g.appendRunBackward(current, traced);
        current = g.prev(current);
      }
      current = g.neighbor(current);
      if (current == first || g.neighbor(current) == first) break;
      if (g.visited[g.crossingOf(current)]) {
        throw ClipFailure("tracing reached a used intersection vertex (inconsistent entry/exit marks)");
      }
    }
    out.push_back(std::move(traced));
  }

  for (const RingInfo& ring : g.subjectRings) {
    if (ring.head == kNone && ring.startsInside == keepsSubjectPiecesInsideClip(op)) {
      out.push_back(copyRing(*g.subject, ring));
    }
  }
  for (const RingInfo& ring : g.clipRings) {
    if (ring.head == kNone && ring.startsInside == keepsClipPiecesInsideSubject(op)) {
      out.push_back(copyRing(*g.clip, ring));
    }
  }
}

}  // namespace

Region traceResult(VertexGraph& g, Op op) {
  Region out;
  if (op == Op::Xor) {
    traceOneOp(g, Op::Difference, out);
    traceOneOp(g, Op::ReverseDifference, out);
  } else {
    traceOneOp(g, op, out);
  }
  return out;
}

}  // namespace gh::detail
