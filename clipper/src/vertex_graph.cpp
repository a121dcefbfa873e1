#include "vertex_graph.h"

namespace gh::detail {
namespace {

// The rings of one operand and the node range of each (nodes[i] is node id base + i).
void appendRings(const Operand& operand, std::uint32_t base, const std::vector<Node>& nodes, std::vector<RingInfo>& rings,
                 std::vector<std::pair<std::uint32_t, std::uint32_t>>& ringsByNode) {
  rings.reserve(operand.ringCount());
  std::uint32_t i = 0;
  const auto count = static_cast<std::uint32_t>(nodes.size());
  for (std::uint32_t ring = 0; ring < operand.ringCount(); ++ring) {
    const std::uint32_t begin = operand.ringStart[ring], end = operand.ringStart[ring + 1];
    const std::uint32_t head = i;
    while (i < count && nodes[i].edge < end) ++i;
    rings.push_back({begin, end, i > head ? base + head : kNone, base + i, false});
    if (i > head) ringsByNode.emplace_back(ring, base + i);
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
  appendRings(r.subject, 0, r.subjectNodes, g.subjectRings, g.ringsByNode);
  appendRings(r.clip, k, r.clipNodes, g.clipRings, g.ringsByNode);
  return g;
}

}  // namespace gh::detail
