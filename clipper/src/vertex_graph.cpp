#include "vertex_graph.h"

namespace gh::detail {
namespace {

// The rings of one operand and the node range of each (nodes[i] is node id base + i), and the
// ring of every node.
void appendRings(const Operand& operand, std::uint32_t base, std::vector<Node>& nodes, std::vector<RingInfo>& rings) {
  rings.reserve(operand.ringCount());
  std::uint32_t i = 0;
  const auto count = static_cast<std::uint32_t>(nodes.size());
  for (std::uint32_t ring = 0; ring < operand.ringCount(); ++ring) {
    const std::uint32_t begin = operand.ringStart[ring], end = operand.ringStart[ring + 1];
    const std::uint32_t head = i;
    for (; i < count && nodes[i].edge < end; ++i) nodes[i].ring = ring;
    rings.push_back({begin, end, i > head ? base + head : kNone, base + i, false});
  }
}

}  // namespace

VertexGraph buildVertexGraph(Phase1Result& r) {
  VertexGraph g;
  g.subject = &r.subject;
  g.clip = &r.clip;
  g.subjectNodes = &r.subjectNodes;
  g.clipNodes = &r.clipNodes;
  const auto k = static_cast<std::uint32_t>(r.crossingCount());
  g.firstClipNode = k;
  appendRings(r.subject, 0, r.subjectNodes, g.subjectRings);
  appendRings(r.clip, k, r.clipNodes, g.clipRings);
  return g;
}

}  // namespace gh::detail
