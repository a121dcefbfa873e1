#include "vertex_graph.h"

namespace gh::detail {
namespace {

// Appends one operand's rings to the graph. `edgeOf(id)` is the crossing's edge in this operand,
// `order` lists crossing ids sorted by that edge and position along it; nodeOfCrossing receives
// the node index of each crossing's copy in this operand.
template <class EdgeOf>
void appendOperand(const Operand& operand, const std::vector<char>& ringInside,
                   const std::vector<Crossing>& crossings, const std::vector<std::uint32_t>& order,
                   EdgeOf edgeOf, VertexGraph& g, std::vector<RingInfo>& rings,
                   std::vector<std::uint32_t>& nodeOfCrossing) {
  std::size_t k = 0;  // position in `order`
  for (std::size_t ring = 0; ring < operand.ringCount(); ++ring) {
    const auto head = static_cast<std::uint32_t>(g.nodes.size());
    bool hasCrossing = false;
    for (std::uint32_t v = operand.ringStart[ring]; v < operand.ringStart[ring + 1]; ++v) {
      Node vertex;
      vertex.p = operand.vertices[v];
      g.nodes.push_back(vertex);
      for (; k < order.size() && edgeOf(crossings[order[k]]) == v; ++k) {
        Node x;
        x.p = crossings[order[k]].point;
        x.neighbor = 0;  // linked to the real neighbour once both operands exist
        nodeOfCrossing[order[k]] = static_cast<std::uint32_t>(g.nodes.size());
        g.nodes.push_back(x);
        hasCrossing = true;
      }
    }
    const auto end = static_cast<std::uint32_t>(g.nodes.size());
    for (std::uint32_t n = head; n < end; ++n) {
      g.nodes[n].next = n + 1 < end ? n + 1 : head;
      g.nodes[n].prev = n > head ? n - 1 : end - 1;
    }
    rings.push_back({head, ringInside[ring] != 0, hasCrossing});
  }
}

}  // namespace

VertexGraph buildVertexGraph(const Phase1Result& r) {
  VertexGraph g;
  g.nodes.reserve(r.subject.size() + r.clip.size() + 2 * r.crossings.size());
  std::vector<std::uint32_t> inSubject(r.crossings.size()), inClip(r.crossings.size());
  appendOperand(
      r.subject, r.subjectRingInside, r.crossings, r.subjectOrder,
      [](const Crossing& c) { return c.subjectEdge; }, g, g.subjectRings, inSubject);
  g.firstClipNode = static_cast<std::uint32_t>(g.nodes.size());
  appendOperand(
      r.clip, r.clipRingInside, r.crossings, r.clipOrder,
      [](const Crossing& c) { return c.clipEdge; }, g, g.clipRings, inClip);
  for (std::size_t i = 0; i < r.crossings.size(); ++i) {
    g.nodes[inSubject[i]].neighbor = inClip[i];
    g.nodes[inClip[i]].neighbor = inSubject[i];
  }
  return g;
}

void markEntryExit(VertexGraph& g) {
  for (const auto* rings : {&g.subjectRings, &g.clipRings}) {
    for (const RingInfo& ring : *rings) {
      if (!ring.hasCrossing) continue;
      bool status = !ring.startsInside;  // entry when starting outside
      std::uint32_t n = ring.head;
      do {
        Node& node = g.nodes[n];
        if (node.isIntersection()) {
          node.entry = status;
          status = !status;
        }
        n = node.next;
      } while (n != ring.head);
    }
  }
}

}  // namespace gh::detail
