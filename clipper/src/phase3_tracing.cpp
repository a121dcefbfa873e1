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

void copyRing(const Operand& op, const RingInfo& ring, FlatRings& out) {
  out.points.insert(out.points.end(), op.vertices.begin() + ring.firstVertex, op.vertices.begin() + ring.endVertex);
  out.closeRing();
}

void traceOneOp(VertexGraph& g, Op op, FlatRings& out) {
  const bool flipSubject = !keepsSubjectPiecesInsideClip(op);
  const bool flipClip = !keepsClipPiecesInsideSubject(op);
  auto forward = [&](std::uint32_t n) { return (g.entry[n] != 0) != (g.isSubjectNode(n) ? flipSubject : flipClip); };
  std::fill(g.visited.begin(), g.visited.end(), 0);
  // Every step moves to another intersection vertex; a closed trace visits each at most once.
  const std::size_t bound = g.nodeCount() + 4;

  for (std::uint32_t first = 0; first < g.firstClipNode; ++first) {
    if (g.visited[first]) continue;
    std::vector<Point>& traced = out.points;
    std::uint32_t current = first;
    for (std::size_t steps = 0;; ++steps) {
      if (steps > bound) throw ClipFailure("tracing did not close within its bound");
      g.visited[g.crossingOf(current)] = 1;
      traced.push_back(g.point(current));
      // Along this operand to the next intersection vertex, then over to the other operand.
      if (forward(current)) {
        const std::uint32_t to = g.next(current);
        g.appendRunForward(current, to, traced);
        current = to;
      } else {
        const std::uint32_t to = g.prev(current);
        g.appendRunBackward(current, to, traced);
        current = to;
      }
      current = g.neighbor(current);
      if (current == first || g.neighbor(current) == first) break;
      if (g.visited[g.crossingOf(current)]) {
        throw ClipFailure("tracing reached a used intersection vertex (inconsistent entry/exit marks)");
      }
    }
    out.closeRing();
  }

  for (const RingInfo& ring : g.subjectRings) {
    if (ring.head == kNone && ring.startsInside == keepsSubjectPiecesInsideClip(op)) {
      copyRing(*g.subject, ring, out);
    }
  }
  for (const RingInfo& ring : g.clipRings) {
    if (ring.head == kNone && ring.startsInside == keepsClipPiecesInsideSubject(op)) {
      copyRing(*g.clip, ring, out);
    }
  }
}

}  // namespace

void traceResult(VertexGraph& g, Op op, FlatRings& out) {
  if (op == Op::Xor) {
    traceOneOp(g, Op::Difference, out);
    traceOneOp(g, Op::ReverseDifference, out);
  } else {
    traceOneOp(g, op, out);
  }
}

Region traceResult(VertexGraph& g, Op op) {
  FlatRings out;
  traceResult(g, op, out);
  return out.toRegion();
}

}  // namespace gh::detail
