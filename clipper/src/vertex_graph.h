// The paper's data structure (Section 4, Figure 6), kept compact: each ring with crossings is a
// circular doubly linked list of its intersection vertices, in order along the ring (phase 1's
// alpha order), each linked to its copy in the other operand (`neighbor`) and carrying the
// entry/exit and visited flags. The paper also links the original vertices into those lists; here
// they stay in the operand's arrays, and the original vertices between two consecutive
// intersection vertices are a contiguous run of their ring, copied in phase 3. Phases 2 and 3 then
// cost O(crossings + output) instead of O(input): what makes the sweep fast on large
// inputs with few crossings. Indices instead of pointers: one allocation, and a bad link is a
// bounds error instead of a wild pointer.
#pragma once

#include <cstdint>
#include <vector>

#include "phase1_result.h"

namespace gh::detail {

inline constexpr std::uint32_t kNone = 0xffffffffu;

struct Node {
  Point p;                       // the crossing point (shared by both copies)
  std::uint32_t next = kNone;    // next intersection vertex along the ring
  std::uint32_t prev = kNone;
  std::uint32_t neighbor = kNone;  // the other operand's copy
  std::uint32_t edge = 0;        // the operand edge it lies on
  std::uint32_t ordinal = 0;     // position along its ring's list (0 = first after the ring start)
  bool entry = false;            // phase 2: does the piece after this vertex lie inside?
  bool visited = false;          // phase 3
};

struct RingInfo {
  std::uint32_t firstVertex;  // the ring's vertices are [firstVertex, endVertex) of its operand
  std::uint32_t endVertex;
  std::uint32_t head;         // its first intersection vertex, kNone if it crosses nothing
  bool startsInside;          // its first vertex is inside the other operand (set by phase 2)
};

struct VertexGraph {
  std::vector<Node> nodes;  // subject intersection vertices first, then the clip's
  std::uint32_t firstClipNode = 0;
  std::vector<RingInfo> subjectRings;
  std::vector<RingInfo> clipRings;
  const Operand* subject = nullptr;  // the vertices actually used (phase 1's copies)
  const Operand* clip = nullptr;
  std::vector<std::uint32_t> subjectRingOfNode;  // ring index of each subject node, likewise clip
  std::vector<std::uint32_t> clipRingOfNode;

  bool isSubjectNode(std::uint32_t n) const { return n < firstClipNode; }
  const Operand& operandOf(std::uint32_t n) const { return isSubjectNode(n) ? *subject : *clip; }
  const RingInfo& ringOf(std::uint32_t n) const {
    return isSubjectNode(n) ? subjectRings[subjectRingOfNode[n]] : clipRings[clipRingOfNode[n - firstClipNode]];
  }

  // Appends to `out` the original vertices passed going forward from intersection vertex `from`
  // to the next one, or backward from `from` to the previous one.
  void appendRunForward(std::uint32_t from, Ring& out) const;
  void appendRunBackward(std::uint32_t from, Ring& out) const;
};

// Builds the lists from phase 1's crossings, sorted along every edge; phase 2 then marks them.
// The graph refers to phase1's operands, which must outlive it.
VertexGraph buildVertexGraph(const Phase1Result& phase1);

}  // namespace gh::detail
