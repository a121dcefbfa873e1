// Sub-quadratic candidate search: every (subject edge, clip edge) pair whose closed bounding
// boxes overlap.
//
// sweepOverlaps: boxes sorted by xmin; one active list per operand. Entering a box scans the other
// operand's active list, drops boxes that ended before it (lazy compaction, so every box leaves
// once), and reports those whose y-ranges overlap. Why a flat sorted list and not an interval
// tree: real outlines cross a sweep line a handful of times, so the active lists stay short and a
// contiguous scan beats tree descents; on the paper's random workload every box overlaps every
// other in x and any structure reports ~n*m pairs. experiments/sweep_benchmark measures it.
//
// The pairs reported are exactly those the all-pairs search would not reject by its bounding-box
// test (closed boxes, <= comparisons), so with the same arithmetic policy phase 1 finds the same
// crossings and the same degeneracies, bit for bit.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "operand.h"

namespace gh::detail {

struct EdgeBox {
  double minX, maxX, minY, maxY;
  std::uint32_t edge;
};

inline std::vector<EdgeBox> edgeBoxes(const Operand& op) {
  std::vector<EdgeBox> boxes(op.size());
  for (std::uint32_t e = 0; e < op.size(); ++e) {
    const Point a = op.from(e), b = op.to(e);
    boxes[e] = {std::min(a.x, b.x), std::max(a.x, b.x), std::min(a.y, b.y), std::max(a.y, b.y), e};
  }
  std::sort(boxes.begin(), boxes.end(),
            [](const EdgeBox& p, const EdgeBox& q) { return p.minX < q.minX || (p.minX == q.minX && p.edge < q.edge); });
  return boxes;
}

// Calls visit(a.edge, b.edge) for every pair of boxes (one from each list, both sorted by minX)
// whose closed boxes overlap.
template <class Visit>
void sweepOverlaps(const std::vector<EdgeBox>& a, const std::vector<EdgeBox>& b, Visit&& visit) {
  std::vector<const EdgeBox*> activeA, activeB;
  std::size_t i = 0, j = 0;
  auto scan = [](std::vector<const EdgeBox*>& active, const EdgeBox& entering, auto&& report) {
    std::size_t kept = 0;
    for (std::size_t k = 0; k < active.size(); ++k) {
      const EdgeBox* other = active[k];
      if (other->maxX < entering.minX) continue;  // ended: drop
      active[kept++] = other;
      if (other->minY <= entering.maxY && entering.minY <= other->maxY) report(*other);
    }
    active.resize(kept);
  };
  while (i < a.size() || j < b.size()) {
    if (j == b.size() || (i < a.size() && a[i].minX <= b[j].minX)) {
      const EdgeBox& e = a[i++];
      scan(activeB, e, [&](const EdgeBox& other) { visit(e.edge, other.edge); });
      activeA.push_back(&e);
    } else {
      const EdgeBox& e = b[j++];
      scan(activeA, e, [&](const EdgeBox& other) { visit(other.edge, e.edge); });
      activeB.push_back(&e);
    }
  }
}

// An x-monotone run of consecutive ring edges, its edges listed by increasing x.
struct MonotoneChain {
  std::vector<std::uint32_t> edges;  // sorted by x: consecutive x-intervals touch, never overlap
  EdgeBox box;                        // union of the edge boxes; box.edge = chain index
};

inline std::vector<MonotoneChain> monotoneChains(const Operand& op) {
  std::vector<MonotoneChain> chains;
  for (std::size_t ring = 0; ring < op.ringCount(); ++ring) {
    int direction = 0;  // +1 increasing x, -1 decreasing, 0 not yet known (vertical so far)
    for (std::uint32_t e = op.ringStart[ring]; e < op.ringStart[ring + 1]; ++e) {
      const Point a = op.from(e), b = op.to(e);
      const int d = (b.x > a.x) - (b.x < a.x);
      const bool starts = e == op.ringStart[ring] || (d != 0 && direction != 0 && d != direction);
      if (starts) {
        if (!chains.empty() && direction < 0) {
          std::reverse(chains.back().edges.begin(), chains.back().edges.end());
        }
        chains.push_back({{}, {a.x, a.x, a.y, a.y, static_cast<std::uint32_t>(chains.size())}});
        direction = 0;
      }
      if (direction == 0) direction = d;
      MonotoneChain& c = chains.back();
      c.edges.push_back(e);
      c.box.minX = std::min({c.box.minX, a.x, b.x}), c.box.maxX = std::max({c.box.maxX, a.x, b.x});
      c.box.minY = std::min({c.box.minY, a.y, b.y}), c.box.maxY = std::max({c.box.maxY, a.y, b.y});
    }
    if (!chains.empty() && direction < 0) std::reverse(chains.back().edges.begin(), chains.back().edges.end());
  }
  return chains;
}

// All edge pairs of two monotone chains with overlapping closed boxes. Along a chain the edges'
// x-intervals are consecutive, so both minX and maxX are non-decreasing: binary search finds where
// the chains' common x-range starts, and for each edge of `a` the edges of `b` overlapping it in
// x form a contiguous run that only moves right.
template <class Visit>
void walkChainPair(const Operand& opA, const MonotoneChain& a, const Operand& opB, const MonotoneChain& b,
                   Visit&& visit) {
  auto box = [](const Operand& op, std::uint32_t e) {
    const Point p = op.from(e), q = op.to(e);
    return EdgeBox{std::min(p.x, q.x), std::max(p.x, q.x), std::min(p.y, q.y), std::max(p.y, q.y), e};
  };
  const double from = std::max(a.box.minX, b.box.minX);
  auto startOf = [&](const Operand& op, const MonotoneChain& c) {
    return static_cast<std::size_t>(
        std::partition_point(c.edges.begin(), c.edges.end(),
                             [&](std::uint32_t e) { return box(op, e).maxX < from; }) -
        c.edges.begin());
  };
  std::size_t first = startOf(opB, b);
  for (std::size_t i = startOf(opA, a); i < a.edges.size(); ++i) {
    const EdgeBox ba = box(opA, a.edges[i]);
    if (ba.minX > b.box.maxX) break;
    while (first < b.edges.size() && box(opB, b.edges[first]).maxX < ba.minX) ++first;
    for (std::size_t k = first; k < b.edges.size(); ++k) {
      const EdgeBox bb = box(opB, b.edges[k]);
      if (bb.minX > ba.maxX) break;
      if (bb.minY <= ba.maxY && ba.minY <= bb.maxY) visit(ba.edge, bb.edge);
    }
  }
}

// The sweep of the paper's phase 1 on monotone chains: chain boxes are swept as above, then each
// overlapping chain pair is walked. Cost O((n + m) + c log c + P) for c chains and P pairs
// overlapping in x; no sort of individual edges, which is what made a plain edge sweep slow.
struct SweepSearch {
  template <class Visit>
  void forEachCandidate(const Operand& subject, const Operand& clip, Visit&& visit) const {
    const std::vector<MonotoneChain> cs = monotoneChains(subject), cc = monotoneChains(clip);
    std::vector<EdgeBox> bs(cs.size()), bc(cc.size());
    for (std::size_t i = 0; i < cs.size(); ++i) bs[i] = cs[i].box;
    for (std::size_t i = 0; i < cc.size(); ++i) bc[i] = cc[i].box;
    auto byMinX = [](const EdgeBox& p, const EdgeBox& q) {
      return p.minX < q.minX || (p.minX == q.minX && p.edge < q.edge);
    };
    std::sort(bs.begin(), bs.end(), byMinX);
    std::sort(bc.begin(), bc.end(), byMinX);
    sweepOverlaps(bs, bc, [&](std::uint32_t i, std::uint32_t j) {
      walkChainPair(subject, cs[i], clip, cc[j], visit);
    });
  }
};

}  // namespace gh::detail
