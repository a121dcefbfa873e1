// The paper's data structure (Section 4, Figure 6), kept implicit: each ring with crossings is a
// circular doubly linked list of its intersection vertices in order along the ring, each linked to
// its copy in the other operand (`neighbor`) and carrying the entry/exit and visited flags.
//
// Phase 1 hands the crossings over in order along the subject and the order along the clip, so
// the lists need no links of their own: node n of the subject is crossing n, its successor is
// n + 1 (or its ring's first node), and node k + j of the clip is crossing clipOrder[j]. Only the
// neighbour map from subject nodes to clip positions, the ring of each node and one flag per node
// are stored: no per-crossing allocation, about 30 bytes per crossing.
//
// The paper also links the original vertices into those lists; here they stay in the operand's
// arrays, and the original vertices between two consecutive intersection vertices are a
// contiguous run of their ring, copied in phase 3. Phases 2 and 3 then cost O(crossings + output)
// instead of O(input): what makes the sweep fast on large inputs with few crossings. Indices
// instead of pointers: a bad link is a bounds error instead of a wild pointer.
#pragma once

#include <cstdint>
#include <vector>

#include "phase1_result.h"

namespace gh::detail {

inline constexpr std::uint32_t kNone = 0xffffffffu;

struct RingInfo {
  std::uint32_t firstVertex;  // the ring's vertices are [firstVertex, endVertex) of its operand
  std::uint32_t endVertex;
  std::uint32_t head;         // its first intersection vertex (node), kNone if it crosses nothing
  std::uint32_t endNode;      // one past its last node
  bool startsInside;          // its first vertex is inside the other operand (set by phase 2)
};

struct VertexGraph {
  const Operand* subject = nullptr;  // the vertices actually used (phase 1's copies)
  const Operand* clip = nullptr;
  const std::vector<Crossing>* crossings = nullptr;  // in order along the subject
  std::uint32_t firstClipNode = 0;                  // k: subject nodes 0..k-1, clip nodes k..2k-1
  std::vector<std::uint32_t> clipToSubject;         // clip position j -> crossing (= subject node)
  std::vector<std::uint32_t> subjectToClip;         // subject node i -> clip position
  std::vector<std::uint32_t> ringOfNode;            // per node, its ring in its operand
  std::vector<RingInfo> subjectRings;
  std::vector<RingInfo> clipRings;
  std::vector<std::uint8_t> entry;    // per node, phase 2: does the piece after it lie inside?
  std::vector<std::uint8_t> visited;  // per crossing, phase 3

  std::uint32_t nodeCount() const { return 2 * firstClipNode; }
  bool isSubjectNode(std::uint32_t n) const { return n < firstClipNode; }
  std::uint32_t crossingOf(std::uint32_t n) const { return isSubjectNode(n) ? n : clipToSubject[n - firstClipNode]; }
  std::uint32_t neighbor(std::uint32_t n) const {
    return isSubjectNode(n) ? firstClipNode + subjectToClip[n] : clipToSubject[n - firstClipNode];
  }
  Point point(std::uint32_t n) const { return (*crossings)[crossingOf(n)].point; }
  std::uint32_t edge(std::uint32_t n) const {
    const Crossing& c = (*crossings)[crossingOf(n)];
    return isSubjectNode(n) ? c.subjectEdge : c.clipEdge;
  }
  const Operand& operandOf(std::uint32_t n) const { return isSubjectNode(n) ? *subject : *clip; }
  const RingInfo& ringOf(std::uint32_t n) const {
    return isSubjectNode(n) ? subjectRings[ringOfNode[n]] : clipRings[ringOfNode[n]];
  }
  std::uint32_t next(std::uint32_t n) const {
    const RingInfo& r = ringOf(n);
    return n + 1 < r.endNode ? n + 1 : r.head;
  }
  std::uint32_t prev(std::uint32_t n) const {
    const RingInfo& r = ringOf(n);
    return n > r.head ? n - 1 : r.endNode - 1;
  }

  // Appends to `out` the original vertices passed going forward from intersection vertex `from`
  // to the next one `to` (= next(from)), or backward from `from` to the previous one (= prev(from)).
  void appendRunForward(std::uint32_t from, std::uint32_t to, std::vector<Point>& out) const {
    const std::uint32_t fromEdge = edge(from), toEdge = edge(to);
    // Same edge and `to` after `from` along it: no original vertex in between.
    if (fromEdge == toEdge && to > from) return;
    const RingInfo& ring = ringOf(from);
    const Point* v = operandOf(from).vertices.data();
    // Otherwise the vertices after from's edge start, up to to's edge start, cyclically in the
    // ring: one contiguous slice, or two when the run wraps past the ring's last vertex.
    const std::uint32_t first = fromEdge + 1 == ring.endVertex ? ring.firstVertex : fromEdge + 1;
    if (first <= toEdge) {
      out.insert(out.end(), v + first, v + toEdge + 1);
    } else {
      out.insert(out.end(), v + first, v + ring.endVertex);
      out.insert(out.end(), v + ring.firstVertex, v + toEdge + 1);
    }
  }
  void appendRunBackward(std::uint32_t from, std::uint32_t to, std::vector<Point>& out) const {
    const std::uint32_t fromEdge = edge(from), toEdge = edge(to);
    if (fromEdge == toEdge && to < from) return;
    const RingInfo& ring = ringOf(from);
    const Point* v = operandOf(from).vertices.data();
    // The forward run from `to` to `from`, reversed: from's edge down to the vertex after to's
    // edge start.
    const std::uint32_t last = toEdge + 1 == ring.endVertex ? ring.firstVertex : toEdge + 1;
    auto backwards = [&out, v](std::uint32_t hi, std::uint32_t lo) {  // v[hi], v[hi-1], ..., v[lo]
      for (std::uint32_t i = hi + 1; i-- > lo;) out.push_back(v[i]);
    };
    if (last <= fromEdge) {
      backwards(fromEdge, last);
    } else {
      backwards(fromEdge, ring.firstVertex);
      backwards(ring.endVertex - 1, last);
    }
  }
};

// Builds the lists from phase 1's ordered crossings; phase 2 then marks them. The graph refers to
// phase1's operands and crossings, which must outlive it.
VertexGraph buildVertexGraph(const Phase1Result& phase1);

}  // namespace gh::detail
