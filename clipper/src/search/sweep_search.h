// Sub-quadratic candidate search: every (subject edge, clip edge) pair whose closed bounding
// boxes overlap. Edges are grouped into x-monotone chains; the chains' boxes are swept
// (sweepOverlaps), and each pair of overlapping chains is walked edge by edge (walkChainPair).
//
// sweepOverlaps: boxes sorted by xmin; one active list per operand. Entering a box scans the other
// operand's active list, drops boxes that ended before it (lazy compaction, so every box leaves
// once), and reports those whose y-ranges overlap. Why a flat sorted list and not an interval
// tree: real outlines cross a sweep line a handful of times, so the active lists stay short and a
// contiguous scan beats tree descents; on the paper's random workload every box overlaps every
// other in x and any structure reports ~n*m pairs. experiments/sweep_benchmark measures it.
//
// The pairs reported are exactly those whose closed boxes overlap. Every arithmetic policy rejects
// the other pairs by its own box test before deciding anything, so with the same policy phase 1
// finds the same crossings and the same degeneracies as with all pairs, bit for bit.
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

// The x-monotone runs of consecutive ring edges of one operand, in one flat array: chain k's
// edges are edges[begin[k] .. begin[k+1]), listed by increasing x (consecutive x-intervals touch,
// never overlap), and box[k] (with box[k].edge = k) bounds them.
struct MonotoneChains {
  std::vector<std::uint32_t> edges;
  std::vector<std::uint32_t> begin;
  std::vector<EdgeBox> box;
  std::size_t size() const { return box.size(); }
};

inline MonotoneChains monotoneChains(const Operand& op) {
  MonotoneChains c;
  c.edges.reserve(op.size());
  auto close = [&c](int direction) {
    if (direction < 0) std::reverse(c.edges.begin() + c.begin.back(), c.edges.end());
  };
  for (std::size_t ring = 0; ring < op.ringCount(); ++ring) {
    int direction = 0;  // +1 increasing x, -1 decreasing, 0 not yet known (vertical so far)
    for (std::uint32_t e = op.ringStart[ring]; e < op.ringStart[ring + 1]; ++e) {
      const Point a = op.from(e), b = op.to(e);
      const int d = (b.x > a.x) - (b.x < a.x);
      if (e == op.ringStart[ring] || (d != 0 && direction != 0 && d != direction)) {
        if (!c.begin.empty()) close(direction);
        c.begin.push_back(static_cast<std::uint32_t>(c.edges.size()));
        c.box.push_back({a.x, a.x, a.y, a.y, static_cast<std::uint32_t>(c.box.size())});
        direction = 0;
      }
      if (direction == 0) direction = d;
      c.edges.push_back(e);
      EdgeBox& box = c.box.back();
      box.minX = std::min({box.minX, a.x, b.x}), box.maxX = std::max({box.maxX, a.x, b.x});
      box.minY = std::min({box.minY, a.y, b.y}), box.maxY = std::max({box.maxY, a.y, b.y});
    }
    if (!c.begin.empty()) close(direction);
  }
  c.begin.push_back(static_cast<std::uint32_t>(c.edges.size()));
  return c;
}

// All edge pairs of chain i of `a` and chain j of `b` with overlapping closed boxes. Along a chain
// both minX and maxX are non-decreasing: binary search finds where the chains' common x-range
// starts, and for each edge of a the overlapping edges of b are a contiguous run that only moves
// right.
template <class Visit>
void walkChainPair(const Operand& opA, const MonotoneChains& a, std::uint32_t i, const Operand& opB,
                   const MonotoneChains& b, std::uint32_t j, Visit&& visit) {
  auto box = [](const Operand& op, std::uint32_t e) {
    const Point p = op.from(e), q = op.to(e);
    return EdgeBox{std::min(p.x, q.x), std::max(p.x, q.x), std::min(p.y, q.y), std::max(p.y, q.y), e};
  };
  const double from = std::max(a.box[i].minX, b.box[j].minX);
  const std::uint32_t* aBegin = a.edges.data() + a.begin[i];
  const std::uint32_t* aEnd = a.edges.data() + a.begin[i + 1];
  const std::uint32_t* bBegin = b.edges.data() + b.begin[j];
  const std::uint32_t* bEnd = b.edges.data() + b.begin[j + 1];
  const double bMaxX = b.box[j].maxX;
  const std::uint32_t* first =
      std::partition_point(bBegin, bEnd, [&](std::uint32_t e) { return box(opB, e).maxX < from; });
  for (const std::uint32_t* ea = std::partition_point(aBegin, aEnd, [&](std::uint32_t e) { return box(opA, e).maxX < from; });
       ea != aEnd; ++ea) {
    const EdgeBox ba = box(opA, *ea);
    if (ba.minX > bMaxX) break;
    while (first != bEnd && box(opB, *first).maxX < ba.minX) ++first;
    for (const std::uint32_t* eb = first; eb != bEnd; ++eb) {
      const EdgeBox bb = box(opB, *eb);
      if (bb.minX > ba.maxX) break;
      if (bb.minY <= ba.maxY && ba.minY <= bb.maxY) visit(ba.edge, bb.edge);
    }
  }
}

// The sweep of the paper's phase 1 on monotone chains: chain boxes are swept as above, then each
// overlapping chain pair is walked. Cost O((n + m) + c log c + P) for c chains and P pairs
// overlapping in x; no sort of individual edges, which is what made a plain edge sweep slow.
struct SweepSearch {
  // The work as units that can be visited in pieces: a unit is one pair of overlapping chains,
  // in the order the sweep met them.
  struct Plan {
    const Operand* subject;
    const Operand* clip;
    MonotoneChains subjectChains, clipChains;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> chainPairs;
    std::size_t units = 0;
    std::size_t pairsPerUnit = 16;  // for splitting the work: a rough mean per chain pair
    static constexpr bool rows = false;  // units are visited pair by pair (onPair)
    template <class OnRow, class OnPair>
    void visit(std::size_t begin, std::size_t end, OnRow&&, OnPair&& onPair) const {
      for (std::size_t u = begin; u < end; ++u) {
        walkChainPair(*subject, subjectChains, chainPairs[u].first, *clip, clipChains, chainPairs[u].second, onPair);
      }
    }
  };

  Plan plan(const Operand& subject, const Operand& clip) const {
    Plan p{&subject, &clip, monotoneChains(subject), monotoneChains(clip), {}, 0, 16};
    std::vector<EdgeBox> bs = p.subjectChains.box, bc = p.clipChains.box;
    auto byMinX = [](const EdgeBox& a, const EdgeBox& b) { return a.minX < b.minX || (a.minX == b.minX && a.edge < b.edge); };
    std::sort(bs.begin(), bs.end(), byMinX);
    std::sort(bc.begin(), bc.end(), byMinX);
    sweepOverlaps(bs, bc, [&p](std::uint32_t i, std::uint32_t j) { p.chainPairs.emplace_back(i, j); });
    p.units = p.chainPairs.size();
    return p;
  }

  template <class Visit>
  void forEachCandidate(const Operand& subject, const Operand& clip, Visit&& visit) const {
    const Plan p = plan(subject, clip);
    p.visit(0, p.units, [](std::uint32_t) {}, visit);
  }
};

}  // namespace gh::detail
