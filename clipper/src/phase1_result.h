// What phase 1 hands to phases 2 and 3, whatever the search and arithmetic: data only, so that
// the vertex graph does not depend on how the crossings were found.
//
// The crossings as the paper's two lists of intersection vertices (Section 4, Figure 6), already
// in order: one node per crossing in order along the subject's edges, one per crossing in order
// along the clip's, each knowing where its copy stands in the other list. Phase 2 marks them
// (vertex_graph.h). Fewer than 2^31 crossings.
#pragma once

#include <cstdint>
#include <vector>

#include "ghclip/region.h"
#include "operand.h"

namespace gh::detail {

// A proper crossing of a subject edge with a clip edge, as phase 1 finds it.
struct Crossing {
  std::uint32_t subjectEdge = 0;
  std::uint32_t clipEdge = 0;
  // The one constructed point shared by both copies of the intersection vertex.
  Point point;
  // Position along each edge in [0, 1] (the paper's alpha values). The paper arithmetic orders
  // crossings along an edge by these; the exact arithmetic starts from them.
  double alphaSubject = 0;
  double alphaClip = 0;
};

// An intersection vertex in one operand's list: 24 bytes.
struct Node {
  Point point;         // the crossing (shared by both copies)
  std::uint32_t edge;  // the operand edge it lies on
  std::uint32_t link;  // bits 0-30: position of its copy in the other list; bit 31: entry (phase 2)

  static constexpr std::uint32_t kNeighborBits = 0x7fffffffu;
  Node() = default;
  Node(Point p, std::uint32_t e, std::uint32_t neighborPosition) : point(p), edge(e), link(neighborPosition) {}
  std::uint32_t neighbor() const { return link & kNeighborBits; }
  // Phase 2: does the piece after it lie inside the other operand?
  bool entry() const { return (link >> 31) != 0; }
  void setNeighbor(std::uint32_t position) { link = (link & ~kNeighborBits) | position; }
  void setEntry(bool entry) { link = (link & kNeighborBits) | (static_cast<std::uint32_t>(entry) << 31); }
};
static_assert(sizeof(Node) == 24, "a node is 24 bytes");

struct Phase1Result {
  Operand subject;  // the vertices actually used (perturbed copies for the paper arithmetic)
  Operand clip;
  std::vector<Node> subjectNodes;  // the crossings in order along the subject: by edge, then along it
  std::vector<Node> clipNodes;     // the same crossings in order along the clip

  std::size_t crossingCount() const { return subjectNodes.size(); }
  // Crossing i in order along the subject: its edges and point.
  std::uint32_t subjectEdge(std::size_t i) const { return subjectNodes[i].edge; }
  std::uint32_t clipEdge(std::size_t i) const { return clipNodes[subjectNodes[i].neighbor()].edge; }
  Point point(std::size_t i) const { return subjectNodes[i].point; }
  // Which crossing (in subject order) is j-th along the clip.
  std::uint32_t clipOrder(std::size_t j) const { return clipNodes[j].neighbor(); }
};

}  // namespace gh::detail
