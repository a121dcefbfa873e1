// The paper's data structure (Section 4, Figure 6): each operand as doubly linked vertex lists,
// one circular list per ring, with every crossing inserted into both operands' lists as a pair
// of intersection vertices linked by `neighbor`. Indices instead of pointers: one allocation,
// and a bad link is a bounds error instead of a wild pointer.
#pragma once

#include <cstdint>
#include <vector>

#include "phase1_intersections.h"

namespace gh::detail {

inline constexpr std::uint32_t kNone = 0xffffffffu;

struct Node {
  Point p;
  std::uint32_t next = kNone;
  std::uint32_t prev = kNone;
  std::uint32_t neighbor = kNone;  // the other operand's copy; kNone for an original vertex
  bool entry = false;              // phase 2: does the piece after this vertex lie inside?
  bool visited = false;            // phase 3

  bool isIntersection() const { return neighbor != kNone; }
};

struct RingInfo {
  std::uint32_t head;  // node of the ring's first original vertex
  bool startsInside;   // that vertex is inside the other operand
  bool hasCrossing;
};

struct VertexGraph {
  std::vector<Node> nodes;  // subject nodes first, then clip nodes
  std::uint32_t firstClipNode = 0;
  std::vector<RingInfo> subjectRings;
  std::vector<RingInfo> clipRings;

  bool isSubjectNode(std::uint32_t n) const { return n < firstClipNode; }
};

// Builds the linked lists from phase 1's crossings, sorted along every edge.
VertexGraph buildVertexGraph(const Phase1Result& phase1);

// Phase 2 (Figure 9): walk each ring from its first vertex, whose status comes from the
// point-in-region test, and mark intersection vertices alternately entry and exit.
void markEntryExit(VertexGraph& graph);

}  // namespace gh::detail
