// The paper's data structure (Section 4, Figure 6): each ring with crossings is a circular doubly
// linked list of its intersection vertices in order along the ring, each linked to its copy in the
// other operand (`neighbor`) and carrying the entry/exit flag.
//
// Phase 1 hands the crossings over as two lists already in order (phase1_result.h), so the lists
// need no links of their own: node i's successor in its list is i + 1, or its ring's first node.
// The graph adds the rings and their node ranges; phase 2 marks the nodes. Node ids: subject
// nodes 0..k-1, clip nodes k..2k-1.
//
// The paper also links the original vertices into those lists; here they stay in the operand's
// arrays, and the original vertices between two consecutive intersection vertices are a
// contiguous run of their ring, copied in phase 3. Phases 2 and 3 then cost O(crossings + output)
// instead of O(input): what makes the sweep fast on large inputs with few crossings. Indices
// instead of pointers: a bad link is a bounds error instead of a wild pointer.
#pragma once

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include "phase1_result.h"

namespace gh::detail {

inline constexpr std::uint32_t kNone = 0xffffffffu;

struct RingInfo {
  std::uint32_t firstVertex;  // the ring's vertices are [firstVertex, endVertex) of its operand
  std::uint32_t endVertex;
  std::uint32_t head;         // its first intersection vertex (node id), kNone if it crosses nothing
  std::uint32_t endNode;      // one past its last node
  bool startsInside;          // its first vertex is inside the other operand (set by phase 2)
};

struct VertexGraph {
  const Operand* subject = nullptr;  // the vertices actually used (phase 1's copies)
  const Operand* clip = nullptr;
  std::vector<Node>* subjectNodes = nullptr;  // phase 1's lists, marked in place
  std::vector<Node>* clipNodes = nullptr;
  std::uint32_t firstClipNode = 0;  // k
  std::vector<RingInfo> subjectRings;
  std::vector<RingInfo> clipRings;
  // The rings with crossings, by their nodes: ring index and one past its last node, in node order.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> ringsByNode;

  std::uint32_t nodeCount() const { return 2 * firstClipNode; }
  bool isSubjectNode(std::uint32_t n) const { return n < firstClipNode; }
  Node& node(std::uint32_t n) { return isSubjectNode(n) ? (*subjectNodes)[n] : (*clipNodes)[n - firstClipNode]; }
  const Node& node(std::uint32_t n) const {
    return isSubjectNode(n) ? (*subjectNodes)[n] : (*clipNodes)[n - firstClipNode];
  }
  // The node id of n's copy in the other list.
  std::uint32_t neighbor(std::uint32_t n) const {
    return isSubjectNode(n) ? firstClipNode + (*subjectNodes)[n].neighbor() : (*clipNodes)[n - firstClipNode].neighbor();
  }
  // The crossing n is a copy of, numbered by its subject node.
  std::uint32_t crossingOf(std::uint32_t n) const { return isSubjectNode(n) ? n : neighbor(n); }
  const Operand& operandOf(std::uint32_t n) const { return isSubjectNode(n) ? *subject : *clip; }
  // The ring of node n (a binary search over the rings with crossings).
  const RingInfo& ringOf(std::uint32_t n) const {
    const auto it = std::upper_bound(ringsByNode.begin(), ringsByNode.end(), n,
                                     [](std::uint32_t node, const auto& ring) { return node < ring.second; });
    return isSubjectNode(n) ? subjectRings[it->first] : clipRings[it->first];
  }
  // The next and previous intersection vertex along n's ring r.
  static std::uint32_t next(std::uint32_t n, const RingInfo& r) { return n + 1 < r.endNode ? n + 1 : r.head; }
  static std::uint32_t prev(std::uint32_t n, const RingInfo& r) { return n > r.head ? n - 1 : r.endNode - 1; }
  std::uint32_t next(std::uint32_t n) const { return next(n, ringOf(n)); }
  std::uint32_t prev(std::uint32_t n) const { return prev(n, ringOf(n)); }
};

// Builds the rings over phase 1's lists; phase 2 then marks them. The graph refers to phase1's
// operands and lists, which must outlive it.
VertexGraph buildVertexGraph(Phase1Result& phase1);

}  // namespace gh::detail
