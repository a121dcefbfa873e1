#include "phase3_tracing.h"

#include <algorithm>

#include "ghclip/errors.h"
#include "parallel.h"
#include "scratch.h"

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

// An operand edge as a number over both operands: the subject's first, then the clip's.
std::uint32_t edgeNumber(const VertexGraph& g, const Operand& op, std::uint32_t edge) {
  return &op == g.subject ? edge : static_cast<std::uint32_t>(g.subject->size()) + edge;
}

void copyRing(const VertexGraph& g, const Operand& op, const RingInfo& ring, FlatRings& out,
              std::vector<std::uint32_t>* lines) {
  out.points.insert(out.points.end(), op.vertices.begin() + ring.firstVertex, op.vertices.begin() + ring.endVertex);
  out.closeRing();
  if (lines) {
    for (std::uint32_t v = ring.firstVertex; v < ring.endVertex; ++v) lines->push_back(edgeNumber(g, op, v));
  }
}

// Where the trace goes from an intersection vertex: the node it reaches over in the other
// operand, and the crossing this vertex is a copy of.
struct Step {
  std::uint32_t next;
  std::uint32_t crossing;
};

// The original vertices passed from `from` to `to`, forward or backward along their ring.
std::uint32_t runLength(const VertexGraph& g, std::uint32_t from, std::uint32_t to, bool forward, const RingInfo& ring) {
  const std::uint32_t fromEdge = g.node(from).edge, toEdge = g.node(to).edge;
  if (forward) {
    if (fromEdge == toEdge && to > from) return 0;
    const std::uint32_t first = fromEdge + 1 == ring.endVertex ? ring.firstVertex : fromEdge + 1;
    return first <= toEdge ? toEdge + 1 - first : (ring.endVertex - first) + (toEdge + 1 - ring.firstVertex);
  }
  if (fromEdge == toEdge && to < from) return 0;
  const std::uint32_t last = toEdge + 1 == ring.endVertex ? ring.firstVertex : toEdge + 1;
  return last <= fromEdge ? fromEdge + 1 - last : (fromEdge + 1 - ring.firstVertex) + (ring.endVertex - last);
}

