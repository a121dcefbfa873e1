#include "vertex_graph.h"


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
