#include "vertex_graph.h"

#include <iterator>

namespace gh::detail {
namespace {

// The rings of one operand and the node range of each: nodes `base + i` for the i-th crossing in
// order along this operand, whose edge is edgeAt(i).
template <class EdgeAt>
void appendRings(const Operand& operand, std::uint32_t base, std::uint32_t count, EdgeAt edgeAt,
                 std::vector<RingInfo>& rings, std::uint32_t* ringOfNode) {
  rings.reserve(operand.ringCount());
  std::uint32_t i = 0;
  for (std::uint32_t ring = 0; ring < operand.ringCount(); ++ring) {
    const std::uint32_t begin = operand.ringStart[ring], end = operand.ringStart[ring + 1];
    const std::uint32_t head = i;
    for (; i < count && edgeAt(i) < end; ++i) ringOfNode[i] = ring;
    rings.push_back({begin, end, i > head ? base + head : kNone, base + i, false});
  }
}

}  // namespace

void VertexGraph::appendRunForward(std::uint32_t from, Ring& out) const {
  const std::uint32_t to = next(from);
  const std::uint32_t fromEdge = edge(from), toEdge = edge(to);
  // Same edge and `to` after `from` along it: no original vertex in between.
  if (fromEdge == toEdge && to > from) return;
  const RingInfo& ring = ringOf(from);
  const Point* v = operandOf(from).vertices.data();
  // Otherwise the vertices after from's edge start, up to to's edge start, cyclically in the ring:
  // one contiguous slice, or two when the run wraps past the ring's last vertex.
  const std::uint32_t first = fromEdge + 1 == ring.endVertex ? ring.firstVertex : fromEdge + 1;
  if (first <= toEdge) {
    out.insert(out.end(), v + first, v + toEdge + 1);
  } else {
    out.insert(out.end(), v + first, v + ring.endVertex);
    out.insert(out.end(), v + ring.firstVertex, v + toEdge + 1);
  }
}

void VertexGraph::appendRunBackward(std::uint32_t from, Ring& out) const {
  const std::uint32_t to = prev(from);
  const std::uint32_t fromEdge = edge(from), toEdge = edge(to);
  if (fromEdge == toEdge && to < from) return;
  const RingInfo& ring = ringOf(from);
  const Point* v = operandOf(from).vertices.data();
  // The forward run from `to` to `from`, reversed: from's edge down to the vertex after to's edge
  // start.
  const std::uint32_t last = toEdge + 1 == ring.endVertex ? ring.firstVertex : toEdge + 1;
  auto backwards = [&out, v](std::uint32_t hi, std::uint32_t lo) {  // v[hi], v[hi-1], ..., v[lo]
    out.insert(out.end(), std::make_reverse_iterator(v + hi + 1), std::make_reverse_iterator(v + lo));
  };
  if (last <= fromEdge) {
    backwards(fromEdge, last);
  } else {
    backwards(fromEdge, ring.firstVertex);
    backwards(ring.endVertex - 1, last);
  }
}

VertexGraph buildVertexGraph(const Phase1Result& r) {
  VertexGraph g;
  g.subject = &r.subject;
  g.clip = &r.clip;
  g.crossings = &r.crossings;
  const auto k = static_cast<std::uint32_t>(r.crossings.size());
  g.firstClipNode = k;
  g.clipToSubject = r.clipOrder;
  g.subjectToClip.resize(k);
  for (std::uint32_t j = 0; j < k; ++j) g.subjectToClip[r.clipOrder[j]] = j;
  g.ringOfNode.resize(2 * static_cast<std::size_t>(k));
  const auto& cs = r.crossings;
  appendRings(
      r.subject, 0, k, [&cs](std::uint32_t i) { return cs[i].subjectEdge; }, g.subjectRings, g.ringOfNode.data());
  appendRings(
      r.clip, k, k, [&](std::uint32_t j) { return cs[r.clipOrder[j]].clipEdge; }, g.clipRings,
      g.ringOfNode.data() + k);
  g.entry.assign(2 * static_cast<std::size_t>(k), 0);
  g.visited.assign(k, 0);
  return g;
}

}  // namespace gh::detail
