#include "vertex_graph.h"

#include <iterator>

namespace gh::detail {
namespace {

// Appends one operand's rings. `edgeOf(id)` is the crossing's edge in this operand, `order` lists
// crossing ids sorted by that edge and position along it; nodeOfCrossing receives the node index
// of each crossing's copy in this operand.
template <class EdgeOf>
void appendOperand(const Operand& operand, const std::vector<Crossing>& crossings,
                   const std::vector<std::uint32_t>& order, EdgeOf edgeOf, VertexGraph& g, std::vector<RingInfo>& rings,
                   std::vector<std::uint32_t>& ringOfNode, std::vector<std::uint32_t>& nodeOfCrossing) {
  std::size_t k = 0;  // position in `order`
  for (std::size_t ring = 0; ring < operand.ringCount(); ++ring) {
    const std::uint32_t begin = operand.ringStart[ring], end = operand.ringStart[ring + 1];
    const auto head = static_cast<std::uint32_t>(g.nodes.size());
    std::uint32_t ordinal = 0;
    for (; k < order.size() && edgeOf(crossings[order[k]]) < end; ++k) {
      Node x;
      x.p = crossings[order[k]].point;
      x.edge = edgeOf(crossings[order[k]]);
      x.ordinal = ordinal++;
      nodeOfCrossing[order[k]] = static_cast<std::uint32_t>(g.nodes.size());
      g.nodes.push_back(x);
      ringOfNode.push_back(static_cast<std::uint32_t>(ring));
    }
    const auto stop = static_cast<std::uint32_t>(g.nodes.size());
    for (std::uint32_t n = head; n < stop; ++n) {
      g.nodes[n].next = n + 1 < stop ? n + 1 : head;
      g.nodes[n].prev = n > head ? n - 1 : stop - 1;
    }
    rings.push_back({begin, end, stop > head ? head : kNone, false});
  }
}

}  // namespace

void VertexGraph::appendRunForward(std::uint32_t from, Ring& out) const {
  const Node& x = nodes[from];
  const Node& y = nodes[x.next];
  const RingInfo& ring = ringOf(from);
  const Point* v = operandOf(from).vertices.data();
  // Same edge and y after x along it: no original vertex in between.
  if (x.edge == y.edge && y.ordinal > x.ordinal) return;
  // Otherwise the vertices after x's edge start, up to y's edge start, cyclically in the ring:
  // one contiguous slice, or two when the run wraps past the ring's last vertex.
  const std::uint32_t first = x.edge + 1 == ring.endVertex ? ring.firstVertex : x.edge + 1;
  if (first <= y.edge) {
    out.insert(out.end(), v + first, v + y.edge + 1);
  } else {
    out.insert(out.end(), v + first, v + ring.endVertex);
    out.insert(out.end(), v + ring.firstVertex, v + y.edge + 1);
  }
}

void VertexGraph::appendRunBackward(std::uint32_t from, Ring& out) const {
  const Node& x = nodes[from];
  const Node& w = nodes[x.prev];
  const RingInfo& ring = ringOf(from);
  const Point* v = operandOf(from).vertices.data();
  if (x.edge == w.edge && w.ordinal < x.ordinal) return;
  // The forward run from w to x, reversed: x.edge down to the vertex after w's edge start.
  const std::uint32_t last = w.edge + 1 == ring.endVertex ? ring.firstVertex : w.edge + 1;
  auto backwards = [&out, v](std::uint32_t hi, std::uint32_t lo) {  // v[hi], v[hi-1], ..., v[lo]
    out.insert(out.end(), std::make_reverse_iterator(v + hi + 1), std::make_reverse_iterator(v + lo));
  };
  if (last <= x.edge) {
    backwards(x.edge, last);
  } else {
    backwards(x.edge, ring.firstVertex);
    backwards(ring.endVertex - 1, last);
  }
}

VertexGraph buildVertexGraph(const Phase1Result& r) {
  VertexGraph g;
  g.subject = &r.subject;
  g.clip = &r.clip;
  g.nodes.reserve(2 * r.crossings.size());
  std::vector<std::uint32_t> inSubject(r.crossings.size()), inClip(r.crossings.size());
  appendOperand(
      r.subject, r.crossings, r.subjectOrder, [](const Crossing& c) { return c.subjectEdge; }, g,
      g.subjectRings, g.subjectRingOfNode, inSubject);
  g.firstClipNode = static_cast<std::uint32_t>(g.nodes.size());
  appendOperand(
      r.clip, r.crossings, r.clipOrder, [](const Crossing& c) { return c.clipEdge; }, g, g.clipRings,
      g.clipRingOfNode, inClip);
  for (std::size_t i = 0; i < r.crossings.size(); ++i) {
    g.nodes[inSubject[i]].neighbor = inClip[i];
    g.nodes[inClip[i]].neighbor = inSubject[i];
  }
  return g;
}

}  // namespace gh::detail
