#include "phase3_tracing.h"

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

Ring copyRing(const VertexGraph& g, std::uint32_t head) {
  Ring ring;
  std::uint32_t n = head;
  do {
    ring.push_back(g.nodes[n].p);
    n = g.nodes[n].next;
  } while (n != head);
  return ring;
}

void traceOneOp(VertexGraph& g, Op op, Region& out) {
  const bool flipSubject = !keepsSubjectPiecesInsideClip(op);
  const bool flipClip = !keepsClipPiecesInsideSubject(op);
  auto forward = [&](std::uint32_t n) {
    return g.nodes[n].entry != (g.isSubjectNode(n) ? flipSubject : flipClip);
  };
  for (Node& node : g.nodes) node.visited = false;
  const std::size_t bound = 2 * g.nodes.size() + 8;

  for (const RingInfo& ring : g.subjectRings) {
    if (!ring.hasCrossing) continue;
    std::uint32_t first = ring.head;
    do {
      if (g.nodes[first].isIntersection() && !g.nodes[first].visited) {
        Ring traced;
        std::uint32_t current = first;
        std::size_t steps = 0;
        for (;;) {
          Node& at = g.nodes[current];
          at.visited = g.nodes[at.neighbor].visited = true;
          traced.push_back(at.p);
          const bool fwd = forward(current);
          do {
            current = fwd ? g.nodes[current].next : g.nodes[current].prev;
            if (!g.nodes[current].isIntersection()) traced.push_back(g.nodes[current].p);
            if (++steps > bound) throw ClipFailure("tracing did not close within its bound");
          } while (!g.nodes[current].isIntersection());
          current = g.nodes[current].neighbor;  // switch operands
          if (current == first || g.nodes[current].neighbor == first) break;
          if (g.nodes[current].visited) {
            throw ClipFailure(
                "tracing reached a used intersection vertex (inconsistent entry/exit marks)");
          }
        }
        out.push_back(std::move(traced));
      }
      first = g.nodes[first].next;
    } while (first != ring.head);
  }

  for (const RingInfo& ring : g.subjectRings) {
    if (!ring.hasCrossing && ring.startsInside == keepsSubjectPiecesInsideClip(op)) {
      out.push_back(copyRing(g, ring.head));
    }
  }
  for (const RingInfo& ring : g.clipRings) {
    if (!ring.hasCrossing && ring.startsInside == keepsClipPiecesInsideSubject(op)) {
      out.push_back(copyRing(g, ring.head));
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