// Traced in three passes, so that only the second walks the answer's rings one vertex after the
// other: (1) for every intersection vertex, independently (in pieces over threads), where the
// trace goes from it and how many points it adds; (2) the walk, over those 8-byte steps only,
// giving the order of the vertices and the rings; (3) the points written, independently, each
// vertex at its offset. The walk is what a trace is in the paper, with its checks: it throws
// ClipFailure if a trace does not close within its bound or reaches a used vertex.
void traceOneOp(VertexGraph& g, Op op, FlatRings& out, unsigned threads, std::vector<std::uint32_t>* lines) {
  const bool flipSubject = !keepsSubjectPiecesInsideClip(op);
  const bool flipClip = !keepsClipPiecesInsideSubject(op);
  const std::uint32_t k = g.firstClipNode, nodes = g.nodeCount();
  // Working arrays in the thread's scratch block (scratch.h), every element written before it is
  // read: phase 1's sort items are gone by now, this takes their place.
  ScratchLayout layout;
  const auto stepsSlot = layout.add<Step>(nodes);
  const auto countsSlot = layout.add<std::uint32_t>(nodes);
  const auto forwardsSlot = layout.add<std::uint8_t>(nodes);
  const auto visitedSlot = layout.add<std::uint8_t>(k);
  const auto sequenceSlot = layout.add<std::uint32_t>(k);
  const auto offsetsSlot = layout.add<std::size_t>(std::size_t{k} + 1);
  std::byte* base = scratch(layout.bytes());
  Step* steps = stepsSlot(base);
  std::uint32_t* counts = countsSlot(base);
  std::uint8_t* forwards = forwardsSlot(base);
  std::uint8_t* visited = visitedSlot(base);
  std::uint32_t* sequence = sequenceSlot(base);
  std::size_t* offsets = offsetsSlot(base);
  const Pieces nodePieces = piecesFor(nodes, threads, 1 << 14);
  runPieces(nodePieces, threads, [&](std::size_t p) {
    const auto begin = static_cast<std::uint32_t>(nodePieces.begin(p)), end = static_cast<std::uint32_t>(nodePieces.end(p));
    if (begin == end) return;
    // The rings of the piece's nodes, in node order: found once, then followed.
    auto ring = std::upper_bound(g.ringsByNode.begin(), g.ringsByNode.end(), begin,
                                 [](std::uint32_t node, const auto& r) { return node < r.second; });
    for (std::uint32_t n = begin; n < end; ++n) {
      while (n >= ring->second) ++ring;
      const RingInfo& info = g.isSubjectNode(n) ? g.subjectRings[ring->first] : g.clipRings[ring->first];
      const Node& at = g.node(n);
      const bool forward = at.entry() != (g.isSubjectNode(n) ? flipSubject : flipClip);
      const std::uint32_t to = forward ? VertexGraph::next(n, info) : VertexGraph::prev(n, info);
      steps[n] = {g.neighbor(to), g.isSubjectNode(n) ? n : at.neighbor()};
      counts[n] = 1 + runLength(g, n, to, forward, info);
      forwards[n] = forward;
    }
  });

  std::fill(visited, visited + k, std::uint8_t{0});
  std::uint32_t walked = 0;
  std::vector<std::uint32_t> ringEnds;
  // Every step moves to another intersection vertex; a closed trace visits each at most once.
  const std::size_t bound = std::size_t{nodes} + 4;
  for (std::uint32_t first = 0; first < k; ++first) {
    if (visited[first]) continue;
    std::uint32_t current = first;
    for (std::size_t count = 0;; ++count) {
      if (count > bound) throw ClipFailure("tracing did not close within its bound");
      visited[steps[current].crossing] = 1;
      if (walked == k) throw ClipFailure("tracing did not close within its bound");
      sequence[walked++] = current;
      current = steps[current].next;
      const std::uint32_t crossing = steps[current].crossing;
      if (crossing == first) break;  // back at the first vertex, or at its other copy
      if (visited[crossing]) {
        throw ClipFailure("tracing reached a used intersection vertex (inconsistent entry/exit marks)");
      }
    }
    ringEnds.push_back(walked);
  }

  offsets[0] = out.points.size();
  for (std::uint32_t i = 0; i < walked; ++i) offsets[i + 1] = offsets[i] + counts[sequence[i]];
  out.points.resize(offsets[walked]);
  if (lines) lines->resize(offsets[walked]);
  const Pieces fillPieces = piecesFor(walked, threads, 1 << 14);
  runPieces(fillPieces, threads, [&](std::size_t p) {
    for (std::size_t i = fillPieces.begin(p); i < fillPieces.end(p); ++i) {
      const std::uint32_t n = sequence[i];
      Point* at = out.points.data() + offsets[i];
      *at++ = g.node(n).point;
      // The answer's edge from the intersection vertex runs along its edge, either way; from an
      // original vertex, along the edge that leaves it in the direction walked.
      const Operand& operand = g.operandOf(n);
      const std::uint32_t edge = g.node(n).edge;
      std::uint32_t* line = lines ? lines->data() + offsets[i] : nullptr;
      if (line) *line++ = edgeNumber(g, operand, edge) | kTracedCrossing;
      if (counts[n] == 1) continue;
      // The run after it: forward from the vertex after its edge's start, or backward from its
      // edge's start, cyclically in its ring.
      const bool forward = forwards[n] != 0;
      const RingInfo& ring = g.ringOf(n);
      const Point* v = operand.vertices.data();
      std::uint32_t vertex = !forward ? edge : edge + 1 == ring.endVertex ? ring.firstVertex : edge + 1;
      for (std::uint32_t c = 1; c < counts[n]; ++c) {
        *at++ = v[vertex];
        const std::uint32_t before = vertex == ring.firstVertex ? ring.endVertex - 1 : vertex - 1;
        if (line) *line++ = edgeNumber(g, operand, forward ? vertex : before);
        if (forward) {
          vertex = vertex + 1 == ring.endVertex ? ring.firstVertex : vertex + 1;
        } else {
          vertex = before;
        }
      }
    }
  });
  for (std::uint32_t end : ringEnds) out.start.push_back(static_cast<std::uint32_t>(offsets[end]));

  for (const RingInfo& ring : g.subjectRings) {
    if (ring.head == kNone && ring.startsInside == keepsSubjectPiecesInsideClip(op)) {
      copyRing(g, *g.subject, ring, out, lines);
    }
  }
  for (const RingInfo& ring : g.clipRings) {
    if (ring.head == kNone && ring.startsInside == keepsClipPiecesInsideSubject(op)) {
      copyRing(g, *g.clip, ring, out, lines);
    }
  }
}

}  // namespace

void traceResult(VertexGraph& g, Op op, FlatRings& out, unsigned threads, std::vector<std::uint32_t>* lines) {
  if (op == Op::Xor) {
    traceOneOp(g, Op::Difference, out, threads, lines);
    traceOneOp(g, Op::ReverseDifference, out, threads, lines);
  } else {
    traceOneOp(g, op, out, threads, lines);
  }
}

Region traceResult(VertexGraph& g, Op op) {
  FlatRings out;
  traceResult(g, op, out);
  return out.toRegion();
}

}  // namespace gh::detail
